#pragma once
// The separation part of the pre-flight report (docs/export.md "Pre-flight report"): the D the
// mission was planned with, the smallest separation its flights keep and the conflicts counted.

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "hullinspect/io/export.hpp"

namespace hullinspect::io {

/// {"d": D (0: the mission had none), "min_cells": the smallest max(|Δx|, |Δy|) between two UAVs
/// at one step of the trace (null with one UAV), "min_m": the same in metres, "uavs": [a, b] and
/// "t_s": where and when (the first such step), "conflicts": the simulator's count (0 without D)}.
/// Adds a warning when the flights come closer than D, or share a cell with no D.
nlohmann::json preflight_separation(const nlohmann::json& trace, const ExportPlan& plan,
                                    std::vector<std::string>& warnings);

}  // namespace hullinspect::io
