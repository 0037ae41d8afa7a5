#pragma once
// Reads a mission trace written by TraceRecorder (format "hullinspect-trace", version 3,
// docs/trace-format.md) and checks its structure, so the viewer and scripts can trust it.

#include <nlohmann/json.hpp>

#include <array>
#include <filesystem>
#include <string>

namespace hullinspect::io {

/// The trace format this build writes and reads.
inline constexpr const char* kTraceFormat = "hullinspect-trace";
/// Version 3 records a mission with launch sites whole (each UAV airborne or not, its battery and
/// its steps away; the sites, battery and separation), so every rule of the physical mission is
/// checked from the trace. Version 2 (no such fields) and 1 (version 2 without layer changes) are
/// still read.
inline constexpr int kTraceVersion = 4;

/// `uav_fields` of the paper's model (no launch site): the values of one UAV in a frame's `u`.
inline constexpr std::array<const char*, 5> kPaperUavFields = {"x", "y", "z", "transit_left",
                                                               "active"};
/// `uav_fields` of a mission with launch sites: the paper's fields, then whether the UAV is
/// airborne (0 on the ground at its site), its battery's steps left (−1 unlimited) and its steps
/// left away from the hull (on the ground, flying out or home).
inline constexpr std::array<const char*, 8> kPhysicalUavFields = {
    "x", "y", "z", "transit_left", "active", "airborne", "battery_left", "away_left"};

/// Parses and validates a trace file. Throws InputError naming the file (and the JSON line, or the
/// offending field such as "frames[12].u") when it cannot be read, is not JSON or breaks the
/// format.
nlohmann::json read_trace(const std::filesystem::path& path);

/// Checks that `trace` follows the format: every required field present with the right type, rows
/// of the grid's size, cell indices and UAV positions inside the grid, one frame per time step.
/// Throws InputError(source, 0, "<field>: <problem>").
void validate_trace(const nlohmann::json& trace, const std::string& source);

}  // namespace hullinspect::io
