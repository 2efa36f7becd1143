// A ROS map_server pair: the YAML is the input up to its first NUL byte, the image the rest.

#include <cstring>

#include "core/map/io/formats.h"
#include "core/map/io/map_io.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace swarmplan;
  const auto* nul = static_cast<const uint8_t*>(std::memchr(data, 0, size));
  const size_t yaml_size = nul == nullptr ? size : static_cast<size_t>(nul - data);
  const size_t image_start = nul == nullptr ? size : yaml_size + 1;
  const std::vector<MapFile> files = {
      MapFile{"m.yaml", fuzz::Bytes(data, yaml_size)},
      MapFile{"m.pgm", fuzz::Bytes(data + image_start, size - image_start)}};
  absl::StatusOr<Map> map = ParseMap("ros-yaml-pgm", files, fuzz::FuzzLoadOptions());
  fuzz::CheckError(map.status(), files);
  // The path LoadMapFile resolves from the YAML: an error names the YAML.
  absl::StatusOr<std::string> image = RosMapImagePath(files.front());
  fuzz::CheckError(image.status(), {files.front()});
  return 0;
}
