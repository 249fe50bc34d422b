// foot: the human foot of Algorithm 4 / App. C.3 (research/morkel.md section 3.1) as a
// cacheable Out procedure, so that the human's two feet and the luggage's many feet are built
// once per distinct argument tuple (Experiment 6).
//
// Construction (y up, toes towards +z, the sole at y = -height, the top at y = 0): one box cell
// of the big toe's column, extruded along +x column by column (2 numToes - 1 columns: toe,
// gap, toe, ... so every toe is exactly one column of cells; the thesis subdivides until every
// toe strip has `threshold` faces, which a grid gives by construction), its top raised by a
// second row, and its back face extruded backwards into 3 cells (ball, arch, and the heel,
// `heel` long). The front
// face's lower row of the toe columns are the toes (named toe0..), each extruded forward once,
// toe i by bigToeLength * 2 / (i + 2) (the thesis's extrudeUnit / (i + 2): the big toe the
// longest). The big toe is bigToe of the width, the small toes and gaps share the rest; on a
// foot whose side is not "left" the columns are mirrored (the thesis mirrors for a name not
// starting with 'l'), so the big toe is on the inside of both feet. The top of the heel cell,
// all columns but the outer two on each side, is the flat face set "foottop" the leg bridges to; every
// other face is subdivided with adaptive sqrt(2) and smoothed.
//
// Numbers the thesis leaves out: the 3 cells along the foot, the toes' length (toeLength of
// the whole length, for the big toe), 2 cell rows in height, toes from the lower row.
#include "body_tools.hpp"
#include "procedural_model_defs.hpp"

#include "genmod/procedural/sqrt2_subdivision.hpp"

#include <algorithm>

namespace genmod::models::detail {
namespace {

PolyMesh build_foot(const Arguments& a, const CallContext&) {
  const char* P = "foot";
  const double length = positive_real(a, P, "length"), width = positive_real(a, P, "width"),
               height = positive_real(a, P, "height");
  const int toes = integer_in(a, P, "numToes", 1, 10);
  const double big = real_in(a, P, "bigToe", 0.05, 1.0);
  const double toe_fraction = real_in(a, P, "toeLength", 0.05, 0.8);
  const std::string& side = a.string("side");
  if (side != "left" && side != "right") refuse_parameter(P, "side", "must be \"left\" or \"right\", got \"" + side + "\"");
  const int levels = integer_in(a, P, "subdivisions", 0, 4);
  const double smoothing = real_in(a, P, "smoothing", 0.0, 1.0);
  if (toes > 1 && big >= 1.0) refuse_parameter(P, "bigToe", "must be < 1 with more than one toe");

  // Column widths from the big toe's side.
  const int columns = 2 * toes - 1;
  std::vector<double> widths(columns, toes > 1 ? (1.0 - big) * width / (2.0 * (toes - 1)) : width);
  widths[0] = toes > 1 ? big * width : width;
  const bool left = side == "left";
  if (!left) std::reverse(widths.begin(), widths.end());
  std::vector<double> edges{-0.5 * width};  // column boundaries along x
  for (double c : widths) edges.push_back(edges.back() + c);
  edges.back() = 0.5 * width;

  const double big_toe = toe_fraction * length, body = length - big_toe;
  const double heel = positive_real(a, P, "heel");
  if (!(heel < 0.8 * body)) refuse_parameter(P, "heel", "must be less than 0.8 of the foot behind the toes");
  const double cz = 0.5 * (body - heel);  // the arch and ball cells
  Workpiece w;
  w.mesh = make_box(Vec3(edges[0], -height, body - cz), Vec3(edges[1], -0.5 * height, body));
  w.name("foot", all_faces(w.mesh));
  for (int k = 1; k < columns; ++k)
    w.extrude_chain(w.select("foot", ratio_box(kHigh, kAll, kAll)), Vec3(edges[k + 1] - edges[k], 0, 0), 1);
  w.extrude_chain(w.select("foot", ratio_box(kAll, kHigh, kAll)), Vec3(0, 0.5 * height, 0), 1);
  w.extrude_chain(w.select("foot", ratio_box(kAll, kAll, kLow)), Vec3(0, 0, -cz), 1);
  w.extrude_chain(w.select("foot", ratio_box(kAll, kAll, kLow)), Vec3(0, 0, -heel), 1);

  // The x ratio range of columns first..last (a quarter of the neighbouring columns' width as
  // margin).
  const auto column_range = [&](int first, int last) {
    const double lo = edges[first] - 0.25 * (first > 0 ? widths[first - 1] : widths[first]);
    const double hi = edges[last + 1] + 0.25 * (last + 1 < columns ? widths[last + 1] : widths[last]);
    return std::pair<double, double>{(lo - edges[0]) / width, (hi - edges[0]) / width};
  };
  // The top over the heel cell, all columns but the outer two on either side (about the
  // ankle's size, so the bridge is a short tube).
  const int margin = columns >= 5 ? 2 : columns >= 3 ? 1 : 0;
  w.name("foottop", w.select("foot", ratio_box(column_range(margin, columns - 1 - margin), kHigh,
                                               {-0.25 * heel / body, (heel + 0.25 * cz) / body})));
  // The toes: the lower row of the front face in the toe columns, counted from the big toe.
  for (int i = 0; i < toes; ++i) {
    const int column = left ? 2 * i : columns - 1 - 2 * i;
    w.name("toe" + std::to_string(i),
           w.select("foot", ratio_box(column_range(column, column), cell_range(0, 0, 2), kHigh)));
  }
  for (int i = 0; i < toes; ++i) {
    const double reach = i == 0 ? length - body : big_toe * 2.0 / (i + 2);
    w.extrude_chain(w.faces("toe" + std::to_string(i)), Vec3(0, 0, reach), 1);
  }
  FaceList rounded = w.faces("foot");
  for (int i = 0; i < toes; ++i) rounded = merged({rounded, w.faces("toe" + std::to_string(i))});
  sqrt2_subdivide(w.mesh, rounded, levels, smoothing);
  return std::move(w.mesh);
}

}  // namespace

ProceduralModelDef foot_definition() {
  ProcedureSpec spec;
  spec.name = "foot";
  spec.mode = Mode::Out;
  spec.cacheable = true;
  spec.params = {param("length", 0.3),   param("width", 0.12),   param("height", 0.07), param("numToes", 5),
                 param("bigToe", 0.3),   param("toeLength", 0.3), param("heel", 0.1),    param("side", "left"), param("subdivisions", 2),
                 param("smoothing", 0.5)};
  spec.out_body = build_foot;
  ProceduralModel info{
      "foot",
      "Morkel's human foot (Algorithm 4), cacheable: toes extruded from a grid of columns; flat top 'foottop' at y = 0",
      {{"length", "heel (z = 0) to the big toe's tip (z = length)"},
       {"width", "across x"},
       {"height", "sole (y = -height) to the top (y = 0)"},
       {"numToes", "toes, 1-10"},
       {"bigToe", "the big toe's share of the width"},
       {"toeLength", "the big toe's share of the length; toe i reaches 2 / (i + 2) of it"},
       {"heel", "z length of the heel cell, whose top (all but the outer two columns each side) is 'foottop'"},
       {"side", "\"left\" (big toe at -x) or \"right\" (mirrored)"},
       {"subdivisions", "sqrt(2) levels on everything but the top, 0-4"},
       {"smoothing", "sqrt(2) smoothing factor, 0..1"}}};
  return {std::move(spec), std::move(info)};
}

}  // namespace genmod::models::detail
