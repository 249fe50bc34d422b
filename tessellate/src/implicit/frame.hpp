// The integer lattice of the implicit mesher and its map to space, and the box clip.
//
// The octree's root is a cube of 2^kLatticeBits lattice units per side. A cell of level L has
// side 2^(kLatticeBits - L) units; cells go down to level kMaxLevel (2 units), so every cell
// center and face center is a lattice point too. Every sample the mesher takes is a lattice
// point or a point computed from lattice points, and a lattice point has one position,
// computed one way (Frame::point), so cells that share a sample agree on it bit for bit.
//
// The mesher meshes g = max(f, clip) where clip is the signed distance to the user's box (< 0
// inside): the solid intersected with the box, closed by the box faces. The root cube holds
// the box with a margin and is offset by a non-dyadic fraction, so the box faces never lie
// on lattice planes (a sample exactly on the zero set would make degenerate vertices).
#pragma once

#include "genmod/kernel/interval.hpp"

#include <array>
#include <cstdint>

namespace genmod::implicit {

inline constexpr int kLatticeBits = 20;
inline constexpr int kMaxLevel = kLatticeBits - 1;
inline constexpr std::uint32_t kRootSize = 1u << kLatticeBits;

// A lattice point packed as x | y << 21 | z << 42 (each coordinate in [0, kRootSize]).
using Key = std::uint64_t;
inline constexpr Key pack(std::uint32_t x, std::uint32_t y, std::uint32_t z) noexcept {
  return Key(x) | (Key(y) << 21) | (Key(z) << 42);
}
inline constexpr std::array<std::uint32_t, 3> unpack(Key k) noexcept {
  return {static_cast<std::uint32_t>(k & 0x1fffff), static_cast<std::uint32_t>((k >> 21) & 0x1fffff),
          static_cast<std::uint32_t>((k >> 42) & 0x1fffff)};
}
inline constexpr Key pack(const std::array<std::uint32_t, 3>& q) noexcept { return pack(q[0], q[1], q[2]); }

using Vec3 = std::array<double, 3>;

class Frame {
 public:
  Frame() = default;
  // Root cube around the box (see the file comment).
  explicit Frame(const std::array<Interval, 3>& box);

  Vec3 point(const std::array<std::uint32_t, 3>& q) const noexcept {
    return {lo_[0] + q[0] * unit_, lo_[1] + q[1] * unit_, lo_[2] + q[2] * unit_};
  }
  Vec3 point(Key k) const noexcept { return point(unpack(k)); }
  double unit() const noexcept { return unit_; }                // lattice unit in space
  double size(int level) const noexcept { return unit_ * static_cast<double>(kRootSize >> level); }

  // Signed distance to the box (max over axes of |p - c| - h), negative inside.
  double clip(const Vec3& p) const noexcept;
  // Its enclosure over a box, and the axes whose term can be the maximum there with the sign
  // of its gradient (+1 / -1, or 0 when the term cannot be the maximum; 2 when both signs
  // occur, the box straddling the center plane).
  Interval clip(const std::array<Interval, 3>& box, std::array<int, 3>* active = nullptr) const noexcept;
  // Gradient of clip at p (a unit axis vector).
  Vec3 clip_gradient(const Vec3& p) const noexcept;

 private:
  Vec3 lo_{}, center_{}, half_{};
  double unit_ = 1.0;
};

}  // namespace genmod::implicit
