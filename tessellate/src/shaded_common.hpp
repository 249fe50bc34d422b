// What both shaded renderers share, so that they sample exactly the same points: the voxel
// centers, which tape input is which axis, and the shading of a heightmap.
#pragma once

#include "genmod/kernel/interval.hpp"
#include "genmod/kernel/tape.hpp"
#include "genmod/tessellate/shaded_render.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace genmod::shaded_detail {

// Voxel centers lo + (k + 0.5) h per axis, computed once in round-to-nearest; y decreases with
// the row (row 0 at the top).
class VoxelGrid {
 public:
  // Checks the options (std::invalid_argument naming the problem; `who` names the caller).
  VoxelGrid(const ShadedOptions& options, const char* who);

  int size() const noexcept { return static_cast<int>(xs_.size()); }
  int depth() const noexcept { return static_cast<int>(zs_.size()); }
  double x(int column) const noexcept { return xs_[static_cast<std::size_t>(column)]; }
  double y(int row) const noexcept { return ys_[static_cast<std::size_t>(row)]; }
  double z(int k) const noexcept { return zs_[static_cast<std::size_t>(k)]; }
  // Hulls of the centers of [a, b) (a < b): the centers are monotone in the index.
  Interval x_hull(int c0, int c1) const noexcept { return Interval::unchecked(x(c0), x(c1 - 1)); }
  Interval y_hull(int r0, int r1) const noexcept { return Interval::unchecked(y(r1 - 1), y(r0)); }
  Interval z_hull(int k0, int k1) const noexcept { return Interval::unchecked(z(k0), z(k1 - 1)); }

 private:
  std::vector<double> xs_, ys_, zs_;
};

// Tape input k is the coordinate axis[k] (0 = x, 1 = y, 2 = z).
struct SpaceInputs {
  std::array<int, 3> axis{};
  std::size_t count = 0;
};
// Checks that the tape is scalar in x(0), x(1), x(2) only (std::invalid_argument otherwise).
SpaceInputs space_inputs(const Tape& tape, const char* who);

// The shaded picture of `heights` (see shaded_render.hpp), in parallel on the caller's arena.
Image shade(const Tape& tape, const SpaceInputs& in, const VoxelGrid& grid, const std::vector<std::uint32_t>& heights);

}  // namespace genmod::shaded_detail
