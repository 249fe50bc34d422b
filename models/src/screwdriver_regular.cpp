// Regular screwdriver tip (thesis Fig 3.17, App. B.2, research/snyder.md 7.18): CPG, a disk
// minus two half-planes, built with the thesis's path builder:
//   w = m_interp(v, 0.015, 0.75); p0 = (w/2, -1); p1 = (w/2, 1); p2 = (-w/2, 1); p3 = (-w/2, -1);
//   newpath(0); moveto(p0);
//   lineto_arc(p1, o, r, 0, 1, fillet);  arcto_line(o, r, p2, p3, 1, 1, fillet);
//   lineto_arc(p3, o, r, 0, 1, fillet);  arcto_line(o, r, p0, p1, 1, 1, fillet);
//   closepath();
//   regular = (getpath(u), m_interp(v, 0, 1));
// The section at height z = v is {|x| <= w(v)/2} intersected with the disk of radius r: two
// vertical chords joined by two arcs; the blade is thinnest (tip_width) at the tip z = 0.
#include "genmod/models/gallery.hpp"
#include "genmod/operators/higher_order.hpp"
#include "genmod/operators/path.hpp"
#include "model_definitions.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace genmod::models {

Fn screwdriver_regular_section(const ParameterValues& p) {
  const double tip = detail::require_positive(p, "tip_width");
  const double blade = detail::require_positive(p, "blade_width");
  const double radius = detail::require_positive(p, "radius");
  const double fillet = detail::param(p, "fillet");
  if (!(std::max(tip, blade) < 2.0 * radius))
    throw std::invalid_argument("parameters 'tip_width' and 'blade_width' must be < 2 radius (the blade is cut "
                                "from the disk), got " + std::to_string(tip) + " and " + std::to_string(blade) +
                                " with radius " + std::to_string(radius));
  if (!(fillet >= 0.0 && fillet < std::min(tip, blade) / 2.0))
    throw std::invalid_argument("parameter 'fillet' must be in [0, min(tip_width, blade_width) / 2), got " +
                                std::to_string(fillet));
  const Fn v = x(1);
  const Fn o = cat({Fn(0.0), Fn(0.0)}), r(radius), f(fillet);
  const Fn w = interp(v, Fn(tip), Fn(blade));
  const Fn p0 = cat({w / 2.0, Fn(-1.0)}), p1 = cat({w / 2.0, Fn(1.0)});
  const Fn p2 = cat({-w / 2.0, Fn(1.0)}), p3 = cat({-w / 2.0, Fn(-1.0)});
  // The thesis's `min` flag is 0 for lineto_arc (the segment runs through the disk and ends
  // where it leaves it: the second intersection) and 1 for arcto_line (the arc ends where the
  // next side's segment enters the disk: the first intersection).
  // The thesis starts at p0 = (w/2, -1), outside the disk; the last arc ends on the line
  // p0 -> p1 it started on, so Path::close() drops that excursion (operators/path.hpp) and
  // the curve is exactly the section's boundary.
  Path path(0);
  path.move_to(p0);
  path.line_to_arc(p1, o, r, /*second=*/true, /*ccw=*/true, f);
  path.arc_to_line(o, r, p2, p3, /*second=*/false, /*ccw=*/true, f);
  path.line_to_arc(p3, o, r, /*second=*/true, /*ccw=*/true, f);
  path.arc_to_line(o, r, p0, p1, /*second=*/false, /*ccw=*/true, f);
  path.close();
  return path.curve(x(0));
}

namespace detail {

Model screwdriver_regular_model() {
  Model m;
  m.name = "screwdriver_regular";
  m.open = true;  // a surface with a boundary, as in the thesis, not a closed object
  m.description = "thesis Fig 3.17 / App. B.2: regular screwdriver tip, a disk minus two half-planes (CPG path)";
  m.parameters = {{"tip_width", 0.015, "blade width at the tip (z = 0), < 2 radius"},
                  {"blade_width", 0.75, "blade width at z = 1 (the width is linear in z), < 2 radius"},
                  {"radius", 0.5, "radius of the shank's disk"},
                  {"fillet", 0.0, "radius of the fillets between the flats and the arcs, in [0, min width / 2)"}};
  m.build = [](const ParameterValues& p) {
    const Fn section = screwdriver_regular_section(p);
    return cat({section[0], section[1], x(1)});
  };
  m.periodic_u = true;
  return m;
}

}  // namespace detail
}  // namespace genmod::models
