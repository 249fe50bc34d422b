#include "genmod/solvers/arclength.hpp"

#include "genmod/operators/integrate.hpp"
#include "genmod/operators/vector.hpp"
#include "genmod/solvers/inverse_operator.hpp"

#include <stdexcept>
#include <string>

namespace genmod {

Fn reparameterize_by_arclength(const Fn& gamma, int parameter) {
  if (parameter < 0 || parameter >= kMaxInputs || !(gamma.input_mask() >> parameter & 1u))
    throw std::invalid_argument("genmod: reparameterize_by_arclength: the curve does not depend on x(" +
                                std::to_string(parameter) + ")");
  const Fn t = x(parameter);
  const Fn speed = length(derivative(gamma, parameter));
  // L(x_p) = integral_0^{x_p} speed; normalized so that the whole curve has length 1.
  const Fn arclength = integrate(speed, Fn(0.0), t, parameter);
  const Fn total = compose(arclength, parameter, Fn(1.0));
  // u(s): L(u) / L(1) = s, where s is the outer value of x(parameter).
  const Fn u = inverse(arclength / total, t, parameter);
  return compose(gamma, parameter, u);
}

}  // namespace genmod
