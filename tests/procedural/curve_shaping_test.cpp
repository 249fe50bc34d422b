#include "genmod/procedural/curve_shaping.hpp"
#include "genmod/procedural/grid_box.hpp"
#include "mesh_test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <random>

namespace genmod {
namespace {

using test::faces_with_centroid_in;
using test::mesh_difference;

bool same_bits(double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; }

// Distance from p to the segment [a, b] in the xy plane.
double distance_to_segment_xy(const Vec3& p, const Vec3& a, const Vec3& b) {
  const double ux = b[0] - a[0], uy = b[1] - a[1];
  const double t = std::clamp(((p[0] - a[0]) * ux + (p[1] - a[1]) * uy) / (ux * ux + uy * uy), 0.0, 1.0);
  return std::hypot(p[0] - a[0] - t * ux, p[1] - a[1] - t * uy);
}

std::vector<int> vertices_of(const PolyMesh& mesh, const FaceList& faces) {
  std::vector<int> out;
  for (auto f : faces)
    for (auto v : mesh.fv_range(f)) out.push_back(v.idx());
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// Claim 26 with a straight line: on the line (seen along z), z bitwise kept, displacement along
// the projected direction, misses and unselected vertices unmoved.
TEST(CurveShaping, StraightLineClaim26) {
  PolyMesh mesh = make_grid_box(Vec3(0, 0, 0), Vec3(1, 1, 1), 4);
  const PolyMesh before = mesh;
  const FaceList side = faces_with_centroid_in(mesh, Vec3(1, -1, -1), Vec3(1, 2, 2));  // the +x face
  ASSERT_EQ(side.size(), 16u);
  const Vec3 a(1.5, 0.3, 5.0), b(2.0, 2.0, 5.0);  // covers y in [0.3, 2]: rows y = 0, 0.25 miss
  const std::size_t met = shape_to_curve(mesh, side, BezierCurve({a, b}), Vec3(1, 0, 0.3), Vec3(0, 0, 2));
  EXPECT_EQ(met, 15u);  // y in {0.5, 0.75, 1} x 5 values of z
  const std::vector<int> selected = vertices_of(before, side);
  for (auto v : mesh.vertices()) {
    const Vec3 &p0 = before.point(v), &p = mesh.point(v);
    const bool in_selection = std::binary_search(selected.begin(), selected.end(), v.idx());
    EXPECT_TRUE(same_bits(p[2], p0[2]));  // along the normal
    EXPECT_TRUE(same_bits(p[1], p0[1]));  // displacement is along x only
    if (!in_selection || p0[1] < 0.3) {
      EXPECT_TRUE(same_bits(p[0], p0[0])) << v.idx();
    } else {
      EXPECT_LE(distance_to_segment_xy(p, a, b), 1e-9) << v.idx();
      EXPECT_GT(p[0], 1.5 - 1e-12);
    }
  }
}

// A tilted normal and a curve behind the vertices: they move back (negative s), stay on the
// projected curve, keep p . n up to rounding, and move parallel to the projected direction.
TEST(CurveShaping, TiltedNormalAndBackwardMoves) {
  PolyMesh mesh = make_grid_box(Vec3(0, 0, 0), Vec3(1, 1, 1), 3);
  const PolyMesh before = mesh;
  const FaceList side = faces_with_centroid_in(mesh, Vec3(1, -1, -1), Vec3(1, 2, 2));
  const Vec3 n = Vec3(0, 1, 1) / std::sqrt(2.0);
  const BezierCurve curve({Vec3(0.6, -3, 0), Vec3(0.2, 0, 0.5), Vec3(0.7, 3, 0)});
  const Vec3 direction(2, 0.5, -0.5);  // already perpendicular to n
  const Vec3 d = direction / direction.norm();
  const std::size_t met = shape_to_curve(mesh, side, curve, direction, n);
  EXPECT_EQ(met, 16u);
  for (int index : vertices_of(before, side)) {
    const PolyMesh::VertexHandle v(index);
    const Vec3 move = mesh.point(v) - before.point(v);
    EXPECT_LT(move[0], 0.0);
    EXPECT_NEAR(OpenMesh::dot(mesh.point(v), n), OpenMesh::dot(before.point(v), n), 1e-12);
    EXPECT_NEAR(OpenMesh::cross(move, d).norm(), 0.0, 1e-12);
    // On the projected curve, checked independently of intersect_line: the in-plane distance
    // to the curve, minimised by a coarse scan and a ternary search around its best sample.
    auto in_plane_distance = [&](double t) {
      const Vec3 q = curve.evaluate(t) - mesh.point(v);
      return (q - n * OpenMesh::dot(q, n)).norm();
    };
    int best = 0;
    for (int k = 1; k <= 2000; ++k)
      if (in_plane_distance(k / 2000.0) < in_plane_distance(best / 2000.0)) best = k;
    double lo = std::max(0.0, (best - 1) / 2000.0), hi = std::min(1.0, (best + 1) / 2000.0);
    for (int iteration = 0; iteration < 200; ++iteration) {
      const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
      (in_plane_distance(m1) < in_plane_distance(m2) ? hi : lo) = (in_plane_distance(m1) < in_plane_distance(m2) ? m2 : m1);
    }
    EXPECT_LT(in_plane_distance(0.5 * (lo + hi)), 1e-9) << index;
  }
}

// Claim 27: at every resolution each shaped vertex is on the curve, and the Hausdorff distance
// between the shaped top boundary polyline and the curve decreases with resolution.
TEST(CurveShaping, LodIndependenceClaim27) {
  // y(t) = t exactly (control points equally spaced in y), so each row y meets it once.
  const BezierCurve curve({Vec3(1.2, 0, 0), Vec3(2.0, 1.0 / 3, 0), Vec3(0.8, 2.0 / 3, 0), Vec3(1.5, 1, 0)});
  std::vector<Vec3> dense;
  for (int k = 0; k <= 20000; ++k) dense.push_back(curve.evaluate(k / 20000.0));
  auto distance_to_polyline = [](const Vec3& p, const std::vector<Vec3>& line) {
    double best = INFINITY;
    for (std::size_t i = 0; i + 1 < line.size(); ++i) best = std::min(best, distance_to_segment_xy(p, line[i], line[i + 1]));
    return best;
  };
  double previous = INFINITY;
  for (int n : {2, 4, 8, 16, 32}) {
    PolyMesh mesh = make_grid_box(Vec3(0, 0, 0), Vec3(1, 1, 1), n);
    const FaceList side = faces_with_centroid_in(mesh, Vec3(1, -1, -1), Vec3(1, 2, 2));
    const std::size_t met = shape_to_curve(mesh, side, curve, Vec3(1, 0, 0), Vec3(0, 0, 1));
    EXPECT_EQ(met, static_cast<std::size_t>((n + 1) * (n + 1)));
    std::map<double, Vec3> top;  // the shaped vertices of the top edge (z = 1), by y
    for (int index : vertices_of(mesh, side)) {
      const Vec3& p = mesh.point(PolyMesh::VertexHandle(index));
      // On the curve: with y(t) = t, the curve point of this row is at t = y.
      EXPECT_NEAR(p[0], curve.evaluate(p[1])[0], 1e-9) << n;
      if (p[2] == 1.0) top[p[1]] = p;
    }
    ASSERT_EQ(top.size(), static_cast<std::size_t>(n + 1));
    std::vector<Vec3> polyline;
    for (const auto& [y, p] : top) polyline.push_back(p);
    double hausdorff = 0.0;
    for (const Vec3& q : dense) hausdorff = std::max(hausdorff, distance_to_polyline(q, polyline));
    for (std::size_t i = 0; i + 1 < polyline.size(); ++i)
      for (int k = 0; k <= 20; ++k) {
        const Vec3 q = polyline[i] + (polyline[i + 1] - polyline[i]) * (k / 20.0);
        hausdorff = std::max(hausdorff, distance_to_polyline(q, dense));
      }
    EXPECT_LT(hausdorff, previous) << "resolution " << n;
    previous = hausdorff;
  }
  EXPECT_LT(previous, 2e-3);
}

// The tools' contract (issue 12) for curve shaping: it moves vertices only, so a closed
// 2-manifold keeps its element counts and stays closed and manifold; a curve the moves keep
// clear of the rest of the solid leaves it valid (no self-intersection), and the same input
// gives the same bytes.
TEST(CurveShaping, ClosedMeshStaysClosedValidAndDeterministic) {
  const PolyMesh box = make_grid_box(Vec3(0, 0, 0), Vec3(2, 1, 1), 6);
  const FaceList top = faces_with_centroid_in(box, Vec3(-1, -1, 1), Vec3(3, 2, 1));
  ASSERT_EQ(top.size(), 36u);
  // An arch across x over the top (apex 0.5 above it) and a dip into it (apex 0.1 below, less
  // than a cell's 1/6: a deeper dip would pull the side walls' top vertices below their next
  // row and fold the walls, a self-intersection of the shape asked for, not of the tool), each
  // moving the top's vertices along z, seen along y.
  for (double rise : {1.0, -0.2}) {
    SCOPED_TRACE("control point " + std::to_string(rise) + " above the top");
    const BezierCurve arch({Vec3(0, 0, 1), Vec3(1, 0, 1 + rise), Vec3(2, 0, 1)});
    PolyMesh a = box, b = box;
    EXPECT_EQ(shape_to_curve(a, top, arch, Vec3(0, 0, 1), Vec3(0, 1, 0)), 49u);  // every top vertex
    shape_to_curve(b, top, arch, Vec3(0, 0, 1), Vec3(0, 1, 0));
    EXPECT_EQ(mesh_difference(a, b), "");
    EXPECT_EQ(a.n_vertices(), box.n_vertices());
    EXPECT_EQ(a.n_edges(), box.n_edges());
    EXPECT_EQ(a.n_faces(), box.n_faces());
    EXPECT_NE(mesh_difference(a, box), "");
    test::expect_valid_closed(a);
  }
}

TEST(CurveShaping, EmptySelectionIsANoOpClaim18) {
  PolyMesh mesh = make_grid_box(Vec3(0, 0, 0), Vec3(1, 1, 1), 2);
  const PolyMesh before = mesh;
  const BezierCurve curve({Vec3(0, 0, 0), Vec3(1, 1, 0)});
  EXPECT_EQ(shape_to_curve(mesh, {}, curve, Vec3(1, 0, 0), Vec3(0, 0, 1)), 0u);
  // Even with vectors that would be refused: a curve built from an empty selection's bounds.
  EXPECT_NO_THROW(shape_to_curve(mesh, {}, curve, Vec3(NAN, 0, 0), Vec3(0, 0, 0)));
  EXPECT_EQ(mesh_difference(mesh, before), "");
}

TEST(CurveShaping, BadInputIsRefusedAndLeavesTheMesh) {
  PolyMesh mesh = make_grid_box(Vec3(0, 0, 0), Vec3(1, 1, 1), 2);
  const PolyMesh before = mesh;
  const FaceList some{mesh.face_handle(0)};
  const BezierCurve curve({Vec3(0, 0, 0), Vec3(1, 1, 0)});
  auto refused = [&](const FaceList& faces, const Vec3& d, const Vec3& n, const std::string& words) {
    try {
      shape_to_curve(mesh, faces, curve, d, n);
      ADD_FAILURE() << "no exception for " << words;
    } catch (const std::invalid_argument& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("shape_to_curve"), std::string::npos) << what;
      EXPECT_NE(what.find(words), std::string::npos) << what;
    }
  };
  refused({PolyMesh::FaceHandle(999)}, Vec3(1, 0, 0), Vec3(0, 0, 1), "not in the mesh");
  refused({PolyMesh::FaceHandle()}, Vec3(1, 0, 0), Vec3(0, 0, 1), "not in the mesh");
  refused(some, Vec3(NAN, 0, 0), Vec3(0, 0, 1), "direction is not finite");
  refused(some, Vec3(1, 0, 0), Vec3(0, INFINITY, 1), "normal is not finite");
  refused(some, Vec3(1, 0, 0), Vec3(0, 0, 0), "normal is zero");
  refused(some, Vec3(0, 0, 3), Vec3(0, 0, 1), "parallel");
  EXPECT_EQ(mesh_difference(mesh, before), "");
  EXPECT_THROW(BezierCurve({Vec3(0, 0, 0)}), std::invalid_argument);
  EXPECT_THROW(BezierCurve({Vec3(0, 0, 0), Vec3(NAN, 0, 0)}), std::invalid_argument);
}

// The line-curve intersection on its own: the nearest of several hits, tangency, a miss, and a
// curve lying along the line.
TEST(CurveShaping, LineCurveIntersection) {
  const Vec3 x(1, 0, 0), z(0, 0, 1);
  // A parabola-like arch over x in [0, 4], peak y = 1 at x = 2; the line y = 0.5 meets it twice.
  const BezierCurve arch({Vec3(0, 0, 0), Vec3(2, 2, 0), Vec3(4, 0, 0)});
  auto hit = intersect_line(arch, Vec3(3.5, 0.5, 7), x, z);
  ASSERT_TRUE(hit);
  // y(t) = 4t(1 - t) = 0.5 at t = (1 +- sqrt(0.5)) / 2; x = 4t; the nearer to x = 3.5 is the larger.
  EXPECT_NEAR(3.5 + hit->s, 2.0 * (1 + std::sqrt(0.5)), 1e-12);
  EXPECT_NEAR(hit->t, (1 + std::sqrt(0.5)) / 2, 1e-12);
  hit = intersect_line(arch, Vec3(0.5, 0.5, 0), x, z);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(0.5 + hit->s, 2.0 * (1 - std::sqrt(0.5)), 1e-12);
  // Tangent at the peak.
  hit = intersect_line(arch, Vec3(-1, 1, 0), x, z);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->s, 3.0, 1e-5);
  EXPECT_FALSE(intersect_line(arch, Vec3(0, 1.001, 0), x, z));
  // A straight curve along the line: a point on it stays, a point beyond it goes to its end.
  const BezierCurve segment({Vec3(0, 0, 0), Vec3(1, 0, 0)});
  hit = intersect_line(segment, Vec3(0.25, 0, 0), x, z);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->s, 0.0, 1e-12);
  hit = intersect_line(segment, Vec3(3, 0, 0), x, z);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->s, -2.0, 1e-12);
}

// Random lines against a wiggly degree-5 curve, against a brute-force scan (dense sign changes
// of the distance across the line, refined by bisection): intersect_line finds a genuine hit
// whenever the scan does, and none farther than the scan's nearest.
TEST(CurveShaping, LineCurveIntersectionAgreesWithABruteForceScan) {
  const BezierCurve curve({Vec3(0, 0, 1), Vec3(1, 3, -2), Vec3(2, -3, 0), Vec3(3, 3, 4), Vec3(4, -3, 0), Vec3(5, 0, 2)});
  const Vec3 z(0, 0, 1);
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> coordinate(-1.0, 6.0), angle(0.0, 6.283185307179586);
  int hits = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 origin(coordinate(rng), coordinate(rng) - 2.5, coordinate(rng));
    const double phi = angle(rng);
    const Vec3 d(std::cos(phi), std::sin(phi), 0.0);
    const Vec3 across = OpenMesh::cross(z, d);
    auto g = [&](double t) { return OpenMesh::dot(curve.evaluate(t) - origin, across); };
    double nearest = INFINITY;
    constexpr int samples = 20000;
    for (int k = 0; k < samples; ++k) {
      double lo = static_cast<double>(k) / samples, hi = static_cast<double>(k + 1) / samples;
      if ((g(lo) < 0.0) == (g(hi) < 0.0)) continue;
      for (int it = 0; it < 60; ++it) {
        const double m = 0.5 * (lo + hi);
        ((g(m) < 0.0) == (g(lo) < 0.0) ? lo : hi) = m;
      }
      nearest = std::min(nearest, std::abs(OpenMesh::dot(curve.evaluate(lo) - origin, d)));
    }
    const auto hit = intersect_line(curve, origin, d, z);
    if (std::isfinite(nearest)) {
      ASSERT_TRUE(hit) << trial;
      ++hits;
    }
    if (hit) {
      EXPECT_LE(std::abs(g(hit->t)), 1e-9) << trial;
      EXPECT_NEAR(hit->s, OpenMesh::dot(curve.evaluate(hit->t) - origin, d), 1e-9) << trial;
      EXPECT_LE(std::abs(hit->s), nearest + 1e-9) << trial;
    }
  }
  EXPECT_GT(hits, 50);  // the scan found hits often enough for the test to mean something
}

}  // namespace
}  // namespace genmod
