// The first touch of a support and the membrane estimate of the deflection for a load
// (analysis/first_touch.hpp), on hand-placed tread points.
#include "tirefem/analysis/first_touch.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace tirefem {
namespace {

// Points of a circle of the radius about the axis at axis_z (radius 300.3 at 300: a tyre grown by 0.3 mm).
std::vector<Eigen::Vector3d> ring(double radius, double axis_z) {
  std::vector<Eigen::Vector3d> x;
  for (int k = -10; k <= 10; ++k) {
    const double phi = 0.013 * k + 0.004;  // no point exactly at φ = 0
    x.emplace_back(0.0, radius * std::sin(phi), axis_z - radius * std::cos(phi));
  }
  return x;
}

double deepest_penetration(const std::vector<Eigen::Vector3d>& x, const SupportSurface& s, double deflection) {
  double g = -1e300;
  for (const auto& p : x) g = std::max(g, s.penetration(p, deflection).value);
  return g;
}

TEST(FirstTouchDeflection, PlaneTouchesTheLowestPoint) {
  // On the axis height of its radius, the lowest point (φ = 0.004) is 300 (1 − cos 0.004) above the road:
  // the plane touches it at that δz.
  const auto x = ring(300.0, 300.0);
  const RoadPlane plane;
  const double ft = first_touch_deflection(x, plane);
  EXPECT_NEAR(ft, 300.0 * (1.0 - std::cos(0.004)), 1e-12);
  EXPECT_NEAR(deepest_penetration(x, plane, ft), 0.0, 1e-12);
  // Grown by 0.3 mm: it presses at δz = 0 and touches 0.3 mm earlier.
  const auto grown = ring(300.3, 300.0);
  const double ft_grown = first_touch_deflection(grown, plane);
  EXPECT_NEAR(ft_grown - ft, -0.3 * std::cos(0.004), 1e-12);
  EXPECT_GT(deepest_penetration(grown, plane, 0.0), 0.0);
}

TEST(FirstTouchDeflection, DrumGapIsZeroThere) {
  const auto x = ring(300.3, 300.0);
  const TestDrum drum(915.0);
  const double ft = first_touch_deflection(x, drum);
  EXPECT_NEAR(deepest_penetration(x, drum, ft), 0.0, 1e-12);
  EXPECT_LT(deepest_penetration(x, drum, ft - 1e-6), 0.0);
  EXPECT_GT(deepest_penetration(x, drum, ft + 1e-6), 0.0);
  // The lowest point is near y = 0, where the drum and the plane agree to the drum's curvature.
  EXPECT_NEAR(ft, first_touch_deflection(x, RoadPlane()), 1e-3);
}

TEST(EstimatedDeflectionForLoad, PressureTimesTheAreaCutOff) {
  // Points 1 mm² each at heights 0, 1, 2, …, 9 mm: at δz the points below δz are cut off.
  std::vector<TreadPoint> points(10);
  std::vector<Eigen::Vector3d> x;
  for (int k = 0; k < 10; ++k) {
    points[k].weight = 1.0;
    x.emplace_back(0.0, 0.0, static_cast<double>(k));
  }
  const RoadPlane plane;
  // p = 2 MPa, full model: 3 points (6 N) need δz just above 2 mm.
  const double d = estimated_deflection_for_load(points, x, plane, 2.0, false, 6.0, 0.0, 20.0);
  EXPECT_GT(d, 2.0);
  EXPECT_LT(d, 2.0 + 2e-3);
  // A half model counts each point twice: 6 N are 2 points.
  const double h = estimated_deflection_for_load(points, x, plane, 2.0, true, 6.0, 0.0, 20.0);
  EXPECT_GT(h, 1.0);
  EXPECT_LT(h, 1.0 + 2e-3);
  // Not reached within the range: its end.
  EXPECT_EQ(estimated_deflection_for_load(points, x, plane, 2.0, false, 1e6, 0.0, 20.0), 20.0);
}

}  // namespace
}  // namespace tirefem
