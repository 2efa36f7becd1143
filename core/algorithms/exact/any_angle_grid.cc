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
        bound(bound),
        squared_limit(bound == ClearanceBound::kUpper ? reach * reach
                      : lower_reach > 0               ? lower_reach * lower_reach
                                                      : -1.0) {}

  // The gap along one axis between sub-cell v (its square, or for kLower its centre) and the
  // blocked map cell whose lowest sub-cell is c.
  double AxisGap(int v, int c) const {
    if (bound == ClearanceBound::kUpper) return std::max({0, c - (v + 1), v - (c + s)});
    return std::max({0.0, c - (v + 0.5), (v + 0.5) - (c + s)});
  }

  // Sub-cell (sx, sy) against the blocked map cell whose lowest sub-cell is `c`.
  bool Near(int sx, int sy, const Cell& c) const {
    const double gx = AxisGap(sx, c.x), gy = AxisGap(sy, c.y);
    return gx * gx + gy * gy < squared_limit;
  }

  int s;
  double reach;
  double lower_reach;
  int window;  // map cells around a blocked cell whose sub-cells may lie near it
  ClearanceBound bound;
  double squared_limit;  // a sub-cell is near when its squared gaps sum to less
};

// SubCellReach::Near for every sub-cell of one map cell against the blocked cells within the
// window around it: the squared gaps per axis first, then per sub-cell a count of the near
// blocked cells without an exit per cell, which the compiler vectorises.
class WindowTest {
 public:
  WindowTest(const OccupancyGrid& grid, const SubCellReach& near_by)
      : grid_(grid),
        near_by_(near_by),
        capacity_((2 * near_by.window + 1) * (2 * near_by.window + 1)) {
    lowest_x_.resize(capacity_);
    lowest_y_.resize(capacity_);
    squared_x_.resize(static_cast<size_t>(near_by.s) * capacity_);
    squared_y_.resize(static_cast<size_t>(near_by.s) * capacity_);
  }

  // Blocks the sub-cells of map cell (x, y) near a blocked cell in `cells` (the sub-cell grid).
  void BlockNear(int x, int y, std::vector<int8_t>& cells) {
    const int s = near_by_.s, window = near_by_.window;
    const int8_t* values = grid_.cells().data();
    int k = 0;
    for (int ny = std::max(0, y - window); ny <= std::min(grid_.height() - 1, y + window); ++ny) {
      const int8_t* row = values + static_cast<size_t>(ny) * grid_.width();
      for (int nx = std::max(0, x - window); nx <= std::min(grid_.width() - 1, x + window); ++nx) {
        lowest_x_[k] = nx * s;
        lowest_y_[k] = ny * s;
        k += OccupancyGrid::IsBlockedValue(row[nx]) ? 1 : 0;
      }
    }
    if (k == 0) return;
    for (int i = 0; i < s; ++i) {
      double* gx = squared_x_.data() + static_cast<size_t>(i) * capacity_;
      double* gy = squared_y_.data() + static_cast<size_t>(i) * capacity_;
      for (int j = 0; j < k; ++j) {
        const double a = near_by_.AxisGap(x * s + i, lowest_x_[j]);
        const double b = near_by_.AxisGap(y * s + i, lowest_y_[j]);
        gx[j] = a * a;
        gy[j] = b * b;
      }
    }
    const int w = grid_.width() * s;
    const double limit = near_by_.squared_limit;
    for (int l = 0; l < s; ++l) {
      const double* gy = squared_y_.data() + static_cast<size_t>(l) * capacity_;
      int8_t* out = cells.data() + static_cast<size_t>(y * s + l) * w + x * s;
      for (int i = 0; i < s; ++i) {
        const double* gx = squared_x_.data() + static_cast<size_t>(i) * capacity_;
        int near = 0;
        for (int j = 0; j < k; ++j) near += gx[j] + gy[j] < limit ? 1 : 0;
        if (near > 0) out[i] = OccupancyGrid::kOccupied;
      }
    }
  }

 private:
  const OccupancyGrid& grid_;
  const SubCellReach& near_by_;
  const int capacity_;
  std::vector<int> lowest_x_, lowest_y_;
  std::vector<double> squared_x_, squared_y_;  // s rows of capacity_: sub-cell column (row) i
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
  // sub-cells measured, against the blocked squares within the window (those that can come
  // closer than the clearance).
  const double reach_cells = clearance / grid.resolution();
  const auto fill = [&](int x, int y) {
    for (int j = 0; j < s; ++j) {
      std::fill_n(cells.begin() + (static_cast<size_t>(y * s + j) * w + x * s), s,
                  OccupancyGrid::kOccupied);
    }
  };
  WindowTest near_blocked(grid, near_by);
  for (int y = 0; y < grid.height(); ++y) {
    for (int x = 0; x < grid.width(); ++x) {
      const double d = grid.DistanceToObstacle(x, y) / grid.resolution();
      if (d == 0.0 || d + std::numbers::sqrt2 * (0.5 + 0.5 / s) < reach_cells) {
        fill(x, y);
        continue;
      }
      if (d - std::numbers::sqrt2 >= reach_cells) continue;
      near_blocked.BlockNear(x, y, cells);
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
