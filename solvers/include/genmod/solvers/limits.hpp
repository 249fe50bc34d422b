// Resource limits shared by the interval solvers, the report of what a search used, and the
// watch that checks them. Every search stops at its limits and says which one it hit; nothing
// is dropped silently.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace genmod {

struct SearchLimits {
  std::size_t max_boxes = 1'000'000;  // boxes taken from the work list
  int max_depth = 200;                // subdivisions along one path
  double time_limit = 0.0;            // seconds of wall time; 0 = none
  // The caller's stop request (not owned; null = none): when it becomes true the search stops
  // at its next box (or round of boxes) and reports LimitHit::Cancelled, with what it has
  // left unexplored, as for the other limits. Python's Ctrl-C sets it.
  const std::atomic<bool>* cancel = nullptr;

  bool cancelled() const noexcept { return cancel != nullptr && cancel->load(std::memory_order_relaxed); }
};

enum class LimitHit : std::uint8_t { None, MaxBoxes, MaxDepth, TimeLimit, Cancelled };

std::string_view limit_name(LimitHit hit) noexcept;

// One search's use of its limits, shared by every solver so that they stop alike: started when
// constructed, reached() names the first of the box, time and cancel limits that has been hit
// (the depth limit is a property of one box, checked by each search where it splits).
class LimitWatch {
 public:
  explicit LimitWatch(const SearchLimits& limits) noexcept
      : limits_(limits), start_(std::chrono::steady_clock::now()) {}
  // MaxBoxes once `boxes` >= max_boxes, TimeLimit once time_limit > 0 seconds have passed,
  // Cancelled once the cancel flag is set; otherwise None.
  LimitHit reached(std::size_t boxes) const noexcept {
    if (boxes >= limits_.max_boxes) return LimitHit::MaxBoxes;
    if (limits_.time_limit > 0.0 && seconds() > limits_.time_limit) return LimitHit::TimeLimit;
    if (limits_.cancelled()) return LimitHit::Cancelled;
    return LimitHit::None;
  }
  double seconds() const noexcept {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  SearchLimits limits_;
  std::chrono::steady_clock::time_point start_;
};

struct SearchReport {
  std::size_t boxes_processed = 0;
  int deepest = 0;                   // largest subdivision depth reached
  LimitHit limit = LimitHit::None;   // the first limit hit, if any
  double seconds = 0.0;
};

}  // namespace genmod
