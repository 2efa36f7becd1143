#pragma once

#include <cstdint>
#include <vector>

namespace swarmplan {

// Exact squared Euclidean distance transform (Felzenszwalb & Huttenlocher 2012), linear in the
// number of cells. `blocked` is row-major width * height; the result holds, for every cell,
// the squared distance in cells from its centre to the nearest blocked cell centre, or
// +infinity when no cell is blocked.
std::vector<double> SquaredDistanceTransform(int width, int height,
                                             const std::vector<uint8_t>& blocked);

}  // namespace swarmplan
