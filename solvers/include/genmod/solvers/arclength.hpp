// Reparameterization by arclength (snyder.md section 2.5, GENMOD's
// m_reparameterize_by_arclength): the same curve, traced at constant speed over [0, 1].
//
// Example:
//   const double pi = std::numbers::pi;
//   Fn theta = (pi / 4) * (x(0) + square(x(0)));
//   Fn gamma = cat({cos(theta), sin(theta)});           // a quarter circle, nonuniform speed
//   Fn even = reparameterize_by_arclength(gamma, 0);     // (cos(pi s / 2), sin(pi s / 2))
//
// With L(u) = integral_0^u |gamma'(t)| dt over the curve's domain [0, 1], the result is
// gamma(u(s)) where u(s) solves L(u) / L(1) = s (the inverse operator). It lives in the
// solvers layer because `inverse` does. Point values, inclusions and derivatives come from
// the integrate and inverse operators, so it nests like any other function. The curve's speed
// must not vanish on a subinterval (L must be strictly increasing).
#pragma once

#include "genmod/kernel/fn.hpp"

namespace genmod {

// gamma is a function of x(parameter) (and possibly of other coordinates, which stay free).
// Throws std::invalid_argument if gamma does not depend on x(parameter).
Fn reparameterize_by_arclength(const Fn& gamma, int parameter);

}  // namespace genmod
