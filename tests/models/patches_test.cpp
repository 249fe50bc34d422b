// Multi-patch models (Model::extra_patches, model_patches): the plate's top and bottom faces
// close its side walls (their edges are the walls' edges, the patches enclose a volume), and
// the furry bear's hairs are tubes rooted in the scalp that follow hair_length and kappa.
#include "genmod/models/gallery.hpp"
#include "genmod/operators/vector.hpp"

#include "models/model_testing.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace genmod::models {
namespace {

using namespace testing;  // the shared helpers of models/model_testing.hpp

// model_patches: the main surface first, with the model's domain and periodic flags, then
// the extra patches; a model without extra patches has one.
TEST(ModelPatches, MainSurfaceFirstThenTheExtraPatches) {
  const Model& plate = find_model("offset_plate");
  const ParameterValues p = resolve_parameters(plate);
  const Fn sides = plate.build(p);
  const std::vector<ModelPatch> patches = model_patches(plate, sides, p);
  ASSERT_EQ(patches.size(), 3u);
  EXPECT_EQ(patches[0].surface.node(0), sides.node(0));
  EXPECT_TRUE(patches[0].periodic_u);
  EXPECT_FALSE(patches[0].periodic_v);
  const Model& torus = find_model("torus");
  const ParameterValues q = resolve_parameters(torus);
  const std::vector<ModelPatch> one = model_patches(torus, torus.build(q), q);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].periodic_u, torus.periodic_u);
  EXPECT_EQ(one[0].periodic_v, torus.periodic_v);
  EXPECT_EQ(one[0].u.hi(), torus.u.hi());
  const Model& beam = find_model("circular_beam");
  const ParameterValues b = resolve_parameters(beam);
  EXPECT_EQ(model_patches(beam, beam.build(b), b).size(), 6u);  // a solid: its six faces
}

// The top face is the plane z = thickness / 2 facing up, the bottom z = -thickness / 2 facing
// down, both inside the walls' edge curve (no fold out of it).
TEST(OffsetPlate, FacesArePlanarInsideTheEdgeAndFaceOutward) {
  const Model& m = find_model("offset_plate");
  for (const ParameterValues& overrides : {ParameterValues{}, ParameterValues{{"thickness", 0.5}, {"edge_radius", 0.09}}}) {
    const ParameterValues p = resolve_parameters(m, overrides);
    const double t = p.at("thickness") / 2;
    const std::vector<ModelPatch> faces = offset_plate_faces(p);
    ASSERT_EQ(faces.size(), 2u);
    Eval sides(m.build(p));
    for (int f = 0; f < 2; ++f) {
      const double z = f == 0 ? t : -t, up = f == 0 ? 1.0 : -1.0;
      const Fn face = faces[static_cast<std::size_t>(f)].surface;
      Eval s(face), normal(cross(derivative(face, 0), derivative(face, 1)));
      // The edge as a polygon for the winding number.
      std::vector<P2> edge;
      for (int i = 0; i <= 2000; ++i) {
        const auto q = sides({i / 2000.0, f == 0 ? 1.0 : 0.0});
        edge.push_back({q[0], q[1]});
      }
      for (int i = 0; i <= 30; ++i)
        for (int j = 0; j <= 30; ++j) {
          const auto q = s({i / 30.0, j / 30.0});
          EXPECT_NEAR(q[2], z, 1e-14);
          if (i == 0 || i == 30 || j == 0 || j == 30) continue;
          EXPECT_GT(up * normal({i / 30.0, j / 30.0})[2], 0.0) << f << ": " << i << ", " << j;
          double winding = 0.0;
          for (std::size_t k = 0; k + 1 < edge.size(); ++k)
            winding += std::atan2((edge[k][0] - q[0]) * (edge[k + 1][1] - q[1]) - (edge[k][1] - q[1]) * (edge[k + 1][0] - q[0]),
                                  (edge[k][0] - q[0]) * (edge[k + 1][0] - q[0]) + (edge[k][1] - q[1]) * (edge[k + 1][1] - q[1]));
          EXPECT_NEAR(winding, 2 * std::numbers::pi, 1e-6) << f << ": " << i << ", " << j;
        }
    }
  }
}

// Each face's outer edge is the walls' edge at the same u, bit for bit, so a mesher glues it
// whole; its inner edge is one point (the centre, a pole) and its u = 0 and u = 1 edges are
// one segment (the face is periodic in u); the three patches enclose the plate's volume (x, y
// and z flux volumes agree), the walls alone do not.
TEST(OffsetPlate, FacesCloseTheWalls) {
  const Model& m = find_model("offset_plate");
  const ParameterValues p = resolve_parameters(m);
  const Fn walls = m.build(p);
  const std::vector<ModelPatch> faces = offset_plate_faces(p);
  Eval s(walls), top(faces[0].surface), bottom(faces[1].surface);
  using Face = std::tuple<Eval*, double, double, double>;  // face, the walls' v, its rim s, its pole s
  for (auto [face, v, rim, pole] : {Face{&top, 1.0, 0.0, 1.0}, Face{&bottom, 0.0, 1.0, 0.0}}) {
    for (int i = 0; i <= 200; ++i) {
      const double u = i / 200.0;
      EXPECT_EQ((*face)({u, rim}), s({u, v})) << v << ", " << i;
      const auto c = (*face)({u, pole});
      EXPECT_EQ(c[0], 0.0);
      EXPECT_EQ(c[1], 0.0);
      EXPECT_EQ((*face)({0.0, u}), (*face)({1.0, u}));
    }
  }
  for (const ModelPatch& f : faces) EXPECT_TRUE(f.periodic_u);
  const auto vol = flux_volumes({{walls}, {faces[0].surface}, {faces[1].surface}}, 300);
  // About the 2 x 1.2 x 0.2 box less its rounded corners, notches and edges.
  EXPECT_GT(vol[2], 0.3);
  EXPECT_LT(vol[2], 0.48);
  // The midpoint rule converges only linearly here (the curve's speed jumps at its knots, in
  // the walls and in the faces' E x E'): at n = 300 the three are 1.5e-3, 2.1e-3 and 3e-3
  // relative from their common limit 0.4403 (n = 4800: within 1e-4), on both sides of it.
  EXPECT_NEAR(vol[0], vol[2], 6e-3 * vol[2]);
  EXPECT_NEAR(vol[1], vol[2], 6e-3 * vol[2]);
  const auto walls_only = flux_volumes({{walls}}, 300);
  EXPECT_GT(std::abs(walls_only[2] - walls_only[0]), 0.5 * vol[2]);
}

// The hairs: 2 hair_rows^2 tubes, each from a root ring on the scalp (the image of the root
// ellipse about its cell's centre) to the tip of furry_bear_hair at the centre; the scalp is
// left to its pieces, four per cell, whose r = 0 edges are the root ring bit for bit.
TEST(FurryBear, HairsStartOnTheScalpAtTheirRootRing) {
  const Model& m = find_model("furry_bear");
  const ParameterValues p = resolve_parameters(m, {{"hair_rows", 5}});
  const std::vector<ModelPatch> hairs = furry_bear_hairs(p), pieces = furry_bear_scalp_pieces(p);
  const std::vector<HairRoot> roots = furry_bear_roots(p);
  ASSERT_EQ(hairs.size(), 50u);
  ASSERT_EQ(roots.size(), 50u);
  ASSERT_EQ(pieces.size(), 220u);  // four per cell and the polar caps, ten each
  EXPECT_EQ(model_patches(m, m.build(p), p).size(), 270u);  // the whole scalp is not among them
  const Fn scalp = m.build(p);
  Eval field(furry_bear_hair(p)), surface(scalp);
  const double r = p.at("hair_radius"), length = p.at("hair_length");
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 10; ++i) {
      const std::size_t h = static_cast<std::size_t>(j * 10 + i);
      const HairRoot& root = roots[h];
      EXPECT_DOUBLE_EQ(root.u, (i + 0.5) / 10);
      EXPECT_DOUBLE_EQ(root.v, (j + 0.5) / 5);
      EXPECT_TRUE(hairs[h].periodic_u);
      Eval tube(hairs[h].surface);
      const auto f = field({root.u, root.v});
      EXPECT_NEAR(norm3(std::vector<double>{f[3] - f[0], f[4] - f[1], f[5] - f[2]}), length, 1e-12);
      for (double theta : {0.0, 0.125, 0.3125, 0.6875}) {  // dyadic: exact in both parameterizations
        // s = 0: on the scalp at the root ellipse, about hair_radius from the hair's base.
        const double phi = 2 * std::numbers::pi * theta - 0.75 * std::numbers::pi;
        const auto on_scalp = surface({root.u + root.a * std::cos(phi), root.v + root.b * std::sin(phi)});
        const auto ring = tube({theta, 0.0});
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(ring[k], on_scalp[k], 1e-14);
        EXPECT_NEAR(norm3(std::vector<double>{ring[0] - f[0], ring[1] - f[1], ring[2] - f[2]}), r, 0.05 * r);
        // s = 1: the tip.
        const auto tip = tube({theta, 1.0});
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(tip[k], f[k + 3], 1e-14);
        // The piece holding this part of the ring starts from it, bit for bit.
        const int k = std::min(3, static_cast<int>(theta * 4));
        const auto edge = Eval(pieces[4 * h + static_cast<std::size_t>(k)].surface)({theta * 4 - k, 0.0});
        for (int c = 0; c < 3; ++c) EXPECT_EQ(edge[c], ring[c]) << h << " " << theta;
      }
    }
}

// A root that does not fit in its cell is refused, naming hair_radius.
TEST(FurryBear, RootMustFitItsCell) {
  const Model& m = find_model("furry_bear");
  const std::string msg = error_of([&] { build_model(m, {{"hair_radius", 0.05}}); });
  EXPECT_NE(msg.find("'hair_radius'"), std::string::npos) << msg;
}

// The tip of one hair moves with hair_length (along the same direction) and with kappa
// (toward S_v, the combing).
TEST(FurryBear, HairsFollowHairLengthAndKappa) {
  const Model& m = find_model("furry_bear");
  auto tip = [&](const ParameterValues& overrides, std::size_t k) {
    const std::vector<ModelPatch> hairs = furry_bear_hairs(resolve_parameters(m, overrides));
    return at(hairs.at(k).surface, 0.0, 1.0);
  };
  // The hair's base: its scalp point (the tube's ring lies around it).
  auto root = [&](std::size_t k) {
    const HairRoot r = furry_bear_roots(resolve_parameters(m)).at(k);
    return at(m.build(resolve_parameters(m)), r.u, r.v);
  };
  for (std::size_t k : {0u, 37u, 150u}) {
    // Shorter (longer hairs of the top row cross at the pole and are rejected): the tip
    // moves in along the same direction by 0.03 / 0.08.
    const auto base = tip({}, k), shorter = tip({{"hair_length", 0.03}}, k), straight = tip({{"kappa", 0.0}}, k);
    const auto r = root(k);
    std::vector<double> d0(3), d1(3);
    for (int i = 0; i < 3; ++i) d0[i] = base[i] - r[i], d1[i] = shorter[i] - r[i];
    EXPECT_LT(norm3(d1), 0.5 * norm3(d0)) << k;
    EXPECT_NEAR(dot3(d0, d1) / (norm3(d0) * norm3(d1)), 1.0, 1e-3) << k;
    // kappa = 0: the hair stands along the normal, so its tip moves.
    double moved = 0.0;
    for (int i = 0; i < 3; ++i) moved += (straight[i] - base[i]) * (straight[i] - base[i]);
    EXPECT_GT(std::sqrt(moved), 0.01) << k;
  }
}

TEST(FurryBear, HairParametersAreValidated) {
  const Model& m = find_model("furry_bear");
  for (const auto& [name, value] : std::vector<std::pair<std::string, double>>{
           {"hair_rows", 0.0}, {"hair_rows", 15.0}, {"hair_rows", 2.5}, {"hair_radius", 0.0}, {"hair_length", -1.0}}) {
    const std::string msg = error_of([&] { build_model(m, {{name, value}}); });
    EXPECT_NE(msg.find("'" + name + "'"), std::string::npos) << name << ": " << msg;
  }
  // 14 rows with straight hairs (combed ones cross at the top pole: CrossingHairsAreRejected).
  EXPECT_EQ(furry_bear_hairs(resolve_parameters(m, {{"hair_rows", 14}, {"kappa", 0.0}})).size(), 392u);
}

// Hairs combed toward the top pole converge on it: at hair_rows 14 with the default kappa and
// hair_length the top row's tubes cross (4,546 intersecting triangle pairs in the mesh).
// Such combinations are rejected naming the three parameters; straight hairs (kappa 0) or
// shorter ones at 14 rows, and the defaults at 13 rows, are apart and build.
TEST(FurryBear, CrossingHairsAreRejected) {
  const Model& m = find_model("furry_bear");
  const std::string msg = error_of([&] { build_model(m, {{"hair_rows", 14}}); });
  for (const char* name : {"'hair_rows'", "'kappa'", "'hair_length'"})
    EXPECT_NE(msg.find(name), std::string::npos) << msg;
  for (const ParameterValues& ok : std::vector<ParameterValues>{{{"hair_rows", 14}, {"kappa", 0.0}},
                                                                {{"hair_rows", 14}, {"hair_length", 0.05}},
                                                                {{"hair_rows", 13}}})
    EXPECT_EQ(error_of([&] { build_model(m, ok); }), "(no exception)");
  // Long hairs cross at the default rows, too: the check is on the geometry, not on a count.
  EXPECT_NE(error_of([&] { build_model(m, {{"hair_length", 0.5}}); }).find("'hair_length'"), std::string::npos);
}

}  // namespace
}  // namespace genmod::models
