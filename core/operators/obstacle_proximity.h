#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "absl/status/statusor.h"
#include "core/map/distance_field.h"
#include "core/map/map.h"

namespace swarmplan {

// Counts the obstacles a polyline comes closer to than a threshold: the xi of the AEM-BSO
// fitness L (1 + M xi). On a ShapeWorld every circle and polygon is one obstacle and distances
// are exact segment distances. On an OccupancyGrid an obstacle is a connected component
// (8-connected) of blocked cells; every cell closer than the threshold to a blocked cell (by the
// grid's distance field) carries the label of the component reached first by a breadth-first
// sweep from all blocked cells, computed once per map and threshold; a segment counts the labels
// of the cells it passes through (a 4-connected traversal of the grid).
// Leaving the map counts as one more obstacle. Built once per search; CountViolations reuses
// its buffers (no allocation). On a ShapeWorld a bucket grid over the bounds, built here, lists
// per bucket the obstacles whose box grown by the threshold overlaps it, so each segment is
// tested only against the obstacles near it.
class ObstacleProximity {
 public:
  // FAILED_PRECONDITION on a terrain.
  static absl::StatusOr<ObstacleProximity> Create(const Map& map, double threshold);

  int CountViolations(const Path& path);
  // The same count for the path of n points (xs[i], ys[i]), with segment_length[i] the length
  // of segment i (n - 1 values), screened by field(): cell[i] is point i's cell in it
  // (FieldCell; -1 outside it) and value[i] the field's value there. A segment whose two ends
  // the field proves farther from every obstacle than the threshold plus half its length is not
  // tested; the others are tested exactly as CountViolations does, so the count is the same (up
  // to rounding at the threshold and the map's edge).
  int CountViolationsScreened(const double* xs, const double* ys, const double* segment_length,
                              const int32_t* cell, const float* value, int n);

  // The map's signed distance field: the ShapeWorld's own, or for a grid one built from its
  // blocked cells, cell for cell (kept in the map's derived cache).
  const DistanceField& field() const { return *field_; }
  // The index of the cell of field() holding (x, y), or -1 outside the field.
  int32_t FieldCell(double x, double y) const {
    const int cx = FloorToInt((x - field_->origin().x()) * field_->inverse_cell_size());
    const int cy = FloorToInt((y - field_->origin().y()) * field_->inverse_cell_size());
    if (static_cast<unsigned>(cx) >= static_cast<unsigned>(field_->width()) ||
        static_cast<unsigned>(cy) >= static_cast<unsigned>(field_->height())) {
      return -1;
    }
    return cy * field_->width() + cx;
  }

  // The map's rectangle in world coordinates.
  Point2 lower() const { return lower_; }
  Point2 upper() const { return upper_; }
  int obstacle_count() const { return obstacle_count_; }

  // The rasters of a grid for one threshold, built once per (map, threshold) and kept in the
  // map's derived cache.
  struct GridLabels {
    int components = 0;
    // Per cell the component closer than the threshold (the first reached by a breadth-first
    // sweep from every blocked cell), or -1.
    std::vector<int32_t> label;
    // Per cell the label whose sweep, continued over the whole grid, reached it first: each
    // labelled cell lies in its own label's region (-1 everywhere on a grid without obstacles).
    std::vector<int32_t> region;
    // Per cell, how far from any point in it every point lies in a cell of its region (world
    // units; negative near a change of region or the grid's edge).
    std::vector<float> region_reach;
  };

 private:
  ObstacleProximity() = default;
  int CountOnWorld(const Path& path);
  int CountOnGrid(const Path& path);
  // The obstacles segment [a, b] comes closer to than the threshold, not yet counted.
  void CountSegmentOnWorld(const Point2& a, const Point2& b, int& count);
  // The grid cell of p: its label, if not yet counted, or outside.
  void VisitGridPoint(const Point2& p, int& count, bool& outside);
  // The cells (a, b] passes through, after a's own cell.
  void WalkSegmentOnGrid(const Point2& a, const Point2& b, int& count, bool& outside);
  // Counts obstacle (or component) k unless it is -1 or already counted in this call.
  void CountObstacle(int32_t k, int& count) {
    if (k >= 0 && seen_stamp_[k] != stamp_) {
      seen_stamp_[k] = stamp_;
      ++count;
    }
  }
  // A fresh stamp for seen_stamp_: marks from earlier calls no longer count.
  void NextStamp();
  // The bucket range (clamped to the grid) covering the box [lo, hi].
  void BucketRange(const Point2& lo, const Point2& hi, int& x0, int& x1, int& y0, int& y1) const;

  const ShapeWorld* world_ = nullptr;
  const OccupancyGrid* grid_ = nullptr;
  double threshold_ = 0.0;
  double inv_res_ = 1.0;  // grid cells per world unit
  Point2 lower_ = Point2::Zero();
  Point2 upper_ = Point2::Zero();
  int obstacle_count_ = 0;
  // ShapeWorld: per obstacle (circles first, then polygons) its box grown by the threshold,
  // and the bucket grid (compressed rows: bucket b lists bucket_items_[bucket_start_[b] ..
  // bucket_start_[b + 1])).
  std::vector<Point2> grown_min_, grown_max_;
  double bucket_inv_size_ = 1.0;
  int buckets_x_ = 0, buckets_y_ = 0;
  std::vector<int32_t> bucket_start_, bucket_items_;
  // The screen's field; a grid's is shared through the map's derived cache.
  const DistanceField* field_ = nullptr;
  std::shared_ptr<const DistanceField> grid_field_;
  // OccupancyGrid: the rasters, and their labels.
  std::shared_ptr<const GridLabels> labels_;
  const int32_t* label_ = nullptr;
  // Per obstacle (or component): the stamp of the last call that counted it.
  std::vector<uint32_t> seen_stamp_;
  uint32_t stamp_ = 0;
};

}  // namespace swarmplan
