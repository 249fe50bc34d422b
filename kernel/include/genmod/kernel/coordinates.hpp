// Coordinates: a list of coordinate indices (a tape's inputs, a search's unknowns or
// parameters), taken from whatever the caller has at hand.
//
// Example:
//   Fn f = x(0) * x(1) + x(2);
//   Tape abc(f, {0, 1, 2});                  // a braced list: input k is x(list[k])
//   std::vector<int> order = {2, 0, 1};
//   Tape cab(f, order);                      // or any contiguous range of int
//   double a = PointEvaluator().eval(abc, {1.0, 2.0, 3.0})[0];   // 1 * 2 + 3 = 5
//   double b = PointEvaluator().eval(cab, {3.0, 1.0, 2.0})[0];   // the same point: 5
//
// It is a view, like std::span<const int> (which it converts to): the list must outlive the
// call it is passed to, as a braced list does (it lives to the end of the full expression).
// Functions that keep the indices copy them.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <ranges>
#include <span>
#include <type_traits>

namespace genmod {

class Coordinates {
 public:
  Coordinates() = default;
  Coordinates(std::initializer_list<int> list) noexcept : view_(list.begin(), list.size()) {}
  template <class Range>
    requires(!std::is_same_v<std::remove_cvref_t<Range>, Coordinates> &&
             std::ranges::contiguous_range<const Range&> && std::ranges::sized_range<const Range&> &&
             std::is_same_v<std::ranges::range_value_t<const Range&>, int>)
  Coordinates(const Range& range) noexcept : view_(std::ranges::data(range), std::ranges::size(range)) {}

  operator std::span<const int>() const noexcept { return view_; }
  std::span<const int> span() const noexcept { return view_; }
  const int* begin() const noexcept { return view_.data(); }
  const int* end() const noexcept { return view_.data() + view_.size(); }
  const int* data() const noexcept { return view_.data(); }
  std::size_t size() const noexcept { return view_.size(); }
  bool empty() const noexcept { return view_.empty(); }
  int operator[](std::size_t i) const noexcept { return view_[i]; }

 private:
  std::span<const int> view_;
};

}  // namespace genmod
