// Moving AI .scen files.

#include "core/map/io/map_io.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace swarmplan;
  const MapFile file{"m.scen", fuzz::Bytes(data, size)};
  absl::StatusOr<std::vector<Scenario>> scenarios = ParseScenarios(file.name, file.bytes);
  fuzz::CheckError(scenarios.status(), {file});
  return 0;
}
