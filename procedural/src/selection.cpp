#include "genmod/procedural/selection.hpp"

#include "tool_checks.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace genmod {

FaceList select_faces(const PolyMesh& mesh, const FaceList& parent, const RatioBox& box) {
  detail::check_faces(mesh, parent, "select");
  const double r[3][2] = {{box.x0, box.x1}, {box.y0, box.y1}, {box.z0, box.z1}};
  for (const auto& axis : r)
    if (!(std::isfinite(axis[0]) && std::isfinite(axis[1])))
      throw std::invalid_argument("select: the ratio box is not finite");
  FaceList selected;
  if (parent.empty()) return selected;
  const auto [lo, hi] = bounds(mesh, parent);
  double magnitude = 0;
  for (int a = 0; a < 3; ++a) magnitude = std::max({magnitude, std::abs(lo[a]), std::abs(hi[a])});
  // Per axis: the extent and the two thresholds on (p - lo); a flat axis passes everything.
  bool flat[3];
  double low[3], high[3];
  for (int a = 0; a < 3; ++a) {
    const double extent = hi[a] - lo[a];
    flat[a] = extent <= 1e-12 * magnitude;
    low[a] = r[a][0] * extent;
    high[a] = r[a][1] * extent;
  }
  for (PolyMesh::FaceHandle f : parent) {
    bool inside = true;
    for (auto v : mesh.fv_range(f)) {
      const Vec3& p = mesh.point(v);
      for (int a = 0; a < 3 && inside; ++a) {
        if (flat[a]) continue;
        const double d = p[a] - lo[a];
        inside = d >= low[a] && d <= high[a];
      }
      if (!inside) break;
    }
    if (inside) selected.push_back(f);
  }
  return selected;
}

FaceSet FaceSets::select(const PolyMesh& mesh, const std::string& parent, const RatioBox& box,
                         const std::string& id) const {
  const FaceList source = parent.empty() ? all_faces(mesh) : get(parent).faces;
  return FaceSet{id, parent, select_faces(mesh, source, box)};
}

void FaceSets::add(PolyMesh& mesh, const FaceSet& set) {
  if (set.id.empty()) throw std::invalid_argument("FaceSets::add: a named set needs a non-empty id");
  detail::check_faces(mesh, set.faces, "FaceSets::add");
  for (PolyMesh::FaceHandle f : set.faces) set_face_label(mesh, f, set.id);
  auto it = std::find_if(sets_.begin(), sets_.end(), [&](const FaceSet& s) { return s.id == set.id; });
  if (it == sets_.end())
    sets_.push_back(set);
  else
    *it = set;
  // Relabelling may have taken faces from other sets.
  update(mesh);
}

bool FaceSets::contains(const std::string& id) const {
  return std::any_of(sets_.begin(), sets_.end(), [&](const FaceSet& s) { return s.id == id; });
}

const FaceSet& FaceSets::get(const std::string& id) const {
  for (const FaceSet& s : sets_)
    if (s.id == id) return s;
  throw std::invalid_argument("FaceSets: no named selection '" + id + "'");
}

void FaceSets::update(const PolyMesh& mesh) {
  for (FaceSet& s : sets_) s.faces = faces_labelled(mesh, s.id);
}

}  // namespace genmod
