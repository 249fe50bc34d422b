#include "genmod/operators/warp.hpp"

#include "dims.hpp"

#include <string>

namespace genmod {

Fn warp_z_by_x(const Fn& cross, const Fn& a, const Fn& b) {
  if (cross.dim() != 3)
    detail::dimension_error("warp_z_by_x", "the cross section has dimension " + std::to_string(cross.dim()) + ", expected 3");
  if (a.dim() != 1 || b.dim() != 1) detail::dimension_error("warp_z_by_x", "a and b must be scalars");
  return cat({cross[0], cross[1], cross[2] + a * square(cross[0]) + b});
}

}  // namespace genmod
