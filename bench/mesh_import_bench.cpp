// Mesh import (docs/hulls.md): the installed DTC (116 062 facets, gzip-compressed ASCII STL, full
// scale, 0.5 m cells) read and projected, end to end and by stage; a Wigley hull for machines
// without openfoam-examples.
//
//   build/release/mesh_import_bench --benchmark_repetitions=5
//   --benchmark_report_aggregates_only=true

#include <benchmark/benchmark.h>
#include "source_dir.hpp"

#include <cstdlib>
#include <filesystem>
#include <string>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/files/atomic_file.hpp"
#include "hullinspect/world/mesh_hull.hpp"

namespace {

using namespace hullinspect;

void BM_DtcImport(benchmark::State& state) {
  std::filesystem::path path;
  try {
    path = world::dtc_mesh_path();
  } catch (const Error& e) {
    state.SkipWithError(e.what());
    return;
  }
  int cells = 0;
  for (auto _ : state) {
    const world::MeshImport r = world::import_mesh_file(path, world::dtc_options());
    cells = r.hull.cell_count();
  }
  state.counters["hull_cells"] = cells;
}
BENCHMARK(BM_DtcImport)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_DtcRead(benchmark::State& state) {
  std::string bytes;
  try {
    bytes = io::read_file(world::dtc_mesh_path());
  } catch (const Error& e) {
    state.SkipWithError(e.what());
    return;
  }
  std::size_t facets = 0;
  for (auto _ : state) facets = world::read_mesh(bytes, "stl", "dtc").size();
  state.counters["facets"] = static_cast<double>(facets);
}
BENCHMARK(BM_DtcRead)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_DtcProjection(benchmark::State& state) {
  std::vector<world::MeshTriangle> triangles;
  try {
    triangles = world::read_mesh(io::read_file(world::dtc_mesh_path()), "stl", "dtc");
  } catch (const Error& e) {
    state.SkipWithError(e.what());
    return;
  }
  world::MeshImportOptions options = world::dtc_options();
  options.cell_size = static_cast<double>(state.range(0)) / 100;
  for (auto _ : state) {
    benchmark::DoNotOptimize(world::project_mesh(triangles, options, "dtc").hull.cell_count());
  }
}
BENCHMARK(BM_DtcProjection)->Arg(50)->Arg(25)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_WigleyImport(benchmark::State& state) {
  const auto path = std::filesystem::temp_directory_path() / "hullinspect_bench_wigley.stl";
  const std::string command = std::string("/usr/bin/python3 ") + HULLINSPECT_SOURCE_DIR +
                              "/tools/make_wigley_hull.py " + path.string() +
                              " --nx 400 --nz 80 --binary > /dev/null";
  if (std::system(command.c_str()) != 0) {
    state.SkipWithError("tools/make_wigley_hull.py failed");
    return;
  }
  for (auto _ : state) {
    benchmark::DoNotOptimize(world::import_mesh_file(path, {}).hull.cell_count());
  }
  std::filesystem::remove(path);
}
BENCHMARK(BM_WigleyImport)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
