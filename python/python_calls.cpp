#include "python_calls.hpp"

#include <pthread.h>

#include <chrono>
#include <csignal>
#include <thread>

#include "hullinspect/core/errors.hpp"

namespace hullinspect::python {

namespace py = pybind11;

namespace {

struct Call {
  const std::function<void()>* body = nullptr;
  std::exception_ptr error;
  bool done = false;
};

/// The calls waiting for the serving thread, and whether one is serving.
struct Server {
  std::mutex mutex;
  std::condition_variable posted;    // a call was posted, or the work finished
  std::condition_variable finished;  // a call was run
  std::deque<Call*> queue;
  bool serving = false;
  bool work_done = false;
  std::atomic<bool> stopped{false};
};

// Blocks SIGINT, SIGTERM and SIGHUP on the calling thread while it lives (threads started
// meanwhile inherit the mask).
class InterruptsBlocked {
 public:
  InterruptsBlocked() {
    sigset_t interrupts;
    sigemptyset(&interrupts);
    for (int signal : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&interrupts, signal);
    pthread_sigmask(SIG_BLOCK, &interrupts, &previous_);
  }
  ~InterruptsBlocked() { pthread_sigmask(SIG_SETMASK, &previous_, nullptr); }
  InterruptsBlocked(const InterruptsBlocked&) = delete;
  InterruptsBlocked& operator=(const InterruptsBlocked&) = delete;

 private:
  sigset_t previous_;
};

Server& server() {
  static Server s;
  return s;
}

}  // namespace

void run_python_call(const std::function<void()>& call) {
  Server& s = server();
  std::unique_lock lock(s.mutex);
  if (!s.serving) {
    lock.unlock();
    call();
    return;
  }
  if (s.stopped) throw Error("interrupted");
  Call posted{&call, nullptr, false};
  s.queue.push_back(&posted);
  s.posted.notify_all();
  s.finished.wait(lock, [&] { return posted.done; });
  if (posted.error) std::rethrow_exception(posted.error);
}

void serve_python_calls(const std::function<void(const std::atomic<bool>& stopped)>& work) {
  Server& s = server();
  {
    std::lock_guard lock(s.mutex);
    if (s.serving) throw Error("run_experiment: already running (it cannot be nested)");
    s.serving = true;
    s.work_done = false;
    s.stopped = false;
  }
  std::exception_ptr work_error;
  std::optional<py::error_already_set> interrupt;
  // The worker, and every thread it starts, blocks the interrupt signals, so that the kernel
  // delivers Ctrl-C to this thread: Python runs its handlers only here, and a signal taken by a
  // worker would not wake a decide() that sleeps on this thread.
  std::optional<InterruptsBlocked> blocked(std::in_place);
  std::thread worker([&] {
    try {
      work(s.stopped);
    } catch (...) {
      work_error = std::current_exception();
    }
    std::lock_guard lock(s.mutex);
    s.work_done = true;
    s.posted.notify_all();
  });
  blocked.reset();  // this thread takes them again
  auto stop_with = [&](py::error_already_set&& e) {
    if (!interrupt) interrupt.emplace(std::move(e));
    s.stopped = true;
  };
  for (;;) {
    Call* call = nullptr;
    bool done = false;
    {
      py::gil_scoped_release release;
      std::unique_lock lock(s.mutex);
      s.posted.wait_for(lock, std::chrono::milliseconds(100),
                        [&] { return !s.queue.empty() || s.work_done; });
      if (!s.queue.empty()) {
        call = s.queue.front();
        s.queue.pop_front();
      }
      done = s.work_done && call == nullptr;
    }
    if (call != nullptr) {
      if (s.stopped) {
        call->error = std::make_exception_ptr(Error("interrupted"));
      } else {
        try {
          (*call->body)();
        } catch (py::error_already_set& e) {
          if (e.matches(PyExc_KeyboardInterrupt)) {
            call->error = std::make_exception_ptr(Error("interrupted"));
            stop_with(std::move(e));
          } else {
            call->error = std::current_exception();
          }
        } catch (...) {
          call->error = std::current_exception();
        }
      }
      std::lock_guard lock(s.mutex);
      call->done = true;
      s.finished.notify_all();
    }
    if (done) break;
    if (PyErr_CheckSignals() != 0) stop_with(py::error_already_set());
  }
  {
    py::gil_scoped_release release;
    worker.join();
  }
  {
    std::lock_guard lock(s.mutex);
    s.serving = false;
  }
  if (interrupt) throw std::move(*interrupt);
  if (work_error) std::rethrow_exception(work_error);
}

}  // namespace hullinspect::python
