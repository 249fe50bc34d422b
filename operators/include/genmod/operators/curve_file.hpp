// The genmod curve file (.crv): a small text format for the curves of curve.hpp, so that
// GENMOD's m_crv("name.crv", in) works on files written by hand or by an editor.
//
// Format (version 1). One statement per line: a keyword, then numbers separated by blanks.
// '#' starts a comment that runs to the end of the line; blank lines are ignored. Keywords:
//
//   crv 1                  first statement: the magic word and the format version
//   type <kind>            polyline | bezier | bspline | nurbs | hermite | catmull-rom
//   dimension <d>          coordinates per point, 1..16
//   degree <p>             bspline and nurbs only (required there), 1..12
//   clamped yes|no         bspline and nurbs without knots: clamped (default) or unclamped
//                          uniform knots; nurbs accepts only `yes`
//   knots <u> <u> ...      bspline and nurbs only, optional (default: uniform on [0, 1]);
//                          several `knots` lines append; n + p + 1 nondecreasing values
//   point <x1> ... <xd>    a control point (or interpolated point); nurbs: d coordinates
//                          then the weight (> 0)
//   tangent <t1> ... <td>  hermite only: the derivative dc/dt at the matching point, one
//                          per point, in the same order
//
// `crv`, `type` and `dimension` come before any point. Example, a quarter circle:
//
//   crv 1
//   type nurbs
//   dimension 2
//   degree 2
//   point 1 0 1
//   point 1 1 0.70710678118654752
//   point 0 1 1
//
// Any error (unknown keyword, a number that does not parse, a wrong count of coordinates,
// a knot vector that is not nondecreasing, too few points, ...) throws CurveFileError, whose
// message names the source and the line ("quarter.crv:6: point has 2 numbers, expected 3").
// Problems only visible at the end (too few points, knot count) name the line of the
// statement they concern, or the last line.
#pragma once

#include "genmod/kernel/line_reader.hpp"
#include "genmod/operators/curve.hpp"

#include <iosfwd>
#include <stdexcept>
#include <string>
#include <string_view>

namespace genmod {

class CurveFileError : public std::invalid_argument {
 public:
  CurveFileError(const std::string& source, int line, const std::string& what);
  int line() const noexcept { return line_; }

 private:
  int line_;
};

// How much a reader takes before it gives up with a CurveFileError: at most max_bytes in all
// (default 1 GiB), max_line per line (default 1 MiB).
using CurveReadLimits = TextReadLimits;

// Parses curve-file text; `source` names it in error messages.
Curve parse_curve(std::string_view text, const std::string& source = "<string>");
// Reads a stream line by line (it is never held whole); CurveFileError for malformed text, a
// limit passed or a read error of the stream (never taken for the end of the input).
Curve read_curve(std::istream& in, const std::string& source = "<stream>", const CurveReadLimits& limits = {});
// Reads a file the same way (CurveFileError with line 0 if it cannot be opened; a directory or a
// failing disk is a read error).
Curve load_curve(const std::string& path, const CurveReadLimits& limits = {});
// GENMOD's m_crv: the curve in `path` evaluated at the scalar function `in`.
Fn crv(const std::string& path, const Fn& in);

}  // namespace genmod
