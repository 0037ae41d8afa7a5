#include "export_options.hpp"

#include "number_options.hpp"

#include <fmt/format.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <cerrno>
#include <cstring>
#include <fstream>

#include "hullinspect/core/errors.hpp"

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
}

namespace {

io::GeoReference geo_from_yaml(const std::string& path) {
  YAML::Node doc;
  try {
    doc = YAML::LoadFile(path);
  } catch (const YAML::BadFile&) {
    throw InputError(path, 0, "cannot open the geo-reference file");
  } catch (const YAML::Exception& e) {
    throw InputError(path, e.mark.line + 1, "not YAML: " + e.msg);
  }
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
          std::pair{!a.geo_file.empty(), "geo"}}) {
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
  std::error_code ec;
  const auto status = fs::status(r.dir, ec);
  if (fs::exists(status) && !fs::is_directory(status)) {
    throw InputError(a.dir, 0, fmt::format("{} must be a directory", dir_option));
  }
  if (!fs::exists(status)) {
    const fs::path parent = r.dir.has_parent_path() ? r.dir.parent_path() : fs::path(".");
    if (!fs::is_directory(parent, ec) || ::access(parent.c_str(), W_OK) != 0) {
      throw InputError(a.dir, 0, fmt::format("cannot create the {} directory", name));
    }
  } else if (::access(r.dir.c_str(), W_OK) != 0) {
    throw InputError(a.dir, 0, "the directory is not writable");
  }
  return r;
}

std::vector<std::string> write_export(const nlohmann::json& trace, const ExportRequest& request,
                                      const std::vector<fs::path>& inputs) {
  const auto files = io::export_files(io::export_plan(trace), request.format, request.geo);
  // Refuse before writing anything: an output that is not a regular file, or one of the inputs.
  for (const auto& f : files) {
    const fs::path path = request.dir / f.name;
    std::error_code ec;
    const auto status = fs::status(path, ec);
    if (fs::exists(status) && !fs::is_regular_file(status)) {
      throw InputError(path.string(), 0, "exists and is not a regular file");
    }
    for (const auto& in : inputs) {
      if (fs::exists(status) && fs::equivalent(path, in, ec)) {
        throw InputError(path.string(), 0, "is an input of this command; choose another directory");
      }
    }
  }
  const bool created = !fs::exists(request.dir);
  if (created) {
    std::error_code ec;
    fs::create_directory(request.dir, ec);
    if (ec)
      throw InputError(request.dir.string(), 0, "cannot create the directory: " + ec.message());
  }
  std::vector<fs::path> temporaries;
  auto abandon = [&] {
    std::error_code ignored;
    for (const auto& t : temporaries) fs::remove(t, ignored);
    if (created) fs::remove(request.dir, ignored);
  };
  const std::string suffix = fmt::format(".tmp-{}", static_cast<long>(::getpid()));
  for (const auto& f : files) {
    const fs::path tmp = request.dir / (f.name + suffix);
    temporaries.push_back(tmp);
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out.write(f.content.data(), static_cast<std::streamsize>(f.content.size()));
    out.flush();
    if (!out) {
      const std::string why = std::strerror(errno);
      abandon();
      throw InputError((request.dir / f.name).string(), 0, "cannot write: " + why);
    }
  }
  std::vector<std::string> names;
  for (std::size_t i = 0; i < files.size(); ++i) {
    std::error_code ec;
    fs::rename(temporaries[i], request.dir / files[i].name, ec);
    if (ec) {
      abandon();
      throw InputError((request.dir / files[i].name).string(), 0,
                       "cannot rename into place: " + ec.message());
    }
    names.push_back(files[i].name);
  }
  return names;
}

}  // namespace hullinspect::cli
