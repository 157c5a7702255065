#pragma once
// Long calls of the Python module: the work runs on its own thread with the GIL released,
// while the calling thread wakes every 50 ms to let Python handle signals. When a signal
// handler raises (Ctrl-C: KeyboardInterrupt), `cancel` is set, the work is awaited (a
// cancellable one stops at its next step; the others finish) and the exception
// propagates to the caller. Exceptions of the work propagate as they are.
#include <pybind11/pybind11.h>

#include <atomic>
#include <chrono>
#include <future>
#include <optional>
#include <thread>
#include <utility>

namespace ccdlab::python {

/// `poll`, when given, is called on the calling thread with the GIL held at each wake
/// (every 50 ms while the work runs, and once at its end): e.g. to report progress to a
/// Python callback. An exception it raises stops the work as a signal does.
template <class F, class Poll = void (*)()>
auto run_interruptible(F&& work, std::atomic<bool>* cancel = nullptr, Poll&& poll = [] {}) -> decltype(work()) {
  using Result = decltype(work());
  std::packaged_task<Result()> task(std::forward<F>(work));
  std::future<Result> result = task.get_future();
  bool interrupted = false;
  {
    pybind11::gil_scoped_release release;
    std::thread worker(std::move(task));
    std::optional<pybind11::error_already_set> poll_error;
    while (result.wait_for(std::chrono::milliseconds(50)) != std::future_status::ready) {
      pybind11::gil_scoped_acquire acquire;
      if (PyErr_CheckSignals() != 0) {  // a handler raised; its exception stays set
        interrupted = true;
        if (cancel) cancel->store(true);
        break;
      }
      try {
        poll();
      } catch (pybind11::error_already_set& e) {
        poll_error = std::move(e);
        if (cancel) cancel->store(true);
        break;
      }
    }
    worker.join();
    if (poll_error) {
      pybind11::gil_scoped_acquire acquire;
      throw std::move(*poll_error);
    }
  }
  if (interrupted) throw pybind11::error_already_set();
  poll();
  return result.get();
}

}  // namespace ccdlab::python
