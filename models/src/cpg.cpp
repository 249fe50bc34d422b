// CPG, Boolean operations on planar cross sections (thesis Fig 3.16 and 3.18,
// research/snyder.md 7.17 and 7.19): a circle and a bean-shaped region
// (models/curves/cpg_bean.crv) combined by union, intersection or difference, the result's
// boundary split at the certified boundary intersections and concatenated into one closed
// curve, then extruded into a prism wall. `cpg_fillet` rounds the corners of the result with
// circular fillets (offset curves intersected).
#include "genmod/models/gallery.hpp"
#include "genmod/solvers/cpg.hpp"
#include "model_definitions.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace genmod::models {

namespace {

RegionOp region_op(const ParameterValues& p) {
  const double op = detail::param(p, "operation");
  if (op == 0.0) return RegionOp::Union;
  if (op == 1.0) return RegionOp::Intersection;
  if (op == 2.0) return RegionOp::Difference;
  throw std::invalid_argument("parameter 'operation' must be 0 (union), 1 (intersection) or 2 (circle minus bean), got " +
                              std::to_string(op));
}

Fn prism(const Fn& boundary, const ParameterValues& p) {
  const double height = detail::require_positive(p, "height");
  return cat({compose(boundary, 0, x(0)), height * x(1)});
}

// `first`, then the parameters of the two regions and the extrusion.
std::vector<ModelParameter> region_parameters(ModelParameter first) {
  return {std::move(first),
          {"radius", 0.5, "radius of the circle (centered at the origin)"},
          {"shift", 0.0, "x translation of the bean region (it overlaps the circle near x = 0.5)"},
          {"height", 0.3, "height of the extruded wall"}};
}

}  // namespace

Fn cpg_circle(const ParameterValues& p) {
  const double r = detail::require_positive(p, "radius");
  const Fn a = (2.0 * std::numbers::pi) * x(0);
  return cat({r * cos(a), r * sin(a)});
}

Fn cpg_bean(const ParameterValues& p) {
  const Fn bean = gallery_curve("cpg_bean")(x(0));
  return bean + cat({Fn(detail::param(p, "shift")), Fn(0.0)});
}

Fn cpg_boundary(const ParameterValues& p) {
  CpgOptions options;
  if (const auto it = p.find("fillet_radius"); it != p.end()) options.fillet_radius = detail::require_positive(p, "fillet_radius");
  const RegionOp op = p.count("operation") ? region_op(p) : RegionOp::Union;
  return region_boolean(cpg_circle(p), cpg_bean(p), op, options);
}

namespace detail {

Model cpg_model() {
  Model m;
  m.name = "cpg";
  m.open = true;  // a surface with a boundary, as in the thesis, not a closed object
  m.description = "thesis Fig 3.16: Boolean operation on planar regions (circle, bean), extruded";
  m.parameters = region_parameters({"operation", 2.0, "0 = union, 1 = intersection, 2 = circle minus bean"});
  m.build = [](const ParameterValues& p) { return prism(cpg_boundary(p), p); };
  m.periodic_u = true;
  return m;
}

Model cpg_fillet_model() {
  Model m;
  m.name = "cpg_fillet";
  m.open = true;  // a surface with a boundary, as in the thesis, not a closed object
  m.description = "thesis Fig 3.18: union of the CPG regions with circular fillets at the corners, extruded";
  m.parameters = region_parameters({"fillet_radius", 0.08, "radius of the fillet arcs (> 0)"});
  m.build = [](const ParameterValues& p) { return prism(cpg_boundary(p), p); };
  m.periodic_u = true;
  return m;
}

}  // namespace detail
}  // namespace genmod::models
