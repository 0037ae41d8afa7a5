#pragma once
// Shared checker of recorded missions: a trace must pass the reader's rules (io::validate_trace:
// motion, no-fly, the ground, the battery and its swaps, the result's counts) and the safety rules
// (io::check_trace_safety: no battery crash, every landing with the reserve, no separation
// conflict), judged from the trace alone.

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/world/hull.hpp"

namespace hullinspect::testing {

/// The trace of `spec`'s mission on `hull`, as `hullinspect run --trace` records it.
nlohmann::json recorded_trace(const planners::MissionSpec& spec, const world::HullMask& hull);

/// Success when `trace` keeps every rule; otherwise the reader's one-line message.
::testing::AssertionResult trace_keeps_the_rules(const nlohmann::json& trace);

}  // namespace hullinspect::testing
