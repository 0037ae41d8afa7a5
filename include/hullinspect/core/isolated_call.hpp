#pragma once
// Runs a piece of untrusted work (a third-party parser on user bytes) in a forked child process,
// so that a crash, a hang or a leak inside it becomes an error of the caller instead of the end
// of hullinspect (docs/reliability.md, "Meshes cannot crash or hang hullinspect"). Linux only.
//
// The child runs `work`, sends back the bytes it returns through a pipe and ends with _exit(0):
// no atexit handlers, no stdio flush, no leak check. Its standard streams are /dev/null (a
// sanitizer report inside the library is part of the crash, not output of hullinspect) and
// crash signals have their default action, so a crash reads the same in every build.
//
// Threads: fork copies only the calling thread. `work` must need no lock that another thread of
// the parent might hold at the fork (glibc's malloc is safe: it is reset in the child; clang-14's
// ASan allocator is not); a child stalled on such a lock ends at the time limit as "did not
// finish", never as a hang. hullinspect calls it before it starts any worker thread (meshes are
// imported while a config is read), so only a program embedding the library (the Python module)
// that imports a mesh while its own threads allocate can meet this.

#include <chrono>
#include <functional>
#include <string>

namespace hullinspect {

struct IsolatedResult {
  bool ok = false;      ///< the child sent its whole output and exited with status 0
  std::string output;   ///< what `work` returned (when ok)
  std::string failure;  ///< when !ok: "crashed: signal 11", "did not finish in 60 s", …
};

/// Runs `work` in a child process and waits at most `limit` (wall time) for its output; a child
/// that is not done by then is killed (SIGKILL). Throws Error only when no child can be started.
IsolatedResult run_isolated(const std::function<std::string()>& work,
                            std::chrono::milliseconds limit);

}  // namespace hullinspect
