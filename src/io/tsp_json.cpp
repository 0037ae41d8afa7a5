#include "hullinspect/io/tsp_json.hpp"

#include <fmt/format.h>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/numbers.hpp"
#include "hullinspect/files/atomic_file.hpp"
#include "hullinspect/files/bounded_read.hpp"
#include "hullinspect/files/json_document.hpp"

namespace hullinspect::io {

namespace {

using nlohmann::json;

grid::Cell parse_cell(const json& value, const std::string& where, const std::string& source) {
  if (!value.is_array() || value.size() != 2 || !value[0].is_number_integer() ||
      !value[1].is_number_integer()) {
    throw InputError(source, 0, fmt::format("{}: expected [x, y] integers", where));
  }
  int xy[2] = {0, 0};
  for (std::size_t k = 0; k < 2; ++k) {
    const json& v = value[k];
    // Unsigned JSON integers may exceed the signed range: compare them as unsigned.
    const bool in_range =
        v.is_number_unsigned()
            ? v.get<std::uint64_t>() <= static_cast<std::uint64_t>(kTspCoordinateLimit)
            : v.get<std::int64_t>() >= -kTspCoordinateLimit &&
                  v.get<std::int64_t>() <= kTspCoordinateLimit;
    if (!in_range) {
      throw InputError(source, 0,
                       fmt::format("{}: coordinate {} is outside [{}, {}]", where, v.dump(),
                                   -kTspCoordinateLimit, kTspCoordinateLimit));
    }
    xy[k] = static_cast<int>(v.get<std::int64_t>());
  }
  return {xy[0], xy[1]};
}

}  // namespace

tsp::SegmentTsp parse_tsp_instance(std::string_view text, const std::string& source) {
  const json document = parse_json_document(text, source, "valid JSON");
  if (!document.is_object()) {
    throw InputError(source, 0, R"(expected a JSON object {"start": [x, y], "segments": [...]})");
  }
  for (const auto& [key, value] : document.items()) {
    if (key != "start" && key != "segments") {
      throw InputError(source, 0,
                       fmt::format(R"(unknown key "{}" (expected "start" and "segments"))",
                                   escape_for_message(key)));
    }
  }
  if (!document.contains("start")) throw InputError(source, 0, R"(missing "start": [x, y])");
  if (!document.contains("segments")) {
    throw InputError(source, 0, R"(missing "segments": [[[x1, y1], [x2, y2]], ...])");
  }
  tsp::SegmentTsp problem;
  problem.start = parse_cell(document["start"], "start", source);
  const json& segments = document["segments"];
  if (!segments.is_array()) {
    throw InputError(source, 0, "segments: expected an array of [[x1, y1], [x2, y2]]");
  }
  problem.segments.reserve(segments.size());
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const json& s = segments[i];
    const std::string where = fmt::format("segments[{}]", i);
    if (!s.is_array() || s.size() != 2) {
      throw InputError(source, 0, fmt::format("{}: expected [[x1, y1], [x2, y2]]", where));
    }
    problem.segments.push_back(
        {parse_cell(s[0], where + "[0]", source), parse_cell(s[1], where + "[1]", source)});
  }
  return problem;
}

// An instance file larger than this is refused before it is read whole.
constexpr std::size_t kMaxTspInstanceBytes = std::size_t{64} << 20;

tsp::SegmentTsp read_tsp_instance(const std::filesystem::path& path) {
  return parse_tsp_instance(read_file(path, kMaxTspInstanceBytes), path.string());
}

nlohmann::ordered_json tsp_instance_json(const tsp::SegmentTsp& problem) {
  nlohmann::ordered_json segments = nlohmann::ordered_json::array();
  for (const auto& s : problem.segments) {
    segments.push_back({{s.first.x, s.first.y}, {s.second.x, s.second.y}});
  }
  nlohmann::ordered_json out;
  out["start"] = {problem.start.x, problem.start.y};
  out["segments"] = std::move(segments);
  return out;
}

nlohmann::ordered_json tsp_solution_json(const tsp::TspSolution& solution) {
  nlohmann::ordered_json order = nlohmann::ordered_json::array();
  for (const auto& v : solution.order) {
    nlohmann::ordered_json visit;
    visit["segment"] = v.segment;
    visit["reversed"] = v.reversed;
    order.push_back(std::move(visit));
  }
  nlohmann::ordered_json out;
  out["length"] = solution.length;
  out["optimal"] = solution.optimal;
  out["lower_bound"] = solution.lower_bound;
  out["order"] = std::move(order);
  out["seconds"] = solution.seconds;
  return out;
}

}  // namespace hullinspect::io
