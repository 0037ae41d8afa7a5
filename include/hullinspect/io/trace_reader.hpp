#pragma once
// Reads a mission trace written by TraceRecorder (format "hullinspect-trace", version 2,
// docs/trace-format.md) and checks its structure, so the viewer and scripts can trust it.

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace hullinspect::io {

/// The trace format this build writes and reads.
inline constexpr const char* kTraceFormat = "hullinspect-trace";
/// Version 2 writes planner layers as changes with periodic whole sets; version 1 (whole sets
/// only) is still read.
inline constexpr int kTraceVersion = 2;

/// Parses and validates a trace file. Throws InputError naming the file (and the JSON line, or the
/// offending field such as "frames[12].u") when it cannot be read, is not JSON or breaks the
/// format.
nlohmann::json read_trace(const std::filesystem::path& path);

/// Checks that `trace` follows the format: every required field present with the right type, rows
/// of the grid's size, cell indices and UAV positions inside the grid, one frame per time step.
/// Throws InputError(source, 0, "<field>: <problem>").
void validate_trace(const nlohmann::json& trace, const std::string& source);

}  // namespace hullinspect::io
