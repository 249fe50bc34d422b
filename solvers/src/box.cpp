#include "genmod/solvers/box.hpp"
#include "genmod/solvers/limits.hpp"

#include <cmath>
#include <stdexcept>

namespace genmod {

double width(std::span<const Interval> box) noexcept {
  double w = 0.0;
  for (const Interval& x : box) w = std::max(w, x.width());
  return w;
}

std::size_t widest_side(std::span<const Interval> box) noexcept {
  std::size_t best = 0;
  double w = -1.0;
  for (std::size_t i = 0; i < box.size(); ++i)
    if (box[i].width() > w) {
      w = box[i].width();
      best = i;
    }
  return best;
}

std::vector<double> midpoint(std::span<const Interval> box) {
  std::vector<double> m;
  m.reserve(box.size());
  for (const Interval& x : box) m.push_back(x.mid());
  return m;
}

bool contains(std::span<const Interval> outer, std::span<const Interval> inner) noexcept {
  if (outer.size() != inner.size()) return false;
  for (std::size_t i = 0; i < outer.size(); ++i)
    if (!outer[i].contains(inner[i])) return false;
  return true;
}

bool contains(std::span<const Interval> box, std::span<const double> point) noexcept {
  if (box.size() != point.size()) return false;
  for (std::size_t i = 0; i < box.size(); ++i)
    if (!box[i].contains(point[i])) return false;
  return true;
}

Box hull(std::span<const Interval> a, std::span<const Interval> b) {
  if (a.size() != b.size()) throw std::invalid_argument("genmod: hull of boxes of different dimensions");
  Box h(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) h[i] = genmod::hull(a[i], b[i]);
  return h;
}

std::pair<Box, Box> bisect(std::span<const Interval> box, std::size_t dim) {
  if (dim >= box.size()) throw std::invalid_argument("genmod: bisect: no side " + std::to_string(dim));
  Box lo(box.begin(), box.end()), hi(box.begin(), box.end());
  const double m = box[dim].mid();
  lo[dim] = Interval::unchecked(box[dim].lo(), m);
  hi[dim] = Interval::unchecked(m, box[dim].hi());
  return {std::move(lo), std::move(hi)};
}

void check_search_box(std::span<const Interval> box, std::size_t dims, const std::string& who) {
  if (box.size() != dims)
    throw std::invalid_argument("genmod: " + who + ": the box has " + std::to_string(box.size()) +
                                " sides, expected " + std::to_string(dims));
  for (std::size_t i = 0; i < box.size(); ++i)
    if (box[i].is_empty() || !box[i].is_bounded())
      throw std::invalid_argument("genmod: " + who + ": side " + std::to_string(i) +
                                  " of the box is empty or unbounded");
}

std::string_view limit_name(LimitHit hit) noexcept {
  switch (hit) {
    case LimitHit::None: return "none";
    case LimitHit::MaxBoxes: return "max_boxes";
    case LimitHit::MaxDepth: return "max_depth";
    case LimitHit::TimeLimit: return "time_limit";
    case LimitHit::Cancelled: return "cancelled";
  }
  return "?";
}

}  // namespace genmod
