#pragma once
// Waypoint-export options shared by `export`, `run --export` and `plan --export` (docs/export.md),
// checked before any mission runs, and the writer of every UAV's file through the command's
// io::OutputSet.

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "hullinspect/files/output_set.hpp"
#include "hullinspect/io/export.hpp"

namespace hullinspect::cli {

/// The waypoint format when --format is not given (the option, its help and ExportRequest use it).
inline constexpr io::ExportFormat kDefaultExportFormat = io::ExportFormat::kCsv;

struct ExportArgs {
  std::string dir;
  std::string format{io::to_string(kDefaultExportFormat)};
  std::string origin;
  std::optional<double> heading;
  std::string geo_file;
  bool force = false;
};

/// Adds --format, --origin, --heading, --geo, --force and the directory option `dir_option`
/// ("--out" for `export`, "--export" for run and plan).
void add_export_options(CLI::App& cmd, ExportArgs& args, const std::string& dir_option);

/// A checked export request.
struct ExportRequest {
  std::filesystem::path dir;
  io::ExportFormat format = kDefaultExportFormat;
  std::optional<io::GeoReference> geo;
  std::string option;    ///< the directory option without dashes ("out", "export"), for messages
  std::string geo_file;  ///< --geo FILE, an input of the command; empty without one
  bool force = false;    ///< write into a directory that already holds files
};

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

/// Writes the export of `trace` into the declared outputs (committed by the command). Returns the
/// file names.
std::vector<std::string> write_export(const nlohmann::json& trace, const ExportRequest& request,
                                      io::OutputSet& outputs);

}  // namespace hullinspect::cli
