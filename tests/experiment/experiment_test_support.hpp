#pragma once
// Helpers for the experiment tests: a small fast config, scratch directories, file access.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/experiment/config.hpp"
#include "hullinspect/experiment/plan.hpp"
#include "hullinspect/files/atomic_file.hpp"

namespace hullinspect::experiment::testing {

/// 2 scenarios × 2 s2 × 2 fleet sizes × 2 algorithms × 6 seeds = 96 lawnmower missions on a
/// 30 × 10 rectangle; the two scenarios share their zones, so a seed gives both the same C.
inline const char* kSmallConfig =
    "name: small\n"
    "hull: rectangle\n"
    "grid: {width: 30, height: 10}\n"
    "scenarios:\n"
    "  - {name: dense, p_c: 0.03, l_c: 3}\n"
    "  - {name: poor-prior, p_c: 0.03, l_c: 3, p_tp: 0.5, p_fp: 0.01}\n"
    "s2: [7, 9]\n"
    "uavs: [1, 2]\n"
    "algorithms: [lawnmower, {name: lawnmower, label: lm-seed2, options: {partition-seed: 2}}]\n"
    "instances: 6\n"
    "curve: {step: 10, end: 200}\n";

/// The error a config produces when parsed (named `source`, relative paths from /cfg) and expanded
/// (every cell validated), or "" if none.
inline std::string config_error(const std::string& yaml, const std::string& source) {
  try {
    ExperimentPlan plan(parse_config(yaml, source, "/cfg"));
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

/// A fresh empty directory under the system temporary directory, removed on destruction.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& name) {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() /
            ("hullinspect-" + std::string(info->name()) + "-" + name + "-" +
             std::to_string(::getpid()));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

inline std::string read(const std::filesystem::path& path) { return io::read_file(path); }

inline int count_lines(const std::string& text) {
  int n = 0;
  for (char c : text) n += c == '\n';
  return n;
}

}  // namespace hullinspect::experiment::testing
