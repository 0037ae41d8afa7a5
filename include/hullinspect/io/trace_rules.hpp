#pragma once
// The rules of a flown mission checked from its trace alone (docs/trace-format.md, "Rules"):
// validate_trace applies the ones every mission the simulator flies keeps; check_trace_safety adds
// the ones a mission flown by the sortie and deconfliction layers keeps on top.

#include <nlohmann/json.hpp>

#include <string>

namespace hullinspect::io {

/// For a trace validate_trace accepted: throws InputError(source, 0, "<field>: <problem>") on the
/// first breach of the safety rules — a UAV that crashed with an empty battery, a landing with
/// less than the reserve left, two UAVs closer than the separation D (or exchanging cells). A
/// trace of the paper's model (no launch site, no battery, no separation) keeps them trivially.
void check_trace_safety(const nlohmann::json& trace, const std::string& source);

}  // namespace hullinspect::io
