// The sphere / cylinder fillet of App. B.1 (research/snyder.md 7.11, claim 31): its ends lie
// on the cylinder and the sphere, and it is tangent-plane (G1) continuous with both, checked
// with the symbolic derivatives of the thesis's 3-input form fillet(u, v, w).
#include "genmod/models/gallery.hpp"

#include "genmod/operators/vector.hpp"
#include "models/model_testing.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace genmod::models {
namespace {

using namespace testing;  // the shared helpers of models/model_testing.hpp

const std::vector<double> kU{0.0, 0.013, 0.21, 0.37, 0.5, 0.618, 0.83, 0.97};
const std::vector<double> kW{0.0, 0.3, 0.5, 1.0};

TEST(SphereCylinderFillet, EndsLieOnTheCylinderAndTheSphere) {
  const ParameterValues p = resolve_parameters(find_model("sphere_cylinder_fillet"));
  Eval f(sphere_cylinder_fillet_family(p));
  for (double u : kU)
    for (double w : kW) {
      const auto a = f({u, 0.0, w}), b = f({u, 1.0, w});
      EXPECT_NEAR(std::hypot(a[1], a[2]), 0.6, 1e-12) << u << ", " << w;
      EXPECT_NEAR(std::sqrt(b[0] * b[0] + (b[1] + 0.1) * (b[1] + 0.1) + (b[2] - 1.5) * (b[2] - 1.5)), 0.6, 1e-12)
          << u << ", " << w;
      // [DERIVED] in snyder.md 7.11: the top of the cylinder and the bottom cap of the sphere,
      // above the circle of radius 0.4.
      const double x0 = 0.4 * std::cos(2 * std::numbers::pi * u), y0 = 0.4 * std::sin(2 * std::numbers::pi * u);
      EXPECT_NEAR(a[0], x0, 1e-12);
      EXPECT_NEAR(a[1], y0, 1e-12);
      EXPECT_NEAR(a[2], std::sqrt(0.36 - y0 * y0), 1e-12);
      EXPECT_NEAR(b[2], 1.5 - std::sqrt(0.36 - x0 * x0 - (y0 + 0.1) * (y0 + 0.1)), 1e-12);
    }
}

// Claim 31: F_u x F_v is parallel to the cylinder normal at v = 0 and to the sphere normal
// at v = 1 (|cos| > 1 - 1e-6), for every bulge w.
TEST(SphereCylinderFillet, IsTangentPlaneContinuousAtBothEnds) {
  const ParameterValues p = resolve_parameters(find_model("sphere_cylinder_fillet"));
  const Fn fillet = sphere_cylinder_fillet_family(p);
  Eval f(fillet), normal(cross(derivative(fillet, 0), derivative(fillet, 1)));
  for (double u : kU)
    for (double w : kW) {
      const auto a = f({u, 0.0, w}), na = normal({u, 0.0, w});
      const std::vector<double> cyl{0.0, a[1], a[2]};
      EXPECT_GT(std::abs(dot3(na, cyl)) / (norm3(na) * norm3(cyl)), 1 - 1e-6) << u << ", " << w;
      const auto b = f({u, 1.0, w}), nb = normal({u, 1.0, w});
      const std::vector<double> sph{b[0], b[1] + 0.1, b[2] - 1.5};
      EXPECT_GT(std::abs(dot3(nb, sph)) / (norm3(nb) * norm3(sph)), 1 - 1e-6) << u << ", " << w;
    }
}

// The model is the family at w = bulge; the bulge changes the interior; other geometry
// constants are parameters; bad values are named.
TEST(SphereCylinderFillet, BulgeIsTheThesisW) {
  const Model& m = find_model("sphere_cylinder_fillet");
  const ParameterValues p = resolve_parameters(m, {{"bulge", 0.8}});
  Eval model(m.build(p)), family(sphere_cylinder_fillet_family(p));
  for (double u : kU)
    for (double v : {0.0, 0.3, 0.5, 1.0}) {
      const auto a = model({u, v}), b = family({u, v, 0.8});
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], 1e-12);
    }
  const auto lo = family({0.2, 0.5, 0.0}), hi = family({0.2, 0.5, 1.0});
  EXPECT_GT(std::hypot(lo[0] - hi[0], lo[1] - hi[1]), 0.05);
  // Moving the sphere: the v = 1 end follows.
  Eval moved(build_model(m, {{"sphere_center_z", 2.0}, {"sphere_radius", 0.7}}));
  for (double u : kU) {
    const auto b = moved({u, 1.0});
    EXPECT_NEAR(std::sqrt(b[0] * b[0] + (b[1] + 0.1) * (b[1] + 0.1) + (b[2] - 2.0) * (b[2] - 2.0)), 0.7, 1e-12);
  }
  EXPECT_NE(error_of([&] { build_model(m, {{"bulge", 1.5}}); }).find("bulge"), std::string::npos);
  EXPECT_NE(error_of([&] { build_model(m, {{"ray_radius", 0.65}}); }).find("ray_radius"), std::string::npos);
}

}  // namespace
}  // namespace genmod::models
