#include "export_options.hpp"

#include "number_options.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <set>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/numbers.hpp"
#include "hullinspect/files/bounded_read.hpp"

namespace hullinspect::cli {

namespace fs = std::filesystem;

void add_export_options(CLI::App& cmd, ExportArgs& a, const std::string& dir_option) {
  cmd.add_option(dir_option, a.dir,
                 "Write each UAV's waypoints into DIR (created if missing; see docs/export.md)")
      ->type_name("DIR");
  cmd.add_option("--format", a.format,
                 "Waypoint format: csv, qgc (QGroundControl .plan), wpl (QGC WPL 110), path "
                 "(nav_msgs/Path YAML)")
      ->capture_default_str();
  cmd.add_option(
         "--origin", a.origin,
         "Geo-reference: WGS-84 latitude, longitude (degrees) and ellipsoidal height (m) of "
         "the ship-frame origin")
      ->type_name("LAT,LON,ALT");
  cmd.add_option("--heading", a.heading,
                 "Geo-reference: ship heading, degrees clockwise from north")
      ->check(real_in(-360.0, 360.0))  // a custom type name hides it from require_exact_numbers()
      ->type_name("DEG");
  cmd.add_option("--geo", a.geo_file,
                 "Geo-reference from a YAML file: origin: [LAT, LON, ALT], heading: DEG")
      ->type_name("FILE");
  cmd.add_flag("--force", a.force,
               "Write into the directory even if it already holds files (files of the same names "
               "are replaced, others are left as they are)");
}

namespace {

// A geo-reference file is a few lines; anything larger is not one.
constexpr std::size_t kMaxGeoFileBytes = std::size_t{1} << 20;

// yaml-cpp keeps the first of two equal keys silently; a file that says `heading` twice is
// ambiguous, so it is refused.
void refuse_duplicate_keys(const YAML::Node& map, const std::string& path) {
  std::set<std::string> seen;
  for (const auto& entry : map) {
    const std::string key = entry.first.Scalar();
    if (!seen.insert(key).second) {
      throw InputError(path, entry.first.Mark().line + 1,
                       fmt::format("duplicate key '{}'", escape_for_message(key, 200)));
    }
  }
}

io::GeoReference geo_from_yaml(const std::string& path) {
  // Read like every input (bounded, regular files only, registered against the outputs).
  const std::string text = io::read_file(path, kMaxGeoFileBytes, "the geo-reference file");
  YAML::Node doc;
  try {
    doc = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw InputError(path, e.mark.line + 1, "not YAML: " + escape_for_message(e.msg, 200));
  }
  if (!doc.IsMap()) {
    throw InputError(path, 0, "expected a YAML mapping with origin: [LAT, LON, ALT] and heading");
  }
  refuse_duplicate_keys(doc, path);
  const auto origin = doc["origin"];
  if (!origin || !origin.IsSequence() || origin.size() != 3) {
    throw InputError(path, origin ? origin.Mark().line + 1 : 0, "origin: expected [LAT, LON, ALT]");
  }
  const auto heading = doc["heading"];
  if (!heading || !heading.IsScalar()) {
    throw InputError(path, 0, "heading: expected degrees clockwise from north");
  }
  try {
    return io::GeoReference(
        {origin[0].as<double>(), origin[1].as<double>(), origin[2].as<double>()},
        heading.as<double>());
  } catch (const YAML::Exception& e) {
    throw InputError(path, e.mark.line + 1, "origin and heading must be numbers");
  } catch (const ParameterError& e) {
    throw InputError(path, 0, e.name() + ": " + e.problem());
  }
}

}  // namespace

std::optional<ExportRequest> resolve_export(const ExportArgs& a, const std::string& dir_option) {
  const std::string name = dir_option.substr(2);
  if (a.dir.empty()) {
    for (const auto& [set, option] :
         {std::pair{!a.origin.empty(), "origin"}, std::pair{a.heading.has_value(), "heading"},
          std::pair{!a.geo_file.empty(), "geo"}, std::pair{a.force, "force"}}) {
      if (set)
        throw ParameterError(option, fmt::format("has no effect without {} DIR", dir_option));
    }
    return std::nullopt;
  }
  ExportRequest r;
  r.dir = a.dir;
  r.format = io::parse_export_format(a.format);
  if (!a.geo_file.empty()) {
    if (!a.origin.empty() || a.heading) {
      throw ParameterError("geo", "give either --geo FILE or --origin and --heading, not both");
    }
    r.geo = geo_from_yaml(a.geo_file);
  } else if (!a.origin.empty() || a.heading) {
    if (a.origin.empty())
      throw ParameterError("origin", "--heading needs --origin LAT,LON,ALT too");
    if (!a.heading) throw ParameterError("heading", "--origin needs --heading DEG too");
    r.geo = io::GeoReference(io::parse_geo_origin(a.origin), *a.heading);
  }
  if ((r.format == io::ExportFormat::kQgc || r.format == io::ExportFormat::kWpl) && !r.geo) {
    throw ParameterError("origin", fmt::format("the {} format needs a geo-reference: give --origin "
                                               "LAT,LON,ALT and --heading DEG (or --geo FILE)",
                                               a.format));
  }
  r.option = name;
  r.geo_file = a.geo_file;
  r.force = a.force;
  return r;
}

void declare_export_dir(io::OutputSet& outputs, const ExportRequest& request) {
  outputs.add_input(request.geo_file, "geo");
  // A new or empty directory, unless --force: files of an earlier export with more UAVs would
  // otherwise stay beside the new ones and read as part of it.
  outputs.add_output_dir(request.dir, request.option, !request.force);
}

void declare_export_files(io::OutputSet& outputs, const ExportRequest& request, int uavs) {
  for (const auto& name : io::export_file_names(request.format, uavs, request.geo.has_value())) {
    outputs.add_output(request.dir / name, request.option);
  }
}

std::vector<std::string> write_export(const nlohmann::json& trace, const ExportRequest& request,
                                      io::OutputSet& outputs) {
  std::vector<std::string> names;
  for (const auto& f : io::export_files(io::export_plan(trace), request.format, request.geo)) {
    outputs.write(request.dir / f.name, f.content);
    names.push_back(f.name);
  }
  return names;
}

}  // namespace hullinspect::cli
