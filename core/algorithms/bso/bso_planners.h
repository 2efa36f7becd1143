#pragma once

#include "core/registry.h"

namespace swarmplan {

// The beetle swarms of the AEM-BSO paper over spline waypoints: bso, aem-bso, aem-bso-linear.
PlannerInfo BsoInfo();
PlannerInfo AemBsoInfo();
PlannerInfo AemBsoLinearInfo();

}  // namespace swarmplan
