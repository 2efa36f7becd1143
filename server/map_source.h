#pragma once

#include <string>

#include "absl/status/statusor.h"
#include "core/map/io/map_io.h"
#include "core/map/map.h"
#include "swarmplan/v1/maps.pb.h"

namespace swarmplan::server {

// Builds a core map from what a client uploaded (files + format, or structured data).
// INVALID_ARGUMENT naming the field, file or line; RESOURCE_EXHAUSTED beyond the limits.
absl::StatusOr<Map> BuildMap(const v1::MapSource& source, const LoadOptions& options);

// The description of a map (kind, size, bounds, obstacles); id, name, times and hash unset.
v1::MapInfo DescribeMap(const Map& map);

// "structured" or the files' format.
std::string SourceFormat(const v1::MapSource& source);

// SHA-256 (hex) of the serialized source.
std::string ContentHash(const std::string& serialized_source);

}  // namespace swarmplan::server
