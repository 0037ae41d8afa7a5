#include "mission_args.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "../apps/hullinspect/number_options.hpp"
#include "hullinspect/core/errors.hpp"
#include "hullinspect/experiment/runner.hpp"

namespace hullinspect::python {

namespace py = pybind11;

namespace {

/// A Python value as the CLI would read it: True/False as true/false, numbers as Python prints
/// them (repr of a float round-trips), anything else as str().
std::string text(const py::handle& value) {
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "true" : "false";
  return py::str(value).cast<std::string>();
}

/// A tuple as one option value: (x, y) → "x,y" for --start, (uav, t) → "uav@t" for --fail.
std::string item_text(const std::string& flag, const py::handle& item) {
  if (!py::isinstance<py::tuple>(item)) return text(item);
  std::string out;
  for (const auto& part : item.cast<py::tuple>()) {
    if (!out.empty()) out += flag == "--fail" ? "@" : ",";
    out += text(part);
  }
  return out;
}

/// The parser `hullinspect run` uses for its mission options.
struct MissionParser {
  cli::MissionArgs args;
  CLI::App app{"hullinspect run"};
  MissionParser() {
    cli::add_mission_options(app, args);
    cli::require_exact_numbers(app);
  }
};

}  // namespace

std::vector<std::string> mission_words(const std::string& algorithm, const py::handle& uavs,
                                       const py::handle& s2, const py::handle& seed,
                                       const std::string& scenario, const std::string& hull_path,
                                       const py::dict& options, const py::dict& params) {
  std::vector<std::string> words = {"--algorithm", algorithm, "--uavs",   text(uavs),   "--s2",
                                    text(s2),      "--seed",  text(seed), "--scenario", scenario};
  if (!hull_path.empty()) words.insert(words.end(), {"--hull", hull_path});
  const MissionParser known;
  for (const auto& [key, value] : params) {
    std::string name = key.cast<std::string>();
    std::replace(name.begin(), name.end(), '_', '-');
    if (name == "starts") name = "start";
    const std::string flag = "--" + name;
    const CLI::Option* option = known.app.get_option_no_throw(flag);
    if (option == nullptr || name == "option" || name == "hull") {
      words.insert(words.end(), {"-O", name + "=" + text(value)});
    } else if (option->get_type_size() == 0) {  // a flag such as --keep-largest
      if (value.cast<bool>()) words.push_back(flag);
    } else if (py::isinstance<py::list>(value)) {
      for (const auto& item : value.cast<py::list>()) {
        words.insert(words.end(), {flag, item_text(flag, item)});
      }
    } else {
      words.insert(words.end(), {flag, item_text(flag, value)});
    }
  }
  for (const auto& [key, value] : options) {
    words.insert(words.end(), {"-O", key.cast<std::string>() + "=" + text(value)});
  }
  return words;
}

cli::MissionArgs parse_mission_words(const std::vector<std::string>& words) {
  MissionParser parser;
  std::vector<std::string> reversed(words.rbegin(), words.rend());  // CLI11 takes them reversed
  try {
    parser.app.parse(reversed);
  } catch (const CLI::ParseError& e) {
    // "--uavs: 'x' is not a valid value (see --help)": name the keyword, not the option.
    std::string message = cli::parse_error_message(e);
    const std::string help = " (see --help)";
    if (message.ends_with(help)) message.resize(message.size() - help.size());
    const auto colon = message.find(": ");
    if (message.rfind("--", 0) == 0 && colon != std::string::npos) {
      throw ParameterError(message.substr(2, colon - 2), message.substr(colon + 2));
    }
    throw Error(message);
  }
  return parser.args;
}

std::string python_keyword(const std::string& name) {
  std::string out = name;
  if (const auto dot = out.rfind('.'); dot != std::string::npos) out = out.substr(dot + 1);
  if (out.rfind("--", 0) == 0) out = out.substr(2);
  std::replace(out.begin(), out.end(), '-', '_');
  if (out == "start") return "starts";
  return out;
}

std::string keyword_message(const ParameterError& error) {
  return python_keyword(error.name()) + ": " + error.problem();
}

py::int_ integer_in(const py::handle& value, const std::string& keyword, const py::int_& min,
                    const py::int_& max) {
  if (py::isinstance<py::int_>(value) && !py::isinstance<py::bool_>(value)) {
    const auto number = py::reinterpret_borrow<py::int_>(value);
    if (number >= min && number <= max) return number;
  }
  throw ParameterError(
      keyword,
      fmt::format("must be an integer in [{}, {}] (got {})", py::repr(min).cast<std::string>(),
                  py::repr(max).cast<std::string>(), py::repr(value).cast<std::string>()));
}

std::uint64_t seed_value(const py::handle& seed) {
  return integer_in(seed, "seed", py::int_(0), py::int_(std::numeric_limits<std::uint64_t>::max()))
      .cast<std::uint64_t>();
}

py::dict mission_defaults() {
  const cli::MissionArgs args;
  py::dict out;
  out["algorithm"] = args.algorithm;
  out["uavs"] = args.uavs;
  out["s2"] = args.s2;
  out["seed"] = args.seed;
  out["scenario"] = args.scenario;
  out["jobs"] = experiment::RunnerOptions{}.jobs;
  return out;
}

}  // namespace hullinspect::python
