#pragma once
// Child programs of the CLI (the report's Python), bounded in time and stopped with the CLI: a
// child that hangs is killed at its time limit, and SIGINT or SIGTERM to hullinspect stops the
// child within a second and unwinds the command (so staged outputs are removed) before hullinspect
// dies of the same signal.

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace hullinspect::cli {

/// Thrown where a command notices that SIGINT or SIGTERM arrived while an InterruptGuard was
/// active; InterruptGuard::die re-raises it once the command has cleaned up.
class Interrupted : public std::runtime_error {
 public:
  explicit Interrupted(int signal);
  int signal() const { return signal_; }

 private:
  int signal_;
};

/// While alive, SIGINT and SIGTERM during run_process only set a flag that run_process (and
/// check()) turn into Interrupted, after stopping the child; at any other time they remove the
/// pending temporaries and staging directories and end hullinspect at once, by the signal. The
/// previous handlers come back with its destruction.
class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  /// Throws Interrupted when a signal has arrived.
  static void check();
  /// Ends the process by the signal's default action (exit status 128 + signal in a shell).
  [[noreturn]] static void die(int signal);
};

struct ProcessResult {
  int status = 0;          ///< exit status; 128 + signal if killed; 127 if it could not start
  bool timed_out = false;  ///< killed at the time limit
};

/// Runs a program (argv[0] is its path; no shell) with the inherited environment and standard
/// input, its standard output and error written to `log` (replaced), and waits at most `seconds`
/// for it (then SIGTERM, and SIGKILL a second later). Throws Interrupted (the child killed) when
/// an InterruptGuard sees a signal while it waits.
ProcessResult run_process(const std::vector<std::string>& argv, const std::filesystem::path& log,
                          double seconds);

}  // namespace hullinspect::cli
