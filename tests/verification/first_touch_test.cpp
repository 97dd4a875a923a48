// The inflated tyre's first touch of the support (analysis/first_touch.hpp) and the studies measured from
// it (deflection_from = "first_touch"), footprints at a given deflection, and the footprint search's start
// from the membrane estimate, on a coarse mesh of the example tyre.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "contact_support.hpp"
#include "tirefem/report/inflation_report.hpp"
#include "tirefem/report/shell_results.hpp"

namespace tirefem::verification {
namespace {

// 36 × 8 as the load-step independence tests, whose tolerance (1e-10) makes two paths to one equilibrium
// agree to 1e-6 in Qz.
const TyreMesh& mesh() {
  static const TyreMesh tm = build_tyre_mesh(example_case().tyre, coarse_mesh(36, 8));
  return tm;
}

const InflationResult& inflated() {
  static const InflationResult r = inflate_for_contact(mesh(), example_case().inflation);
  return r;
}

ContactSettings settings() {
  ContactSettings s = test_contact_settings();
  s.residual_tolerance = 1e-10;
  return s;
}

StaticContactResult curve(LoadCurveStudy study, DeflectionOrigin origin) {
  study.deflection_from = origin;
  const Case& c = example_case();
  return run_load_curve(mesh(), c.tyre, c.inflation, settings(), study, {}, &inflated());
}

FootprintStudy footprint(const SupportDescription& support, DeflectionOrigin origin) {
  FootprintStudy f;
  f.name = "f";
  f.support = support;
  f.deflection_from = origin;
  return f;
}

StaticContactResult run(const FootprintStudy& f) {
  const Case& c = example_case();
  return run_footprint(mesh(), c.tyre, c.inflation, settings(), f, {}, &inflated());
}

// The first touch is where the inflated tread surface is lowest. A tread point moves with the breaker
// face, so at the equator under the axle the surface has sunk by the crown's radial growth there. On this
// mesh the lowest point is the tread point nearest there (s = 1.4 mm, φ = −0.3°), and the first touch is
// minus the crown growth (crown_radius_growth_mm, the mean over the circumference) to 0.016 mm. (On the
// 120 × 46 mesh the growth under the axle, 0.558 mm at s = 1.7 mm, exceeds that mean, 0.506 mm, and the
// first touch is −0.551 mm.) The drum (1.83 m) touches at the same point; the plane's gap there is zero.
TEST(FirstTouch, IsMinusTheCrownGrowthOnPlaneAndDrum) {
  const Case& c = example_case();
  const auto elements = evaluate_element_results(mesh(), c.tyre, inflated().displacement, Kinematics::nonlinear);
  const double growth = summarize_inflation(mesh(), inflated().displacement, elements).crown_radius_growth_mm;
  FootprintStudy plane = footprint(plane_support(), DeflectionOrigin::first_touch);
  plane.deflection = 0.0;
  FootprintStudy drum = footprint(drum_support(1830.0), DeflectionOrigin::first_touch);
  drum.deflection = 0.0;
  const StaticContactResult p = run(plane), d = run(drum);
  ASSERT_TRUE(p.completed) << p.failure;
  ASSERT_TRUE(d.completed) << d.failure;
  std::printf("  crown growth %.5f mm; first touch: plane %.5f mm, drum %.5f mm; Qz there %.2e N, %.2e N\n", growth,
              p.first_touch_deflection_mm, d.first_touch_deflection_mm, p.points.back().patch.Qz_N,
              d.points.back().patch.Qz_N);
  std::size_t deepest = 0;
  for (std::size_t q = 0; q < p.tread_points.size(); ++q)
    if (p.final_state.tread[q].penetration > p.final_state.tread[deepest].penetration) deepest = q;
  std::printf("  deepest tread point at s = %.3f mm, φ = %.4f rad, z = %.5f mm\n", p.tread_points[deepest].u,
              p.tread_points[deepest].v, p.final_state.tread[deepest].position.z());
  EXPECT_LT(p.tread_points[deepest].u, 2.0);
  EXPECT_LT(std::abs(p.tread_points[deepest].v), 0.01);
  // To the contact solve's remainder: the solve at the first touch starts from the inflated state and
  // moves it by the Newton tolerance (residual 1e-8 of ~0.5 mm displacements: nanometres), not to 1e-12.
  EXPECT_NEAR(p.final_state.tread[deepest].position.z(), p.first_touch_deflection_mm, 1e-9);
  EXPECT_NEAR(p.final_state.tread[deepest].penetration, 0.0, 1e-9);
  EXPECT_LT(p.first_touch_deflection_mm, 0.0);
  EXPECT_NEAR(p.first_touch_deflection_mm, -growth, 0.02);
  EXPECT_NEAR(d.first_touch_deflection_mm, p.first_touch_deflection_mm, 0.02);
  // At the first touch the deepest tread point is at g = 0 (to round-off): no load.
  ASSERT_EQ(p.points.size(), 1u);
  EXPECT_NEAR(p.final_state.deflection_mm, p.first_touch_deflection_mm, 1e-15);
  EXPECT_LT(std::abs(p.points.back().patch.Qz_N), 1e-6);
  EXPECT_LT(std::abs(d.points.back().patch.Qz_N), 1e-6);
}

// The curve measured from the first touch is the curve from the undeformed tyre shifted by the first touch:
// at d from the first touch Qz equals Qz at d + first touch from the undeformed tyre (the same equilibrium,
// reached on other paths, to the Newton tolerance); its first point carries no load, while the undeformed
// origin's first point (δz = 0) already presses.
TEST(FirstTouch, LoadCurveFromFirstTouchIsTheShiftedCurve) {
  const StaticContactResult b = curve(load_curve("b", plane_support(), 6.0, 2), DeflectionOrigin::first_touch);
  ASSERT_TRUE(b.completed) << b.failure;
  const double ft = b.first_touch_deflection_mm;
  const StaticContactResult a = curve(load_curve("a", plane_support(), 6.0 + ft, 2), DeflectionOrigin::undeformed);
  ASSERT_TRUE(a.completed) << a.failure;
  EXPECT_EQ(a.first_touch_deflection_mm, ft);
  ASSERT_EQ(b.points.size(), 3u);
  EXPECT_NEAR(b.points[0].deflection_mm, ft, 1e-15);
  EXPECT_NEAR(deflection_from_origin(b, b.points[2].deflection_mm), 6.0, 1e-12);
  EXPECT_NEAR(b.points[2].deflection_mm, a.points[2].deflection_mm, 1e-12);
  const PatchFigures &pa = a.points[2].patch, &pb = b.points[2].patch;
  const double rel = std::abs(pa.Qz_N - pb.Qz_N) / pa.Qz_N;
  std::printf("  first touch %.5f mm; Qz at 6 mm from it %.8f N, at %.5f mm from undeformed %.8f N (relative "
              "difference %.2e); Qz at the first touch %.2e N, at δz = 0 %.3f N\n",
              ft, pb.Qz_N, 6.0 + ft, pa.Qz_N, rel, b.points[0].patch.Qz_N, a.points[0].patch.Qz_N);
  EXPECT_LT(rel, 1e-6);
  EXPECT_EQ(pa.contact_area_mm2, pb.contact_area_mm2);
  EXPECT_LT(std::abs(b.points[0].patch.Qz_N), 1e-6);
  // Only the point(s) at the lowest spot, pressed by the solve's remainder (nanometres, see
  // IsMinusTheCrownGrowthOnPlaneAndDrum), may count as touching: at most the tread points of one element.
  double largest_weight = 0.0;
  for (const TreadPoint& p : b.tread_points) largest_weight = std::max(largest_weight, p.weight);
  const int per_element = settings().quadrature * settings().quadrature;
  EXPECT_LE(b.points[0].patch.contact_area_mm2, per_element * largest_weight);
  EXPECT_GT(a.points[0].patch.Qz_N, 1e-3 * pa.Qz_N);
}

// A footprint at a given deflection is that load point; a footprint at a load lands on the same state.
TEST(FirstTouch, FootprintAtADeflectionAndAtItsLoadAgree) {
  const StaticContactResult b = curve(load_curve("b", plane_support(), 6.0, 1), DeflectionOrigin::first_touch);
  ASSERT_TRUE(b.completed) << b.failure;
  FootprintStudy at_deflection = footprint(plane_support(), DeflectionOrigin::first_touch);
  at_deflection.deflection = 6.0;
  const StaticContactResult f = run(at_deflection);
  ASSERT_TRUE(f.completed) << f.failure;
  EXPECT_FALSE(f.target_Qz_N.has_value());
  EXPECT_EQ(f.given_deflection_mm, 6.0);
  EXPECT_NEAR(deflection_from_origin(f, f.final_state.deflection_mm), 6.0, 1e-12);
  EXPECT_NEAR(f.points.back().patch.Qz_N, b.points.back().patch.Qz_N, 1e-9 * b.points.back().patch.Qz_N);

  FootprintStudy at_load = footprint(plane_support(), DeflectionOrigin::undeformed);
  at_load.target_load = b.points.back().patch.Qz_N;
  const StaticContactResult l = run(at_load);
  ASSERT_TRUE(l.completed) << l.failure;
  std::printf("  Qz %.2f N at 6 mm from first touch (δz %.4f mm); the search at that load ends at δz %.4f mm after "
              "%zu load points\n",
              b.points.back().patch.Qz_N, b.points.back().deflection_mm, l.final_state.deflection_mm,
              l.points.size());
  EXPECT_LE(std::abs(l.points.back().patch.Qz_N - at_load.target_load), at_load.load_tolerance * at_load.target_load);
  // Qz rises by ~20 % per mm here, so the load tolerance (1e-3) holds δz to ~0.005 mm.
  EXPECT_NEAR(l.final_state.deflection_mm, b.points.back().deflection_mm, 0.05);
}

// A load below the inflated tyre's load at δz = 0: the footprint lies between the first touch and 0.
TEST(FirstTouch, FootprintBelowTheLoadAtZeroDeflection) {
  FootprintStudy zero = footprint(plane_support(), DeflectionOrigin::undeformed);
  zero.deflection = 0.0;
  const StaticContactResult z = run(zero);
  ASSERT_TRUE(z.completed) << z.failure;
  FootprintStudy small = footprint(plane_support(), DeflectionOrigin::undeformed);
  small.target_load = 0.5 * z.points.back().patch.Qz_N;
  const StaticContactResult s = run(small);
  ASSERT_TRUE(s.completed) << s.failure;
  EXPECT_GT(s.final_state.deflection_mm, s.first_touch_deflection_mm);
  EXPECT_LT(s.final_state.deflection_mm, 0.0);
  EXPECT_LE(std::abs(s.points.back().patch.Qz_N - small.target_load), small.load_tolerance * small.target_load);
}

}  // namespace
}  // namespace tirefem::verification
