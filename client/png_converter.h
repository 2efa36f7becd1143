#pragma once

#include <string>

#include "absl/status/statusor.h"

namespace swarmplan::client {

// Converts an SVG file to PNG with the first converter found on PATH: rsvg-convert (librsvg2-bin),
// inkscape, or ImageMagick (magick / convert). FAILED_PRECONDITION with what to install when
// none is available; INTERNAL when the converter fails. Returns the converter's name.
absl::StatusOr<std::string> ConvertSvgToPng(const std::string& svg_file,
                                            const std::string& png_file);

}  // namespace swarmplan::client
