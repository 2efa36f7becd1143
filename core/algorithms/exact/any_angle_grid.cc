#include "core/algorithms/exact/any_angle_grid.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
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

namespace {

// The clearance of ClearanceGrid in sub-cells, and whether a sub-cell lies near a blocked map
// cell by the bound's test: kUpper blocks a sub-cell whose square comes closer than `reach` to
// the blocked square; kLower one whose centre lies closer than `reach` less half a sub-cell
// diagonal (every point of it then lies closer than `reach`: distance is 1-Lipschitz).
struct SubCellReach {
  SubCellReach(const OccupancyGrid& grid, double clearance, ClearanceBound bound)
      : s(ClearanceSubdivision(grid)),
        reach(clearance / grid.resolution() * s),
        lower_reach(reach - std::numbers::sqrt2 / 2),
        window(static_cast<int>(std::ceil(clearance / grid.resolution())) + 1),
        bound(bound) {}

  // Sub-cell (sx, sy) against the blocked map cell whose lowest sub-cell is `c`.
  bool Near(int sx, int sy, const Cell& c) const {
    if (bound == ClearanceBound::kUpper) {
      const double gx = std::max({0, c.x - (sx + 1), sx - (c.x + s)});
      const double gy = std::max({0, c.y - (sy + 1), sy - (c.y + s)});
      return gx * gx + gy * gy < reach * reach;
    }
    const double gx = std::max({0.0, c.x - (sx + 0.5), (sx + 0.5) - (c.x + s)});
    const double gy = std::max({0.0, c.y - (sy + 0.5), (sy + 0.5) - (c.y + s)});
    return lower_reach > 0 && gx * gx + gy * gy < lower_reach * lower_reach;
  }

  int s;
  double reach;
  double lower_reach;
  int window;  // map cells around a blocked cell whose sub-cells may lie near it
  ClearanceBound bound;
};

OccupancyGrid SubdividedGrid(const OccupancyGrid& grid, int s, std::vector<int8_t> cells) {
  MapLimits limits;
  limits.max_cells = std::max<int64_t>(limits.max_cells, static_cast<int64_t>(cells.size()));
  absl::StatusOr<OccupancyGrid> subdivided =
      OccupancyGrid::Create(grid.width() * s, grid.height() * s, std::move(cells),
                            grid.resolution() / s, grid.origin(), limits);
  // The map's extent split into more cells of the same total size: Create cannot fail.
  return *std::move(subdivided);
}

// The sub-cells of a ClearanceGrid that lie near one of the map cells `blocked` (repeats
// included).
std::vector<Cell> SubCellsNear(const OccupancyGrid& grid, const std::vector<Cell>& blocked,
                               const SubCellReach& near_by) {
  const int s = near_by.s;
  const int w = grid.width() * s, h = grid.height() * s;
  std::vector<Cell> near;
  for (const Cell& b : blocked) {
    if (!grid.InBounds(b)) continue;
    const Cell lowest{b.x * s, b.y * s};
    const int x0 = std::max(0, (b.x - near_by.window) * s);
    const int x1 = std::min(w - 1, (b.x + near_by.window + 1) * s - 1);
    const int y0 = std::max(0, (b.y - near_by.window) * s);
    const int y1 = std::min(h - 1, (b.y + near_by.window + 1) * s - 1);
    for (int sy = y0; sy <= y1; ++sy) {
      for (int sx = x0; sx <= x1; ++sx) {
        const bool inside = sx / s == b.x && sy / s == b.y;
        if (inside || near_by.Near(sx, sy, lowest)) near.push_back({sx, sy});
      }
    }
  }
  return near;
}

}  // namespace

OccupancyGrid ClearanceGrid(const OccupancyGrid& grid, double clearance, ClearanceBound bound) {
  const SubCellReach near_by(grid, clearance, bound);
  const int s = near_by.s;
  const int w = grid.width() * s, h = grid.height() * s;
  std::vector<int8_t> cells(static_cast<size_t>(w) * h, OccupancyGrid::kFree);
  // Per cell, from D, the distance between its centre and the nearest blocked cell's (the
  // grid's own distance field): every point of the cell lies at least D - sqrt(2) and at most
  // D + sqrt(2) / 2 from the nearest blocked square. Only cells between the two need their
  // sub-cells measured, against the blocked squares within `window` cells (those that can come
  // closer than the clearance).
  const double reach_cells = clearance / grid.resolution();
  const int window = near_by.window;
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
          for (const Cell& c : near) {
            if (near_by.Near(sx, sy, c)) {
              cells[static_cast<size_t>(sy) * w + sx] = OccupancyGrid::kOccupied;
              break;
            }
          }
        }
      }
    }
  }
  return SubdividedGrid(grid, s, std::move(cells));
}

OccupancyGrid ClearanceGridBlocking(const OccupancyGrid& base, const OccupancyGrid& grid,
                                    const std::vector<Cell>& blocked, double clearance,
                                    ClearanceBound bound) {
  // A sub-cell is blocked when it lies near any blocked cell: the base's blocked sub-cells stay,
  // and those near a newly blocked cell join them.
  return base.WithBlocked(SubCellsNear(grid, blocked, SubCellReach(grid, clearance, bound)));
}

AnyAngleGrid AnyAngleGrid::Build(const OccupancyGrid& grid, double clearance,
                                 ClearanceBound bound) {
  if (clearance > 0) {
    return OnPlanningGrid(
        std::make_shared<const OccupancyGrid>(ClearanceGrid(grid, clearance, bound)));
  }
  AnyAngleGrid result;
  result.planning_ = &grid;
  result.FindRuns();
  return result;
}

AnyAngleGrid AnyAngleGrid::BuildBlocking(const AnyAngleGrid& base, const OccupancyGrid& grid,
                                         const std::vector<Cell>& blocked, double clearance,
                                         ClearanceBound bound) {
  if (clearance <= 0) return Build(grid, clearance, bound);
  const std::vector<Cell> near = SubCellsNear(grid, blocked, SubCellReach(grid, clearance, bound));
  AnyAngleGrid result;
  result.subdivided_ =
      std::make_shared<const OccupancyGrid>(base.planning_grid().WithBlocked(near));
  result.planning_ = result.subdivided_.get();
  // Only the rows that hold a newly blocked sub-cell have other runs than the base's.
  std::vector<uint8_t> changed(result.height(), 0);
  for (const Cell& c : near) changed[c.y] = 1;
  result.runs_.reserve(base.runs_.size() + near.size());
  result.row_start_.reserve(result.height() + 1);
  for (int y = 0; y < result.height(); ++y) {
    result.row_start_.push_back(static_cast<int>(result.runs_.size()));
    if (changed[y]) {
      result.AppendRunsOfRow(y);
    } else {
      result.runs_.insert(result.runs_.end(), base.RunsBegin(y), base.RunsEnd(y));
    }
  }
  result.row_start_.push_back(static_cast<int>(result.runs_.size()));
  return result;
}

AnyAngleGrid AnyAngleGrid::OnPlanningGrid(std::shared_ptr<const OccupancyGrid> subdivided) {
  AnyAngleGrid result;
  result.subdivided_ = std::move(subdivided);
  result.planning_ = result.subdivided_.get();
  result.FindRuns();
  return result;
}

void AnyAngleGrid::FindRuns() {
  row_start_.reserve(height() + 1);
  for (int y = 0; y < height(); ++y) {
    row_start_.push_back(static_cast<int>(runs_.size()));
    AppendRunsOfRow(y);
  }
  row_start_.push_back(static_cast<int>(runs_.size()));
}

void AnyAngleGrid::AppendRunsOfRow(int y) {
  const OccupancyGrid& planning = *planning_;
  int x = 0;
  while (x < planning.width()) {
    if (planning.IsBlocked(x, y)) {
      ++x;
      continue;
    }
    const int begin = x;
    while (x < planning.width() && !planning.IsBlocked(x, y)) ++x;
    runs_.push_back(Run{begin, x});
  }
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
    bytes += cells * sizeof(int8_t);
  }
  return bytes;
}

std::shared_ptr<const AnyAngleGrid> AnyAngleGridFor(const Map& map, double clearance,
                                                    ClearanceBound bound) {
  const OccupancyGrid& grid = *map.grid();
  const char* side = bound == ClearanceBound::kUpper ? "upper" : "lower";
  const std::string key = absl::StrFormat("any-angle-grid clearance=%a bound=%s", clearance, side);
  if (const Map::GridPatch* patch = map.patch(); patch != nullptr && clearance > 0) {
    const std::shared_ptr<const AnyAngleGrid> base =
        AnyAngleGridFor(*patch->base, clearance, bound);
    return map.Derived<AnyAngleGrid>(key, [&] {
      return AnyAngleGrid::BuildBlocking(*base, grid, patch->blocked, clearance, bound);
    });
  }
  return map.Derived<AnyAngleGrid>(key,
                                   [&] { return AnyAngleGrid::Build(grid, clearance, bound); });
}

}  // namespace swarmplan
