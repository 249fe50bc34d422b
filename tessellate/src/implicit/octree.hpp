// The implicit mesher's octree: cells classified by interval arithmetic with tape pruning, and
// the neighbour queries the cell mesher needs (face pieces across a face, lattice points on a
// segment).
#pragma once

#include "genmod/kernel/interval_evaluator.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/tessellate/implicit_mesher.hpp"
#include "implicit/frame.hpp"

#include <atomic>
#include <chrono>
#include <cstdint>
#include <vector>

namespace genmod::implicit {

enum class CellKind : std::uint8_t { Internal, Outside, Inside, Surface };

inline constexpr std::uint32_t kNone = 0xffffffffu;

struct Cell {
  std::array<std::uint32_t, 3> corner{};  // lattice coordinates of the low corner
  std::uint8_t level = 0;
  CellKind kind = CellKind::Internal;
  bool certified = false;  // Surface: the normal-cone test held
  bool bounded_gradient = false;  // Surface: interval bounds of the gradient were available
  std::uint32_t children = kNone;  // Internal: index of the first of 8 consecutive children
  std::uint32_t tapes = kNone;     // Surface: index into Octree::tapes()

  std::uint32_t size() const noexcept { return kRootSize >> level; }
};

// The pruned tapes of a surface cell: valid on the closed cell.
struct CellTapes {
  Tape value, gradient;
};

// What classification needs besides the cell.
struct ClassifyContext {
  const Frame* frame;
  const ImplicitMeshSettings* settings;
  const Tape* hessian;  // tightens the gradient's enclosure when the cone test fails
  int min_level;  // cells of this level or finer are at min_feature
  int max_cell_level;  // cells coarser than this that contain surface are split
};

struct ClassifyWorker {
  IntervalEvaluator intervals;
  TapeSimplifier simplifier;
  std::size_t evaluations = 0;
};

class Octree {
 public:
  // Builds the octree down to the settings' limits. `deadline` (if not max) and `cancel`
  // (if set and true) stop splitting.
  Octree(const ImplicitSurface& surface, const ClassifyContext& context,
         std::chrono::steady_clock::time_point deadline, const std::atomic<bool>* cancel, ImplicitMeshStats& stats);

  const std::vector<Cell>& cells() const noexcept { return cells_; }
  const Cell& cell(std::uint32_t i) const noexcept { return cells_[i]; }
  const CellTapes& tapes(const Cell& c) const noexcept { return tapes_[c.tapes]; }
  const ClassifyContext& context() const noexcept { return context_; }

  // Splits surface cells (whose level is above min_level) into 8 classified children.
  void split(const std::vector<std::uint32_t>& surface_cells, ImplicitMeshStats& stats);
  bool cell_limit_reached() const noexcept {
    return cells_.size() >= context_.settings->max_cells || memory_bytes() > context_.settings->max_memory;
  }
  // The bytes held by the cells and their pruned tapes (the clause arrays).
  std::size_t memory_bytes() const noexcept {
    return cells_.size() * sizeof(Cell) + tapes_.size() * sizeof(CellTapes) + tape_bytes_;
  }

  // The 27 nodes around a leaf c: entry 9 (dz + 1) + 3 (dy + 1) + (dx + 1) is the node of
  // c's level (or the leaf above it) at c's corner + (dx, dy, dz) * size, kNone outside the
  // root; entry 13 is c. The queries below start from it instead of the root.
  using Neighborhood = std::array<std::uint32_t, 27>;
  Neighborhood neighborhood(const Cell& c) const;

  // The leaves across face (axis, side = +1 / -1) of cell c that touch it, as the squares
  // they cover on that face: (u0, v0, u1, v1) in the face's two other axes (axis + 1, axis + 2
  // mod 3). A single entry equal to c's own face when the neighbour is as large or larger, or
  // when the face is on the root boundary.
  void face_pieces(const Cell& c, const Neighborhood& nb, int axis, int side,
                   std::vector<std::array<std::uint32_t, 4>>& out) const;

  // The surface leaves whose closed box meets the closed lattice box [lo, hi].
  void surface_leaves_touching(const std::array<std::uint32_t, 3>& lo, const std::array<std::uint32_t, 3>& hi,
                               std::vector<std::uint32_t>& out) const;

  // Lattice points that are corners of leaves, strictly inside the segment along `axis`
  // from t0 to t1 through the lattice point `on` (its axis coordinate ignored), ascending. The
  // segment is an edge of a leaf on the boundary of c (t1 - t0 a power of two dividing t0).
  void points_on_segment(const Cell& c, const Neighborhood& nb, int axis, const std::array<std::uint32_t, 3>& on,
                         std::uint32_t t0, std::uint32_t t1, std::vector<std::uint32_t>& out) const;

 private:
  struct Pending {
    std::uint32_t cell;
    CellTapes tapes;
  };
  // Classifies `pending` (in parallel); returns the children to classify next.
  std::vector<Pending> classify_all(std::vector<Pending>& pending, bool allow_split, ImplicitMeshStats& stats);

  // False (and the limit recorded) when 8 more cells would pass max_cells or max_memory.
  bool room_for_children(ImplicitMeshStats& stats) const;

  std::vector<Cell> cells_;
  std::vector<CellTapes> tapes_;
  std::size_t tape_bytes_ = 0;
  ClassifyContext context_;
};

}  // namespace genmod::implicit
