// Matching interpolated cross sections (thesis Fig 3.10, research/snyder.md 7.12): a surface
// between two closed curves by linear interpolation of cross sections, S(u, v) =
// (interp(v, inner(u), outer(u)), height v). The curves' parameterizations do not match
// (models/curves/matching_{inner,outer}.crv start half a turn apart), so plain
// interpolation collapses the sections through the middle; `method` picks the remedy:
//   0: none (the mismatch, for comparison);
//   1: the inner curve reparameterized to the polar angle of the outer (inverse operator);
//   2: minimum distance: inner(s*(u)) with s*(u) the closest point of the inner curve to
//      outer(u) (global minimization operator), as in the figure.
#include "genmod/models/gallery.hpp"
#include "genmod/operators/higher_order.hpp"
#include "genmod/solvers/cross_section_matching.hpp"
#include "model_definitions.hpp"

#include <stdexcept>
#include <string>

namespace genmod::models {

Fn matching_inner(const ParameterValues& p) {
  const double method = detail::param(p, "method");
  const Fn inner = gallery_curve("matching_inner")(x(0)), outer = gallery_curve("matching_outer")(x(0));
  if (method == 0.0) return inner;
  if (method == 1.0) return match_polar_angle(inner, outer, 0);
  if (method == 2.0) return reparameterize_to_closest(inner, outer, 0);
  throw std::invalid_argument("parameter 'method' must be 0 (none), 1 (polar angle) or 2 (minimum distance), got " +
                              std::to_string(method));
}

namespace detail {

Model cross_section_matching_model() {
  Model m;
  m.name = "cross_section_matching";
  m.description = "thesis Fig 3.10: interpolation between two closed curves with the inner curve matched to the outer";
  m.parameters = {{"method", 2.0, "0 = no matching, 1 = polar angle (inverse), 2 = minimum distance (minimize)"},
                  {"height", 0.5, "height of the outer curve (the inner one is at 0)"}};
  m.build = [](const ParameterValues& p) {
    const double height = require_positive(p, "height");
    const Fn outer = gallery_curve("matching_outer")(x(0));
    const Fn section = interp(x(1), matching_inner(p), outer);
    return cat({section, height * x(1)});
  };
  m.periodic_u = true;
  m.open = true;  // a band between the two curves, open at both of them
  return m;
}

}  // namespace detail
}  // namespace genmod::models
