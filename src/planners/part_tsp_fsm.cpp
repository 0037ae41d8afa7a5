#include "hullinspect/planners/part_tsp_fsm.hpp"

#include "hullinspect/sim/types.hpp"

namespace hullinspect::planners::part_tsp {

FsmDecision evaluate_fsm(const FsmInput& in, int r1, int r2) {
  if (in.h == 0 && in.unknown == 0) return FsmDecision::kDone;
  if (in.z == 2) {
    const bool descend = in.h > 0 && (in.t_d >= r1 || in.unknown == 0);
    return descend ? FsmDecision::kChangePlane : FsmDecision::kStay;
  }
  const bool ascend = in.h == 0 && in.t_i >= r2 && in.unknown > 0;
  return ascend ? FsmDecision::kChangePlane : FsmDecision::kStay;
}

std::int8_t target_value(int z, int h) {
  return z == 1 && h > 0 ? sim::kCorrosionSeen : sim::kUnknown;
}

}  // namespace hullinspect::planners::part_tsp
