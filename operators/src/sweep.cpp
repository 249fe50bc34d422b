#include "genmod/operators/sweep.hpp"

#include "dims.hpp"
#include "genmod/operators/higher_order.hpp"
#include "genmod/operators/vector.hpp"

#include <string>

namespace genmod {

using detail::require_dim;

Fn curve_in(const Fn& curve, int parm) {
  if (parm < 0 || parm >= 64) detail::dimension_error("curve_in", "parameter index " + std::to_string(parm) + " out of range");
  if ((curve.input_mask() & ~std::uint64_t{1}) != 0)
    detail::dimension_error("curve_in", "the curve depends on coordinates other than x(0)");
  if (parm == 0) return curve;
  return compose(curve, 0, x(parm));
}

Fn profile_product(const Fn& cross, const Fn& profile) {
  require_dim("profile_product", "the cross section", cross, 2);
  require_dim("profile_product", "the profile", profile, 2);
  return cat({cross[0] * profile[0], cross[1] * profile[0], profile[1]});
}

Fn wire_product(const Fn& cross, const Fn& wire, int wire_parm) {
  require_dim("wire_product", "the cross section", cross, 2);
  require_dim("wire_product", "the wire", wire, 2);
  if (wire_parm < 0 || wire_parm >= 64 || ((wire.input_mask() >> wire_parm) & 1U) == 0)
    detail::dimension_error("wire_product", "the wire does not depend on x(" + std::to_string(wire_parm) + ")");
  const Fn t = normalize(derivative(wire, wire_parm));
  const Fn n = cat({-t[1], t[0]});
  const Fn xy = n * cross[0] + wire;
  return cat({xy[0], xy[1], cross[1]});
}

Fn rail_product(const Fn& cross, const Fn& rail1, const Fn& rail2) {
  require_dim("rail_product", "the cross section", cross, 2);
  require_dim("rail_product", "rail1", rail1, 2);
  require_dim("rail_product", "rail2", rail2, 2);
  const Fn t = rail2 - rail1;
  const Fn m = 0.5 * (rail1 + rail2);
  const Fn xy = 0.5 * t * cross[0] + m;
  return cat({xy[0], xy[1], cross[1]});
}

Fn quasi_linear(const Fn& cross, const Matrix& m, const Fn& t) {
  if (m.rows() != 3 || m.cols() != 3)
    detail::dimension_error("quasi_linear", "the matrix is " + std::to_string(m.rows()) + "x" + std::to_string(m.cols()) +
                                                ", expected 3x3");
  require_dim("quasi_linear", "the offset", t, 3);
  Fn p;
  if (cross.dim() == 3) p = cross;
  else if (cross.dim() == 2) p = cat({cross, 0.0});
  else detail::dimension_error("quasi_linear", "the cross section has dimension " + std::to_string(cross.dim()) + ", expected 2 or 3");
  return m * p + t;
}

Matrix homogeneous(const Matrix& m, const Fn& t) {
  if (m.rows() != 3 || m.cols() != 3)
    detail::dimension_error("homogeneous", "the matrix is " + std::to_string(m.rows()) + "x" + std::to_string(m.cols()) +
                                               ", expected 3x3");
  require_dim("homogeneous", "the offset", t, 3);
  const Fn a = m.fn();
  return Matrix(cat({a[0], a[1], a[2], t[0], a[3], a[4], a[5], t[1], a[6], a[7], a[8], t[2], 0.0, 0.0, 0.0, 1.0}), 4, 4);
}

Fn interp_cross_sections(const Fn& alpha, const Fn& c1, const Fn& c2) {
  require_dim("interp_cross_sections", "alpha", alpha, 1);
  detail::require_same_dim("interp_cross_sections", c1.dim(), c2.dim());
  return interp(alpha, c1, c2);
}

Fn hermite_cross_sections(const Fn& alpha, const Fn& p1, const Fn& p2, const Fn& t1, const Fn& t2) {
  require_dim("hermite_cross_sections", "alpha", alpha, 1);
  detail::require_same_dim("hermite_cross_sections", p1.dim(), p2.dim());
  detail::require_same_dim("hermite_cross_sections", p1.dim(), t1.dim());
  detail::require_same_dim("hermite_cross_sections", p1.dim(), t2.dim());
  return hermite_interp(alpha, p1, p2, t1, t2);
}

Fn profile_surface(const Fn& cross, const Fn& profile) {
  return profile_product(curve_in(cross, 0), curve_in(profile, 1));
}

Fn wire_surface(const Fn& cross, const Fn& wire) { return wire_product(curve_in(cross, 0), curve_in(wire, 1), 1); }

Fn rail_surface(const Fn& cross, const Fn& rail1, const Fn& rail2) {
  return rail_product(curve_in(cross, 0), curve_in(rail1, 1), curve_in(rail2, 1));
}

Fn interp_surface(const Fn& c1, const Fn& c2, const Fn& height) {
  require_dim("interp_surface", "c1", c1, 2);
  require_dim("interp_surface", "c2", c2, 2);
  require_dim("interp_surface", "the height", height, 1);
  return cat({interp_cross_sections(x(1), curve_in(c1, 0), curve_in(c2, 0)), curve_in(height, 1)});
}

}  // namespace genmod
