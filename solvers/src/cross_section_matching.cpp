#include "genmod/solvers/cross_section_matching.hpp"

#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/operators/integrate.hpp"
#include "genmod/operators/periodic.hpp"
#include "genmod/solvers/inverse_operator.hpp"
#include "genmod/solvers/minimize_operator.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace genmod {
namespace {

[[noreturn]] void fail(const char* op, const std::string& what) {
  throw std::invalid_argument(std::string("genmod: ") + op + ": " + what);
}

void require_curve(const char* op, const Fn& c, const char* name, int parm, std::size_t dim) {
  if (parm < 0 || parm >= kMaxInputs)
    fail(op, "parameter " + std::to_string(parm) + " is outside [0, " + std::to_string(kMaxInputs) + ")");
  if (dim != 0 && c.dim() != dim)
    fail(op, std::string(name) + " has dimension " + std::to_string(c.dim()) + ", expected " + std::to_string(dim));
  if (!(c.input_mask() >> parm & 1u)) fail(op, std::string(name) + " does not depend on x(" + std::to_string(parm) + ")");
}

// The unwrapped polar angle's increase since u = 0 as a fraction of its total: 0 at u = 0, 1 at
// u = 1, increasing for a star-shaped CCW curve. The integrand is d(theta)/du, which has no
// branch cut (atan2 alone jumps by 2 pi where the curve crosses the negative x axis).
Fn turn_fraction(const Fn& c, int parm) {
  const Fn d = derivative(c, parm);
  const Fn omega = (c[0] * d[1] - c[1] * d[0]) / (square(c[0]) + square(c[1]));
  const Fn turned = integrate(omega, Fn(0.0), x(parm), parm);
  return turned / compose(turned, parm, Fn(1.0));
}

}  // namespace

Fn match_polar_angle(const Fn& c1, const Fn& c2, int parm) {
  constexpr const char* op = "match_polar_angle";
  require_curve(op, c1, "c1", parm, 2);
  require_curve(op, c2, "c2", parm, 2);
  constexpr double kTurn = 2.0 * std::numbers::pi;
  const Fn start1 = compose(atan2(c1[1], c1[0]), parm, Fn(0.0));
  const Fn start2 = compose(atan2(c2[1], c2[0]), parm, Fn(0.0));
  // c2's angle, as a fraction of a turn measured from c1's start, reduced into [0, 1).
  const Fn target = (start2 - start1) / kTurn + turn_fraction(c2, parm);
  const Fn reduced = target - floor(target);
  const Fn s = inverse(turn_fraction(c1, parm), reduced, parm);
  return compose(c1, parm, s);
}

namespace {

// The squared distance between inner at the search coordinate and outer (a smooth objective
// with the distance's minimizers).
Fn squared_distance(const Fn& candidate, const Fn& outer) {
  Fn squared = Fn(0.0);
  for (std::size_t j = 0; j < candidate.dim(); ++j) squared += square(candidate[j] - outer[j]);
  return squared;
}

}  // namespace

Fn reparameterize_to_closest(const Fn& inner, const Fn& outer, int parm, double epsilon) {
  constexpr const char* op = "reparameterize_to_closest";
  require_curve(op, inner, "inner", parm, 0);
  require_curve(op, outer, "outer", parm, inner.dim());
  if (!std::isfinite(epsilon) || epsilon <= 0.0) fail(op, "epsilon must be finite and > 0");
  // The search variable: the lowest coordinate neither curve uses (parm is outer's, and free).
  const std::uint64_t used = inner.input_mask() | outer.input_mask();
  if (used == ~std::uint64_t{0}) fail(op, "no free coordinate left for the search variable");
  const int s = std::countr_one(used);
  const int unknowns[] = {s};
  const Fn closest = minimize_operator(squared_distance(compose(inner, parm, x(s)), outer), Fn(1.0), unknowns,
                                       Box{Interval(0.0, 1.0)}, epsilon);
  if (!(is_closed_curve(inner, parm) && is_closed_curve(outer, parm)))
    return compose(inner, parm, closest);
  // Closed curves: s*(u) goes once around inner as u goes around outer, so on [0, 1] it jumps
  // from 1 to 0 somewhere, and there the closest points near s = 0 and near s = 1 tie. The search
  // follows u instead: s = u + c + t with t in [-1/2, 1/2] and c = s*(0), inner wrapped around
  // its seam, so t*(u) stays inside its range and is continuous while the closest point stays
  // within half a turn of u + c (the minimize operator then certifies it unique). inner is
  // continued periodically (periodic.hpp) so that the derivative enclosures the certificate
  // needs stay tight where the closest point crosses inner's seam.
  const double c = evaluate(compose(closest, parm, Fn(0.0)), std::vector<double>{})[0];
  if (!std::isfinite(c)) return compose(inner, parm, closest);
  const Fn along = x(parm) + c + x(s);
  const Fn offset = minimize_operator(squared_distance(periodic(inner, parm, along), outer), Fn(1.0), unknowns,
                                      Box{Interval(-0.5, 0.5)}, epsilon);
  return periodic(inner, parm, x(parm) + c + offset);
}

}  // namespace genmod
