#pragma once

#include <string>
#include <vector>

#include "core/map/point.h"

namespace swarmplan::client {

// A minimal SVG document builder. Coordinates are pixels; `attributes` are written verbatim
// (e.g. R"(fill="#333" stroke="none")"); text is escaped.
class SvgWriter {
 public:
  SvgWriter(double width, double height);

  void Rect(double x, double y, double width, double height, const std::string& attributes);
  void Circle(double cx, double cy, double r, const std::string& attributes);
  void Line(double x1, double y1, double x2, double y2, const std::string& attributes);
  void Polygon(const std::vector<Point2>& points, const std::string& attributes);
  void Polyline(const std::vector<Point2>& points, const std::string& attributes);
  void Text(double x, double y, const std::string& text, const std::string& attributes);
  void BeginGroup(const std::string& attributes);
  void EndGroup();
  void Comment(const std::string& text);

  // The complete document.
  std::string Finish() const;

 private:
  void AppendPoints(const std::vector<Point2>& points);

  double width_;
  double height_;
  std::string body_;
};

// Pixel coordinates as short text: at most two decimals, no trailing zeros.
std::string FormatPixel(double value);
std::string EscapeXml(const std::string& text);

}  // namespace swarmplan::client
