#pragma once
// Waypoint-export options shared by `export`, `run --export` and `plan --export` (docs/export.md),
// checked before any mission runs, and the writer of every UAV's file through the command's
// io::OutputSet.

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "hullinspect/files/output_set.hpp"
#include "hullinspect/io/export.hpp"
#include "hullinspect/io/geo_survey.hpp"
#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/sim/mission_result.hpp"

namespace hullinspect::cli {

/// The waypoint format when --format is not given (the option, its help and ExportRequest use it).
inline constexpr io::ExportFormat kDefaultExportFormat = io::ExportFormat::kCsv;

struct ExportArgs {
  std::string dir;
  std::vector<std::string> formats;  ///< empty: kDefaultExportFormat
  std::string origin;
  std::optional<double> heading;
  std::string geo_file;
  std::vector<std::string> launch;  ///< X,Y grid positions
  std::optional<int> max_waypoints;
  std::optional<double> simplify;       ///< metres
  std::optional<double> launch_height;  ///< metres, ship frame Z
  std::optional<double> geoid_height;   ///< metres above the WGS-84 ellipsoid
  std::vector<std::string> firmwares;   ///< empty: px4
  std::string finish = "land";
  std::string drone = "m350";
  bool force = false;
};

/// Adds --format (repeatable, or all), --origin, --heading, --geo, --launch, --max-waypoints,
/// --firmware, --finish, --drone, --force and the directory option `dir_option` ("--out" for
/// `export`,
/// "--export" for run and plan).
/// `launch_option`: declare --launch here (the export of a trace); run and plan take the mission's
/// own --launch sites instead (copy them with take_mission_launch).
void add_export_options(CLI::App& cmd, ExportArgs& args, const std::string& dir_option,
                        bool launch_option);
/// The mission's launch sites fly the exported sorties too (only when exporting).
inline void take_mission_launch(ExportArgs& args, const std::vector<std::string>& sites) {
  if (!args.dir.empty()) args.launch = sites;
}

/// A --geo survey with a point given as a grid cell (docs/export.md, "Two surveyed points"): the
/// cell's ship-frame point is the hull's surface at its centre, known only with the mission's
/// frame, so the geo-reference is computed when the export is written.
struct CellSurvey {
  std::array<io::SurveyedPoint, 2> points;         ///< x, y, z filled for `ship:` points only
  std::array<std::optional<grid::Cell>, 2> cells;  ///< (col, row) of `cell:` points
  std::array<int, 2> lines{};                      ///< each point's line in the file
  double tolerance_m = io::kDefaultSurveyToleranceM;
  std::string path;  ///< the --geo file
  int line = 0;      ///< the survey's line
};

/// A checked export request.
struct ExportRequest {
  std::filesystem::path dir;
  std::vector<io::ExportFormat> formats{kDefaultExportFormat};
  io::ExportSettings settings;
  std::optional<io::GeoReference> geo;
  std::optional<CellSurvey> cell_survey;  ///< replaces `geo` until the mission's frame is known
  std::string option;    ///< the directory option without dashes ("out", "export"), for messages
  std::string geo_file;  ///< --geo FILE, an input of the command; empty without one
  bool force = false;    ///< write into a directory that already holds files
};

/// A battery-limited mission lands and takes off again: its export is cut into one sortie per
/// take-off (io::ExportSettings::flown_sorties, from the result's sim::SortieRecord), each with its
/// own files. With unlimited flight nothing changes: one sortie per UAV.
void take_mission_sorties(ExportRequest& request, const planners::MissionSpec& spec,
                          const sim::MissionResult& result);

/// Checks the options (format, geo-reference) before anything runs; nullopt when no directory
/// was given. Throws ParameterError / InputError with one line.
std::optional<ExportRequest> resolve_export(const ExportArgs& args, const std::string& dir_option);

/// Declares the export in the command's OutputSet before anything runs: the directory (created if
/// missing) and the --geo file as an input (declare_export_dir), then, once the fleet size is
/// known, the file of each of `uavs` UAVs (declare_export_files, io::export_file_names). The set's
/// check() then refuses a directory that is a file, an output that is a device, FIFO or directory,
/// or one that is the same file as an input; its commit() puts every file in place with the
/// command's other outputs, and a failure before that leaves nothing behind.
void declare_export_dir(io::OutputSet& outputs, const ExportRequest& request);
void declare_export_files(io::OutputSet& outputs, const ExportRequest& request, int uavs);

/// What write_export wrote: the file names, and what a format could not carry (one sentence
/// each, for the command to print).
struct ExportWritten {
  std::vector<std::string> names;
  std::vector<std::string> notes;
  std::optional<io::GeoReference> geo;  ///< the geo-reference the files were written with
};

/// Writes the export of `trace` into the declared outputs (committed by the command); a sortie
/// split into parts declares its part files here.
/// `source` names the file the trace's geometry came from (the trace, or the mission's hull).
ExportWritten write_export(const nlohmann::json& trace, const std::string& source,
                           const ExportRequest& request, io::OutputSet& outputs);

/// "csv", "qgc and wpl": the formats of a request, for the commands' summary lines.
std::string format_list(const ExportRequest& request);

}  // namespace hullinspect::cli
