// Offsets (thesis Fig 3.11, research/snyder.md 7.13): a smooth closed curve and the family of
// its offsets, swept into one surface:
//   S(u, v) = (offset(c, r(v))(u), r(v)),  r(v) = interp(v, -r_max, r_max),
// so every level z = r is the offset of c by r (the curve itself at z = 0). The thesis's
// normal (erratum E5, operators/offset.hpp): a positive r moves the counterclockwise curve
// inward, a negative one outward. The curve is models/curves/offsets_curve.crv, a bean with
// a concave dent; offsets stay smooth while |r| is below its smallest radius of curvature
// (about 0.37), beyond which they would cusp and self-intersect (Fig 3.11's warning).
#include "genmod/models/gallery.hpp"
#include "genmod/operators/higher_order.hpp"
#include "genmod/operators/offset.hpp"
#include "model_definitions.hpp"

#include <stdexcept>
#include <string>

namespace genmod::models {

namespace {
constexpr double kMaxOffset = 0.35;  // below the curve's smallest radius of curvature (~0.37)
}

Curve offsets_curve(const ParameterValues&) { return gallery_curve("offsets_curve"); }

Fn offsets_surface(const Fn& curve, double r_max) {
  const Fn r = interp(x(1), Fn(-r_max), Fn(r_max));
  const Fn offset = offset_curve(curve, r, 0);
  return cat({offset[0], offset[1], r});
}

namespace detail {

Model offsets_model() {
  Model m;
  m.name = "offsets";
  m.open = true;  // a surface with a boundary, as in the thesis, not a closed object
  m.description = "thesis Fig 3.11: a smooth closed curve and its offsets by r in [-r_max, r_max] (z = r)";
  m.parameters = {{"r_max", 0.25,
                   "largest offset distance (the thesis shows 0.1 and 0.25), in (0, 0.35]: "
                   "z = r runs from -r_max (outward) to +r_max (inward)"}};
  m.build = [](const ParameterValues& p) {
    const double r_max = require_positive(p, "r_max");
    if (r_max > kMaxOffset)
      throw std::invalid_argument("parameter 'r_max' must be <= 0.35 (the curve's smallest radius of "
                                  "curvature is about 0.37), got " + std::to_string(r_max));
    return offsets_surface(offsets_curve(p)(x(0)), r_max);
  };
  m.periodic_u = true;
  return m;
}

}  // namespace detail
}  // namespace genmod::models
