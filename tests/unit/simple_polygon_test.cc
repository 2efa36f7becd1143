#include "core/geometry/simple_polygon.h"

#include <cmath>
#include <string>
#include <vector>

#include "core/map/shape_world.h"
#include "gmock/gmock.h"
#include "gtest/gtest.h"

namespace swarmplan {
namespace {

using ::testing::HasSubstr;

TEST(SimplePolygonTest, AcceptsSimplePolygonsOfEitherOrientation) {
  const std::vector<Point2> square = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  EXPECT_TRUE(CheckSimplePolygon(square).ok());
  EXPECT_TRUE(CheckSimplePolygon({{0, 2}, {2, 2}, {2, 0}, {0, 0}}).ok());
  // A comb: many edges share x ranges without meeting.
  std::vector<Point2> comb = {{0, 0}};
  for (int tooth = 0; tooth < 50; ++tooth) {
    comb.push_back({2.0 * tooth + 1, 0});
    comb.push_back({2.0 * tooth + 1, 10});
    comb.push_back({2.0 * tooth + 2, 10});
    comb.push_back({2.0 * tooth + 2, 0});
  }
  comb.push_back({101, 0});
  comb.push_back({101, -1});
  comb.push_back({0, -1});
  EXPECT_TRUE(CheckSimplePolygon(comb).ok());
}

TEST(SimplePolygonTest, RejectsUnequalLobesNamingTheEdges) {
  // A figure eight with lobes of areas 3.5 and 2: non-zero signed area, yet not simple.
  const std::vector<Point2> lobes = {{0, 0}, {4, 2}, {4, 0}, {0, 2}, {-1, 1.5}, {-1, 0.5}};
  const absl::Status status = CheckSimplePolygon(lobes);
  EXPECT_EQ(status.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(status.message(), HasSubstr("self-intersecting"));
  EXPECT_THAT(status.message(), HasSubstr("edge 0 (0, 0)-(4, 2)"));
  EXPECT_THAT(status.message(), HasSubstr("edge 2 (4, 0)-(0, 2)"));
}

TEST(SimplePolygonTest, TouchingNonAdjacentEdgesCountAsIntersecting) {
  // Vertex 4 lies on edge 0-1: the boundary touches itself.
  EXPECT_FALSE(CheckSimplePolygon({{0, 0}, {4, 0}, {4, 4}, {2, 1}, {2, 0}, {0, 4}}).ok());
  // Two lobes sharing one vertex, visited twice.
  EXPECT_FALSE(CheckSimplePolygon({{0, 0}, {2, 0}, {2, 2}, {0, 0}, {-2, 0}, {-2, -2}}).ok());
  // Within kGeometryEpsilon counts as touching.
  EXPECT_FALSE(CheckSimplePolygon({{0, 0}, {4, 0}, {4, 4}, {2, 1e-10}, {0, 4}}).ok());
  EXPECT_TRUE(CheckSimplePolygon({{0, 0}, {4, 0}, {4, 4}, {2, 1e-6}, {0, 4}}).ok());
}

TEST(SimplePolygonTest, RejectsSpikesAlongAnEdge) {
  // The boundary goes out to (3, 0) and back along the same line.
  const absl::Status status = CheckSimplePolygon({{0, 0}, {3, 0}, {1, 0}, {1, 1}});
  EXPECT_EQ(status.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(status.message(), HasSubstr("turns back"));
}

TEST(SimplePolygonTest, BoundsTheVertexCount) {
  std::vector<Point2> circle;
  for (size_t i = 0; i <= kMaxPolygonVertices; ++i) {
    const double angle = 2 * 3.141592653589793 * static_cast<double>(i) / (kMaxPolygonVertices + 1);
    circle.push_back({std::cos(angle), std::sin(angle)});
  }
  EXPECT_EQ(CheckSimplePolygon(circle).code(), absl::StatusCode::kResourceExhausted);
  circle.pop_back();
  EXPECT_TRUE(CheckSimplePolygon(circle).ok());
}

TEST(SimplePolygonTest, ShapeWorldRejectsSelfIntersectingPolygonsByIndex) {
  const Bounds2 bounds{{-5, -5}, {5, 5}};
  Polygon good{{{0, 0}, {1, 0}, {0, 1}}};
  Polygon lobes{{{0, 0}, {4, 2}, {4, 0}, {0, 2}, {-1, 1.5}, {-1, 0.5}}};
  auto world = ShapeWorld::Create(bounds, {}, {good, lobes});
  ASSERT_FALSE(world.ok());
  EXPECT_EQ(world.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(world.status().message(), HasSubstr("polygons[1]: polygon is self-intersecting"));
  EXPECT_TRUE(ShapeWorld::Create(bounds, {}, {good}).ok());
}

}  // namespace
}  // namespace swarmplan
