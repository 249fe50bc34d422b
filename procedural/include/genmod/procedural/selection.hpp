// Selection by regions (Morkel §2.2): a ratio box relative to the AABB of a parent face set, and
// named face sets kept per model and recomputed from face labels.
//
// Why ratios of a parent's box: selections survive edits that shift indices and are
// independent of the model's size; a child selected from a named parent (torso -> arm) needs
// few parameters. A face is selected only if all its vertices are inside the closed box.
#pragma once

#include "genmod/procedural/poly_mesh.hpp"

#include <string>
#include <vector>

namespace genmod {

// Ratios of the parent's AABB per axis: [x0, x1] x [y0, y1] x [z0, z1]. Values outside [0, 1]
// are legal (a wider or narrower box); they must be finite.
struct RatioBox {
  double x0 = 0, x1 = 1, y0 = 0, y1 = 1, z0 = 0, z1 = 1;
};

// The faces of `parent` (in its order) all of whose vertices lie in `box` relative to the AABB
// of `parent`. The test is (p - lo) >= r0 * (hi - lo) and (p - lo) <= r1 * (hi - lo): every
// operand scales exactly under a power-of-two uniform scale, so such a scale selects the same
// faces (claim 16). An axis whose extent is <= 1e-12 times the box's magnitude is flat and
// passes for every vertex, so select(0,1,0,1,0,1, flat cap) returns the cap (claim 18; Java's
// 0/0 would select nothing). An empty parent gives an empty result. Throws
// std::invalid_argument ("select: ...") for a face not in the mesh, a deleted face or a
// non-finite ratio.
FaceList select_faces(const PolyMesh& mesh, const FaceList& parent, const RatioBox& box);

// A selection: its name, the name of the set it was selected from ("" for the whole mesh) and
// its faces.
struct FaceSet {
  std::string id;
  std::string parent;
  FaceList faces;
};

// The named selections of one model, in registration order. Membership is carried by face
// labels (genmod's faces carry one label each), so after a tool rebuilds the mesh, update()
// recomputes every set from the labels: new faces that inherited a label join, deleted faces
// leave. Because a face has one label, registering a child relabels its faces: they move from
// the parent set to the child (Morkel's removeLabelFromFaceSet done at once).
class FaceSets {
 public:
  // Selects `box` relative to the named set `parent` ("" = all faces of the mesh) and returns
  // a set with id `id` and that parent; it is not registered. Throws std::invalid_argument for
  // an unknown parent.
  FaceSet select(const PolyMesh& mesh, const std::string& parent, const RatioBox& box,
                 const std::string& id) const;
  // Registers `set` (replacing a set of the same id) and labels its faces with its id. Throws
  // std::invalid_argument for an empty id or a face not in the mesh.
  void add(PolyMesh& mesh, const FaceSet& set);
  bool contains(const std::string& id) const;
  // Throws std::invalid_argument for an unknown id.
  const FaceSet& get(const std::string& id) const;
  // Recomputes every set's faces from the labels of `mesh`.
  void update(const PolyMesh& mesh);
  std::size_t size() const { return sets_.size(); }

 private:
  std::vector<FaceSet> sets_;
};

}  // namespace genmod
