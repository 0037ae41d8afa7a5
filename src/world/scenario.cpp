#include "hullinspect/world/scenario.hpp"

namespace hullinspect::world {

namespace {

OptionMap with_halves(std::string_view name, OptionMap options);

constexpr int kMaxLc = 999;

Params<CorrosionScenario> scenario_params(const std::string& name, CorrosionScenario defaults) {
  Params<CorrosionScenario> p(name, defaults);
  p.number("p-c", &CorrosionScenario::p_c, 0.0, 1.0,
           "probability that a hull cell is a corrosion centre (back half when front-p-c differs)")
      .integer("l-c", &CorrosionScenario::l_c, 1, kMaxLc,
               "largest corrosion rectangle side, odd (back half when front-l-c differs)")
      .number("front-p-c", &CorrosionScenario::front_p_c, 0.0, 1.0,
              "p-c of the front half (x >= a/2); follows p-c when only p-c is given")
      .integer("front-l-c", &CorrosionScenario::front_l_c, 1, kMaxLc,
               "l-c of the front half (x >= a/2); follows l-c when only l-c is given")
      .number("p-tp", &CorrosionScenario::p_tp, 0.0, 1.0,
              "probability that a true centre is also a prior centre")
      .number("p-fp", &CorrosionScenario::p_fp, 0.0, 1.0,
              "probability that another hull cell is a false prior centre");
  return p;
}

void add(ScenarioRegistry& r, const std::string& name, const std::string& description,
         CorrosionScenario defaults) {
  r.add_builtin(make_entry<CorrosionScenario, CorrosionScenario>(
      name, description, scenario_params(name, defaults),
      [](const CorrosionScenario& s) { return std::make_unique<CorrosionScenario>(s); }));
}

void add_builtins(ScenarioRegistry& r) {
  add(r, "perfect", "homogeneous corrosion, perfect prior (C' = C)",
      {0.005, 5, 0.005, 5, 1.0, 0.0});
  add(r, "imperfect", "homogeneous corrosion, prior with false negatives and positives",
      {0.005, 5, 0.005, 5, 0.6, 0.003});
  add(r, "inhomogeneous", "more and larger clusters in the front half, perfect prior",
      {0.0025, 3, 0.01, 7, 1.0, 0.0});
  add(r, "combined", "inhomogeneous corrosion and a poor prior (Fig. 8 c2)",
      {0.0025, 3, 0.01, 7, 0.4, 0.005});
}

/// "p-c" alone sets both halves (as --p-c always did). The options are checked as given first, so
/// an error names the option the user wrote.
OptionMap with_halves(std::string_view name, OptionMap options) {
  scenarios().get(name).resolve(options);
  for (const char* key : {"p-c", "l-c"}) {
    const std::string front = std::string("front-") + key;
    if (auto it = options.find(key); it != options.end() && !options.contains(front)) {
      options[front] = it->second;
    }
  }
  return options;
}

}  // namespace

CorrosionParams CorrosionScenario::corrosion(int grid_width) const {
  if (p_c == front_p_c && l_c == front_l_c) {
    return CorrosionParams::homogeneous(grid_width, p_c, l_c, p_tp, p_fp);
  }
  return CorrosionParams::front_back(grid_width, p_c, l_c, front_p_c, front_l_c, p_tp, p_fp);
}

ScenarioRegistry& scenarios() {
  static ScenarioRegistry registry("scenario", "scenario", &add_builtins);
  return registry;
}

CorrosionScenario scenario(std::string_view name, const OptionMap& options) {
  return *scenarios().make(name, with_halves(name, options));
}

OptionMap resolve_scenario_options(std::string_view name, const OptionMap& options) {
  return scenarios().resolve(name, with_halves(name, options));
}

}  // namespace hullinspect::world
