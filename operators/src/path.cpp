#include "genmod/operators/path.hpp"

#include "dims.hpp"
#include "genmod/operators/higher_order.hpp"
#include "genmod/operators/vector.hpp"

#include <numbers>
#include <string>

namespace genmod {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

Fn rot90(const Fn& a) { return cat({-a[1], a[0]}); }

// The parameter t of base + t dir on the circle (o, r): the smaller root, or the larger one
// when `second`. The plain quadratic formula: only the absolute error of t matters for the
// point, and it is a few ulps of |B| / A either way. A line missing the circle is NaN.
Fn line_circle(const Fn& base, const Fn& dir, const Fn& o, const Fn& r, bool second) {
  const Fn w = base - o;
  const Fn a = dot(dir, dir), b = dot(dir, w), c = dot(w, w) - square(r);
  const Fn root = sqrt(square(b) - a * c);
  return (second ? -b + root : -b - root) / a;
}

struct Fillet {
  Fn on_line, center, on_circle;
};

// The fillet of radius f at the corner where the line base + t dir meets the circle (o, r)
// (intersection `second`). kappa = +1: internally tangent (the segment leaves the disk there),
// -1: externally; sigma = +1 when the fillet lies to the left of the line's direction.
Fillet fillet_at(const Fn& base, const Fn& dir, const Fn& o, const Fn& r, bool second, double kappa, double sigma,
                 const Fn& f) {
  const Fn side = sigma * f * normalize(rot90(dir));
  const Fn shifted = base + side;  // the line of fillet centers
  const Fn center_distance = r - kappa * f;
  const Fn center = shifted + line_circle(shifted, dir, o, center_distance, second) * dir;
  return {center - side, center, o + (center - o) * (r / center_distance)};
}

bool is_zero(const Fn& f) {
  double value = 1.0;
  return f.is_constant(&value) && value == 0.0;
}

}  // namespace

Path::Path(int coord) : coord_(coord) {
  if (coord < 0 || coord >= 64) detail::dimension_error("Path", "coordinate " + std::to_string(coord) + " out of range");
}

void Path::require_open(const char* op) const {
  if (closed_) detail::dimension_error(op, "the path is closed");
  if (!current_) detail::dimension_error(op, "no current point (call move_to first)");
}

void Path::require_point(const char* op, const char* what, const Fn& p) const {
  if (p.dim() != 2)
    detail::dimension_error(op, std::string(what) + " has dimension " + std::to_string(p.dim()) + ", expected 2");
  if ((p.input_mask() >> coord_) & 1U)
    detail::dimension_error(op, std::string(what) + " depends on the path coordinate x(" + std::to_string(coord_) + ")");
}

Fn Path::segment(const Fn& a, const Fn& b) const { return interp(x(coord_), a, b); }

// A rotation of (from - center) about center by the turning angle to (to - center) in the
// requested sense, the radius blended linearly so the arc ends exactly at `to` even when the
// two distances differ by rounding. atan2 gives the signed angle in (-pi, pi]; adding or
// subtracting 2 pi makes it go the requested way (the cut is 1e-9 past zero, so a numerically
// empty arc never becomes a full circle).
Fn Path::arc(const Fn& center, const Fn& from, const Fn& to, bool ccw) const {
  const Fn a = from - center, b = to - center;
  const Fn signed_angle = atan2(a[0] * b[1] - a[1] * b[0], dot(a, b));
  const Fn turn = ccw ? select(signed_angle < -1e-9, signed_angle + kTwoPi, signed_angle)
                      : select(signed_angle > 1e-9, signed_angle - kTwoPi, signed_angle);
  const Fn s = x(coord_);
  const Fn angle = s * turn;
  const Fn scale = 1.0 + s * (length(b) / length(a) - 1.0);
  return center + (cos(angle) * a + sin(angle) * rot90(a)) * scale;
}

void Path::move_to(const Fn& p) {
  require_point("Path::move_to", "the point", p);
  if (closed_ || !pieces_.empty() || current_) detail::dimension_error("Path::move_to", "the path is already started");
  start_ = current_ = p;
}

void Path::line_to(const Fn& p) {
  require_open("Path::line_to");
  require_point("Path::line_to", "the point", p);
  if (pieces_.empty()) {
    first_line_ = Line{*current_, p};
    first_end_ = p;
  }
  pieces_.push_back(segment(*current_, p));
  current_ = p;
  last_line_.reset();
}

void Path::line_to_arc(const Fn& p, const Fn& center, const Fn& radius, bool second, bool ccw, const Fn& fillet) {
  require_open("Path::line_to_arc");
  require_point("Path::line_to_arc", "the point", p);
  require_point("Path::line_to_arc", "the center", center);
  if (radius.dim() != 1 || fillet.dim() != 1) detail::dimension_error("Path::line_to_arc", "radius and fillet must be scalars");
  double fv = 0.0;
  if (fillet.is_constant(&fv) && fv < 0.0) detail::dimension_error("Path::line_to_arc", "negative fillet radius");
  const Fn base = *current_, dir = p - base;
  Fn end, next;
  std::optional<Fillet> round;
  if (is_zero(fillet)) {
    end = next = base + line_circle(base, dir, center, radius, second) * dir;
  } else {
    const double kappa = second ? 1.0 : -1.0;
    round = fillet_at(base, dir, center, radius, second, kappa, kappa * (ccw ? 1.0 : -1.0), fillet);
    end = round->on_line;
    next = round->on_circle;
  }
  if (pieces_.empty()) {
    first_line_ = Line{base, p};
    first_end_ = end;
  }
  pieces_.push_back(segment(base, end));
  if (round) pieces_.push_back(arc(round->center, end, next, second == ccw));
  current_ = next;
  last_line_.reset();
}

void Path::arc_to_line(const Fn& center, const Fn& radius, const Fn& p1, const Fn& p2, bool second, bool ccw,
                       const Fn& fillet) {
  require_open("Path::arc_to_line");
  require_point("Path::arc_to_line", "the center", center);
  require_point("Path::arc_to_line", "p1", p1);
  require_point("Path::arc_to_line", "p2", p2);
  if (radius.dim() != 1 || fillet.dim() != 1) detail::dimension_error("Path::arc_to_line", "radius and fillet must be scalars");
  double fv = 0.0;
  if (fillet.is_constant(&fv) && fv < 0.0) detail::dimension_error("Path::arc_to_line", "negative fillet radius");
  const Fn dir = p2 - p1;
  if (is_zero(fillet)) {
    const Fn end = p1 + line_circle(p1, dir, center, radius, second) * dir;
    pieces_.push_back(arc(center, *current_, end, ccw));
    current_ = end;
  } else {
    // Entering the disk along p1 -> p2 (first intersection) the fillet lies inside it.
    const double kappa = second ? -1.0 : 1.0;
    const double sigma = kappa * (ccw ? 1.0 : -1.0);
    const Fillet round = fillet_at(p1, dir, center, radius, second, kappa, sigma, fillet);
    pieces_.push_back(arc(center, *current_, round.on_circle, ccw));
    pieces_.push_back(arc(round.center, round.on_circle, round.on_line, sigma > 0));
    current_ = round.on_line;
  }
  last_line_ = Line{p1, p2};
}

void Path::close() {
  require_open("Path::close");
  if (pieces_.empty()) detail::dimension_error("Path::close", "the path has no pieces");
  if (last_line_ && first_line_ && identical(last_line_->from, first_line_->from) &&
      identical(last_line_->to, first_line_->to)) {
    pieces_.front() = segment(*current_, first_end_);
  } else if (!identical(*current_, *start_)) {
    pieces_.push_back(segment(*current_, *start_));
  }
  closed_ = true;
}

Fn Path::curve(const Fn& in) const {
  if (pieces_.empty()) detail::dimension_error("Path::curve", "the path has no pieces");
  if (in.dim() != 1) detail::dimension_error("Path::curve", "the parameter must be scalar");
  return concat(coord_, in, pieces_);
}

std::size_t Path::pieces() const { return pieces_.size(); }

Fn mirror_x(const Fn& half, int parm) {
  if (half.dim() != 2)
    detail::dimension_error("mirror_x", "the half path has dimension " + std::to_string(half.dim()) + ", expected 2");
  if (parm < 0 || parm >= 64) detail::dimension_error("mirror_x", "parameter index " + std::to_string(parm) + " out of range");
  const Fn s = x(parm);
  const Fn back = compose(half, parm, 1.0 - s);
  return concat(parm, s, {half, cat({-back[0], back[1]})});
}

}  // namespace genmod
