// One map format, named by SWARMPLAN_FUZZ_FORMAT at compile time, from one file of fuzzer bytes.

#include "core/map/io/map_io.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace swarmplan;
  const std::vector<MapFile> files = {MapFile{SWARMPLAN_FUZZ_FILE_NAME, fuzz::Bytes(data, size)}};
  absl::StatusOr<Map> map = ParseMap(SWARMPLAN_FUZZ_FORMAT, files, fuzz::FuzzLoadOptions());
  fuzz::CheckError(map.status(), files);
  return 0;
}
