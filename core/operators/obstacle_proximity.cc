#include "core/operators/obstacle_proximity.h"

#include <algorithm>
#include <cmath>
#include <deque>

#include "absl/status/status.h"
#include "absl/strings/str_format.h"
#include "core/geometry/distance_transform.h"
#include "core/geometry/primitives.h"

namespace swarmplan {
namespace {

bool BoxesOverlap(const Point2& amin, const Point2& amax, const Point2& bmin, const Point2& bmax) {
  return amin.x() <= bmax.x() && bmin.x() <= amax.x() && amin.y() <= bmax.y() &&
         bmin.y() <= amax.y();
}

// The obstacle buckets per side of the bounds' larger dimension.
constexpr double kBucketsPerSide = 32.0;

// The signed distance field of a grid's blocked cells, cell for cell: a free cell's value is
// the grid's own distance at it less half a cell, rounded to float.
DistanceField GridSignedDistanceField(const OccupancyGrid& grid) {
  std::vector<uint8_t> blocked(static_cast<size_t>(grid.width()) * grid.height());
  for (int y = 0; y < grid.height(); ++y) {
    for (int x = 0; x < grid.width(); ++x) {
      blocked[static_cast<size_t>(y) * grid.width() + x] = grid.IsBlocked(x, y) ? 1 : 0;
    }
  }
  return DistanceField::FromBlockedCells(grid.width(), grid.height(), blocked, grid.resolution(),
                                         grid.origin(), /*cap_at_edge=*/false);
}

// Per cell of a w x h region raster, a distance (world units, cell size `cell`) within which
// every point lies in a cell of the same region. A cell Y of another region is reached from c
// through a line of 8-adjacent cells, the last one of c's region beside a different region
// ("edge": so are the grid's border cells) and within |Y - c| + 0.71 cells of c; so every cell
// within D - 0.71 of c, D the distance to the nearest edge cell, lies in c's region. A point
// within r of a point of cell c has its cell's centre within r + 1.42 of c's:
// r = D - 1.5 sqrt(2) cells (less a margin for rounding) holds.
std::vector<float> SameRegionReach(int w, int h, const std::vector<int32_t>& region, double cell) {
  std::vector<uint8_t> edge(static_cast<size_t>(w) * h, 0);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const size_t i = static_cast<size_t>(y) * w + x;
      bool is_edge = x == 0 || y == 0 || x == w - 1 || y == h - 1;
      for (int dy = -1; dy <= 1 && !is_edge; ++dy) {
        for (int dx = -1; dx <= 1 && !is_edge; ++dx) {
          is_edge = region[static_cast<size_t>(y + dy) * w + (x + dx)] != region[i];
        }
      }
      edge[i] = is_edge ? 1 : 0;
    }
  }
  const std::vector<double> squared = SquaredDistanceTransform(w, h, edge);
  std::vector<float> reach(edge.size());
  for (size_t i = 0; i < edge.size(); ++i) {
    reach[i] = static_cast<float>((std::sqrt(squared[i]) - 1.5 * std::sqrt(2.0) - 1e-3) * cell);
  }
  return reach;
}

// Spreads the labels of the labelled cells (label >= 0) by an 8-connected breadth-first sweep
// to every cell the predicate `enter` admits; cells already labelled keep their label.
template <class Enter>
void SpreadLabels(int w, int h, std::vector<int32_t>& label, Enter enter) {
  std::deque<Cell> queue;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (label[static_cast<size_t>(y) * w + x] >= 0) queue.push_back({x, y});
    }
  }
  while (!queue.empty()) {
    const Cell c = queue.front();
    queue.pop_front();
    const int32_t own = label[static_cast<size_t>(c.y) * w + c.x];
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = c.x + dx, ny = c.y + dy;
        if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
        int32_t& next = label[static_cast<size_t>(ny) * w + nx];
        if (next >= 0 || !enter(nx, ny)) continue;
        next = own;
        queue.push_back({nx, ny});
      }
    }
  }
}

// The label rasters of ObstacleProximity on a grid for one threshold; shared through the map's
// derived cache by every search on it.
ObstacleProximity::GridLabels BuildGridLabels(const OccupancyGrid& grid, double threshold) {
  ObstacleProximity::GridLabels out;
  const int w = grid.width(), h = grid.height();
  out.label.assign(static_cast<size_t>(w) * h, -1);
  auto index = [w](int x, int y) { return static_cast<size_t>(y) * w + x; };
  // Components of blocked cells, 8-connected.
  std::deque<Cell> queue;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (!grid.IsBlocked(x, y) || out.label[index(x, y)] >= 0) continue;
      out.label[index(x, y)] = out.components;
      queue.push_back({x, y});
      while (!queue.empty()) {
        const Cell c = queue.front();
        queue.pop_front();
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            const int nx = c.x + dx, ny = c.y + dy;
            if (!grid.InBounds(nx, ny) || !grid.IsBlocked(nx, ny)) continue;
            if (out.label[index(nx, ny)] >= 0) continue;
            out.label[index(nx, ny)] = out.components;
            queue.push_back({nx, ny});
          }
        }
      }
      ++out.components;
    }
  }
  // Every cell closer than the threshold takes the label of the component its sweep reaches
  // first.
  SpreadLabels(w, h, out.label,
               [&](int x, int y) { return grid.DistanceToObstacle(x, y) < threshold; });
  // Regions: the same sweep continued over every cell, so each labelled cell lies in the
  // region of its own label.
  out.region = out.label;
  SpreadLabels(w, h, out.region, [](int, int) { return true; });
  out.region_reach = SameRegionReach(w, h, out.region, grid.resolution());
  return out;
}

}  // namespace

absl::StatusOr<ObstacleProximity> ObstacleProximity::Create(const Map& map, double threshold) {
  ObstacleProximity p;
  p.threshold_ = threshold;
  if (const ShapeWorld* world = map.world()) {
    p.world_ = world;
    p.field_ = &world->distance_field();
    p.lower_ = world->bounds().min;
    p.upper_ = world->bounds().max;
    for (const Circle& circle : world->circles()) {
      p.grown_min_.push_back(circle.center.array() - circle.radius - threshold);
      p.grown_max_.push_back(circle.center.array() + circle.radius + threshold);
    }
    const Point2 margin(threshold, threshold);
    for (const Polygon& poly : world->polygons()) {
      Point2 lo = poly.vertices[0], hi = poly.vertices[0];
      for (const Point2& v : poly.vertices) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
      }
      p.grown_min_.push_back(lo - margin);
      p.grown_max_.push_back(hi + margin);
    }
    p.obstacle_count_ = static_cast<int>(world->ObstacleCount());
    p.seen_stamp_.assign(p.obstacle_count_, 0);
    const double span = std::max(world->bounds().Width(), world->bounds().Height());
    p.bucket_inv_size_ = kBucketsPerSide / span;
    p.buckets_x_ =
        std::max(1, static_cast<int>(std::ceil(world->bounds().Width() * p.bucket_inv_size_)));
    p.buckets_y_ =
        std::max(1, static_cast<int>(std::ceil(world->bounds().Height() * p.bucket_inv_size_)));
    // Two passes over the obstacles: count per bucket, then fill.
    std::vector<int32_t> fill(static_cast<size_t>(p.buckets_x_) * p.buckets_y_ + 1, 0);
    for (int pass = 0; pass < 2; ++pass) {
      for (int k = 0; k < p.obstacle_count_; ++k) {
        int x0, x1, y0, y1;
        p.BucketRange(p.grown_min_[k], p.grown_max_[k], x0, x1, y0, y1);
        for (int by = y0; by <= y1; ++by) {
          for (int bx = x0; bx <= x1; ++bx) {
            const size_t b = static_cast<size_t>(by) * p.buckets_x_ + bx;
            if (pass == 0) {
              ++fill[b + 1];
            } else {
              p.bucket_items_[fill[b]++] = k;
            }
          }
        }
      }
      if (pass == 0) {
        for (size_t b = 1; b < fill.size(); ++b) fill[b] += fill[b - 1];
        p.bucket_start_ = fill;
        p.bucket_items_.resize(fill.back());
      }
    }
    return p;
  }
  const OccupancyGrid* grid = map.grid();
  if (grid == nullptr) {
    return absl::FailedPreconditionError("obstacle proximity: needs a 2D map, not a terrain");
  }
  p.grid_ = grid;
  p.grid_field_ = map.Derived<DistanceField>("signed-distance-field",
                                             [grid] { return GridSignedDistanceField(*grid); });
  p.field_ = p.grid_field_.get();
  p.inv_res_ = 1.0 / grid->resolution();
  p.lower_ = grid->origin();
  p.upper_ = grid->origin() + Point2(grid->width(), grid->height()) * grid->resolution();
  p.labels_ = map.Derived<GridLabels>(absl::StrFormat("obstacle-labels %.17g", threshold),
                                      [&] { return BuildGridLabels(*grid, threshold); });
  p.label_ = p.labels_->label.data();
  p.obstacle_count_ = p.labels_->components;
  p.seen_stamp_.assign(p.obstacle_count_, 0);
  return p;
}

int ObstacleProximity::CountViolations(const Path& path) {
  return world_ != nullptr ? CountOnWorld(path) : CountOnGrid(path);
}

void ObstacleProximity::NextStamp() {
  if (++stamp_ == 0) {  // wrapped: forget every mark
    std::fill(seen_stamp_.begin(), seen_stamp_.end(), 0);
    stamp_ = 1;
  }
}

void ObstacleProximity::BucketRange(const Point2& lo, const Point2& hi, int& x0, int& x1, int& y0,
                                    int& y1) const {
  auto bucket = [this](double v, double origin, int count) {
    const double scaled = (v - origin) * bucket_inv_size_;
    if (!(scaled > 0.0)) return 0;  // also NaN
    if (scaled >= count) return count - 1;
    return static_cast<int>(scaled);
  };
  x0 = bucket(lo.x(), lower_.x(), buckets_x_);
  x1 = bucket(hi.x(), lower_.x(), buckets_x_);
  y0 = bucket(lo.y(), lower_.y(), buckets_y_);
  y1 = bucket(hi.y(), lower_.y(), buckets_y_);
}

int ObstacleProximity::CountOnWorld(const Path& path) {
  if (path.empty()) return 0;
  NextStamp();
  bool outside = false;
  for (const Point3& q : path) {
    outside = outside || q.x() < lower_.x() || q.y() < lower_.y() || q.x() > upper_.x() ||
              q.y() > upper_.y();
  }
  int count = outside ? 1 : 0;
  const size_t segments = path.size() > 1 ? path.size() - 1 : 1;
  for (size_t i = 0; i < segments; ++i) {
    CountSegmentOnWorld(path[i].head<2>(), path[std::min(i + 1, path.size() - 1)].head<2>(), count);
  }
  return count;
}

void ObstacleProximity::CountSegmentOnWorld(const Point2& a, const Point2& b, int& count) {
  const int circles = static_cast<int>(world_->circles().size());
  const Point2 smin = a.cwiseMin(b), smax = a.cwiseMax(b);
  int x0, x1, y0, y1;
  BucketRange(smin, smax, x0, x1, y0, y1);
  for (int by = y0; by <= y1; ++by) {
    for (int bx = x0; bx <= x1; ++bx) {
      const size_t bucket = static_cast<size_t>(by) * buckets_x_ + bx;
      for (int32_t j = bucket_start_[bucket]; j < bucket_start_[bucket + 1]; ++j) {
        const int32_t k = bucket_items_[j];
        if (seen_stamp_[k] == stamp_) continue;
        if (!BoxesOverlap(smin, smax, grown_min_[k], grown_max_[k])) continue;
        const double distance =
            k < circles ? SegmentCircleDistance(a, b, world_->circles()[k])
                        : SegmentPolygonDistance(a, b, world_->polygons()[k - circles].vertices);
        if (distance < threshold_) {
          seen_stamp_[k] = stamp_;
          ++count;
        }
      }
    }
  }
}

int ObstacleProximity::CountOnGrid(const Path& path) {
  if (path.empty()) return 0;
  NextStamp();
  int count = 0;
  bool outside = false;
  VisitGridPoint(path[0].head<2>(), count, outside);
  for (size_t i = 0; i + 1 < path.size(); ++i) {
    WalkSegmentOnGrid(path[i].head<2>(), path[i + 1].head<2>(), count, outside);
  }
  return count + (outside ? 1 : 0);
}

void ObstacleProximity::VisitGridPoint(const Point2& p, int& count, bool& outside) {
  const int cx = FloorToInt((p.x() - lower_.x()) * inv_res_);
  const int cy = FloorToInt((p.y() - lower_.y()) * inv_res_);
  if (cx < 0 || cy < 0 || cx >= grid_->width() || cy >= grid_->height()) {
    outside = true;
    return;
  }
  CountObstacle(label_[static_cast<size_t>(cy) * grid_->width() + cx], count);
}

void ObstacleProximity::WalkSegmentOnGrid(const Point2& a, const Point2& b, int& count,
                                          bool& outside) {
  // The cells (a, b] passes through, in order: a 4-connected traversal from a's cell to b's.
  // The next step crosses the nearer of the next x and y cell borders; comparing the fractions
  // of the segment to them, each scaled by |dx| |dy|, needs no division.
  const double gx0 = (a.x() - lower_.x()) * inv_res_, gy0 = (a.y() - lower_.y()) * inv_res_;
  const double gx1 = (b.x() - lower_.x()) * inv_res_, gy1 = (b.y() - lower_.y()) * inv_res_;
  int cx = FloorToInt(gx0), cy = FloorToInt(gy0);
  const int ex = FloorToInt(gx1), ey = FloorToInt(gy1);
  int steps_x = std::abs(ex - cx), steps_y = std::abs(ey - cy);
  const int sx = ex > cx ? 1 : -1, sy = ey > cy ? 1 : -1;
  const double adx = std::abs(gx1 - gx0), ady = std::abs(gy1 - gy0);
  double next_x = (sx > 0 ? cx + 1 - gx0 : gx0 - cx) * ady;
  double next_y = (sy > 0 ? cy + 1 - gy0 : gy0 - cy) * adx;
  const int w = grid_->width(), h = grid_->height();
  while (steps_x + steps_y > 0) {
    if (steps_y == 0 || (steps_x > 0 && next_x < next_y)) {
      cx += sx;
      next_x += ady;
      --steps_x;
    } else {
      cy += sy;
      next_y += adx;
      --steps_y;
    }
    if (static_cast<unsigned>(cx) >= static_cast<unsigned>(w) ||
        static_cast<unsigned>(cy) >= static_cast<unsigned>(h)) {
      outside = true;
    } else {
      CountObstacle(label_[static_cast<size_t>(cy) * w + cx], count);
    }
  }
}

int ObstacleProximity::CountViolationsScreened(const double* xs, const double* ys,
                                               const double* segment_length, const int32_t* cell,
                                               const float* value, int n) {
  if (n <= 0) return 0;
  NextStamp();
  int count = 0;
  const double h = field_->cell_size();
  // Float rounding of the field's values: under a thousandth of a cell on fields of up to
  // 2^13 cells a side.
  const double rounding = 1e-3 * h;
  if (world_ != nullptr) {
    // A segment is skipped when the field proves both ends farther than threshold + half its
    // length from every obstacle: each of its points is within half its length of an end.
    const double margin = threshold_ + DistanceField::kCellSlack * h + rounding;
    auto clear = [&](int i) { return cell[i] < 0 ? -1.0 : value[i] - margin; };
    bool outside = false;
    for (int i = 0; i < n; ++i) {
      outside = outside || xs[i] < lower_.x() || ys[i] < lower_.y() || xs[i] > upper_.x() ||
                ys[i] > upper_.y();
    }
    if (outside) ++count;
    if (n == 1) {
      CountSegmentOnWorld(Point2(xs[0], ys[0]), Point2(xs[0], ys[0]), count);
      return count;
    }
    double clear_a = clear(0);
    for (int i = 0; i + 1 < n; ++i) {
      const double clear_b = clear(i + 1);
      const double half = 0.5 * segment_length[i];
      if (!(clear_a > half && clear_b > half)) {
        CountSegmentOnWorld(Point2(xs[i], ys[i]), Point2(xs[i + 1], ys[i + 1]), count);
      }
      clear_a = clear_b;
    }
    return count;
  }
  // Grid: every cell a segment passes through holds a point within half the segment of one
  // end, so its centre lies within that plus a cell diagonal of the end's cell centre. The
  // segment is not walked when the grid's distance at both ends' cells (the field's value plus
  // half a cell; only cells closer than the threshold carry labels) proves them clear, nor
  // when both ends lie in one label's region farther than half the segment from any other
  // region (region_reach): the walk would meet only that label, inside the grid, so it adds
  // nothing once the label is counted, and counts it when an end's cell carries it (every
  // vertex's cell is visited by some walk).
  const double margin = threshold_ + h * (std::sqrt(2.0) - 0.5) + rounding;
  const int32_t* region = labels_->region.data();
  const float* reach = labels_->region_reach.data();
  const int32_t w = grid_->width();
  const double side_step_limit = (w - 2) * grid_->resolution();
  bool outside = false;
  VisitGridPoint(Point2(xs[0], ys[0]), count, outside);
  for (int i = 0; i + 1 < n; ++i) {
    const int32_t cell_a = cell[i], cell_b = cell[i + 1];
    const double half = 0.5 * segment_length[i];
    if (value[i] - margin > half && value[i + 1] - margin > half) {
      // far from every labelled cell (checked first: most segments are; a point outside the
      // field has value 0, which is never far)
    } else if (cell_a < 0 || cell_b < 0) {
      WalkSegmentOnGrid(Point2(xs[i], ys[i]), Point2(xs[i + 1], ys[i + 1]), count, outside);
    } else if (cell_a == cell_b) {
      // the walk visits no cell
    } else if (cell_b == cell_a + w || cell_b == cell_a - w ||
               ((cell_b == cell_a + 1 || cell_b == cell_a - 1) &&
                segment_length[i] < side_step_limit)) {
      // A side neighbour: the walk visits that cell alone. (Indices one apart are neighbours
      // in a row when the segment is too short to wrap to the next row: under w - 2 cells.)
      CountObstacle(label_[cell_b], count);
    } else if (region[cell_a] == region[cell_b] && reach[cell_a] > half && reach[cell_b] > half) {
      const int32_t label = region[cell_a];
      if (label >= 0 && seen_stamp_[label] != stamp_) {
        if (label_[cell_a] == label || label_[cell_b] == label) {
          CountObstacle(label, count);
        } else {
          WalkSegmentOnGrid(Point2(xs[i], ys[i]), Point2(xs[i + 1], ys[i + 1]), count, outside);
        }
      }
    } else {
      WalkSegmentOnGrid(Point2(xs[i], ys[i]), Point2(xs[i + 1], ys[i + 1]), count, outside);
    }
  }
  return count + (outside ? 1 : 0);
}

}  // namespace swarmplan
