// Untrusted work in a forked child process (include/hullinspect/core/isolated_call.hpp).
#include "hullinspect/core/isolated_call.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <ctime>

#include "hullinspect/core/errors.hpp"

namespace hullinspect {

namespace {

using Clock = std::chrono::steady_clock;

/// The child's end of the pipe; every higher descriptor is closed in the child.
constexpr int kResultFd = 3;
/// Exit statuses of the child's own failures (the parent reports them as "exited with status N").
constexpr int kChildSetupFailed = 120;
constexpr int kChildWorkThrew = 121;
constexpr int kChildWriteFailed = 122;
/// Larger outputs are refused: the header of a child that went wrong before writing it.
constexpr std::uint64_t kMaxOutputBytes = std::uint64_t{1} << 40;

bool write_all(int fd, const char* p, std::size_t n) {
  while (n > 0) {
    const ssize_t w = ::write(fd, p, n);
    if (w < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    p += w;
    n -= static_cast<std::size_t>(w);
  }
  return true;
}

[[noreturn]] void run_child(const std::function<std::string()>& work, int result_fd) {
  // A crash reads the same in every build: no sanitizer, libFuzzer or Python handler turns a
  // SIGSEGV into a report and another exit status.
  for (int s : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGTRAP, SIGSYS}) ::signal(s, SIG_DFL);
  if (result_fd != kResultFd && ::dup2(result_fd, kResultFd) < 0) ::_exit(kChildSetupFailed);
  const int null = ::open("/dev/null", O_RDWR);
  if (null < 0) ::_exit(kChildSetupFailed);
  for (int fd = 0; fd <= 2; ++fd) {
    if (null != fd && ::dup2(null, fd) < 0) ::_exit(kChildSetupFailed);
  }
  // Pipes of other threads' children must not be held open here (their readers wait for EOF).
  ::close_range(kResultFd + 1, ~0U, 0);
  std::string out;
  try {
    out = work();
  } catch (...) {
    ::_exit(kChildWorkThrew);
  }
  const std::uint64_t size = out.size();
  if (!write_all(kResultFd, reinterpret_cast<const char*>(&size), sizeof size) ||
      !write_all(kResultFd, out.data(), out.size())) {
    ::_exit(kChildWriteFailed);
  }
  ::_exit(0);
}

int milliseconds_until(Clock::time_point deadline) {
  const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - Clock::now()).count();
  return static_cast<int>(std::clamp<std::int64_t>(left, 0, 1000));
}

/// The child's output: "" with complete = false when it ended early, failed or timed out.
struct Received {
  std::string bytes;
  bool complete = false;
  bool timed_out = false;
  int read_errno = 0;
};

// Reads the 8-byte size, then the output straight into one buffer of that size (no regrowing:
// the DTC's 4 MB reply costs one allocation).
Received receive(int fd, Clock::time_point deadline) {
  Received r;
  char header[sizeof(std::uint64_t)];
  std::size_t header_have = 0;
  std::size_t have = 0;
  bool sized = false;
  while (true) {
    if (Clock::now() >= deadline) {
      r.timed_out = true;
      r.bytes.clear();
      return r;
    }
    pollfd p{fd, POLLIN, 0};
    const int ready = ::poll(&p, 1, milliseconds_until(deadline));
    if (ready < 0 && errno != EINTR) {
      r.read_errno = errno;
      r.bytes.clear();
      return r;
    }
    if (ready <= 0) continue;
    char* into = sized ? r.bytes.data() + have : header + header_have;
    const std::size_t room = sized ? r.bytes.size() - have : sizeof header - header_have;
    const ssize_t n = ::read(fd, into, room);
    if (n < 0) {
      if (errno == EINTR || errno == EAGAIN) continue;
      r.read_errno = errno;
      r.bytes.clear();
      return r;
    }
    if (n == 0) {  // EOF before the whole output
      r.bytes.clear();
      return r;
    }
    if (sized) {
      have += static_cast<std::size_t>(n);
    } else {
      header_have += static_cast<std::size_t>(n);
      if (header_have < sizeof header) continue;
      std::uint64_t expected = 0;
      std::memcpy(&expected, header, sizeof expected);
      if (expected > kMaxOutputBytes) return r;
      r.bytes.resize(static_cast<std::size_t>(expected));
      sized = true;
    }
    if (have == r.bytes.size()) {
      r.complete = true;
      return r;
    }
  }
}

/// Waits for the child until `deadline`, then kills it. Returns the wait status, or -1 when the
/// child cannot be waited for (SIGCHLD ignored by the embedding process).
int reap(pid_t pid, Clock::time_point deadline, bool& killed) {
  while (true) {
    int status = 0;
    const pid_t r = ::waitpid(pid, &status, killed ? 0 : WNOHANG);
    if (r == pid) return status;
    if (r < 0 && errno != EINTR) return -1;
    if (r == 0 && Clock::now() >= deadline) {
      ::kill(pid, SIGKILL);
      killed = true;
      continue;
    }
    if (r == 0) {
      const timespec pause{0, 1'000'000};
      ::nanosleep(&pause, nullptr);
    }
  }
}

std::string seconds_text(std::chrono::milliseconds limit) {
  return fmt::format("{:g} s", static_cast<double>(limit.count()) / 1000);
}

}  // namespace

IsolatedResult run_isolated(const std::function<std::string()>& work,
                            std::chrono::milliseconds limit) {
  const Clock::time_point deadline = Clock::now() + limit;
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) {
    throw Error(fmt::format("cannot start a child process: {}", std::strerror(errno)));
  }
  // Fewer wake-ups for large outputs (the DTC sends 4 MB); the default size works too.
  (void)::fcntl(fds[0], F_SETPIPE_SZ, 1 << 20);
  const pid_t pid = ::fork();
  if (pid < 0) {
    const int e = errno;
    ::close(fds[0]);
    ::close(fds[1]);
    throw Error(fmt::format("cannot start a child process: {}", std::strerror(e)));
  }
  if (pid == 0) {
    ::close(fds[0]);
    run_child(work, fds[1]);
  }
  ::close(fds[1]);
  Received received = receive(fds[0], deadline);
  ::close(fds[0]);
  bool killed = false;
  if (received.timed_out) {
    ::kill(pid, SIGKILL);
    killed = true;
  }
  const int status = reap(pid, deadline, killed);

  IsolatedResult result;
  if (received.timed_out || killed) {
    result.failure = "did not finish in " + seconds_text(limit);
  } else if (status != -1 && WIFSIGNALED(status)) {
    result.failure = fmt::format("crashed: signal {}", WTERMSIG(status));
  } else if (status != -1 && WIFEXITED(status) && WEXITSTATUS(status) != 0) {
    result.failure = fmt::format("exited with status {}", WEXITSTATUS(status));
  } else if (received.read_errno != 0) {
    result.failure =
        fmt::format("its output cannot be read: {}", std::strerror(received.read_errno));
  } else if (!received.complete) {
    result.failure = "ended before sending its whole result";
  } else {
    result.ok = true;
    result.output = std::move(received.bytes);
  }
  return result;
}

}  // namespace hullinspect
