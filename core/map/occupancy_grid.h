#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "absl/status/statusor.h"
#include "core/map/limits.h"
#include "core/map/point.h"

namespace swarmplan {

// A 2D grid of cells with values like nav_msgs/OccupancyGrid: 0 free ... 100 occupied,
// -1 unknown. Cell (x, y) covers [origin + (x, y) * resolution, origin + (x + 1, y + 1) *
// resolution) in world coordinates. Immutable; built once, shared between jobs.
//
// The grid keeps the exact Euclidean distance (in world units) from every cell centre to the
// nearest blocked cell centre, so clearance queries are a table look-up. The field is computed on
// its first use (thread-safe) and shared by copies of the grid: a grid that only validates a
// request, or plans without a clearance, never pays for it.
class OccupancyGrid {
 public:
  static constexpr int8_t kUnknown = -1;
  static constexpr int8_t kFree = 0;
  static constexpr int8_t kOccupied = 100;
  // A cell is blocked when its value is unknown or at least this.
  static constexpr int8_t kBlockedThreshold = 50;
  // For a valid value: unknown (-1, 255 as a byte) and kBlockedThreshold..100 are the bytes from
  // the threshold up.
  static bool IsBlockedValue(int8_t v) { return static_cast<uint8_t>(v) >= kBlockedThreshold; }

  // `cells` is row-major, width * height values, each -1 or 0..100.
  static absl::StatusOr<OccupancyGrid> Create(int width, int height, std::vector<int8_t> cells,
                                              double resolution = 1.0,
                                              Point2 origin = Point2::Zero(),
                                              const MapLimits& limits = {});

  int width() const { return width_; }
  int height() const { return height_; }
  double resolution() const { return resolution_; }
  const Point2& origin() const { return origin_; }
  const std::vector<int8_t>& cells() const { return cells_; }

  bool InBounds(int x, int y) const { return x >= 0 && y >= 0 && x < width_ && y < height_; }
  bool InBounds(Cell c) const { return InBounds(c.x, c.y); }
  int8_t value(int x, int y) const { return cells_[Index(x, y)]; }
  // Outside the grid counts as blocked.
  bool IsBlocked(int x, int y) const { return !InBounds(x, y) || IsBlockedValue(value(x, y)); }
  bool IsBlocked(Cell c) const { return IsBlocked(c.x, c.y); }
  bool IsFree(Cell c) const { return !IsBlocked(c); }

  // Distance in world units from the centre of (x, y) to the nearest blocked cell centre
  // (infinity when no cell is blocked). 0 on blocked cells.
  double DistanceToObstacle(int x, int y) const { return distance_field()[Index(x, y)]; }
  const std::vector<double>& distance_field() const {
    return distance_field_computed() ? distance_->values : ComputeDistanceField();
  }
  // Whether the distance field has been computed (by this grid or a copy).
  bool distance_field_computed() const { return distance_->ready.load(std::memory_order_acquire); }

  // This grid with `cells` blocked too: set to kOccupied, skipping cells outside the grid or
  // blocked already (repeats are fine). When this grid's distance field has been computed, the
  // new grid's is derived from it on first use, measured again only near the new cells.
  OccupancyGrid WithBlocked(const std::vector<Cell>& cells) const;

  Point2 CellCenter(Cell c) const { return origin_ + Point2(c.x + 0.5, c.y + 0.5) * resolution_; }
  // The cell containing a world point (may be outside the grid).
  Cell CellAt(const Point2& p) const;

  int64_t BlockedCount() const { return blocked_count_; }

 private:
  OccupancyGrid() = default;
  size_t Index(int x, int y) const { return static_cast<size_t>(y) * width_ + x; }

  struct LazyDistanceField {
    std::once_flag once;
    std::atomic<bool> ready{false};
    std::vector<double> values;
    // Set by WithBlocked: the computed field of the grid this one was made from, and the cells
    // blocked since.
    std::shared_ptr<const LazyDistanceField> base;
    std::vector<Cell> added;
  };
  const std::vector<double>& ComputeDistanceField() const;
  // The field from `base`, the field of a grid that differs from this one only in `added`.
  std::vector<double> DerivedDistanceField(const std::vector<double>& base,
                                           const std::vector<Cell>& added) const;

  int width_ = 0;
  int height_ = 0;
  double resolution_ = 1.0;
  Point2 origin_ = Point2::Zero();
  std::vector<int8_t> cells_;
  std::shared_ptr<LazyDistanceField> distance_ = std::make_shared<LazyDistanceField>();
  int64_t blocked_count_ = 0;
};

}  // namespace swarmplan
