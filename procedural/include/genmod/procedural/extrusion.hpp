// Multi-face extrusion (Morkel §2.3): a face set moves by a vector, with side quads only along
// the boundary of the set, so a closed manifold stays closed and manifold and neighbours in the
// set get no internal walls.
#pragma once

#include "genmod/procedural/poly_mesh.hpp"

namespace genmod {

// Extrudes `faces` of `mesh` by `by` and returns the caps, one per input face in the input's
// order. Each vertex of the set is copied once, to position + by (bitwise); a cap has the new
// vertices in its face's winding; each boundary edge (vj -> vj+1) of a face becomes the side
// quad [old vj+1, new vj+1, new vj, old vj]; the input faces and the vertices left without
// faces are removed. Side and cap faces carry the label of their face. For a disk-like set
// with b boundary edges (V, E, F) changes by (+b, +2b, +b).
//
// The mesh is rebuilt: old vertices keep their relative order and come first, then the new
// vertices; faces outside the set keep their order, followed per input face by its sides and
// its cap. Old handles are invalid afterwards (recompute named sets with FaceSets::update).
// An empty set leaves the mesh untouched. Throws std::invalid_argument ("extrude: ...") for a
// face not in the mesh, a deleted or repeated face, a non-finite vector, or a set whose
// faces touch at a vertex only (the wall edge through it would carry four faces; the mesh is
// then left as it was). A zero or inward
// vector gives a degenerate but legal result (as in the thesis).
FaceList extrude(PolyMesh& mesh, const FaceList& faces, const Vec3& by);

}  // namespace genmod
