// Solids, time and fields in the gallery (research/snyder.md 7.22-7.24): the circular beam
// (a generative solid), the time-varying curve (fixed arclength through integrate + inverse),
// the wing (wire product along it) and the furry bear (a hair field on a scalp).
#include "genmod/models/gallery.hpp"

#include "genmod/operators/vector.hpp"
#include "genmod/tessellate/lattice.hpp"
#include "models/model_testing.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace genmod::models {
namespace {

using namespace testing;  // the shared helpers of models/model_testing.hpp

std::vector<double> cross3(const std::vector<double>& a, const std::vector<double>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// Length of the xy trace of f(s, v) for s in [0, 1] at fixed v, as a polyline of n segments
// (one lattice evaluation: the u_t inside is computed once).
double slice_length(const Fn& f, double v, std::size_t n) {
  const std::vector<double> xyz = evaluate_lattice(f, Lattice({{0, 0.0, 1.0, n + 1}, {1, v, v, 1}}), LatticeMethod::Tables);
  const std::size_t d = f.dim();
  double length = 0;
  for (std::size_t k = 0; k < n; ++k)
    length += std::hypot(xyz[(k + 1) * d] - xyz[k * d], xyz[(k + 1) * d + 1] - xyz[k * d + 1]);
  return length;
}

// ---- circular beam (7.22) ---------------------------------------------------------------

TEST(CircularBeam, SectionsArePerpendicularToTheArc) {
  const Model& m = find_model("circular_beam");
  ASSERT_TRUE(m.solid);
  const ParameterValues p = resolve_parameters(m);
  Eval s(m.build(p));
  const double r = p.at("radius"), angle = p.at("angle"), width = p.at("width"), height = p.at("height");
  for (double w : kSamples) {
    const double th = angle * w;
    const double c[2] = {r * std::cos(th), r * std::sin(th)}, t[2] = {-std::sin(th), std::cos(th)};
    for (double u : kSamples)
      for (double v : kSamples) {
        const auto S = s({u, v, w});
        EXPECT_NEAR((S[0] - c[0]) * t[0] + (S[1] - c[1]) * t[1], 0.0, 1e-12) << u << ", " << v << ", " << w;
        EXPECT_NEAR(std::hypot(S[0] - c[0], S[1] - c[1]), width * std::abs(u - 0.5), 1e-12);
        EXPECT_NEAR(S[2], height * (v - 0.5), 1e-15);
      }
  }
}

// The six meshed faces are consistently oriented outward: the divergence-theorem volume of
// the triangles is positive and equals the integral of det J over the brick (Gauss-Legendre
// quadrature of the symbolic Jacobian), which is width height radius angle (Pappus).
TEST(CircularBeam, MeshedFacesEncloseTheJacobianVolume) {
  const Model& m = find_model("circular_beam");
  const ParameterValues p = resolve_parameters(m);
  const Fn s = m.build(p);
  const Mesh mesh = mesh_model(m, s, 64);
  double mesh_volume = 0;
  for (const auto& tri : mesh.triangles) {
    const auto& a = mesh.vertices[tri[0]];
    const auto& b = mesh.vertices[tri[1]];
    const auto& c = mesh.vertices[tri[2]];
    mesh_volume += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                    a[2] * (b[0] * c[1] - b[1] * c[0])) / 6.0;
  }
  const Fn det = dot(derivative(s, 0), cross(derivative(s, 1), derivative(s, 2)));
  Eval jac(det);
  const double gx[3] = {0.5 - 0.5 * std::sqrt(0.6), 0.5, 0.5 + 0.5 * std::sqrt(0.6)};
  const double gw[3] = {5.0 / 18, 8.0 / 18, 5.0 / 18};
  double integral = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        const double d = jac({gx[i], gx[j], gx[k]})[0];
        EXPECT_GT(d, 0.0);
        integral += gw[i] * gw[j] * gw[k] * d;
      }
  const double exact = p.at("width") * p.at("height") * p.at("radius") * p.at("angle");
  EXPECT_NEAR(integral, exact, 1e-12 * exact);
  EXPECT_GT(mesh_volume, 0.0);
  EXPECT_NEAR(mesh_volume / integral, 1.0, 1e-3);
  EXPECT_NE(error_of([&] { build_model(m, {{"width", 2.5}}); }).find("width"), std::string::npos);
}

// ---- time-varying curve (7.23) ----------------------------------------------------------

// Every time slice of the space-time surface is the curve c(., t) truncated at arclength
// lambda: dense polyline length ~ lambda; the root is fixed; z = t.
TEST(TimeVaryingCurve, EveryTimeSliceHasArclengthLambda) {
  const Model& m = find_model("time_varying_curve");
  for (double lambda : {1.0, 1.7}) {
    const ParameterValues p = resolve_parameters(m, {{"arclength", lambda}});
    const Fn s = m.build(p);
    for (double v : {0.0, 0.15, 0.5, 0.77, 1.0})
      EXPECT_NEAR(slice_length(s, v, 20000), lambda, 1e-4) << "lambda " << lambda << ", v " << v;
    Eval e(s), end(time_varying_curve_end(p)), c(time_varying_curve_c(p));
    for (double v : kSamples) {
      const double t = -0.1 + v;
      const auto root = e({0.0, v});
      EXPECT_EQ(root[0], 0.0);
      EXPECT_EQ(root[1], 0.0);
      EXPECT_NEAR(root[2], t, 1e-15);
      const double ut = end({0.0, t})[0];
      EXPECT_GT(ut, 0.0);
      EXPECT_LE(ut, lambda);  // |dc/du| >= 1
      for (double sp : {0.3, 1.0}) {
        const auto S = e({sp, v}), q = c({sp * ut, t});
        EXPECT_NEAR(S[0], q[0], 1e-10);
        EXPECT_NEAR(S[1], q[1], 1e-10);
      }
    }
  }
  // The finite form (not the printed 1 / (2 u^2)): c(u, t) = (u, a u^2 sin(2 pi (t - 0.1 u))).
  const ParameterValues p = resolve_parameters(m);
  Eval c(time_varying_curve_c(p));
  EXPECT_NEAR(c({0.8, 0.3})[1], 0.5 * 0.64 * std::sin(2 * std::numbers::pi * (0.3 - 0.08)), 1e-15);
}

// ---- wing (7.23) ------------------------------------------------------------------------

TEST(Wing, IsAWireProductAlongTheCurveAtItsTime) {
  const Model& m = find_model("wing");
  const ParameterValues p = resolve_parameters(m);
  expect_wire_product(m.build(p), wing_cross(p), wing_wire(p));
  Eval s(m.build(p)), wire(wing_wire(p));
  // The spar is the time-varying curve's slice at the wing's time: same points, span lambda.
  const double time = p.at("time");
  Eval slice(build_model(find_model("time_varying_curve")));
  for (double v : kSamples) {
    const auto a = wire({0.0, v}), b = slice({v, time + 0.1});
    EXPECT_NEAR(a[0], b[0], 1e-9);
    EXPECT_NEAR(a[1], b[1], 1e-9);
  }
  double length = 0;
  for (int k = 0; k < 20000; ++k) {
    const auto a = wire({0.0, k / 20000.0}), b = wire({0.0, (k + 1) / 20000.0});
    length += std::hypot(b[0] - a[0], b[1] - a[1]);
  }
  EXPECT_NEAR(length, p.at("arclength"), 1e-4);
  // Another time, another wing: the tip moves.
  Eval later(build_model(m, {{"time", time + 0.5}}));
  const auto tip0 = s({0.25, 1.0}), tip1 = later({0.25, 1.0});
  EXPECT_GT(std::hypot(tip0[0] - tip1[0], tip0[1] - tip1[1]), 0.1);
}

// ---- furry bear (7.24) ------------------------------------------------------------------

TEST(FurryBear, HairGrowsFromTheScalpCombedTowardSv) {
  const Model& m = find_model("furry_bear");
  for (double kappa : {0.0, 1.5, 4.0}) {
    const ParameterValues p = resolve_parameters(m, {{"kappa", kappa}, {"hair_length", 0.12}});
    // The scalp depends on `size` only. It is built at the default hair_length: hairs of 0.12
    // combed toward the top pole cross there, which the model rejects (its tubes would
    // intersect), while the field itself is defined.
    const Fn scalp = m.build(resolve_parameters(m));
    Eval s(scalp), hair(furry_bear_hair(p));
    Eval su(derivative(scalp, 0)), sv(derivative(scalp, 1));
    for (double u : kSamples)
      for (double v : {0.05, 0.21, 0.37, 0.5, 0.618, 0.83, 0.95}) {
        const auto S = s({u, v}), V = hair({u, v});
        ASSERT_EQ(V.size(), 6u);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(V[k], S[k], 1e-15);  // base on the scalp
        const std::vector<double> d{V[3] - V[0], V[4] - V[1], V[5] - V[2]};
        EXPECT_NEAR(norm3(d), 0.12, 1e-12);
        const auto Su = su({u, v}), Sv = sv({u, v});
        const auto N = cross3(Su, Sv);
        // Leans from N toward S_v by atan(kappa |S_v| / |N|), in the plane of N and S_v.
        const double expected = std::atan(kappa * norm3(Sv) / norm3(N));
        EXPECT_NEAR(std::atan2(norm3(cross3(d, N)), dot3(d, N)), expected, 1e-9)
            << kappa << ": " << u << ", " << v;
        EXPECT_NEAR(dot3(d, cross3(N, Sv)) / (norm3(d) * norm3(N) * norm3(Sv)), 0.0, 1e-12);
        if (kappa > 0) {
          EXPECT_GT(dot3(d, Sv), 0.0);
        }
        // The scalp is a surface of revolution of the profile, outward normal.
        EXPECT_GT(dot3(N, std::vector<double>{S[0], S[1], 0.0}) + (std::hypot(S[0], S[1]) < 1e-9 ? 1.0 : 0.0), 0.0);
      }
  }
  EXPECT_NE(error_of([&] { build_model(m, {{"kappa", -1.0}}); }).find("kappa"), std::string::npos);
  EXPECT_NE(error_of([&] { build_model(m, {{"hair_length", 0.0}}); }).find("hair_length"), std::string::npos);
}

}  // namespace
}  // namespace genmod::models
