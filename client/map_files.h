#pragma once

#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "core/map/map.h"
#include "swarmplan/v1/maps.pb.h"

// Map content on the client side: files read for an upload, files saved from the server, and
// the core map rebuilt from what the server returns (for rendering).
namespace swarmplan::client {

// Reads a map file for UploadMap. The format is guessed from the extension when empty; for
// ros-yaml-pgm the image the YAML names is read too. Files are named by their base names.
absl::StatusOr<v1::MapFiles> ReadMapFiles(const std::string& path, const std::string& format);

// Writes the files of an uploaded map into `dir` (structured maps as JSON); returns the paths.
absl::StatusOr<std::vector<std::string>> SaveMapSource(const v1::MapSource& source,
                                                       const std::string& dir);

// Parses what GetMap(include_source) returns into a core map.
absl::StatusOr<Map> MapFromSource(const v1::MapSource& source);

}  // namespace swarmplan::client
