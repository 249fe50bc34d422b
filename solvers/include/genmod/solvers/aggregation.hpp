// Solution aggregation (snyder.md section 4.9): merge touching or overlapping boxes into
// connected groups and report each group's interval hull.
//
// Two closed boxes are connected when they intersect (a shared face or corner counts). Groups
// are found with union-find over a sweep along the first side; then groups whose hulls
// intersect are merged until all hulls are pairwise disjoint (the "repeat" of Snyder's add(),
// since a hull may reach a box that touched neither original). The output is deterministic:
// groups are ordered by their smallest member index, members ascending.
//
// Example:
//   std::vector<Box> boxes = {{Interval(0, 1)}, {Interval(1, 2)}, {Interval(5, 6)}};
//   for (const Aggregate& g : aggregate(boxes))        // two groups: [0, 2] and [5, 6]
//     std::cout << g.members.size() << " boxes around " << midpoint(g.hull)[0] << "\n";
#pragma once

#include "genmod/solvers/box.hpp"

#include <cstddef>
#include <span>
#include <vector>

namespace genmod {

struct Aggregate {
  Box hull;                          // interval hull of the members
  std::vector<std::size_t> members;  // indices into the input, ascending
};

// Boxes closer than `gap` (max norm) also count as connected: contraction (HC4, Newton)
// shrinks boxes away from their neighbours, so a solver aggregates at its resolution epsilon.
// Throws std::invalid_argument if the boxes do not all have the same dimension or gap < 0.
std::vector<Aggregate> aggregate(std::span<const Box> boxes, double gap = 0.0);

// True if the closed boxes intersect (touching counts), or are within `gap` of each other.
bool touches(std::span<const Interval> a, std::span<const Interval> b, double gap = 0.0) noexcept;

}  // namespace genmod
