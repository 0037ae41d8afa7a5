#pragma once
// Where Python code runs while an experiment's worker threads fly missions with Python planners.
//
// CPython delivers SIGINT (KeyboardInterrupt) to the main thread only, and a time.sleep() or any
// other blocking call in another thread cannot be interrupted. So while run_experiment() runs,
// every Python call of a planner (constructor, start, decide) is handed to the main thread, which
// runs them one at a time (they hold the GIL anyway, so nothing is lost) and checks for signals
// between them: Ctrl-C interrupts a planner's decide() where it is, and the experiment stops.
// Outside run_experiment() (run_mission, Session) Python calls run on the calling thread.

#include <atomic>
#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>

#include <pybind11/pybind11.h>

namespace hullinspect::python {

/// Runs `call` (which takes the GIL itself) on the thread that serves Python calls: the main thread
/// inside serve_python_calls(), else the calling thread. Rethrows what `call` threw. Throws Error
/// ("interrupted") without running it once the serving thread saw an interrupt.
void run_python_call(const std::function<void()>& call);

/// Runs `work` on a new thread and, on this thread (the GIL held on entry), serves the Python calls
/// posted meanwhile and checks for signals every 100 ms until `work` returns. `stopped` is set when
/// a signal handler raised (KeyboardInterrupt): `work` should then stop soon; the Python error is
/// re-raised once it has. `work`'s exception is rethrown otherwise.
void serve_python_calls(const std::function<void(const std::atomic<bool>& stopped)>& work);

}  // namespace hullinspect::python
