// sqrt(2) subdivision (Morkel §2.5, after Li, Ma and Bao 2004), global and adaptive, with
// Morkel's smoothing factor. Chosen because faces only double per step, any polygon works and
// the output is quads.
//
// The rule (the spec's [decision]; the thesis does not give Li et al.'s weights), per level on
// the separable set S:
//  * face point of f in S: the centroid of f's vertices (before this level's moves);
//  * an old vertex v moves only if it is not on the mesh boundary and all its faces are in S:
//    v' = v + s * (mean of the face points of its faces - v); every other vertex stays;
//    so s = 0 keeps old vertices bitwise, positions are affine in s, and s outside [0,1] is
//    legal (s = 2 and -2 give Morkel's star shapes);
//  * each edge {a, b} with a face in S: F = its face in S (the face of the edge's first
//    half-edge if both are), a -> b in F's winding, G = the face across. If G is in S the edge
//    becomes the quad [a, fp(G), b, fp(F)], otherwise (G outside S or an open boundary) the
//    triangle [a, b, fp(F)]; old edges between faces of S disappear, faces of S are replaced.
//  * labels: genmod faces carry one label, so a new face takes the label of F (the spec's union
//    of labels(F) and labels(G) when both carry the same label, which is the case inside one
//    named region).
// On a closed mesh with everything selected: F' = E, E' = 2E, V' = V + F, all quads. The
// cube corner (1,1,1) of [-1,1]^3 goes to (1/3,1/3,1/3) at s = 1.
#pragma once

#include "genmod/procedural/poly_mesh.hpp"

namespace genmod {

// `levels` adaptive levels on `faces` (the separable faces; each further level refines the
// faces created by the previous one) with smoothing factor `smoothing`. Returns the faces
// created by the last level. Faces outside the set keep their vertex positions and vertex
// lists bitwise. The mesh is rebuilt (old vertices keep their indices, then the face points;
// faces outside the set keep their order, then the new faces in edge order), so old face
// handles are invalid afterwards. An empty set or zero levels leaves the mesh untouched.
// Throws std::invalid_argument ("sqrt2_subdivide: ...") for a face not in the mesh, a deleted
// or repeated face, negative levels or a non-finite smoothing factor. Needs a manifold mesh
// (open or closed).
FaceList sqrt2_subdivide(PolyMesh& mesh, const FaceList& faces, int levels, double smoothing);

// `levels` global steps: every face selected.
void sqrt2_subdivide_all(PolyMesh& mesh, int levels, double smoothing);

}  // namespace genmod
