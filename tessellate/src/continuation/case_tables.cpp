// The tetrahedral (16-case, six tetrahedra) and cube (256-case) tables of the continuation
// polygonizer, generated from the rules in continuation_polygonizer.hpp rather than typed in.
#include "genmod/tessellate/continuation_polygonizer.hpp"

#include <stdexcept>
#include <string>

namespace genmod {

namespace {

using Corner = std::uint8_t;

std::array<int, 3> corner_position(Corner c) { return {c & 1, (c >> 1) & 1, (c >> 2) & 1}; }

// Twice the midpoint of the segment between corners a and b (integers, so exact).
std::array<int, 3> doubled_midpoint(const CornerPair& e) {
  const auto p = corner_position(e[0]), q = corner_position(e[1]);
  return {p[0] + q[0], p[1] + q[1], p[2] + q[2]};
}

// Orients a triangle so its normal points toward the outside corner of its first vertex, using
// the triangle through the edge midpoints. Any triangle with its vertices inside the same three
// segments has the same orientation relative to the sides (it never degenerates as its vertices
// slide along them), so the midpoints decide it exactly.
CaseTriangle oriented(CaseTriangle t) {
  const auto m0 = doubled_midpoint(t[0]), m1 = doubled_midpoint(t[1]), m2 = doubled_midpoint(t[2]);
  const int u[3] = {m1[0] - m0[0], m1[1] - m0[1], m1[2] - m0[2]};
  const int v[3] = {m2[0] - m0[0], m2[1] - m0[1], m2[2] - m0[2]};
  const int n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  const auto in = corner_position(t[0][0]), out = corner_position(t[0][1]);
  const int dot = n[0] * (out[0] - in[0]) + n[1] * (out[1] - in[1]) + n[2] * (out[2] - in[2]);
  if (dot == 0) throw std::logic_error("genmod: continuation case tables: a degenerate case triangle");
  if (dot < 0) std::swap(t[1], t[2]);
  return t;
}

struct Tables {
  std::array<std::array<Corner, 4>, 6> tets{};
  std::array<std::array<std::vector<CaseTriangle>, 16>, 6> tet_cases;
  std::array<std::vector<CaseTriangle>, 256> cube_cases;

  Tables() {
    // Kuhn's decomposition: for each order (a1, a2, a3) of the axes, the path 0 -> e_a1 ->
    // e_a1 + e_a2 -> (1,1,1) along cube edges. Every tetrahedron contains the diagonal 0-7.
    const int orders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    for (int t = 0; t < 6; ++t) {
      const Corner a = static_cast<Corner>(1 << orders[t][0]);
      const Corner b = static_cast<Corner>(a | (1 << orders[t][1]));
      tets[t] = {0, a, b, 7};
      for (unsigned mask = 0; mask < 16; ++mask) tet_cases[t][mask] = tetrahedron_triangles(tets[t], mask);
    }
    for (unsigned mask = 0; mask < 256; ++mask) cube_cases[mask] = cube_triangles(mask);
  }

  static std::vector<CaseTriangle> tetrahedron_triangles(const std::array<Corner, 4>& tet, unsigned mask) {
    std::vector<Corner> in, out;
    for (int i = 0; i < 4; ++i) (mask >> i & 1 ? in : out).push_back(tet[i]);
    std::vector<CaseTriangle> result;
    if (in.size() == 1 || in.size() == 3) {
      // One corner alone on its side: a triangle across its three edges.
      const bool lone_inside = in.size() == 1;
      const Corner lone = lone_inside ? in[0] : out[0];
      const std::vector<Corner>& others = lone_inside ? out : in;
      CaseTriangle t;
      for (int k = 0; k < 3; ++k)
        t[k] = lone_inside ? CornerPair{lone, others[k]} : CornerPair{others[k], lone};
      result.push_back(oriented(t));
    } else if (in.size() == 2) {
      // Two and two: the quad through the four crossed edges, in cyclic order (consecutive
      // edges share a corner), split along one diagonal.
      const CornerPair q[4] = {{in[0], out[0]}, {in[0], out[1]}, {in[1], out[1]}, {in[1], out[0]}};
      result.push_back(oriented({q[0], q[1], q[2]}));
      result.push_back(oriented({q[0], q[2], q[3]}));
    }
    return result;
  }

  // The cube's faces as corner cycles counter-clockwise seen from outside the cube. Along each
  // face's cycle, a crossed edge is entered going from outside to inside (an "entry") or the
  // other way; each face line runs from an entry to the next crossed edge along the cycle, so
  // on an ambiguous face the lines cut off the two inside corners. A crossed cube edge is an
  // entry of exactly one of its two faces (they run along it in opposite directions), so the
  // face lines join into closed loops; each loop, followed in line direction, winds with its
  // normal toward the outside and is cut into a fan.
  static std::vector<CaseTriangle> cube_triangles(unsigned mask) {
    auto inside = [mask](int c) { return (mask >> c & 1) != 0; };
    // next[a][b]: the edge after the crossed edge {a, b} (stored as a * 8 + b, inside first).
    int next[64];
    for (int& n : next) n = -1;
    for (int axis = 0; axis < 3; ++axis) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      for (int side = 0; side < 2; ++side) {
        int cycle[4];
        const int uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};  // counter-clockwise seen from +axis
        for (int k = 0; k < 4; ++k) {
          const int kk = side == 1 ? k : 3 - k;  // reversed on the face looking toward -axis
          cycle[k] = (side << axis) | (uv[kk][0] << u) | (uv[kk][1] << v);
        }
        for (int k = 0; k < 4; ++k) {
          const int a = cycle[k], b = cycle[(k + 1) % 4];
          if (inside(a) || !inside(b)) continue;  // not an entry (outside a -> inside b)
          for (int s = 1; s <= 3; ++s) {
            const int c = cycle[(k + s) % 4], d = cycle[(k + s + 1) % 4];
            if (inside(c) != inside(d)) {
              const int from = b * 8 + a;  // inside corner first
              next[from] = inside(c) ? c * 8 + d : d * 8 + c;
              break;
            }
          }
        }
      }
    }
    std::vector<CaseTriangle> result;
    bool used[64] = {};
    for (int start = 0; start < 64; ++start) {
      if (next[start] < 0 || used[start]) continue;
      std::vector<CornerPair> loop;
      for (int e = start; !used[e]; e = next[e]) {
        if (next[e] < 0) throw std::logic_error("genmod: continuation case tables: an open face-line chain");
        used[e] = true;
        loop.push_back({static_cast<Corner>(e / 8), static_cast<Corner>(e % 8)});
      }
      triangulate(loop, result);
    }
    return result;
  }

  // Whether two crossed cube edges lie in one cube face (their four corners agree in a
  // coordinate).
  static bool on_one_face(const CornerPair& a, const CornerPair& b) {
    const int all = a[0] & a[1] & b[0] & b[1], none = ~(a[0] | a[1] | b[0] | b[1]) & 7;
    return (all | none) != 0;
  }

  // Cuts a loop into triangles whose inner edges (chords) never join two vertices of one cube
  // face: such a chord could also be a chord of the neighbour sharing that face, and the edge
  // would then have four triangles. Chords inside the cube belong to this cube alone. Chooses,
  // by dynamic programming over the polygon, the triangulation that takes the lowest apex at
  // each step (a fan from loop[0] when it is allowed).
  static void triangulate(const std::vector<CornerPair>& loop, std::vector<CaseTriangle>& out) {
    const int n = static_cast<int>(loop.size());
    auto allowed = [&](int i, int j) { return j - i == 1 || (i == 0 && j == n - 1) || !on_one_face(loop[i], loop[j]); };
    // ok[i][j]: the sub-polygon loop[i..j] (closed by the chord i-j) can be triangulated.
    std::vector<std::vector<int>> apex(n, std::vector<int>(n, -1));
    std::vector<std::vector<bool>> ok(n, std::vector<bool>(n, false));
    for (int i = 0; i + 1 < n; ++i) ok[i][i + 1] = true;
    for (int len = 2; len < n; ++len)
      for (int i = 0; i + len < n; ++i) {
        const int j = i + len;
        if (!allowed(i, j)) continue;
        for (int k = i + 1; k < j; ++k)
          if (ok[i][k] && ok[k][j]) {
            ok[i][j] = true;
            apex[i][j] = k;
            break;
          }
      }
    if (!ok[0][n - 1]) throw std::logic_error("genmod: continuation case tables: a loop without an allowed triangulation");
    std::vector<std::pair<int, int>> todo{{0, n - 1}};
    while (!todo.empty()) {
      const auto [i, j] = todo.back();
      todo.pop_back();
      if (j - i < 2) continue;
      const int k = apex[i][j];
      out.push_back({loop[i], loop[k], loop[j]});
      todo.push_back({k, j});
      todo.push_back({i, k});
    }
  }
};

const Tables& tables() {
  static const Tables t;
  return t;
}

}  // namespace

std::span<const std::array<std::uint8_t, 4>> cube_tetrahedra() { return tables().tets; }

std::span<const CaseTriangle> tetrahedron_case(int tet, unsigned inside_mask) {
  if (tet < 0 || tet >= 6 || inside_mask >= 16)
    throw std::invalid_argument("genmod: tetrahedron_case: tetrahedron " + std::to_string(tet) + " (0..5), mask " +
                                std::to_string(inside_mask) + " (0..15)");
  return tables().tet_cases[tet][inside_mask];
}

std::span<const CaseTriangle> cube_case(unsigned inside_mask) {
  if (inside_mask >= 256)
    throw std::invalid_argument("genmod: cube_case: mask " + std::to_string(inside_mask) + " (0..255)");
  return tables().cube_cases[inside_mask];
}

}  // namespace genmod
