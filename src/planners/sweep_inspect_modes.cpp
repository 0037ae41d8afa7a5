// Sweep-Inspect's state machine (docs/sweep-inspect.md, "The state machine"): a UAV's mode and
// every transition out of it, one function per mode. A mode's function returns the UAV's action,
// or nullopt when it moved the UAV to another mode (or re-planned its sweep) so that the new mode
// decides this step's action; decide_uav runs them until one acts.

#include "hullinspect/planners/sweep_inspect_planner.hpp"

#include "hullinspect/planners/band_rejoin.hpp"

namespace hullinspect::planners {

sim::Action SweepInspectPlanner::decide_uav(int k, const sim::UavState& u,
                                            const sim::PlannerView& view) {
  Uav& p = uavs_[static_cast<std::size_t>(k)];
  if (u.failed) {
    p = Uav{};
    p.mode = Mode::kFailed;
    return sim::Action::kHover;
  }
  if (u.in_transit()) return sim::Action::kHover;
  take_handed_prior(p, u, prior_[static_cast<std::size_t>(k)]);
  for (;;) {
    std::optional<sim::Action> action;
    switch (p.mode) {
      case Mode::kPrior:
        action = prior_tour_step(k, u, view);
        break;
      case Mode::kSweep:
        action = sweep_mode(k, u, view);
        break;
      case Mode::kReturn:
        action = return_mode(k, u, view);
        break;
      case Mode::kInspect:
        action = inspect_mode(k, u, view);
        break;
      case Mode::kDone:
        p.mode = Mode::kHelp;
        break;  // work may have appeared
      case Mode::kHelp:
        action = help_mode(k, u, view);
        break;
      case Mode::kFailed:
        return sim::Action::kHover;
    }
    if (action) return *action;
  }
}

void SweepInspectPlanner::take_handed_prior(Uav& p, const sim::UavState& u,
                                            const std::vector<int>& prior) {
  // Prior cells handed over from a failed UAV: leave the sweep (or help) for them, come back.
  if (prior.empty() || u.z != 2) return;
  if (p.mode != Mode::kSweep && p.mode != Mode::kHelp && p.mode != Mode::kDone) return;
  p.after_prior = p.mode == Mode::kSweep ? Mode::kReturn : Mode::kHelp;
  if (p.mode == Mode::kSweep) p.resume = u.pos;
  p.target_cell = -1;
  p.mode = Mode::kPrior;
}

std::optional<sim::Action> SweepInspectPlanner::sweep_mode(int k, const sim::UavState& u,
                                                           const sim::PlannerView& view) {
  Uav& p = uavs_[static_cast<std::size_t>(k)];
  if (p.low) {
    // A dense zone's sweep at z = 1: every cell seen is inspected on the way.
    if (p.replan) {
      p.replan = false;
      p.sweep.assign(sweep_from(k, u.pos));
      if (!p.low) return std::nullopt;  // the share planned from here starts at z = 2
    }
    if (u.z == 2) return sim::Action::kChangePlane;
    return follow_sweep(k, u, view);
  }
  if (u.z == 1) {  // arrived below for an inspection
    p.mode = Mode::kInspect;
    return std::nullopt;
  }
  if (p.replan) {
    // Its cells were re-split after a failure: strips over its new share from here.
    p.replan = false;
    p.sweep.assign(sweep_from(k, u.pos));
  }
  return sweep_at_z2(k, u, view);
}

std::optional<sim::Action> SweepInspectPlanner::sweep_at_z2(int k, const sim::UavState& u,
                                                            const sim::PlannerView& view) {
  Uav& p = uavs_[static_cast<std::size_t>(k)];
  if (detection_abreast(k, u.pos, view)) {
    p.resume = u.pos;
    return sim::Action::kChangePlane;
  }
  return follow_sweep(k, u, view);
}

std::optional<sim::Action> SweepInspectPlanner::return_mode(int k, const sim::UavState& u,
                                                            const sim::PlannerView& view) {
  Uav& p = uavs_[static_cast<std::size_t>(k)];
  if (u.z == 1) {  // descended again for an inspection before it was back
    p.mode = Mode::kInspect;
    return std::nullopt;
  }
  if (p.replan) {
    // Its cells were re-split after a failure: strips over its new share from here.
    p.replan = false;
    p.mode = Mode::kSweep;
    p.sweep.assign(sweep_from(k, u.pos));
    return sweep_at_z2(k, u, view);
  }
  if (u.pos == p.resume) {
    p.mode = Mode::kSweep;
    return sweep_at_z2(k, u, view);
  }
  return step(k, u.pos, p.resume);
}

std::optional<sim::Action> SweepInspectPlanner::inspect_mode(int k, const sim::UavState& u,
                                                             const sim::PlannerView& view) {
  Uav& p = uavs_[static_cast<std::size_t>(k)];
  if (u.z == 2) {  // climbed back: resume the sweep
    p.mode = Mode::kReturn;
    p.target_cell = -1;
    if (u.pos == p.resume) return std::nullopt;
    return step(k, u.pos, p.resume);
  }
  int cell = -1;
  p.viewpoint = inspection_viewpoint(k, u.pos, p.resume, radius_, p.viewpoint, cell, view);
  p.target_cell = cell;
  if (cell < 0) {
    // Nothing left to inspect here: rejoin the sweep, or plan it anew from here.
    p.resume = band_rejoin_point({p.resume, p.sweep.target(), p.axis}, u.pos, h2_, view,
                                 *uav_distances_[static_cast<std::size_t>(k)]);
    if (replan_after_inspection(k, u.pos, view) && p.low) {
      // The sweep planned from here starts with dense columns, swept at z = 1: no climb.
      p.mode = Mode::kSweep;
      return std::nullopt;
    }
    return sim::Action::kChangePlane;
  }
  p.target = p.viewpoint;
  return step(k, u.pos, p.target);
}

std::optional<sim::Action> SweepInspectPlanner::help_mode(int k, const sim::UavState& u,
                                                          const sim::PlannerView& view) {
  Uav& p = uavs_[static_cast<std::size_t>(k)];
  if (p.replan && (u.z == 2 || p.low)) {
    // Cells re-split after a failure while it was helping: sweep them.
    p.replan = false;
    p.sweep.assign(sweep_from(k, u.pos));
    p.sweep_planned = true;
    p.target_cell = -1;
    const sim::Action a = p.sweep.next_action(u.pos);
    if (a != sim::Action::kHover) {
      p.mode = Mode::kSweep;
      return a;
    }
  }
  return help_step(k, u, view);
}

}  // namespace hullinspect::planners
