#pragma once

#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "swarmplan/v1/jobs.pb.h"

// Paths on disk: what `plan --output` and `jobs get --output` write, and what `render --path`
// reads back.
namespace swarmplan::client {

// "json", "csv", "geojson", "vda5050" (given with --output-format: its files are .json).
std::vector<std::string> PathFormats();

// The format for a file: `format` when given, else from the extension (.json, .csv,
// .geojson). INVALID_ARGUMENT when neither says.
absl::StatusOr<std::string> PathFormatFor(const std::string& file, const std::string& format);

// Writes the job's path (the smoothed one; the raw one too in JSON):
//   json     {"job_id", "algorithm", "state", "map_id", "seed", "length", "path": [[x, y, z]...],
//             "raw_path": [...]}
//   csv      header "x,y,z", one point per line
//   geojson  a FeatureCollection with one LineString feature (properties: job_id, algorithm...)
//   vda5050  a VDA 5050 order (Vda5050Order)
// FAILED_PRECONDITION when the job has no path.
absl::Status WritePathFile(const std::string& file, const std::string& format, const v1::Job& job);

struct PathFile {
  std::string label;  // the job id or algorithm the file names, else the file's stem
  std::vector<v1::Point> points;
};

// Reads a path written by WritePathFile (of a VDA 5050 order, its nodes' positions), or any
// GeoJSON with a LineString, a JSON array of [x, y(, z)] or {"x", "y"(, "z")}, or a CSV with
// x,y(,z) columns.
absl::StatusOr<PathFile> ReadPathFile(const std::string& file);

}  // namespace swarmplan::client
