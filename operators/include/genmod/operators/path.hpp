// The CPG path builder of thesis App. B.2 (research/snyder.md sections 7.17-7.19): planar paths
// of straight segments and circular arcs whose points are Fns (they may depend on the sweep
// parameter, e.g. a slot width w(v)), finished into one curve by uniform concatenation.
// Line / circle intersections are analytic (the quadratic formula) and arcs are rotations of
// the start radius by a turning angle from atan2, so the finished curve is an ordinary Fn:
// points, inclusions and derivatives come from the kernel.
//
// Example:
//   Fn w = 0.4 + 0.2 * x(1);                       // slot width, a function of v = x(1)
//   Fn o = cat({0.0, 0.0});                        // the disk's center
//   Path p;                                        // a curve of x(0)
//   p.move_to(cat({w / 2, -1.0}));                 // outside the disk: see close()
//   p.line_to_arc(cat({w / 2, 1.0}), o, 0.5, true, true);
//   p.arc_to_line(o, 0.5, cat({-w / 2, 1.0}), cat({-w / 2, -1.0}), false, true);
//   p.line_to_arc(cat({-w / 2, -1.0}), o, 0.5, true, true);
//   p.arc_to_line(o, 0.5, cat({w / 2, -1.0}), cat({w / 2, 1.0}), false, true);
//   p.close();
//   Fn tip = cat({p.curve(x(0)), x(1)});          // {|x| <= w/2} intersected with the disk
//
// Choices where the thesis is silent ([MISSING] in section 7.18):
//  * `second`: the thesis's `min` flag inverted. Along the line's direction the circle is met
//    twice, at t1 <= t2; second = false takes t1 (where the line enters the disk), second = true
//    takes t2 (where it leaves). The thesis's min = 1 is second = false, min = 0 is second = true.
//  * move_to outside the circle: the path starts at the move_to point, and close() drops that
//    excursion when the path ends on the line it started on (see close()).
//  * Fillets: at a corner between a segment and the circle the fillet is the circle of radius
//    f tangent to both on the side the path turns to: internally tangent (center at distance
//    R - f from the circle's center) where the segment leaves the disk, externally tangent
//    (R + f) where it enters. The path runs segment -> fillet arc -> arc (or arc -> fillet arc
//    -> the next segment along the line). A fillet larger than the geometry allows is an
//    error (NaN). A non-constant fillet must be > 0 everywhere.
//  * Arcs turn by at most a full circle; an arc whose end coincides with its start (to 1e-9
//    radians, on the wrong side) is taken as empty, never as a full turn.
// The points must not depend on x(coord). Misuse (drawing before move_to, drawing after
// close(), wrong dimensions, a negative constant fillet) throws std::invalid_argument naming
// Path and the problem.
#pragma once

#include "genmod/kernel/fn.hpp"

#include <cstddef>
#include <optional>
#include <vector>

namespace genmod {

class Path {
 public:
  // newpath(coord): the pieces are functions of x(coord) in [0, 1].
  explicit Path(int coord = 0);

  // The start point. Only once, before any piece (one path is one curve).
  void move_to(const Fn& p);
  // A segment from the current point to p.
  void line_to(const Fn& p);
  // A segment from the current point toward p ending where it meets the circle (center,
  // radius): the first or `second` intersection along the direction current -> p. `ccw` is the
  // sense of the arc that follows (it decides the side of the fillet). fillet > 0 rounds the
  // corner with a fillet of that radius, 0 keeps it sharp; the current point is then the
  // fillet's tangent point on the circle.
  void line_to_arc(const Fn& p, const Fn& center, const Fn& radius, bool second, bool ccw, const Fn& fillet = Fn(0.0));
  // An arc of the circle (center, radius) in sense ccw from the current point (on the circle)
  // to where the line p1 -> p2 meets the circle (first or `second` intersection along
  // p1 -> p2); with a fillet, the arc ends at the fillet, which ends on the line. The current
  // point is the end on the line, so the next segment runs along p1 -> p2.
  void arc_to_line(const Fn& center, const Fn& radius, const Fn& p1, const Fn& p2, bool second, bool ccw,
                   const Fn& fillet = Fn(0.0));
  // closepath: a segment back to the first point, unless the current point is that point (the
  // same function). When the last call was arc_to_line onto the line (move_to point -> target
  // of the first line_to / line_to_arc), i.e. the path came back to the line it started on,
  // the first segment is instead rebuilt to start at the current point and nothing is added:
  // the part of that line outside the arcs (the thesis's move_to point outside the circle)
  // is dropped and the curve closes without a degenerate piece.
  void close();

  // getpath: the pieces uniformly concatenated, x(coord) replaced by the scalar `in`.
  Fn curve(const Fn& in) const;
  std::size_t pieces() const;

 private:
  struct Line {
    Fn from, to;
  };
  void require_open(const char* op) const;
  void require_point(const char* op, const char* what, const Fn& p) const;
  Fn segment(const Fn& a, const Fn& b) const;
  Fn arc(const Fn& center, const Fn& from, const Fn& to, bool ccw) const;

  int coord_;
  std::vector<Fn> pieces_;
  std::optional<Fn> start_, current_;
  std::optional<Line> first_line_;  // the line of the first piece (move_to point -> its target)
  Fn first_end_;                    // where the first segment ends
  std::optional<Line> last_line_;   // the line the last arc_to_line ended on
  bool closed_ = false;
};

// GENMOD's m_mirrorx: a half path c(u) on x >= 0 from (0, -D) to (0, D) completed by its
// mirror image (-c0(1 - u), c1(1 - u)); a closed curve of x(parm): [0, 1/2] the half, [1/2, 1]
// the mirror. The half has dimension 2.
Fn mirror_x(const Fn& half, int parm = 0);

}  // namespace genmod
