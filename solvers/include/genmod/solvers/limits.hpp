// Resource limits shared by the interval solvers, and the report of what a search used.
// Every search stops at its limits and says which one it hit; nothing is dropped silently.
#pragma once

#include <atomic>
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

struct SearchReport {
  std::size_t boxes_processed = 0;
  int deepest = 0;                   // largest subdivision depth reached
  LimitHit limit = LimitHit::None;   // the first limit hit, if any
  double seconds = 0.0;
};

}  // namespace genmod
