#pragma once

#include <string>

#include "absl/status/statusor.h"

namespace swarmplan {

// Inertia weight schedules from w_max at t = 0 down to w_min at t = t_max:
// linear (BSO eq 4) and the cosine-of-square-root schedule of AEM-BSO eq 6.
enum class InertiaSchedule { kLinear, kCosine };

absl::StatusOr<InertiaSchedule> ParseInertiaSchedule(const std::string& name);

double InertiaWeight(InertiaSchedule schedule, double w_max, double w_min, int t, int t_max);

}  // namespace swarmplan
