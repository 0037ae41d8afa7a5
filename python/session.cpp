#include "session.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <tuple>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/io/result_json.hpp"
#include "hullinspect/world/standoff_surface.hpp"

namespace hullinspect::python {

namespace {

std::uint8_t plane_bit(int plane) {
  return static_cast<std::uint8_t>(1U << plane);
}

}  // namespace

Session::Session(std::shared_ptr<const world::HullMask> hull, planners::MissionSpec spec,
                 grid::Grid<std::int8_t> prior, bool record_trace)
    : hull_(std::move(hull)), spec_(std::move(spec)) {
  // The start cells, computed once by the validation: the planner and the simulator use them.
  starts_ = planners::validate(spec_, *hull_);
  // A live session is fed by real UAVs already in the air; the simulated legs between launch
  // sites and the hull (docs/model.md §12) have no counterpart in it.
  if (!spec_.params.launch_sites.empty()) {
    throw ParameterError("launch",
                         "is not available in a live session (the UAVs report from the "
                         "air; plan their flights out and home with run())");
  }
  const int cells = hull_->width() * hull_->height();
  instance_.truth = grid::Grid<std::int8_t>(hull_->width(), hull_->height(), -1);
  for (int i : hull_->cells()) instance_.truth[i] = 0;
  instance_.prior = std::move(prior);
  instance_.seed = spec_.seed;

  initial_map_ = grid::Grid<std::int8_t>(hull_->width(), hull_->height(), sim::kNotHull);
  for (int i : hull_->cells()) {
    initial_map_[i] = instance_.prior[i] == 1 ? sim::kCorrosionSeen : sim::kUnknown;
  }
  for (const auto& c : starts_)
    initial_uavs_.push_back(sim::UavState{c, spec_.params.start_z, 0, false});
  pending_.assign(static_cast<std::size_t>(spec_.params.uavs), sim::Action::kHover);
  stamp_.assign(static_cast<std::size_t>(cells), -1);
  expected_planes_.assign(static_cast<std::size_t>(cells), 0);
  reported_planes_.assign(static_cast<std::size_t>(cells), 0);
  reported_value_.assign(static_cast<std::size_t>(cells), 0);

  planner_ = planners::make_planner(spec_.algorithm, spec_.planner_options);
  if (planner_->sees_truth()) {
    throw ParameterError("algorithm", fmt::format("'{}' needs the ground truth, which a live "
                                                  "session does not have",
                                                  spec_.algorithm));
  }
  if (record_trace) recorder_.emplace(instance_, io::spec_json(spec_, hull_->source()));
}

std::vector<std::array<int, 3>> Session::expected_readings(const std::vector<int>& failed) const {
  std::vector<std::array<int, 3>> out;
  const auto& params = spec_.params;
  const auto states = uavs();
  for (std::size_t k = 0; k < states.size(); ++k) {
    sim::UavState u = states[k];
    if (mission_) {  // where the pending action leaves the UAV (Simulator::step's rules)
      const sim::Simulator& sim = mission_->simulator();
      if (u.failed ||
          std::find(failed.begin(), failed.end(), static_cast<int>(k)) != failed.end()) {
        continue;
      }
      if (u.in_transit()) {
        if (--u.transit_left == 0) u.z = 3 - u.z;
      } else if (pending_[k] == sim::Action::kChangePlane) {
        u.transit_left = sim.plane_change_steps() - 1;
        if (u.transit_left == 0) u.z = 3 - u.z;
      } else {
        u.pos = sim::moved(u.pos, pending_[k], hull_->width(), hull_->height(),
                           sim.flight_steps().plane[0]);
      }
      if (u.in_transit()) continue;
    }
    const int half = params.half_side(u.z);
    for (int y = std::max(0, u.pos.y - half); y <= std::min(hull_->height() - 1, u.pos.y + half);
         ++y) {
      for (int x = std::max(0, u.pos.x - half); x <= std::min(hull_->width() - 1, u.pos.x + half);
           ++x) {
        if (hull_->is_hull(x, y)) out.push_back({x, y, u.z});
      }
    }
  }
  // One entry per (cell, plane), in (y, x, plane) order.
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) {
    return std::tie(a[1], a[0], a[2]) < std::tie(b[1], b[0], b[2]);
  });
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

void Session::check_readings(const std::vector<CellReading>& readings,
                             const std::vector<int>& failed) {
  const int t = time();
  for (std::size_t j = 0; j < failed.size(); ++j) {
    const int k = failed[j];
    if (!mission_) {
      throw Error(
          fmt::format("failed: no UAV can fail before the first step (t = 0); give its "
                      "readings or leave it out of the fleet"));
    }
    if (k < 0 || k >= spec_.params.uavs) {
      throw Error(fmt::format("failed[{}]: no UAV {} in a fleet of {}", j, k, spec_.params.uavs));
    }
  }
  ++call_;
  const auto expected = expected_readings(failed);
  for (const auto& [x, y, plane] : expected) {
    const auto i = static_cast<std::size_t>(hull_->mask().index(x, y));
    if (stamp_[i] != call_) {
      stamp_[i] = call_;
      expected_planes_[i] = 0;
      reported_planes_[i] = 0;
    }
    expected_planes_[i] |= plane_bit(plane);
  }
  for (std::size_t j = 0; j < readings.size(); ++j) {
    const auto& r = readings[j];
    if (!hull_->mask().contains(r.x, r.y)) {
      throw Error(fmt::format("readings[{}]: cell ({}, {}) is outside the {} × {} grid", j, r.x,
                              r.y, hull_->width(), hull_->height()));
    }
    if (r.plane != 1 && r.plane != 2) {
      throw Error(fmt::format("readings[{}]: plane must be 1 or 2 (got {})", j, r.plane));
    }
    const auto i = static_cast<std::size_t>(hull_->mask().index(r.x, r.y));
    if (stamp_[i] != call_ || (expected_planes_[i] & plane_bit(r.plane)) == 0) {
      throw Error(
          fmt::format("readings[{}]: no UAV senses cell ({}, {}) from plane {} at t = {} "
                      "(Session.expected_readings() lists the cells)",
                      j, r.x, r.y, r.plane, mission_ ? t + 1 : 0));
    }
    const auto value = static_cast<std::int8_t>(r.corroded ? 1 : 0);
    if (reported_planes_[i] != 0 && reported_value_[i] != value) {
      throw Error(fmt::format("readings[{}]: cell ({}, {}) is reported both corroded and clean", j,
                              r.x, r.y));
    }
    reported_planes_[i] |= plane_bit(r.plane);
    reported_value_[i] = value;
  }
  for (const auto& [x, y, plane] : expected) {
    const auto i = static_cast<std::size_t>(hull_->mask().index(x, y));
    if ((reported_planes_[i] & plane_bit(plane)) == 0) {
      throw Error(
          fmt::format("readings: no reading of cell ({}, {}) from plane {} at t = {} ({} "
                      "cells expected; Session.expected_readings() lists them)",
                      x, y, plane, mission_ ? t + 1 : 0, expected.size()));
    }
  }
}

std::vector<sim::Action> Session::step(const std::vector<CellReading>& readings,
                                       const std::vector<int>& failed) {
  if (finished()) {
    throw Error(fmt::format("the mission has finished (t = {}, {}); start a new Session", time(),
                            complete() ? "complete" : "incomplete"));
  }
  check_readings(readings, failed);
  for (const auto& r : readings) {
    instance_.truth(r.x, r.y) = static_cast<std::int8_t>(r.corroded ? 1 : 0);
  }
  if (!mission_) {
    // The simulator senses t = 0 from the first readings, so the mission starts only now; the
    // MissionStepper builds it as every simulated mission is built.
    planners::MissionOptions options;
    if (recorder_) options.observers.push_back(&*recorder_);
    mission_.emplace(*hull_, instance_, spec_.params, starts_, *planner_,
                     planners::with_spec(spec_, options));
  } else {
    for (int k : failed) mission_->simulator().fail_uav_at(k, mission_->simulator().time());
    mission_->apply();
  }
  if (finished()) return {};
  const auto actions = mission_->decide();
  pending_.assign(actions.begin(), actions.end());
  return pending_;
}

sim::MissionResult Session::result() const {
  if (!mission_) throw Error("the mission has not started: call step() with the first readings");
  return mission_->result();
}

nlohmann::json Session::trace() const {
  if (!recorder_) throw Error("trace: this Session records no trace (pass keep_trace=True)");
  return recorder_->finish(result());
}

}  // namespace hullinspect::python
