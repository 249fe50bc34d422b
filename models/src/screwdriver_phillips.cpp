// Phillips screwdriver tip (thesis Fig 3.17, App. B.2, research/snyder.md 7.18): CPG, a disk
// whose radius shrinks toward the tip minus four 90-degree wedges whose vertices move toward
// the centre. The path traces the x >= 0 half and m_mirrorx completes it:
//   r = m_crv("radius.crv", v)[1]; depth = m_crv("depth.crv", v);
//   p = (depth[1], 0); p1 = (0, p[0]); p2 = (0, -p[0]);
//   d1 = (cos 45, sin 45); d2 = (d1[0], -d1[1]); d0 = (d1[1], d1[0]); d3 = (d1[1], -d1[0]);
//   newpath(0); moveto(p2);
//   lineto_arc(p2 + d3, o, r, 0, 1, fillet); arcto_line(o, r, p + d2, p, 1, 1, fillet);
//   lineto(p);
//   lineto_arc(p + d1, o, r, 0, 1, fillet);  arcto_line(o, r, p1 + d0, p1, 1, 1, fillet);
//   lineto(p1);
//   phillips = (m_mirrorx(getpath(u)), depth[0]);
// (As printed, the wedge vertex is p = (depth[1], 0) and p1 = (0, p[0]) = (0, D) as intended.)
// The curves are models/curves/screwdriver_phillips_{radius,depth}.crv.
#include "genmod/models/gallery.hpp"
#include "genmod/operators/path.hpp"
#include "model_definitions.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace genmod::models {

namespace {
double depth_scale(const ParameterValues& p) {
  const double s = detail::require_positive(p, "depth_scale");
  if (!(s <= 1.5))
    throw std::invalid_argument("parameter 'depth_scale' must be in (0, 1.5] (the wedges must stay inside the "
                                "disk), got " + std::to_string(s));
  return s;
}
}  // namespace

Fn screwdriver_phillips_radius(const ParameterValues&) { return gallery_curve("screwdriver_phillips_radius")(x(1))[1]; }

Fn screwdriver_phillips_depth(const ParameterValues& p) {
  return gallery_curve("screwdriver_phillips_depth")(x(1))[1] * depth_scale(p);
}

Fn screwdriver_phillips_section(const ParameterValues& p) {
  const Fn o = cat({Fn(0.0), Fn(0.0)});
  const Fn r = screwdriver_phillips_radius(p);
  const Fn depth = screwdriver_phillips_depth(p);
  const Fn pv = cat({depth, Fn(0.0)}), p1 = cat({Fn(0.0), depth}), p2 = cat({Fn(0.0), -depth});
  const double c = std::sqrt(0.5);  // cos and sin of theta / 2 = 45 degrees
  const Fn d1 = cat({Fn(c), Fn(c)}), d2 = cat({Fn(c), Fn(-c)}), d0 = cat({Fn(c), Fn(c)}), d3 = cat({Fn(c), Fn(-c)});
  const Fn fillet(0.0);
  Path path(0);
  path.move_to(p2);
  path.line_to_arc(p2 + d3, o, r, /*second=*/true, /*ccw=*/true, fillet);
  path.arc_to_line(o, r, pv + d2, pv, /*second=*/false, /*ccw=*/true, fillet);
  path.line_to(pv);
  path.line_to_arc(pv + d1, o, r, /*second=*/true, /*ccw=*/true, fillet);
  path.arc_to_line(o, r, p1 + d0, p1, /*second=*/false, /*ccw=*/true, fillet);
  path.line_to(p1);
  return mirror_x(path.curve(x(0)), 0);
}

namespace detail {

Model screwdriver_phillips_model() {
  Model m;
  m.name = "screwdriver_phillips";
  m.open = true;  // a surface with a boundary, as in the thesis, not a closed object
  m.description = "thesis Fig 3.17 / App. B.2: Phillips tip, a shrinking disk minus four 90-degree wedges (CPG path, mirrored)";
  m.parameters = {{"depth_scale", 1.0, "multiplies the wedge-vertex distance D (depth curve), in (0, 1.5]"},
                  {"length", 1.0, "multiplies the height z of the sections (the tip is at z = 0)"}};
  m.build = [](const ParameterValues& p) {
    const double length = require_positive(p, "length");
    const Fn section = screwdriver_phillips_section(p);
    return cat({section[0], section[1], gallery_curve("screwdriver_phillips_depth")(x(1))[0] * length});
  };
  m.periodic_u = true;
  return m;
}

}  // namespace detail
}  // namespace genmod::models
