// Pieces shared by the human figure's procedures (foot, leg, arm, head, torso, human) and the
// tree: profile shaping of a column's sides onto a Bezier curve, and attaching a part (a mesh
// with a flat root face set) to a cell of a workpiece by a bridge.
#pragma once

#include "furniture_tools.hpp"
#include "genmod/procedural/affine.hpp"

#include <string>
#include <vector>

namespace genmod::models::detail {

// Shapes the side of `faces` facing `sign` along axis `move` onto the profile
// move = centre + sign * half * f(t), t = (p[along] - start) / (end - start), where f is the
// Bezier curve through the control values `f` spaced evenly over t in [0, 1] (the curve is
// extended by 2% beyond both ends with the end values, so every vertex of the column meets it).
// Vertices move along `move`, seen along the third axis (shape_to_curve).
void shape_profile(PolyMesh& mesh, const FaceList& faces, int along, double start, double end, int move,
                   double centre, double sign, double half, const std::vector<double>& f);

// Appends `part` mapped by `xf` to w.mesh and bridges the part's faces labelled `root_label`
// (mapped) to `cell` (faces of w.mesh), the new triangles labelled `label`. The mesh is not
// garbage-collected, so other handles stay valid.
void attach_part(Workpiece& w, const PolyMesh& part, const std::string& root_label, const FaceList& cell,
                 const Affine& xf, const std::string& label);

// Rotation by `radians` about the y axis (orientation kept), as an Affine without translation.
Affine rotation_y(double radians);

}  // namespace genmod::models::detail
