#include "client/svg_writer.h"

#include <cmath>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"

namespace swarmplan::client {

std::string FormatPixel(double value) {
  std::string text = absl::StrFormat("%.2f", std::abs(value) < 0.005 ? 0.0 : value);
  while (text.back() == '0') text.pop_back();
  if (text.back() == '.') text.pop_back();
  return text;
}

std::string EscapeXml(const std::string& text) {
  std::string escaped;
  for (char c : text) {
    switch (c) {
      case '&':
        escaped += "&amp;";
        break;
      case '<':
        escaped += "&lt;";
        break;
      case '>':
        escaped += "&gt;";
        break;
      case '"':
        escaped += "&quot;";
        break;
      default:
        escaped += c;
    }
  }
  return escaped;
}

SvgWriter::SvgWriter(double width, double height) : width_(width), height_(height) {}

void SvgWriter::Rect(double x, double y, double width, double height,
                     const std::string& attributes) {
  absl::StrAppend(&body_, "<rect x=\"", FormatPixel(x), "\" y=\"", FormatPixel(y), "\" width=\"",
                  FormatPixel(width), "\" height=\"", FormatPixel(height), "\" ", attributes,
                  "/>\n");
}

void SvgWriter::Circle(double cx, double cy, double r, const std::string& attributes) {
  absl::StrAppend(&body_, "<circle cx=\"", FormatPixel(cx), "\" cy=\"", FormatPixel(cy), "\" r=\"",
                  FormatPixel(r), "\" ", attributes, "/>\n");
}

void SvgWriter::Line(double x1, double y1, double x2, double y2, const std::string& attributes) {
  absl::StrAppend(&body_, "<line x1=\"", FormatPixel(x1), "\" y1=\"", FormatPixel(y1), "\" x2=\"",
                  FormatPixel(x2), "\" y2=\"", FormatPixel(y2), "\" ", attributes, "/>\n");
}

void SvgWriter::AppendPoints(const std::vector<Point2>& points) {
  body_ += "points=\"";
  for (size_t i = 0; i < points.size(); ++i) {
    if (i > 0) body_ += ' ';
    absl::StrAppend(&body_, FormatPixel(points[i].x()), ",", FormatPixel(points[i].y()));
  }
  body_ += "\" ";
}

void SvgWriter::Polygon(const std::vector<Point2>& points, const std::string& attributes) {
  body_ += "<polygon ";
  AppendPoints(points);
  absl::StrAppend(&body_, attributes, "/>\n");
}

void SvgWriter::Polyline(const std::vector<Point2>& points, const std::string& attributes) {
  body_ += "<polyline ";
  AppendPoints(points);
  absl::StrAppend(&body_, attributes, "/>\n");
}

void SvgWriter::Text(double x, double y, const std::string& text, const std::string& attributes) {
  absl::StrAppend(&body_, "<text x=\"", FormatPixel(x), "\" y=\"", FormatPixel(y), "\" ",
                  attributes, ">", EscapeXml(text), "</text>\n");
}

void SvgWriter::BeginGroup(const std::string& attributes) {
  absl::StrAppend(&body_, "<g ", attributes, ">\n");
}

void SvgWriter::EndGroup() { body_ += "</g>\n"; }

void SvgWriter::Comment(const std::string& text) {
  std::string safe = text;
  for (size_t at = safe.find("--"); at != std::string::npos; at = safe.find("--")) {
    safe.replace(at, 2, "- -");
  }
  absl::StrAppend(&body_, "<!-- ", safe, " -->\n");
}

std::string SvgWriter::Finish() const {
  const std::string width = FormatPixel(width_);
  const std::string height = FormatPixel(height_);
  return absl::StrCat("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n",
                      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"", width, "\" height=\"",
                      height, "\" viewBox=\"0 0 ", width, " ", height,
                      "\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n", body_,
                      "</svg>\n");
}

}  // namespace swarmplan::client
