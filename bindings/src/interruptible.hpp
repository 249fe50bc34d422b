// Long C++ work that Ctrl-C can stop: searches, meshing and batches. The work runs on its own
// thread with the GIL released while the calling thread waits, checking Python's signals every
// 50 ms; on Ctrl-C it sets the work's cancel flag (SearchLimits::cancel, the meshers' and the
// batch's `cancel`), waits for the work to stop at its next step and raises KeyboardInterrupt,
// so nothing half-done is returned. C++ exceptions pass through.
#pragma once

#include <pybind11/pybind11.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

namespace genmod::python {

// Runs search() (which must read `cancel` through its options) and returns its result.
template <class Search>
auto run_interruptible(std::atomic<bool>& cancel, Search&& search) -> decltype(search()) {
  std::optional<decltype(search())> result;
  std::exception_ptr error;
  bool interrupted = false;
  {
    pybind11::gil_scoped_release unlocked;
    std::mutex m;
    std::condition_variable finished;
    bool done = false;
    std::thread worker([&] {
      try {
        result.emplace(search());
      } catch (...) {
        error = std::current_exception();
      }
      std::lock_guard<std::mutex> lock(m);
      done = true;
      finished.notify_one();
    });
    std::unique_lock<std::mutex> lock(m);
    while (!finished.wait_for(lock, std::chrono::milliseconds(50), [&] { return done; })) {
      lock.unlock();
      {
        pybind11::gil_scoped_acquire locked;
        if (PyErr_CheckSignals() != 0) interrupted = true;  // the exception stays set
      }
      lock.lock();
      if (interrupted) {
        cancel.store(true, std::memory_order_relaxed);
        finished.wait(lock, [&] { return done; });
      }
    }
    lock.unlock();
    worker.join();
  }
  if (interrupted) throw pybind11::error_already_set();
  if (error) std::rethrow_exception(error);
  return std::move(*result);
}

}  // namespace genmod::python
