#include "core/map/map.h"

#include "absl/strings/str_join.h"

namespace swarmplan {

const char* MapKindName(MapKind kind) {
  switch (kind) {
    case MapKind::kOccupancyGrid:
      return "occupancy-grid";
    case MapKind::kShapeWorld:
      return "shape-world";
    case MapKind::kTerrain:
      return "terrain";
  }
  return "unknown";
}

std::string JoinMapKinds(const std::vector<MapKind>& kinds) {
  return absl::StrJoin(kinds, ", ",
                       [](std::string* out, MapKind kind) { out->append(MapKindName(kind)); });
}

}  // namespace swarmplan
