// A mesh hull named by a config is identified by the mesh as the config names it: the manifest's
// fingerprint and runs.csv (run ids, hull hash) are the same however the config's own path is
// spelled, and an experiment started with one spelling resumes with another from elsewhere.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/config_spellings.hpp"

namespace hullinspect::testing {
namespace {

namespace fs = std::filesystem;

TEST(MeshConfigIdentity, TheConfigPathsSpellingChangesNoIdAndResumeWorksFromElsewhere) {
  const fs::path dir = fs::absolute(make_temp_dir("mesh-config-identity"));
  fs::create_directories(dir / "k");
  std::ofstream(dir / "k" / "k3.stl")
      << "solid t\n facet normal 0 -1 0\n  outer loop\n   vertex 0 0 0\n   vertex 2 0 0\n"
         "   vertex 0 0 2\n  endloop\n endfacet\nendsolid t\n";
  std::ofstream(dir / "k" / "k3.yaml")
      << "name: k3\nhull: {mesh: k3.stl}\ns1: 1\ns2: 3\nuavs: 1\nalgorithms: [lawnmower]\n"
         "instances: 2\ncurve: {step: 10, end: 100}\n";
  expect_one_experiment_however_spelled(dir, "k", "k3.yaml");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace hullinspect::testing
