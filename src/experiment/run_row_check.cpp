#include "hullinspect/experiment/run_row_check.hpp"

#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <unordered_map>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/numbers.hpp"
#include "hullinspect/experiment/csv.hpp"
#include "hullinspect/experiment/run_record.hpp"
#include "hullinspect/world/battery.hpp"
#include "hullinspect/world/hull.hpp"

namespace hullinspect::experiment {

namespace {

/// The position of each runs.csv column (built once: every stored row is looked up through it).
const std::unordered_map<std::string, std::size_t>& runs_columns() {
  static const auto columns = [] {
    std::unordered_map<std::string, std::size_t> out;
    const auto header = runs_header();
    for (std::size_t k = 0; k < header.size(); ++k) out.emplace(header[k], k);
    return out;
  }();
  return columns;
}

/// A runs.csv row's outcome fields by column name, once each is known to be an integer in range.
class Outcome {
 public:
  explicit Outcome(const std::vector<std::string>& fields) : fields_(fields) {}
  const std::string& text(const std::string& name) const {
    return fields_[runs_columns().at(name)];
  }
  /// The field parsed in [0, max]; an empty optional field (T_c, T_m, min_separation) gives
  /// nothing.
  std::optional<long long> parse(const std::string& name, long long max) const {
    const std::string& v = text(name);
    if (v.empty() && (name == "T_c" || name == "T_m" || name == "min_separation")) {
      return std::nullopt;
    }
    try {
      return parse_integer<long long>(v, 0, max);
    } catch (const NumberError& e) {
      throw Error(fmt::format("{} {}", name, e.what()));
    }
  }
  long long get(const std::string& name, long long max = kMaxStoredCount) const {
    return *parse(name, max);
  }
  /// A field of seconds in [0, max]; an empty min_battery_s gives nothing.
  std::optional<double> seconds(const std::string& name, double max) const {
    const std::string& v = text(name);
    if (v.empty() && name == "min_battery_s") return std::nullopt;
    try {
      return parse_real(v, 0, max);
    } catch (const NumberError& e) {
      throw Error(fmt::format("{} {}", name, e.what()));
    }
  }
  /// A time column (seconds: steps × the step of `timing`) as its steps, at most `max`; without a
  /// speed the seconds are the steps and parse() reads them.
  std::optional<long long> steps(const std::string& name, long long max,
                                 const world::MissionParams& timing) const {
    if (!timing.speed_m_s) return parse(name, max);
    const std::string& v = text(name);
    if (v.empty() && (name == "T_c" || name == "T_m")) return std::nullopt;
    double seconds = 0;
    try {
      seconds = parse_real(v, 0, static_cast<double>(max) * timing.step_seconds() + 1);
    } catch (const NumberError& e) {
      throw Error(fmt::format("{} {}", name, e.what()));
    }
    const auto n = std::llround(seconds / timing.step_seconds());
    if (n > max || fmt::format("{}", timing.seconds(n)) != v) {
      throw Error(fmt::format("{} is '{}', not a whole number of {}-second steps up to {}", name,
                              escape_for_message(v), timing.step_seconds(), max));
    }
    return n;
  }

 private:
  const std::vector<std::string>& fields_;
};

/// The outcome checks: ranges first, then the relations the simulator guarantees (SPEC §4: the
/// mission stops at T_m, T_c and T_m are first times, every UAV spends each step on one action).
std::string outcome_problem(const ExperimentPlan& plan, const RunKey& run, const Outcome& o) {
  const auto& c = plan.config();
  const Cell& cell = plan.cells()[static_cast<std::size_t>(run.cell)];
  const long long uavs = c.uavs[static_cast<std::size_t>(cell.uavs)];
  const long long limit = c.mission.time_limit;
  const long long hull = c.hull_cells;

  const auto timing = c.timing();
  const bool complete = o.get("complete", 1) == 1;
  const auto t_c = o.steps("T_c", limit, timing);
  const auto t_m = o.steps("T_m", limit, timing);
  const auto bound_t_c = *o.steps("bound_T_c", kMaxStoredCount, timing);
  const auto bound_t_m = *o.steps("bound_T_m", kMaxStoredCount, timing);
  const long long steps = o.get("steps", limit);
  const long long hull_cells = o.get("hull_cells", hull);
  const long long corroded = o.get("corroded_cells", hull);
  (void)o.get("unreachable_cells", hull);
  (void)o.get("failed_uavs", uavs);
  for (const char* counter :
       {"detections", "observations", "redundant_observations", "moves", "hovers", "plane_changes",
        "steps_z1", "steps_z2", "steps_transit", "tsp_solves", "tsp_unproven", "tsp_fallbacks",
        "replans", "assignments", "partition_fallbacks", "separation_conflicts"}) {
    (void)o.get(counter);
  }
  if (o.text("separation") != std::to_string(c.mission.separation)) {
    return fmt::format("separation is '{}' but this experiment's is {}",
                       escape_for_message(o.text("separation")), c.mission.separation);
  }
  // The smallest max(|dx|, |dy|) between two airborne UAVs: a distance on the grid.
  const auto least_separation = o.parse("min_separation", world::kMaxGridSide - 1);
  const long long conflicts = o.get("separation_conflicts");
  // Batteries (docs/model.md, "Batteries and sorties"), parsed here, related at the end.
  const long long sorties = o.get("sorties");
  const auto flight = o.seconds("flight_s", 1e18);
  const long long crashes = o.get("battery_crashes", uavs);
  const auto least_battery = o.seconds("min_battery_s", c.mission.endurance.value_or(1e18));

  if (complete != t_m.has_value()) {
    return complete ? "complete is 1 but T_m is empty (a complete mission has a T_m)"
                    : fmt::format("complete is 0 but T_m is {} (a mission with a T_m is complete)",
                                  o.text("T_m"));
  }
  if (t_m && steps != *t_m) {
    return fmt::format("steps is {} but a complete mission stops at T_m = {}", steps,
                       o.text("T_m"));
  }
  if (t_c && t_m && *t_c > *t_m) {
    return fmt::format(
        "T_c is {} but T_m is {} (every corroded cell is inspected once the hull is "
        "known)",
        o.text("T_c"), o.text("T_m"));
  }
  if (complete && !t_c) return "complete is 1 but T_c is empty (a complete mission has a T_c)";
  if (t_c && *t_c > steps) {
    return fmt::format("T_c is {} but the mission ended at steps = {}", o.text("T_c"), steps);
  }
  if (corroded > hull_cells) {
    return fmt::format("corroded_cells is {} but hull_cells is only {}", corroded, hull_cells);
  }
  if (o.get("redundant_observations") > o.get("observations")) {
    return fmt::format("redundant_observations is {} but observations is {}",
                       o.get("redundant_observations"), o.get("observations"));
  }
  if (o.get("tsp_unproven") > o.get("tsp_solves") || o.get("tsp_fallbacks") > o.get("tsp_solves")) {
    return fmt::format("tsp_unproven ({}) and tsp_fallbacks ({}) cannot exceed tsp_solves ({})",
                       o.get("tsp_unproven"), o.get("tsp_fallbacks"), o.get("tsp_solves"));
  }
  // Each step of each working UAV is one of: a move, a hover, or a step in transit (the first
  // of which is the plane change); a step that does not end in transit ends on plane 1 or 2.
  const long long uav_steps = uavs * steps;
  const long long actions = o.get("moves") + o.get("hovers") + o.get("steps_transit");
  if (actions > uav_steps) {
    return fmt::format("moves + hovers + steps_transit is {} but {} UAVs × {} steps is only {}",
                       actions, uavs, steps, uav_steps);
  }
  const long long planes = o.get("steps_z1") + o.get("steps_z2");
  if (planes > uav_steps) {
    return fmt::format("steps_z1 + steps_z2 is {} but {} UAVs × {} steps is only {}", planes, uavs,
                       steps, uav_steps);
  }
  if (o.get("plane_changes") > o.get("steps_transit")) {
    return fmt::format("plane_changes is {} but steps_transit is only {}", o.get("plane_changes"),
                       o.get("steps_transit"));
  }
  if (bound_t_c > bound_t_m) {
    return fmt::format("bound_T_c is {} but bound_T_m is only {}", o.text("bound_T_c"),
                       o.text("bound_T_m"));
  }
  // Without separation (D = 0) the simulator measures nothing (docs/model.md §13).
  if (c.mission.separation == 0 && (least_separation || conflicts != 0)) {
    return fmt::format(
        "min_separation is '{}' and separation_conflicts {} but this experiment has no "
        "separation (D = 0: the first is empty, the second 0)",
        escape_for_message(o.text("min_separation")), conflicts);
  }
  if (least_separation && uavs < 2) {
    return fmt::format("min_separation is {} but a single UAV has no other to be apart from",
                       *least_separation);
  }
  if (least_battery.has_value() != c.mission.endurance.has_value()) {
    return c.mission.endurance
               ? "min_battery_s is empty but this experiment's UAVs have batteries"
               : fmt::format("min_battery_s is {} but this experiment's flight is unlimited",
                             *least_battery);
  }
  if (crashes > o.get("failed_uavs", uavs)) {
    return fmt::format("battery_crashes is {} but failed_uavs is only {} (a crash fails the UAV)",
                       crashes, o.get("failed_uavs", uavs));
  }
  if (c.launch_sites.empty() && sorties != 0) {
    return fmt::format("sorties is {} but this experiment's UAVs start in the air (no launch site)",
                       sorties);
  }
  const double flight_limit =
      static_cast<double>(uavs) * c.timing().step_seconds() * static_cast<double>(steps);
  if (*flight > flight_limit) {
    return fmt::format("flight_s is {} but {} UAVs × {} steps fly at most {} s", *flight, uavs,
                       steps, flight_limit);
  }
  return {};
}

}  // namespace

std::string run_row_problem(const ExperimentPlan& plan, const RunKey& run, std::string_view line) {
  const auto fields = split_csv_line(line);
  static const auto header = runs_header();
  if (!fields || fields->size() != header.size()) return "malformed row";
  const auto expected = run_parameter_fields(plan, run);
  for (std::size_t k = 0; k < expected.size(); ++k) {
    if ((*fields)[k] != expected[k]) {
      return fmt::format("{} is '{}' but run {} of this experiment has '{}'", header[k],
                         escape_for_message((*fields)[k]), run.id, escape_for_message(expected[k]));
    }
  }
  const Outcome outcome(*fields);
  const auto expected_failures = run_failures_field(plan, run);
  if (outcome.text("failures") != expected_failures) {
    return fmt::format("failures is '{}' but run {} of this experiment has '{}'",
                       escape_for_message(outcome.text("failures")), run.id,
                       escape_for_message(expected_failures));
  }
  try {
    return outcome_problem(plan, run, outcome);
  } catch (const Error& e) {
    return e.what();
  }
}

std::string samples_row_problem(const ExperimentPlan& plan, const RunKey& run,
                                std::string_view runs_line, std::string_view samples_line) {
  const auto fields = split_csv_line(samples_line);
  const auto times = plan.config().curve.times();
  if (!fields || fields->size() != 1 + 2 * times.size()) return "malformed row";
  if ((*fields)[0] != run.id) {
    return fmt::format("run_id is '{}', expected '{}'", (*fields)[0], run.id);
  }
  const auto run_fields = *split_csv_line(runs_line);
  const Outcome o(run_fields);
  const auto timing = plan.config().timing();
  const auto t_c = o.steps("T_c", kMaxStoredCount, timing);
  const auto t_m = o.steps("T_m", kMaxStoredCount, timing);
  const long long hull_cells = o.get("hull_cells");
  const long long corroded = o.get("corroded_cells");
  // One series per half of the row: inspected corroded cells, then known hull cells. Each only
  // grows, stays below its total before its first time (T_c, T_m) and equals it from then on.
  struct Series {
    std::size_t first;
    long long total;
    std::optional<long long> reached;
    const char* first_time;
    const char* column;
  };
  for (const Series s : {Series{1, corroded, t_c, "T_c", "inspected"},
                         Series{1 + times.size(), hull_cells, t_m, "T_m", "known"}}) {
    long long previous = 0;
    for (std::size_t i = 0; i < times.size(); ++i) {
      // The column's name (samples_header's), made only for a message.
      const auto name = [&] { return fmt::format("{}_{}", s.column, times[i]); };
      long long v = 0;
      try {
        v = parse_integer<long long>((*fields)[s.first + i], 0, s.total);
      } catch (const NumberError& e) {
        return fmt::format("{} {}", name(), e.what());
      }
      if (v < previous) {
        return fmt::format("{} is {} but the count was already {} (it never decreases)", name(), v,
                           previous);
      }
      previous = v;
      const bool after = s.reached && times[i] >= *s.reached;
      // With launch sites T_m is the last landing, after the hull is known (docs/model.md).
      const bool known_before_landing =
          s.column == std::string_view("known") && !after && !plan.config().launch_sites.empty();
      if (after != (v == s.total) && !known_before_landing) {
        return after ? fmt::format("{} is {} but from {} = {} on it is {}", name(), v, s.first_time,
                                   *s.reached, s.total)
                     : fmt::format("{} is {}, the total, but {} is {}", name(), v, s.first_time,
                                   s.reached ? std::to_string(*s.reached) : "empty");
      }
    }
  }
  return {};
}

}  // namespace hullinspect::experiment
