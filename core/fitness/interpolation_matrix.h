#pragma once

#include <Eigen/Core>
#include <memory>

#include "core/operators/waypoint_path.h"

namespace swarmplan {

// The path start -> k waypoints -> goal of WaypointPathBuilder as a linear map of its k + 2
// knots: point i of the path is (x.row(i) . knot x's, y.row(i) . knot y's). With a uniform
// spline parameter the samples of the not-a-knot spline are such a fixed map; so are the
// straight and the nearest-neighbour (staircase) paths. x and y differ only for the staircase.
struct InterpolationMatrix {
  Eigen::MatrixXd x, y;  // (path points) x (k + 2)
  int points() const { return static_cast<int>(x.rows()); }
  int knots() const { return static_cast<int>(x.cols()); }
};

// Built by running the reference builder on unit knots.
InterpolationMatrix BuildInterpolationMatrix(Interpolation interpolation, int waypoints,
                                             int samples);

// The matrix for (interpolation, waypoints, samples), built once per process and shared
// (thread-safe). Large matrices (over kMaxCachedEntries coefficients) and entries beyond
// kMaxCachedMatrices are built for the caller alone, so hostile sizes cannot fill the cache.
std::shared_ptr<const InterpolationMatrix> CachedInterpolationMatrix(Interpolation interpolation,
                                                                     int waypoints, int samples);

inline constexpr int64_t kMaxCachedEntries = 1 << 16;
inline constexpr int kMaxCachedMatrices = 256;

}  // namespace swarmplan
