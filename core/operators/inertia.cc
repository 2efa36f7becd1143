#include "core/operators/inertia.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "absl/strings/str_cat.h"

namespace swarmplan {

absl::StatusOr<InertiaSchedule> ParseInertiaSchedule(const std::string& name) {
  if (name == "linear") return InertiaSchedule::kLinear;
  if (name == "cosine") return InertiaSchedule::kCosine;
  return absl::InvalidArgumentError(
      absl::StrCat("inertia: unknown schedule '", name, "' (linear, cosine)"));
}

double InertiaWeight(InertiaSchedule schedule, double w_max, double w_min, int t, int t_max) {
  const double ratio = t_max > 0 ? std::clamp(static_cast<double>(t) / t_max, 0.0, 1.0) : 1.0;
  switch (schedule) {
    case InertiaSchedule::kLinear:
      return w_max - (w_max - w_min) * ratio;
    case InertiaSchedule::kCosine:
      return w_min + (w_max - w_min) * std::cos(std::numbers::pi / 2.0 * std::sqrt(ratio));
  }
  return w_min;
}

}  // namespace swarmplan
