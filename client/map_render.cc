#include "client/map_render.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "client/svg_writer.h"

namespace swarmplan::client {
namespace {

constexpr double kMargin = 12.0;
constexpr double kTitleHeight = 24.0;
constexpr double kLegendLine = 18.0;
constexpr double kInsetHeight = 200.0;
const char* const kPalette[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e",
                                "#9467bd", "#8c564b", "#e377c2", "#17becf"};

const char* PathColor(size_t i) { return kPalette[i % (sizeof(kPalette) / sizeof(kPalette[0]))]; }

// World rectangle of the map in world coordinates.
struct WorldBox {
  double min_x, min_y, max_x, max_y;
};

WorldBox MapBox(const Map& map) {
  if (const OccupancyGrid* grid = map.grid()) {
    const Point2& o = grid->origin();
    return {o.x(), o.y(), o.x() + grid->width() * grid->resolution(),
            o.y() + grid->height() * grid->resolution()};
  }
  if (const ShapeWorld* world = map.world()) {
    const Bounds2& b = world->bounds();
    return {b.min.x(), b.min.y(), b.max.x(), b.max.y()};
  }
  const Terrain& terrain = *map.terrain();
  const Point2& o = terrain.origin();
  return {o.x(), o.y(), o.x() + terrain.width() * terrain.cell_size(),
          o.y() + terrain.depth() * terrain.cell_size()};
}

// World -> pixel mapping of the map area.
class Viewport {
 public:
  Viewport(const WorldBox& box, double scale, double left, double top, bool y_up)
      : box_(box), scale_(scale), left_(left), top_(top), y_up_(y_up) {}

  Point2 ToPixel(double x, double y) const {
    const double px = left_ + (x - box_.min_x) * scale_;
    const double py = y_up_ ? top_ + (box_.max_y - y) * scale_ : top_ + (y - box_.min_y) * scale_;
    return Point2(px, py);
  }
  // A world rectangle [x0, x1] x [y0, y1] as pixel rect (x, y, w, h).
  void Rect(SvgWriter& svg, double x0, double y0, double x1, double y1,
            const std::string& attributes) const {
    const Point2 a = ToPixel(x0, y0);
    const Point2 b = ToPixel(x1, y1);
    svg.Rect(std::min(a.x(), b.x()), std::min(a.y(), b.y()), std::abs(b.x() - a.x()),
             std::abs(b.y() - a.y()), attributes);
  }
  double scale() const { return scale_; }
  double width() const { return (box_.max_x - box_.min_x) * scale_; }
  double height() const { return (box_.max_y - box_.min_y) * scale_; }

 private:
  WorldBox box_;
  double scale_;
  double left_;
  double top_;
  bool y_up_;
};

// Rows of cells, runs of equal class merged into one rect; class 0 is not drawn.
template <typename ClassOf, typename FillOf>
void DrawCellRuns(SvgWriter& svg, const Viewport& view, int width, int height, double cell,
                  double x_origin, double y_origin, ClassOf class_of, FillOf fill_of) {
  for (int y = 0; y < height; ++y) {
    int x = 0;
    while (x < width) {
      const int kind = class_of(x, y);
      int end = x + 1;
      while (end < width && class_of(end, y) == kind) ++end;
      if (kind != 0) {
        view.Rect(svg, x_origin + x * cell, y_origin + y * cell, x_origin + end * cell,
                  y_origin + (y + 1) * cell, absl::StrCat("fill=\"", fill_of(kind), "\""));
      }
      x = end;
    }
  }
}

void DrawGrid(SvgWriter& svg, const Viewport& view, const OccupancyGrid& grid) {
  svg.Comment(absl::StrCat("occupancy grid ", grid.width(), "x", grid.height(), ", resolution ",
                           grid.resolution()));
  svg.BeginGroup("shape-rendering=\"crispEdges\"");
  DrawCellRuns(
      svg, view, grid.width(), grid.height(), grid.resolution(), grid.origin().x(),
      grid.origin().y(),
      [&](int x, int y) {
        const int8_t value = grid.value(x, y);
        if (value == OccupancyGrid::kUnknown) return 2;
        return value >= OccupancyGrid::kBlockedThreshold ? 1 : 0;
      },
      [](int kind) { return kind == 1 ? "#333333" : "#9e9e9e"; });
  svg.EndGroup();
}

void DrawWorld(SvgWriter& svg, const Viewport& view, const ShapeWorld& world) {
  svg.Comment(absl::StrCat("shape world: ", world.circles().size(), " circles, ",
                           world.polygons().size(), " polygons"));
  svg.BeginGroup("fill=\"#555555\" stroke=\"#333333\" stroke-width=\"1\"");
  for (const Circle& circle : world.circles()) {
    const Point2 c = view.ToPixel(circle.center.x(), circle.center.y());
    svg.Circle(c.x(), c.y(), circle.radius * view.scale(), "");
  }
  for (const Polygon& polygon : world.polygons()) {
    std::vector<Point2> pixels;
    for (const Point2& v : polygon.vertices) pixels.push_back(view.ToPixel(v.x(), v.y()));
    svg.Polygon(pixels, "");
  }
  svg.EndGroup();
}

void DrawTerrain(SvgWriter& svg, const Viewport& view, const Terrain& terrain) {
  svg.Comment(absl::StrCat("terrain ", terrain.width(), "x", terrain.depth(), ", heights ",
                           terrain.min_height(), "..", terrain.max_height(), ", ceiling ",
                           terrain.ceiling()));
  constexpr int kLevels = 64;  // grey levels; equal neighbours merge into one rect
  const double low = terrain.min_height();
  const double span = std::max(terrain.max_height() - low, 1e-12);
  svg.BeginGroup("shape-rendering=\"crispEdges\"");
  DrawCellRuns(
      svg, view, terrain.width(), terrain.depth(), terrain.cell_size(), terrain.origin().x(),
      terrain.origin().y(),
      [&](int x, int y) {
        const double h = terrain.HeightAt(x, y);
        if (std::isnan(h)) return kLevels + 1;  // no data
        return 1 +
               std::clamp(static_cast<int>((h - low) / span * (kLevels - 1) + 0.5), 0, kLevels - 1);
      },
      [](int kind) {
        if (kind == kLevels + 1) return std::string("#c0392b");
        const int grey = 40 + (kind - 1) * (235 - 40) / (kLevels - 1);
        return absl::StrFormat("#%02x%02x%02x", grey, grey, grey);
      });
  svg.EndGroup();
}

void DrawPaths(SvgWriter& svg, const Viewport& view, const std::vector<RenderedPath>& paths) {
  const double stroke = std::clamp(view.scale() * 0.25, 1.5, 3.0);
  const double marker = stroke * 2.5;
  for (size_t i = 0; i < paths.size(); ++i) {
    const RenderedPath& path = paths[i];
    if (path.points.empty()) continue;
    std::vector<Point2> pixels;
    for (const Point3& p : path.points) pixels.push_back(view.ToPixel(p.x(), p.y()));
    svg.Comment(absl::StrCat("path ", path.label));
    svg.Polyline(pixels, absl::StrCat("fill=\"none\" stroke=\"", PathColor(i), "\" stroke-width=\"",
                                      FormatPixel(stroke),
                                      "\" stroke-linejoin=\"round\" stroke-linecap=\"round\""));
    svg.Circle(pixels.front().x(), pixels.front().y(), marker,
               "fill=\"#2ecc71\" stroke=\"#145a32\" stroke-width=\"1.5\"");
    svg.Rect(pixels.back().x() - marker, pixels.back().y() - marker, 2 * marker, 2 * marker,
             "fill=\"#e74c3c\" stroke=\"#641e16\" stroke-width=\"1.5\"");
  }
}

double PathLength(const RenderedPath& path) {
  double length = 0.0;
  for (size_t i = 1; i < path.points.size(); ++i) {
    length += (path.points[i] - path.points[i - 1]).norm();
  }
  return length;
}

void DrawLegend(SvgWriter& svg, double left, double top, const std::vector<RenderedPath>& paths) {
  for (size_t i = 0; i < paths.size(); ++i) {
    const double y = top + i * kLegendLine;
    svg.Line(left, y + 9, left + 24, y + 9,
             absl::StrCat("stroke=\"", PathColor(i), "\" stroke-width=\"3\""));
    svg.Text(left + 30, y + 13,
             absl::StrCat(paths[i].label, "  (", paths[i].points.size(), " points, length ",
                          absl::StrFormat("%.4g", PathLength(paths[i])), ")"),
             "font-size=\"12\" fill=\"#222\"");
  }
}

std::string Number(double value) { return absl::StrFormat("%.5g", value); }

// Best fitness against iteration in the box (left, top, width, height).
void DrawConvergence(SvgWriter& svg, double left, double top, double width, double height,
                     const std::vector<ConvergenceCurve>& curves) {
  svg.Rect(left, top, width, height, "fill=\"white\" stroke=\"#888\" stroke-width=\"1\"");
  double max_iteration = 0.0;
  double low = std::numeric_limits<double>::infinity();
  double high = -std::numeric_limits<double>::infinity();
  bool any_feasible = false;
  for (const ConvergenceCurve& curve : curves) {
    for (const ConvergencePoint& point : curve.best) any_feasible |= point.feasible;
  }
  for (const ConvergenceCurve& curve : curves) {
    for (const ConvergencePoint& point : curve.best) {
      if (!std::isfinite(point.best)) continue;
      max_iteration = std::max(max_iteration, point.iteration);
      if (any_feasible && !point.feasible) continue;
      low = std::min(low, point.best);
      high = std::max(high, point.best);
    }
  }
  svg.Text(left + width / 2, top + 16,
           any_feasible ? "convergence: best fitness per iteration (feasible range)"
                        : "convergence: best fitness per iteration",
           "font-size=\"12\" text-anchor=\"middle\" fill=\"#222\"");
  if (!std::isfinite(low)) {
    svg.Text(left + width / 2, top + height / 2, "no finite fitness values",
             "font-size=\"12\" text-anchor=\"middle\" fill=\"#888\"");
    return;
  }
  if (high - low < 1e-12) {
    high = low + std::max(std::abs(low) * 0.01, 1e-6);
  }
  const double plot_left = left + 64, plot_right = left + width - 12;
  const double plot_top = top + 26, plot_bottom = top + height - 30;
  const double x_span = std::max(max_iteration, 1.0);
  auto to_pixel = [&](double iteration, double best) {
    const double clipped = std::min(best, high);
    return Point2(plot_left + iteration / x_span * (plot_right - plot_left),
                  plot_bottom - (clipped - low) / (high - low) * (plot_bottom - plot_top));
  };
  svg.Line(plot_left, plot_bottom, plot_right, plot_bottom, "stroke=\"#444\"");
  svg.Line(plot_left, plot_top, plot_left, plot_bottom, "stroke=\"#444\"");
  const std::string tick = "font-size=\"10\" fill=\"#444\"";
  svg.Text(plot_left - 4, plot_top + 4, Number(high), tick + " text-anchor=\"end\"");
  svg.Text(plot_left - 4, plot_bottom, Number(low), tick + " text-anchor=\"end\"");
  svg.Text(plot_left, plot_bottom + 14, "0", tick + " text-anchor=\"middle\"");
  svg.Text(plot_right, plot_bottom + 14, Number(max_iteration), tick + " text-anchor=\"end\"");
  svg.Text((plot_left + plot_right) / 2, plot_bottom + 24, "iteration",
           tick + " text-anchor=\"middle\"");
  for (size_t i = 0; i < curves.size(); ++i) {
    std::vector<Point2> pixels;
    for (const ConvergencePoint& point : curves[i].best) {
      if (!std::isfinite(point.best)) continue;
      const Point2 p = to_pixel(point.iteration, point.best);
      // The best is non-increasing: one point per pixel column keeps the shape.
      if (!pixels.empty() && std::abs(p.x() - pixels.back().x()) < 0.5) {
        pixels.back() = p;
      } else {
        pixels.push_back(p);
      }
    }
    if (pixels.size() == 1) {
      svg.Circle(pixels[0].x(), pixels[0].y(), 3, absl::StrCat("fill=\"", PathColor(i), "\""));
    } else if (!pixels.empty()) {
      svg.Polyline(pixels,
                   absl::StrCat("fill=\"none\" stroke=\"", PathColor(i), "\" stroke-width=\"2\""));
    }
  }
}

}  // namespace

std::string RenderMapSvg(const Map& map, const std::vector<RenderedPath>& paths,
                         const std::vector<ConvergenceCurve>& curves,
                         const RenderOptions& options) {
  const WorldBox box = MapBox(map);
  const double world_width = std::max(box.max_x - box.min_x, 1e-9);
  const double world_height = std::max(box.max_y - box.min_y, 1e-9);
  const double scale =
      std::min(options.max_width_px / world_width, options.max_height_px / world_height);
  const double top = kMargin + (options.title.empty() ? 0.0 : kTitleHeight);
  const Viewport view(box, scale, kMargin, top, options.y_up);
  const double content_width = std::max(view.width(), 360.0);
  const bool inset = options.convergence_inset && !curves.empty();
  double height = top + view.height() + kMargin + paths.size() * kLegendLine;
  const double inset_top = height + (paths.empty() ? 0.0 : kMargin);
  if (inset) height = inset_top + kInsetHeight + kMargin;
  SvgWriter svg(content_width + 2 * kMargin, height);
  svg.Rect(0, 0, content_width + 2 * kMargin, height, "fill=\"#fafafa\"");
  if (!options.title.empty()) {
    svg.Text(kMargin, kMargin + 14, options.title, "font-size=\"15\" fill=\"#222\"");
  }
  svg.Rect(kMargin, top, view.width(), view.height(), "fill=\"white\" stroke=\"#222\"");
  if (const OccupancyGrid* grid = map.grid()) DrawGrid(svg, view, *grid);
  if (const ShapeWorld* world = map.world()) DrawWorld(svg, view, *world);
  if (const Terrain* terrain = map.terrain()) DrawTerrain(svg, view, *terrain);
  DrawPaths(svg, view, paths);
  DrawLegend(svg, kMargin, top + view.height() + kMargin / 2, paths);
  if (inset) DrawConvergence(svg, kMargin, inset_top, content_width, kInsetHeight, curves);
  return svg.Finish();
}

std::string RenderConvergenceSvg(const std::vector<ConvergenceCurve>& curves,
                                 const std::string& title) {
  constexpr double kWidth = 640, kHeight = 360;
  const double top = kMargin + (title.empty() ? 0.0 : kTitleHeight);
  const double height = top + kHeight + kMargin + curves.size() * kLegendLine;
  SvgWriter svg(kWidth + 2 * kMargin, height);
  svg.Rect(0, 0, kWidth + 2 * kMargin, height, "fill=\"#fafafa\"");
  if (!title.empty()) svg.Text(kMargin, kMargin + 14, title, "font-size=\"15\" fill=\"#222\"");
  DrawConvergence(svg, kMargin, top, kWidth, kHeight, curves);
  for (size_t i = 0; i < curves.size(); ++i) {
    const double y = top + kHeight + kMargin / 2 + i * kLegendLine;
    svg.Line(kMargin, y + 9, kMargin + 24, y + 9,
             absl::StrCat("stroke=\"", PathColor(i), "\" stroke-width=\"3\""));
    svg.Text(kMargin + 30, y + 13,
             absl::StrCat(curves[i].label, "  (", curves[i].best.size(), " iterations)"),
             "font-size=\"12\" fill=\"#222\"");
  }
  return svg.Finish();
}

}  // namespace swarmplan::client
