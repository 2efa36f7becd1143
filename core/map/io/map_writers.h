#pragma once

#include <string>

#include "core/map/occupancy_grid.h"
#include "core/map/shape_world.h"

namespace swarmplan {

// Text in the formats of ParseMap (map_io.h) that parses back to the same map: for the worlds
// the benchmarks generate and ship, and for anyone who builds a map in code.

// The `ascii` format: one line per row, first line y = 0, '#' for a blocked cell and '.' for a
// free one. Resolution and origin are not part of the format (they read back as 1 and 0).
std::string FormatAsciiMap(const OccupancyGrid& grid);

// The `shapes-json` format with a "name" member. Numbers are written in their shortest form
// that reads back to the same double.
std::string FormatShapesJson(const ShapeWorld& world, const std::string& name);

}  // namespace swarmplan
