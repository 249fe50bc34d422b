#include "body_tools.hpp"

#include "genmod/procedural/bezier_curve.hpp"
#include "genmod/procedural/curve_shaping.hpp"
#include "genmod/procedural/stitching.hpp"

#include <cmath>

namespace genmod::models::detail {

void shape_profile(PolyMesh& mesh, const FaceList& faces, int along, double start, double end, int move,
                   double centre, double sign, double half, const std::vector<double>& f) {
  if (faces.empty() || f.size() < 2) return;
  const int third = 3 - along - move;
  std::vector<Vec3> points;
  const double span = end - start;
  const auto point = [&](double t, double value) {
    Vec3 p(0, 0, 0);
    p[along] = start + t * span;
    p[move] = centre + sign * half * value;
    p[third] = 0;
    return p;
  };
  points.push_back(point(-0.02, f.front()));
  for (std::size_t i = 0; i < f.size(); ++i) points.push_back(point(static_cast<double>(i) / (f.size() - 1), f[i]));
  points.push_back(point(1.02, f.back()));
  Vec3 direction(0, 0, 0), normal(0, 0, 0);
  direction[move] = sign;
  normal[third] = 1;
  shape_to_curve(mesh, faces, BezierCurve(points), direction, normal);
}

void attach_part(Workpiece& w, const PolyMesh& part, const std::string& root_label, const FaceList& cell,
                 const Affine& xf, const std::string& label) {
  const int first_face = static_cast<int>(w.mesh.n_faces());
  FaceList root;
  for (PolyMesh::FaceHandle f : faces_labelled(part, root_label)) root.emplace_back(first_face + f.idx());
  append_mesh(w.mesh, part, xf);
  bridge(w.mesh, root, cell, label);
}

Affine rotation_y(double radians) {
  Affine a;
  const double c = std::cos(radians), s = std::sin(radians);
  a.m = {{{c, 0, s, 0}, {0, 1, 0, 0}, {-s, 0, c, 0}}};
  return a;
}

}  // namespace genmod::models::detail
