#pragma once

#include <cstdint>

#include "absl/time/time.h"
#include "core/planner.h"
#include "core/stop_token.h"

namespace swarmplan {

// The result of an exact search, which is one iteration: the observer sees it once, with
// best = mean = the path's length; found when the path is not empty.
SearchResult FinishExactSearch(Path path, int64_t expanded, absl::Time started, Observer& observer);
// The same with the cost the search minimised (terrain: the terrain objective) as the fitness.
SearchResult FinishExactSearch(Path path, double cost, int64_t expanded, absl::Time started,
                               Observer& observer);

// The result of a search ended by the stop token before it finished.
SearchResult StoppedExactSearch(StopReason reason);

}  // namespace swarmplan
