#include "hullinspect/experiment/manifest.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <ctime>
#include <thread>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/experiment/build_data.hpp"
#include "hullinspect/files/atomic_file.hpp"
#include "hullinspect/files/bounded_read.hpp"
#include "hullinspect/files/json_document.hpp"
#include "hullinspect/version.hpp"

namespace hullinspect::experiment {

std::string utc_now() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&now, &tm);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return text;
}

int host_cores() {
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

std::string host_name() {
  char name[256] = {};
  if (::gethostname(name, sizeof name - 1) != 0) return "unknown";
  return name;
}

nlohmann::json base_manifest(const ExperimentPlan& plan) {
  nlohmann::json m;
  m["tool"] = "hullinspect";
  m["version"] = kVersion;
  m["git_revision"] = std::string(git_revision());
  m["config_source"] = plan.config().source;
  m["fingerprint"] = config_fingerprint(plan.config());
  m["runs_total"] = plan.runs().size();
  m["cells"] = plan.cells().size();
  m["host"] = {{"name", host_name()}, {"cores", host_cores()}};
  m["config"] = config_json(plan.config());
  return m;
}

nlohmann::json read_manifest(const std::filesystem::path& dir) {
  const auto path = dir / "manifest.json";
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    throw InputError(path.string(), 0, "not found (is this a hullinspect experiment directory?)");
  }
  return io::parse_json_document(io::read_file(path, std::size_t{64} << 20), path.string(),
                                 "a JSON manifest");
}

void write_manifest(const std::filesystem::path& dir, const nlohmann::json& manifest) {
  io::write_file_atomic(dir / "manifest.json", manifest.dump(2) + "\n");
}

}  // namespace hullinspect::experiment
