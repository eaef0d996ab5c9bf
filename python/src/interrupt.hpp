// SPDX-License-Identifier: MIT
// Ctrl-C and progress callbacks in the long C++ loops (optimise, the
// studies). The loop runs on a worker thread with the GIL released while the
// calling thread wakes every 20 ms to run Python's signal handlers
// (PyErr_CheckSignals, under the GIL; they run on the main thread only, which
// is why the loop is moved off it). A handler that raises — SIGINT's
// KeyboardInterrupt — sets the run's CancellationToken, the engine's own stop
// hook: the algorithm stops between generations (Nelder–Mead: between
// iterations) with its best so far, and the caller raises the handler's
// exception once it has built that result. A progress callback returning True
// sets the same token. Python calls the run makes (the objective, the
// callback) re-acquire the GIL on the worker.
#pragma once

#include <pybind11/pybind11.h>

#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <type_traits>
#include <utility>

#include "hula/optim/run_report.hpp"

namespace hula::python {

class Interruptible {
 public:
  /// The token to give the engine (StopCriteria::cancel, NelderMeadOptions::cancel, StudyRunOptions::cancel).
  [[nodiscard]] const optim::CancellationToken* token() const noexcept { return &token_; }
  /// Stops the run at its next check (a callback asked to stop).
  void stop() noexcept { token_.cancel(); }

  /// Runs work() on a worker thread; the GIL is held on entry and on return. Rethrows what work() threw.
  template <class F>
  std::invoke_result_t<F&> run(F&& work) {
    using R = std::invoke_result_t<F&>;
    std::optional<R> result;
    std::exception_ptr error;
    {
      const pybind11::gil_scoped_release release;
      std::mutex m;
      std::condition_variable cv;
      bool done = false;
      std::thread worker([&] {
        try {
          result.emplace(work());
        } catch (...) {
          error = std::current_exception();
        }
        const std::lock_guard lock(m);
        done = true;
        cv.notify_one();
      });
      std::unique_lock lock(m);
      while (!cv.wait_for(lock, std::chrono::milliseconds(20), [&] { return done; })) {
        lock.unlock();
        check_signals();
        lock.lock();
      }
      lock.unlock();
      worker.join();
    }
    if (error) std::rethrow_exception(error);
    return std::move(*result);
  }

  /// The exception a signal handler raised during run() (KeyboardInterrupt), or None.
  [[nodiscard]] pybind11::object interrupt() const { return interrupt_ ? *interrupt_ : pybind11::none(); }

 private:
  void check_signals() {
    const pybind11::gil_scoped_acquire gil;
    if (interrupt_ || PyErr_CheckSignals() == 0) return;
    const pybind11::error_already_set raised;  // fetches the handler's exception, with its traceback
    interrupt_ = raised.value();
    token_.cancel();
  }

  optim::CancellationToken token_;
  std::optional<pybind11::object> interrupt_;
};

}  // namespace hula::python
