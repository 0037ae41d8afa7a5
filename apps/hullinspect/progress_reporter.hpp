#pragma once
// Shows an experiment's progress on stderr: a redrawn bar when stderr is a terminal, otherwise one
// line per minute (for batch logs), and a final line either way.

#include <chrono>
#include <string>

#include "hullinspect/experiment/runner.hpp"

namespace hullinspect::cli {

class ProgressReporter {
 public:
  explicit ProgressReporter(bool terminal);
  /// Called after every finished run (serialised by the runner).
  void update(const experiment::Progress& progress);
  /// Ends the bar's line.
  void finish();

 private:
  std::string line(const experiment::Progress& p) const;

  bool terminal_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point last_;
  experiment::Progress latest_;
};

/// "1h02m", "3m07s", "12s".
std::string format_duration(double seconds);

}  // namespace hullinspect::cli
