#include "core/fitness/fleet_objective.h"

#include <cmath>

#include "absl/strings/str_cat.h"

namespace swarmplan {

absl::Status ValidateFleetObjective(const FleetObjective& fleet) {
  const struct {
    const char* name;
    double value;
  } fields[] = {{"preferred_clearance", fleet.preferred_clearance},
                {"clearance_weight", fleet.clearance_weight},
                {"turning_radius", fleet.turning_radius},
                {"curvature_weight", fleet.curvature_weight},
                {"violation_weight", fleet.violation_weight}};
  for (const auto& field : fields) {
    if (!std::isfinite(field.value) || field.value < 0) {
      return absl::InvalidArgumentError(
          absl::StrCat("preferences.", field.name, ": must be finite and >= 0, got ", field.value));
    }
  }
  return absl::OkStatus();
}

}  // namespace swarmplan
