#include "core/algorithms/exact/any_angle_grid.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "absl/strings/str_format.h"
#include "core/geometry/distance_transform.h"

namespace swarmplan {

OccupancyGrid InflateGrid(const OccupancyGrid& grid, double clearance) {
  const int w = grid.width(), h = grid.height();
  // The distance between the squares of cells (i, j) and (k, l) is
  // hypot(max(|i - k| - 1, 0), max(|j - l| - 1, 0)): the centre distance from (i, j) to the
  // blocked set dilated by one cell in the 8-neighbourhood.
  std::vector<uint8_t> dilated(static_cast<size_t>(w) * h, 0);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (!grid.IsBlocked(x, y)) continue;
      for (int ny = std::max(0, y - 1); ny <= std::min(h - 1, y + 1); ++ny) {
        for (int nx = std::max(0, x - 1); nx <= std::min(w - 1, x + 1); ++nx) {
          dilated[static_cast<size_t>(ny) * w + nx] = 1;
        }
      }
    }
  }
  const std::vector<double> squared = SquaredDistanceTransform(w, h, dilated);
  const double reach = clearance / grid.resolution() + 1.0 / 16.0;
  std::vector<int8_t> cells(static_cast<size_t>(w) * h, OccupancyGrid::kFree);
  for (size_t i = 0; i < cells.size(); ++i) {
    if (squared[i] < reach * reach) cells[i] = OccupancyGrid::kOccupied;
  }
  // Same size, resolution and origin as a grid that was valid: Create cannot fail.
  absl::StatusOr<OccupancyGrid> inflated =
      OccupancyGrid::Create(w, h, std::move(cells), grid.resolution(), grid.origin());
  return *std::move(inflated);
}

AnyAngleGrid AnyAngleGrid::Build(const OccupancyGrid& grid, double clearance) {
  AnyAngleGrid result;
  if (clearance > 0) {
    result.inflated_ = std::make_shared<const OccupancyGrid>(InflateGrid(grid, clearance));
    result.planning_ = result.inflated_.get();
  } else {
    result.planning_ = &grid;
  }
  const OccupancyGrid& planning = *result.planning_;
  result.row_start_.reserve(planning.height() + 1);
  for (int y = 0; y < planning.height(); ++y) {
    result.row_start_.push_back(static_cast<int>(result.runs_.size()));
    int x = 0;
    while (x < planning.width()) {
      if (planning.IsBlocked(x, y)) {
        ++x;
        continue;
      }
      const int begin = x;
      while (x < planning.width() && !planning.IsBlocked(x, y)) ++x;
      result.runs_.push_back(Run{begin, x});
    }
  }
  result.row_start_.push_back(static_cast<int>(result.runs_.size()));
  return result;
}

const AnyAngleGrid::Run* AnyAngleGrid::RunsBegin(int y) const {
  if (y < 0 || y >= height()) return runs_.data();
  return runs_.data() + row_start_[y];
}

const AnyAngleGrid::Run* AnyAngleGrid::RunsEnd(int y) const {
  if (y < 0 || y >= height()) return runs_.data();
  return runs_.data() + row_start_[y + 1];
}

const AnyAngleGrid::Run* AnyAngleGrid::RunAt(int y, int x) const {
  if (Blocked(x, y)) return nullptr;
  const Run* end = RunsEnd(y);
  const Run* it = std::upper_bound(RunsBegin(y), end, x,
                                   [](int value, const Run& run) { return value < run.end; });
  return it != end && it->begin <= x ? it : nullptr;
}

int64_t AnyAngleGrid::MemoryBytes() const {
  int64_t bytes =
      static_cast<int64_t>(runs_.capacity() * sizeof(Run) + row_start_.capacity() * sizeof(int));
  if (inflated_ != nullptr) {
    const int64_t cells = static_cast<int64_t>(inflated_->width()) * inflated_->height();
    bytes += cells * (sizeof(int8_t) + sizeof(uint8_t) + sizeof(double));
  }
  return bytes;
}

std::shared_ptr<const AnyAngleGrid> AnyAngleGridFor(const Map& map, double clearance) {
  const OccupancyGrid& grid = *map.grid();
  return map.Derived<AnyAngleGrid>(absl::StrFormat("any-angle-grid clearance=%a", clearance),
                                   [&] { return AnyAngleGrid::Build(grid, clearance); });
}

}  // namespace swarmplan
