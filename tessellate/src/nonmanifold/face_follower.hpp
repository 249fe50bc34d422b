// The face-vertex search of the non-manifold polygonizer (§5.7.4, Fig. 4.22): a strip of
// small equilateral triangles walks along the boundary between two regions inside a
// tetrahedron face until its apex lands in a third region.
#pragma once

#include "nonmanifold/region_evaluator.hpp"

#include <optional>

namespace genmod::nonmanifold {

// `face` is the triangle; p1 (in region a) and p2 (in region b) are the ends of a short
// segment across the a|b boundary on one of its edges. Each step puts an apex on the far side
// of the current segment (the first one toward the face's interior), samples its region and
// replaces the end of the same region, so the segment keeps straddling the boundary. Returns
// the centroid of the first triangle whose apex is in neither region, or nothing when the
// walk leaves the face (by more than a triangle side) or takes more than `max_steps` steps.
std::optional<Point> follow_to_junction(RegionEvaluator& f, const std::array<Point, 3>& face, Point p1, Point p2, int a,
                                        int b, std::size_t max_steps);

}  // namespace genmod::nonmanifold
