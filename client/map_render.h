#pragma once

#include <string>
#include <vector>

#include "core/map/map.h"

// Drawing of maps, paths and convergence curves as SVG (see svg_writer.h).
namespace swarmplan::client {

struct RenderedPath {
  std::string label;           // legend text
  std::vector<Point3> points;  // map coordinates; z ignored
};

struct ConvergencePoint {
  double iteration = 0.0;
  double best = 0.0;      // best fitness so far
  bool feasible = false;  // the best so far is collision-free
};

struct ConvergenceCurve {
  std::string label;
  std::vector<ConvergencePoint> best;
};

struct RenderOptions {
  double max_width_px = 900.0;
  double max_height_px = 700.0;
  // Whether map y grows upward on the page (world convention) or downward (text-file grids,
  // whose first line is y = 0).
  bool y_up = true;
  std::string title;
  // Draw the convergence curves in a panel below the map.
  bool convergence_inset = false;
};

// The map (grid cells as row-merged rects, shapes as circles and polygons, terrain as a grey
// height map), the paths as polylines with start and goal markers, a legend, and optionally the
// convergence curves.
std::string RenderMapSvg(const Map& map, const std::vector<RenderedPath>& paths,
                         const std::vector<ConvergenceCurve>& curves, const RenderOptions& options);

// The convergence curves alone: best fitness against iteration. The fitness axis spans the
// feasible values when there are any (infeasible penalties are drawn clipped at the top).
std::string RenderConvergenceSvg(const std::vector<ConvergenceCurve>& curves,
                                 const std::string& title);

}  // namespace swarmplan::client
