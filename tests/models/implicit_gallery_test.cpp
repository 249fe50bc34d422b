// The implicit gallery: each model meshes into a valid closed mesh in its box, with the
// topology its description promises; sphere_gyroid is data/sphere_gyroid.vm; parameters are
// checked.
#include "genmod/kernel/point_evaluator.hpp"
#include "genmod/kernel/vm_format.hpp"
#include "genmod/models/implicit_gallery.hpp"
#include "genmod/tessellate/validate.hpp"

#include <gtest/gtest.h>

#include <random>

namespace genmod::models {
namespace {

TEST(ImplicitGallery, EveryModelMeshesValid) {
  ASSERT_EQ(implicit_gallery().size(), 13u);
  for (const ImplicitModel& m : implicit_gallery()) {
    SCOPED_TRACE(m.name);
    const ImplicitMesh mesh = mesh_implicit(build_implicit_model(m), m.box, {.min_feature = 2 * m.min_feature});
    const MeshValidity v = validate(mesh.mesh);
    EXPECT_TRUE(v.valid()) << describe(v);
    EXPECT_GT(v.triangles, 100u);
    if (m.name == "tanglecube") {
      EXPECT_EQ(v.euler_characteristic, -8);
    }
    if (m.name == "drilled_block") {
      EXPECT_EQ(v.euler_characteristic, 0);
    }
    if (m.name == "starfish" || m.name == "tee" || m.name == "rotated_pair" || m.name == "ramiform" ||
        m.name == "arc_convolution" || m.name == "arm" || m.name == "hand" || m.name == "polygon_slab") {
      EXPECT_EQ(v.components, 1u);
      EXPECT_EQ(v.euler_characteristic, 2);
    }
    if (m.name == "blobby") {
      EXPECT_EQ(v.components, 4u);
      EXPECT_EQ(v.euler_characteristic, 8);
    }
  }
}

TEST(ImplicitGallery, SphereGyroidIsTheBenchmarkFile) {
  const Fn model = build_implicit_model(*find_implicit_model("sphere_gyroid"));
  const Fn file = load_vm(std::string(GENMOD_DATA_DIR) + "/sphere_gyroid.vm");
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-5, 5);
  for (int i = 0; i < 1000; ++i) {
    const std::vector<double> p{u(rng), u(rng), u(rng)};
    EXPECT_NEAR(evaluate(model, p)[0], evaluate(file, p)[0], 1e-12);
  }
}

TEST(ImplicitGallery, ParametersAreChecked) {
  const ImplicitModel* m = find_implicit_model("drilled_block");
  ASSERT_NE(m, nullptr);
  EXPECT_EQ(find_implicit_model("teapot"), nullptr);
  EXPECT_THROW(build_implicit_model(*m, {{"radius", 1.0}}), std::invalid_argument);
  EXPECT_THROW(build_implicit_model(*m, {{"hole_radius", 2.0}}), std::invalid_argument);
  EXPECT_THROW(build_implicit_model(*m, {{"half_side", -1.0}}), std::invalid_argument);
  EXPECT_NO_THROW(build_implicit_model(*m, {{"hole_radius", 0.25}}));
}

}  // namespace
}  // namespace genmod::models
