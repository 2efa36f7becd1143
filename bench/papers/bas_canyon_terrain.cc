#include "bench/papers/bas_canyon_terrain.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "core/random.h"

namespace swarmplan::bench {
namespace {

struct Rock {
  double x, y, height, radius;
};

double Fraction(const CanyonShape& shape, double x) { return x / (shape.width - 1); }

}  // namespace

double RightBranchY(const CanyonShape& shape, double x) {
  const double u = Fraction(shape, x);
  return shape.mouth_y + shape.right_bulge * std::sin(std::numbers::pi * u) +
         shape.right_wiggle * std::sin(3 * std::numbers::pi * u);
}

double LeftBranchY(const CanyonShape& shape, double x) {
  return shape.mouth_y - shape.left_bulge * std::sin(std::numbers::pi * Fraction(shape, x));
}

std::vector<double> CanyonHeights(const CanyonShape& shape, uint64_t seed) {
  Rng rng(seed);
  std::vector<Rock> rocks;
  for (int k = 0; k < shape.rocks; ++k) {
    Rock rock;
    rock.x = rng.Uniform(0.0, shape.width - 1);
    rock.y = rng.Uniform(0.0, shape.depth - 1);
    rock.height = rng.Uniform(shape.rock_min, shape.rock_max);
    rock.radius = rng.Uniform(1.0, 2.5);
    rocks.push_back(rock);
  }
  const auto valley = [&](double d) {
    return std::exp(-(d / shape.half_width) * (d / shape.half_width));
  };
  std::vector<double> heights(static_cast<size_t>(shape.width) * shape.depth);
  for (int y = 0; y < shape.depth; ++y) {
    for (int x = 0; x < shape.width; ++x) {
      const double right = (shape.plateau - shape.right_floor) * valley(y - RightBranchY(shape, x));
      const double left = (shape.plateau - shape.left_floor) * valley(y - LeftBranchY(shape, x));
      double h = shape.plateau - std::max(right, left);
      for (const Rock& rock : rocks) {
        const double dx = x - rock.x;
        const double dy = y - rock.y;
        h += rock.height * std::exp(-(dx * dx + dy * dy) / (rock.radius * rock.radius));
      }
      heights[static_cast<size_t>(y) * shape.width + x] = std::round(h * 100.0) / 100.0;
    }
  }
  return heights;
}

std::string HeightsToAsc(int width, int depth, const std::vector<double>& heights) {
  std::string text =
      absl::StrCat("ncols ", width, "\nnrows ", depth, "\nxllcenter 0\nyllcenter 0\ncellsize 1\n");
  for (int y = depth - 1; y >= 0; --y) {
    for (int x = 0; x < width; ++x) {
      if (x > 0) text += ' ';
      text += absl::StrFormat("%.2f", heights[static_cast<size_t>(y) * width + x]);
    }
    text += '\n';
  }
  return text;
}

}  // namespace swarmplan::bench
