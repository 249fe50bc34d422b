// Briefcase handle (thesis Fig 3.5, research/snyder.md 7.6): the rail product of a rounded
// grip cross section between two nested arch rails:
//   cross = m_crv("cross.crv", m_x(0));
//   rail1 = m_crv("rail1.crv", m_x(1)); rail2 = m_crv("rail2.crv", m_x(1));
//   handle = m_rail(cross, rail1, rail2);
// Substitute curves (curves/briefcase_handle_*.crv): a closed Hermite grip profile with x in
// [-1, 1] and two Catmull-Rom arches with matched parameters (rail1 outer, rail2 inner). The
// cross section's x runs from rail1 (x = -1) to rail2 (x = +1); its y is world z.
#include "genmod/models/gallery.hpp"
#include "genmod/operators/sweep.hpp"
#include "model_definitions.hpp"

namespace genmod::models {

namespace {
Fn scaled_rail(const ParameterValues& p, const char* name) {
  const double width = detail::require_positive(p, "width");
  const double height = detail::require_positive(p, "height");
  const Fn r = gallery_curve(name)(x(0));
  return cat({r[0] * (width / 2.0), r[1] * height});
}
}  // namespace

Fn briefcase_handle_cross(const ParameterValues& p) {
  const double depth = detail::require_positive(p, "depth");
  const Fn c = gallery_curve("briefcase_handle_cross")(x(0));
  return cat({c[0], c[1] * (depth / 2.0)});
}

Fn briefcase_handle_rail1(const ParameterValues& p) { return scaled_rail(p, "briefcase_handle_rail1"); }
Fn briefcase_handle_rail2(const ParameterValues& p) { return scaled_rail(p, "briefcase_handle_rail2"); }

namespace detail {

Model briefcase_handle_model() {
  Model m;
  m.name = "briefcase_handle";
  m.open = true;  // a surface with a boundary, as in the thesis, not a closed object
  m.description = "thesis Fig 3.5: rail product of a rounded grip cross section between two nested arch rails";
  m.parameters = {{"width", 2.0, "span of the outer arch along x (the inner arch spans 0.76 of it)"},
                  {"height", 1.0, "height of the outer arch along y (the inner arch reaches 0.72 of it)"},
                  {"depth", 0.3, "thickness of the grip along z"}};
  m.build = [](const ParameterValues& p) {
    return rail_product(briefcase_handle_cross(p), curve_in(briefcase_handle_rail1(p), 1),
                        curve_in(briefcase_handle_rail2(p), 1));
  };
  m.periodic_u = true;
  return m;
}

}  // namespace detail
}  // namespace genmod::models
