#include "implicit/frame.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace genmod::implicit {

Frame::Frame(const std::array<Interval, 3>& box) {
  double half_max = 0.0;
  for (int k = 0; k < 3; ++k) {
    center_[k] = 0.5 * (box[k].lo() + box[k].hi());
    half_[k] = 0.5 * (box[k].hi() - box[k].lo());
    half_max = std::max(half_max, half_[k]);
  }
  // Side 2 * 1.0625 * half_max: a margin of 1/34 of the side around the box's longest axis.
  // The offset of 1/(64 pi) of the side is irrational, so no box face is a lattice plane.
  const double side = 2.125 * half_max;
  unit_ = side / static_cast<double>(kRootSize);
  const double shift = side / (64.0 * std::numbers::pi);
  for (int k = 0; k < 3; ++k) lo_[k] = center_[k] - 0.5 * side + shift;
}

double Frame::clip(const Vec3& p) const noexcept {
  double d = -std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) d = std::max(d, std::fabs(p[k] - center_[k]) - half_[k]);
  return d;
}

Interval Frame::clip(const std::array<Interval, 3>& box, std::array<int, 3>* active) const noexcept {
  namespace id = interval_detail;
  std::array<Interval, 3> term;
  Interval d;
  {
    const RoundingScope up;  // one mode switch for the whole enclosure
    id::Raw m;
    for (int k = 0; k < 3; ++k) {
      const id::Raw t = boost::numeric::abs(id::raw(box[k]) - id::Raw(center_[k])) - id::Raw(half_[k]);
      term[k] = id::cook(t);
      m = k == 0 ? t : boost::numeric::max(m, t);
    }
    d = id::cook(m);
  }
  if (active) {
    for (int k = 0; k < 3; ++k) {
      if (term[k].hi() < d.lo()) {
        (*active)[k] = 0;
      } else if (box[k].lo() >= center_[k]) {
        (*active)[k] = 1;
      } else if (box[k].hi() <= center_[k]) {
        (*active)[k] = -1;
      } else {
        (*active)[k] = 2;
      }
    }
  }
  return d;
}

Vec3 Frame::clip_gradient(const Vec3& p) const noexcept {
  int best = 0;
  double d = -std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    const double t = std::fabs(p[k] - center_[k]) - half_[k];
    if (t > d) {
      d = t;
      best = k;
    }
  }
  Vec3 g{0, 0, 0};
  g[best] = p[best] >= center_[best] ? 1.0 : -1.0;
  return g;
}

}  // namespace genmod::implicit
