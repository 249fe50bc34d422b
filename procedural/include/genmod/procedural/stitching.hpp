// Stitching (Morkel §4.1.8, spec §2.6): joining the boundary loops of two face selections with
// a strip of triangles, on one mesh (bridge: a tube or handle) or between two meshes (stitch: a
// transplant of one mesh's selection onto the hole left by the other's).
#pragma once

#include "genmod/procedural/poly_mesh.hpp"

#include <string>

namespace genmod {

// bridge(mesh, sel_a, sel_b, label), in place. sel_a and sel_b must each be disk-like
// (edge-connected, not touching an open boundary of the mesh, one boundary loop through
// distinct vertices, Euler characteristic V - E + F = 1) and share no vertex. Their faces are
// deleted, with the edges and vertices inside them (OpenMesh marks them deleted; no garbage
// collection, so other handles stay valid), and the two boundary loops, of n and m vertices,
// are joined by exactly n + m new triangles labelled `label`, returned in creation order:
//   * loop A is walked in the winding of the deleted faces of sel_a, loop B against the
//     winding of sel_b, so both run the same way round the tube and each loop edge gets a new
//     face on the side its deleted face was on: the result is consistently oriented, and
//     closed and manifold when the mesh was;
//   * alignment: the closest pair (a_i, b_j) (squared distances, the first pair in loop order
//     on ties; each loop starts at its smallest vertex index) is the first rung;
//   * zipper: from rung (a, b), the next triangle advances along A when the new rung
//     |a' - b| is shorter than |a - b'|, else along B; ties advance along A (here and in the
//     alignment, squared lengths within 1e-9 relative are ties, so that scaled or moved copies
//     of the loops are joined alike); a choice that
//     would give a zero-area triangle (twice its area at most 1e-14 times the largest squared
//     distance between a vertex of A and one of B) is avoided when the other is not; a step
//     that would use up a loop while the other is still at its first rung's vertex (the rung
//     it would add is one of the first ones: a third face on it) is not taken when the other
//     step is possible; a loop that is used up forces the other.
// On a closed mesh the genus goes up by one when both loops are on one component, and two
// components become one otherwise.
// An empty sel_a or sel_b changes nothing and returns no faces (there is nothing to join).
// Throws std::invalid_argument naming bridge and the problem (the mesh unchanged) for: a face
// not in the mesh, a selection that is not disk-like, selections that share a face or a
// vertex, a rung that is already an edge of the mesh, a zero-area triangle the greedy zipper
// could not avoid (it looks one triangle ahead; a configuration with a loop vertex on the line
// of an edge of the other loop can end on a flat closing triangle).
FaceList bridge(PolyMesh& mesh, const FaceList& sel_a, const FaceList& sel_b, const std::string& label = "");

// stitch(a, sel_a, b, sel_b, label) -> a new mesh made of exactly the faces of `a` in sel_a
// ("the selection from the first model replaces the selection of the second") and the faces of
// `b` not in sel_b, joined along the boundary loop of sel_a and the hole of sel_b by the
// zipper of bridge (new triangles labelled `label`). Vertices and faces keep their labels and
// their relative index order: a's part first, then b's, then the joining triangles; vertices
// that no kept face uses are dropped. The meshes are not moved: place `a` before stitching.
// If sel_a or sel_b is empty nothing is joined: the result is just the kept faces (with both
// empty, a copy of b's faces). Throws std::invalid_argument naming stitch for a face not in
// its mesh or a non-empty selection that is not disk-like (as for bridge), or a zero-area
// triangle the zipper could not avoid.
PolyMesh stitch(const PolyMesh& a, const FaceList& sel_a, const PolyMesh& b, const FaceList& sel_b,
                const std::string& label = "");

}  // namespace genmod
