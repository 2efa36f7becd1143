#include "core/stop_token.h"

namespace swarmplan {

const char* StopReasonName(StopReason reason) {
  switch (reason) {
    case StopReason::kNone:
      return "none";
    case StopReason::kCancelled:
      return "cancelled";
    case StopReason::kDeadline:
      return "deadline";
    case StopReason::kIterationCap:
      return "iteration-cap";
  }
  return "unknown";
}

}  // namespace swarmplan
