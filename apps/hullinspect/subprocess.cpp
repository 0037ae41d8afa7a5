#include "subprocess.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <string>
#include <thread>

#include "hullinspect/files/pending_temporaries.hpp"

extern char** environ;

namespace hullinspect::cli {

namespace {

std::atomic<int> g_signal{0};
struct sigaction g_old_int {};
struct sigaction g_old_term {};

// True from just before a child is spawned until it has been reaped.
std::atomic<bool> g_child_running{false};

// While a child runs, the signal is remembered: run_process stops the child and the command
// unwinds. Otherwise nothing needs waiting for, and the command stops at once (within a second
// even while it reads or computes between checks): the pending temporaries and staging
// directories are removed and hullinspect dies of the signal.
void remember_signal(int signal) {
  g_signal.store(signal);
  if (g_child_running.load()) return;
  io::remove_pending_temporaries();
  struct sigaction defaults {};
  defaults.sa_handler = SIG_DFL;
  sigemptyset(&defaults.sa_mask);
  ::sigaction(signal, &defaults, nullptr);
  ::raise(signal);
}

// Marks a child as running for the lifetime of one run_process call.
struct ChildRunning {
  ChildRunning() { g_child_running.store(true); }
  ~ChildRunning() { g_child_running.store(false); }
  ChildRunning(const ChildRunning&) = delete;
  ChildRunning& operator=(const ChildRunning&) = delete;
};

using Clock = std::chrono::steady_clock;

/// Waits for `pid` without blocking for more than a few milliseconds at a time; true when it ended.
bool reap(pid_t pid, int& status) {
  const pid_t r = ::waitpid(pid, &status, WNOHANG);
  return r == pid || (r < 0 && errno != EINTR);
}

/// SIGTERM, then SIGKILL if the child is still there a second later; waits for it.
int stop_child(pid_t pid) {
  int status = 0;
  ::kill(pid, SIGTERM);
  const auto deadline = Clock::now() + std::chrono::milliseconds(800);
  while (Clock::now() < deadline) {
    if (reap(pid, status)) return status;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ::kill(pid, SIGKILL);
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return status;
}

}  // namespace

Interrupted::Interrupted(int signal)
    : std::runtime_error(signal == SIGINT ? "interrupted (SIGINT)" : "interrupted (SIGTERM)"),
      signal_(signal) {}

InterruptGuard::InterruptGuard() {
  g_signal.store(0);
  struct sigaction sa {};
  sa.sa_handler = remember_signal;
  sigemptyset(&sa.sa_mask);
  ::sigaction(SIGINT, &sa, &g_old_int);
  ::sigaction(SIGTERM, &sa, &g_old_term);
}

InterruptGuard::~InterruptGuard() {
  ::sigaction(SIGINT, &g_old_int, nullptr);
  ::sigaction(SIGTERM, &g_old_term, nullptr);
}

void InterruptGuard::check() {
  if (const int s = g_signal.load(); s != 0) throw Interrupted(s);
}

void InterruptGuard::die(int signal) {
  std::signal(signal, SIG_DFL);
  std::raise(signal);
  std::_Exit(128 + signal);
}

ProcessResult run_process(const std::vector<std::string>& argv, const std::filesystem::path& log,
                          double seconds) {
  const ChildRunning running;
  InterruptGuard::check();
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  // The child starts with default signal dispositions, whatever hullinspect's are.
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  sigset_t defaults;
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGINT);
  sigaddset(&defaults, SIGTERM);
  posix_spawnattr_setsigdefault(&attr, &defaults);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGDEF);
  pid_t pid = 0;
  const int spawned = ::posix_spawn(&pid, args[0], &actions, &attr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attr);
  ProcessResult result;
  if (spawned != 0) {
    result.status = 127;
    return result;
  }
  const auto deadline = Clock::now() + std::chrono::duration<double>(seconds);
  int status = 0;
  for (;;) {
    if (reap(pid, status)) break;
    if (const int s = g_signal.load(); s != 0) {
      stop_child(pid);
      throw Interrupted(s);
    }
    if (Clock::now() >= deadline) {
      status = stop_child(pid);
      result.timed_out = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  if (WIFEXITED(status)) {
    result.status = WEXITSTATUS(status);
  } else if (WIFSIGNALED(status)) {
    result.status = 128 + WTERMSIG(status);
  } else {
    result.status = 127;
  }
  return result;
}

}  // namespace hullinspect::cli
