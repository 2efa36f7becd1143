#include "core/algorithms/exact/any_angle_grid.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "absl/strings/str_format.h"
#include "core/geometry/distance_transform.h"

namespace swarmplan {

int ClearanceSubdivision(const OccupancyGrid& grid) {
  const int64_t cells = static_cast<int64_t>(grid.width()) * grid.height();
  for (const int s : {4, 2}) {
    if (cells * s * s <= kMaxSubdividedCells) return s;
  }
  return 1;
}

OccupancyGrid ClearanceGrid(const OccupancyGrid& grid, double clearance, ClearanceBound bound) {
  const int s = ClearanceSubdivision(grid);
  const int w = grid.width() * s, h = grid.height() * s;
  const auto index = [w](int x, int y) { return static_cast<size_t>(y) * w + x; };
  std::vector<uint8_t> obstacle(static_cast<size_t>(w) * h, 0);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) obstacle[index(x, y)] = grid.IsBlocked(x / s, y / s) ? 1 : 0;
  }
  // Distances in the planning grid's cells. kUpper: the distance between the squares of cells
  // (i, j) and (k, l) is hypot(max(|i - k| - 1, 0), max(|j - l| - 1, 0)), the centre distance
  // from (i, j) to the obstacle dilated by one cell in the 8-neighbourhood. kLower: a point of
  // cell (i, j) lies within half a diagonal of its centre, which lies within the centre
  // distance of an obstacle cell's centre.
  std::vector<uint8_t> dilated;
  if (bound == ClearanceBound::kUpper) {
    dilated.assign(obstacle.size(), 0);
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        if (!obstacle[index(x, y)]) continue;
        for (int ny = std::max(0, y - 1); ny <= std::min(h - 1, y + 1); ++ny) {
          for (int nx = std::max(0, x - 1); nx <= std::min(w - 1, x + 1); ++nx) {
            dilated[index(nx, ny)] = 1;
          }
        }
      }
    }
  }
  const std::vector<double> squared =
      SquaredDistanceTransform(w, h, bound == ClearanceBound::kUpper ? dilated : obstacle);
  const double reach = clearance / grid.resolution() * s;
  const double lower_reach = reach - std::numbers::sqrt2 / 2;
  std::vector<int8_t> cells(obstacle.size(), OccupancyGrid::kFree);
  for (size_t i = 0; i < cells.size(); ++i) {
    const bool blocked =
        bound == ClearanceBound::kUpper
            ? squared[i] < reach * reach
            : obstacle[i] || (lower_reach > 0 && squared[i] < lower_reach * lower_reach);
    if (blocked) cells[i] = OccupancyGrid::kOccupied;
  }
  MapLimits limits;
  limits.max_cells = std::max<int64_t>(limits.max_cells, static_cast<int64_t>(cells.size()));
  absl::StatusOr<OccupancyGrid> subdivided =
      OccupancyGrid::Create(w, h, std::move(cells), grid.resolution() / s, grid.origin(), limits);
  // The map's extent split into more cells of the same total size: Create cannot fail.
  return *std::move(subdivided);
}

AnyAngleGrid AnyAngleGrid::Build(const OccupancyGrid& grid, double clearance,
                                 ClearanceBound bound) {
  AnyAngleGrid result;
  if (clearance > 0) {
    result.subdivided_ =
        std::make_shared<const OccupancyGrid>(ClearanceGrid(grid, clearance, bound));
    result.planning_ = result.subdivided_.get();
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
  if (subdivided_ != nullptr) {
    const int64_t cells = static_cast<int64_t>(subdivided_->width()) * subdivided_->height();
    bytes += cells * (sizeof(int8_t) + sizeof(uint8_t));
  }
  return bytes;
}

std::shared_ptr<const AnyAngleGrid> AnyAngleGridFor(const Map& map, double clearance,
                                                    ClearanceBound bound) {
  const OccupancyGrid& grid = *map.grid();
  const char* side = bound == ClearanceBound::kUpper ? "upper" : "lower";
  return map.Derived<AnyAngleGrid>(
      absl::StrFormat("any-angle-grid clearance=%a bound=%s", clearance, side),
      [&] { return AnyAngleGrid::Build(grid, clearance, bound); });
}

}  // namespace swarmplan
