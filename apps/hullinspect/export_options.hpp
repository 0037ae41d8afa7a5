#pragma once
// Waypoint-export options shared by `export`, `run --export` and `plan --export` (docs/export.md),
// checked before any mission runs, and the writer that commits every UAV's file together.

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

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
};

/// Adds --format, --origin, --heading, --geo and the directory option `dir_option` ("--out" for
/// `export`, "--export" for run and plan).
void add_export_options(CLI::App& cmd, ExportArgs& args, const std::string& dir_option);

/// A checked export request.
struct ExportRequest {
  std::filesystem::path dir;
  io::ExportFormat format = kDefaultExportFormat;
  std::optional<io::GeoReference> geo;
};

/// Checks the options (format, geo-reference, the directory) before anything runs; nullopt when
/// no directory was given. Throws ParameterError / InputError with one line.
std::optional<ExportRequest> resolve_export(const ExportArgs& args, const std::string& dir_option);

/// Writes the export of `trace` into the request's directory: every file is written under a
/// temporary name first and renamed only when all were written; none may be a directory, a device
/// or one of `inputs`. Returns the file names written.
std::vector<std::string> write_export(const nlohmann::json& trace, const ExportRequest& request,
                                      const std::vector<std::filesystem::path>& inputs);

}  // namespace hullinspect::cli
