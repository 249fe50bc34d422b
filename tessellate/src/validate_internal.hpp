// Pieces of validate() (validate.hpp), split so that only validate_geometry.cpp includes CGAL.
#pragma once

#include "genmod/tessellate/validate.hpp"

#include <cstdint>
#include <vector>

namespace genmod::validation {

// Triangles whose three corners are valid, distinct vertex indices.
std::vector<std::uint32_t> proper_triangles(const Mesh& mesh, MeshValidity& v);

// Edges, boundary / non-manifold / misoriented edges, non-manifold vertices, components,
// Euler characteristics, volumes, unused and coincident vertices. Fills component_info.
void check_topology(const Mesh& mesh, const std::vector<std::uint32_t>& proper, MeshValidity& v);

// Degenerate (collinear) triangles among `proper`, with CGAL's exact predicates; returns the
// non-degenerate ones.
std::vector<std::uint32_t> check_degenerate(const Mesh& mesh, const std::vector<std::uint32_t>& proper,
                                            MeshValidity& v);

// Counts intersecting pairs among `triangles` (non-degenerate ones).
std::size_t count_self_intersections(const Mesh& mesh, const std::vector<std::uint32_t>& triangles, int threads);

// Per component: outward or not, and nesting level (CGAL's volume decomposition). Requires a
// closed, manifold, oriented, intersection-free, non-degenerate mesh.
void check_outward(const Mesh& mesh, MeshValidity& v);

// Distance of the mesh from f = 0.
SurfaceDistance measure_surface_distance(const Mesh& mesh, const Tape& surface, int face_samples,
                                         double search_radius, int threads);

}  // namespace genmod::validation
