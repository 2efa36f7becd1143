#include "core/algorithms/exact/any_angle_grid.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "absl/strings/str_format.h"

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
  std::vector<int8_t> cells(static_cast<size_t>(w) * h, OccupancyGrid::kFree);
  // In sub-cells. kUpper blocks a sub-cell whose square comes closer than `reach` to a blocked
  // square; kLower one whose centre lies closer than `reach` less half a sub-cell diagonal (every
  // point of it then lies closer than `reach`: distance is 1-Lipschitz).
  const double reach = clearance / grid.resolution() * s;
  const double lower_reach = reach - std::numbers::sqrt2 / 2;
  // Per cell, from D, the distance between its centre and the nearest blocked cell's (the
  // grid's own distance field): every point of the cell lies at least D - sqrt(2) and at most
  // D + sqrt(2) / 2 from the nearest blocked square. Only cells between the two need their
  // sub-cells measured, against the blocked squares within `window` cells (those that can come
  // closer than the clearance).
  const double reach_cells = clearance / grid.resolution();
  const int window = static_cast<int>(std::ceil(reach_cells)) + 1;
  const auto fill = [&](int x, int y) {
    for (int j = 0; j < s; ++j) {
      std::fill_n(cells.begin() + (static_cast<size_t>(y * s + j) * w + x * s), s,
                  OccupancyGrid::kOccupied);
    }
  };
  std::vector<Cell> near;
  for (int y = 0; y < grid.height(); ++y) {
    for (int x = 0; x < grid.width(); ++x) {
      const double d = grid.DistanceToObstacle(x, y) / grid.resolution();
      if (d == 0.0 || d + std::numbers::sqrt2 * (0.5 + 0.5 / s) < reach_cells) {
        fill(x, y);
        continue;
      }
      if (d - std::numbers::sqrt2 >= reach_cells) continue;
      near.clear();
      for (int ny = std::max(0, y - window); ny <= std::min(grid.height() - 1, y + window); ++ny) {
        for (int nx = std::max(0, x - window); nx <= std::min(grid.width() - 1, x + window); ++nx) {
          if (grid.IsBlocked(nx, ny)) near.push_back({nx * s, ny * s});
        }
      }
      if (near.empty()) continue;
      for (int j = 0; j < s; ++j) {
        for (int i = 0; i < s; ++i) {
          const int sx = x * s + i, sy = y * s + j;
          bool blocked = false;
          for (const Cell& c : near) {
            if (bound == ClearanceBound::kUpper) {
              const double gx = std::max({0, c.x - (sx + 1), sx - (c.x + s)});
              const double gy = std::max({0, c.y - (sy + 1), sy - (c.y + s)});
              blocked = gx * gx + gy * gy < reach * reach;
            } else {
              const double gx = std::max({0.0, c.x - (sx + 0.5), (sx + 0.5) - (c.x + s)});
              const double gy = std::max({0.0, c.y - (sy + 0.5), (sy + 0.5) - (c.y + s)});
              blocked = lower_reach > 0 && gx * gx + gy * gy < lower_reach * lower_reach;
            }
            if (blocked) break;
          }
          if (blocked) cells[static_cast<size_t>(sy) * w + sx] = OccupancyGrid::kOccupied;
        }
      }
    }
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
