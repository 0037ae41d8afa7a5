// hullinspect partition: divide a hull among n UAVs and report the regions (and write them).

#include <fmt/format.h>

#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string_view>

#include "commands.hpp"
#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/plural.hpp"
#include "hullinspect/files/output_set.hpp"
#include "hullinspect/grid/distance.hpp"
#include "hullinspect/partition/fallback.hpp"
#include "hullinspect/partition/flight_split.hpp"
#include "hullinspect/partition/partitioner.hpp"
#include "hullinspect/world/mission_params.hpp"
#include "hullinspect/world/no_fly.hpp"
#include "hullinspect/world/standoff_surface.hpp"
#include "mission_options.hpp"
#include "number_options.hpp"

namespace hullinspect::cli {

namespace {

// One symbol per UAV in the --out mask; '.' marks non-hull cells.
constexpr std::string_view kRegionSymbols =
    "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz";

struct PartitionArgs {
  // The mission options this command shares (--uavs, --hull, --start, --s1, --s2, the mesh and
  // no-fly options), read through their declarations.
  MissionArgs declared;
  std::uint64_t seed = 0;
  std::string partitioner{partition::kDefaultPartitioner};
  std::vector<std::string> options;  // key=value
  bool json = false;
  bool no_fallback = false;  // the partitioner's own result, without the missions' fallback
  std::string out_path;
};

// Explicit starts that snap onto one hull cell: name the cells as the user gave them.
void reject_shared_starts(const std::vector<grid::Cell>& given,
                          const std::vector<grid::Cell>& snapped) {
  for (std::size_t k = 0; k < given.size(); ++k) {
    for (std::size_t other = 0; other < k; ++other) {
      if (snapped[k] != snapped[other]) continue;
      throw ParameterError(
          "start", fmt::format("UAVs {} and {} both start on cell ({}, {}) (given ({}, {}) and "
                               "({}, {}); cells off the hull snap to the nearest hull cell); every "
                               "UAV needs its own start cell",
                               other, k, snapped[k].x, snapped[k].y, given[other].x, given[other].y,
                               given[k].x, given[k].y));
    }
  }
}

OptionMap parse_options(const std::vector<std::string>& pairs) {
  OptionMap map;
  for (const auto& kv : pairs) {
    const auto eq = kv.find('=');
    if (eq == std::string::npos || eq == 0) {
      throw ParameterError("option", fmt::format("expects KEY=VALUE (got '{}')", kv));
    }
    map[kv.substr(0, eq)] = kv.substr(eq + 1);
  }
  return map;
}

// The flight space as the report shows it (no-fly zones only; empty otherwise).
struct FlightSpace {
  world::Reachability reach;
  std::vector<int> component;  // per UAV: the flight component of its start
};

// Independent check, for the report, that each region is one the UAV can fly: 4-connected, and
// with no-fly zones every cell of it that can be seen at all is seen from the UAV's own flight
// component (docs/model.md §8).
std::vector<bool> connected_regions(const world::HullMask& hull, const partition::Partition& p,
                                    int n, const FlightSpace& flight) {
  std::vector<bool> connected(static_cast<std::size_t>(n), false);
  grid::Grid<std::uint8_t> region(hull.width(), hull.height(), 0);
  grid::Grid<int> labels;
  grid::BfsScratch scratch;
  const grid::Grid<int>& seen_from = flight.reach.seen_from;
  const grid::EdgeSteps seam = world::seam_links(hull);  // a region may cross the seam
  for (int k = 0; k < n; ++k) {
    bool flyable = true;
    for (int i = 0; i < region.size(); ++i) {
      region[i] = p.owner[i] == k;
      if (region[i] && seen_from.size() > 0 && seen_from[i] >= 0 &&
          seen_from[i] != flight.component[static_cast<std::size_t>(k)])
        flyable = false;
    }
    connected[static_cast<std::size_t>(k)] =
        flyable && grid::label_components(region, labels, scratch, seam) == 1;
  }
  return connected;
}

// The UAVs of flight component c, as "0, 1, 3".
std::string component_uavs(const FlightSpace& flight, int c) {
  std::string text;
  for (std::size_t k = 0; k < flight.component.size(); ++k) {
    if (flight.component[k] != c) continue;
    text += fmt::format("{}{}", text.empty() ? "" : ", ", k);
  }
  return text;
}

std::string region_mask(const world::HullMask& hull, const partition::Partition& p,
                        const PartitionArgs& args) {
  std::string text = fmt::format(
      "; hullinspect partition: {}, {}, seed {}, hull {}\n"
      "; one symbol per cell, top row (y = {}) first: UAV 0-9, then A-Z = 10-35, a-z = 36-61; "
      "'.' = not hull\n",
      p.fallback.empty()
          ? args.partitioner
          : fmt::format("{} (as a mission falls back from {})", p.fallback, args.partitioner),
      plural(args.declared.uavs, "UAV"), args.seed, hull.source(), hull.height() - 1);
  for (int y = hull.height() - 1; y >= 0; --y) {
    for (int x = 0; x < hull.width(); ++x) {
      const int k = p.owner(x, y);
      text += k < 0 ? '.' : kRegionSymbols[static_cast<std::size_t>(k)];
    }
    text += '\n';
  }
  return text;
}

void print_summary(const PartitionArgs& args, const world::HullMask& hull,
                   const std::vector<grid::Cell>& starts, const partition::Partition& p,
                   const std::vector<bool>& connected, const FlightSpace& flight) {
  std::cout << fmt::format("{}: {} on {} ({}), seed {}\n", args.partitioner,
                           plural(args.declared.uavs, "UAV"), hull.source(),
                           plural(hull.cell_count(), "hull cell"), args.seed);
  if (!p.fallback.empty()) {
    std::cout << fmt::format("  partition produced by {} ({} did not converge; as in a mission)\n",
                             p.fallback, args.partitioner);
  }
  const world::Reachability& reach = flight.reach;
  if (reach.unreachable_z1 > 0) {
    std::cout << fmt::format("  no-fly zones: {} cannot be inspected, {} cannot be seen at all\n",
                             plural(reach.unreachable_z1, "hull cell"), reach.unreachable_z2);
  }
  const bool split = reach.flight_components > 1;
  if (split) {
    std::cout << fmt::format(
        "  the no-fly zones cut the flight space into {} parts; each part's "
        "cells go to its own UAVs:\n",
        reach.flight_components);
    for (int c = 0; c < reach.flight_components; ++c) {
      int seen = 0;
      for (int i : hull.cells()) seen += reach.seen_from[i] == c ? 1 : 0;
      std::cout << fmt::format("    part {}: UAVs {}; {} seen from it\n", c,
                               component_uavs(flight, c), plural(seen, "hull cell"));
    }
  }
  if (p.converged) {
    std::cout << fmt::format(
        "  converged after {} iterations in {:.3f} ms; tolerance reached {:g} "
        "cell{}\n",
        p.iterations, p.seconds * 1e3, p.tolerance, p.tolerance == 1 ? "" : "s");
  } else {
    std::cout << fmt::format(
        "  NOT converged after {} iterations in {:.3f} ms; best connected "
        "partition found, largest imbalance {:g} cells\n",
        p.iterations, p.seconds * 1e3, p.tolerance);
  }
  std::cout << "  UAV  start        cells     desired  connected" << (split ? "  part" : "")
            << "\n";
  for (std::size_t k = 0; k < starts.size(); ++k) {
    const std::string_view yes_no = connected[k] ? "yes" : "NO";
    std::cout << fmt::format("  {:>3}  {:<11}  {:>5}  {:>10.2f}  ", k,
                             fmt::format("({}, {})", starts[k].x, starts[k].y), p.region_cells[k],
                             p.desired_weight[k]);
    if (split) {
      std::cout << fmt::format("{:<9}  {}\n", yes_no, flight.component[k]);
    } else {
      std::cout << yes_no << "\n";
    }
  }
}

nlohmann::json summary_json(const PartitionArgs& args, const world::HullMask& hull,
                            const std::vector<grid::Cell>& starts, const partition::Partition& p,
                            const std::vector<bool>& connected, const FlightSpace& flight) {
  nlohmann::json regions = nlohmann::json::array();
  for (std::size_t k = 0; k < starts.size(); ++k) {
    regions.push_back({{"uav", k},
                       {"start", {starts[k].x, starts[k].y}},
                       {"cells", p.region_cells[k]},
                       {"desired", p.desired_weight[k]},
                       {"connected", static_cast<bool>(connected[k])}});
    if (flight.reach.any_no_fly) regions.back()["flight_component"] = flight.component[k];
  }
  nlohmann::json out = {{"partitioner", args.partitioner},
                        {"produced_by", p.fallback.empty() ? args.partitioner : p.fallback},
                        {"hull", hull.source()},
                        {"hull_cells", hull.cell_count()},
                        {"uavs", args.declared.uavs},
                        {"seed", args.seed},
                        {"iterations", p.iterations},
                        {"converged", p.converged},
                        {"tolerance", p.tolerance},
                        {"seconds", p.seconds},
                        {"regions", regions},
                        {"warnings", p.warnings}};
  if (flight.reach.any_no_fly) {
    out["flight_components"] = flight.reach.flight_components;
    out["unreachable_cells"] = flight.reach.unreachable_z1;
    out["unreachable_z2_cells"] = flight.reach.unreachable_z2;
  }
  return out;
}

int run_partition(const PartitionArgs& args) {
  io::OutputSet outputs;
  const MissionArgs& mission = args.declared;
  if (mission.hull != "default") outputs.add_input(mission.hull, "hull");
  outputs.add_output(args.out_path, "out");
  outputs.check();
  const world::HullMask hull = load_mission_hull(mission);
  world::MissionParams params;
  params.uavs = mission.uavs;
  params.s1 = mission.s1;  // footprints: which flight component sees a hull cell
  params.s2 = mission.s2;
  params.theta_deg = mission.theta;  // and the neighbour flights of an unrolled hull
  if (hull.geometry()) params.cell_size_m = hull.geometry()->cell_size;
  for (const auto& s : mission.starts) params.starts.push_back(parse_xy(s));
  params.no_fly = build_no_fly(mission.no_fly, mission.no_fly_boxes, hull);
  std::vector<grid::Cell> starts;
  try {
    starts = world::validate(params, hull);
  } catch (const ParameterError& e) {
    // The library names the field "starts"; on this command line it is --start.
    if (e.name() != "starts") throw;
    throw ParameterError("start", e.problem());
  }
  if (!args.out_path.empty() && args.declared.uavs > static_cast<int>(kRegionSymbols.size())) {
    throw ParameterError("out",
                         fmt::format("a region mask has symbols for at most {} UAVs (got {})",
                                     kRegionSymbols.size(), args.declared.uavs));
  }
  std::unique_ptr<partition::Partitioner> partitioner;
  try {
    partitioner = partition::make_partitioner(args.partitioner, parse_options(args.options));
  } catch (const ParameterError& e) {
    // Partitioner options come from -O, so name them as "darp.cc" rather than as a flag.
    if (e.name() == "partitioner" || e.name() == "option") throw;
    throw ParameterError("option", fmt::format("{}: {}", e.name(), e.problem()));
  }
  partition::PartitionRequest request;
  request.hull = &hull;
  request.starts = std::move(starts);
  request.seed = args.seed;
  FlightSpace flight;
  if (params.no_fly) {
    // DARP's initial distances follow the shortest flights around the no-fly zones, and each
    // flight component's cells are partitioned among its own UAVs.
    flight.reach = world::compute_reachability(hull, params.no_fly.get(), params.s1, params.s2,
                                               request.starts);
    request.allowed = flight.reach.flyable;
    request.seen_from = flight.reach.seen_from;
  }
  // On an unrolled hull, the flights a mission's partition follows: their lengths and the seam.
  request.flights = world::neighbour_flights(hull, params).longer_plane();
  reject_shared_starts(params.starts, request.starts);
  flight.component = partition::start_components(request);
  // By default the partition a mission would fly (the fallback rule of docs/model.md), so that this
  // command and every mission on the same hull agree.
  const partition::Partition result =
      args.no_fallback
          ? partition::partition_per_flight_component(
                request,
                [&](const partition::PartitionRequest& one) { return partitioner->partition(one); })
          : partition::partition_with_fallback(args.partitioner, parse_options(args.options),
                                               request);
  const auto connected = connected_regions(hull, result, args.declared.uavs, flight);
  if (!args.out_path.empty()) outputs.write(args.out_path, region_mask(hull, result, args));
  if (args.json) {
    std::cout << summary_json(args, hull, request.starts, result, connected, flight).dump() << "\n";
  } else {
    print_summary(args, hull, request.starts, result, connected, flight);
    for (const auto& w : result.warnings) std::cerr << "hullinspect: warning: " << w << "\n";
  }
  check_stdout();
  outputs.commit();
  return result.converged ? 0 : 3;
}

}  // namespace

void add_partition_command(CLI::App& app, CommandAction& action) {
  auto args = std::make_shared<PartitionArgs>();
  CLI::App* cmd =
      app.add_subcommand("partition", "Divide the hull among the UAVs and report the regions");
  std::string partitioners;
  std::string names;
  for (const auto& info : partition::partitioner_registry()) {
    partitioners += fmt::format("  {}: {}\n{}", info.name, info.description,
                                describe_params(info.options, "    "));
    names += (names.empty() ? "" : ", ") + info.name;
  }
  cmd->footer(
      "Partitioners and their options (-O KEY=VALUE):\n" + partitioners +
      "The partition is the one a mission uses: when darp does not converge and the transfer "
      "partitioner balances the same request better, transfer's (--no-fallback: darp's own).\n"
      "Exit status: 0 converged, 3 not converged (the best connected partition found is still "
      "reported and written), 2 invalid input, 1 other failure.\n"
      "Example: hullinspect partition --uavs 4 --seed 7 --out regions.txt");
  add_declared_options(*cmd, args->declared, declarations_named({"uavs", "hull"}));
  cmd->get_option("--uavs")->required()->default_str("");  // no default: it must be given
  add_mesh_options(*cmd, args->declared);
  add_declared_options(*cmd, args->declared, declarations_named({"start"}));
  cmd->add_option("--seed", args->seed, "Partitioner seed")->capture_default_str();
  cmd->add_option("--partitioner", args->partitioner, "Partitioner: " + names)
      ->capture_default_str();
  cmd->add_option("--option,-O", args->options,
                  "Partitioner option as key=value, e.g. iteration-limit=500 (repeatable; listed "
                  "below)")
      ->type_name("KEY=VALUE");
  cmd->add_flag("--no-fallback", args->no_fallback,
                "Show the partitioner's own result, even when a mission would fall back to "
                "transfer's partition");
  add_no_fly_options(*cmd, args->declared);
  // With no-fly zones the footprints say which hull cells can be inspected and from where.
  add_declared_options(*cmd, args->declared, declarations_named({"s1", "s2"}));
  cmd->add_flag("--json", args->json,
                "Print one JSON object (partitioner, hull, hull_cells, uavs, seed, iterations, "
                "converged, tolerance, seconds, regions, warnings)");
  cmd->add_option("--out", args->out_path,
                  "Write the assignment matrix A as a text mask: one symbol per UAV (0-9, A-Z, "
                  "a-z), '.' for non-hull cells, top row first")
      ->type_name("FILE");
  cmd->callback([args, &action] { action = [args] { return run_partition(*args); }; });
}

}  // namespace hullinspect::cli
