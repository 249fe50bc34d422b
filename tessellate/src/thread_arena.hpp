// Running a renderer's parallel work on the number of threads the caller asked for.
#pragma once

#include <tbb/task_arena.h>

#include <stdexcept>
#include <string>
#include <utility>

namespace genmod::raster_detail {

// Runs f inside a TBB arena of `threads` workers (0 = all cores). std::invalid_argument for
// a negative count; `who` names the caller.
template <class F>
void run_with_threads(int threads, const char* who, F&& f) {
  if (threads < 0)
    throw std::invalid_argument(std::string("genmod: ") + who + ": threads must be >= 0 (0 = all cores), got " +
                                std::to_string(threads));
  tbb::task_arena arena(threads == 0 ? tbb::task_arena::automatic : threads);
  arena.execute(std::forward<F>(f));
}

}  // namespace genmod::raster_detail
