// The stability of the inflated state (analysis/inflation.hpp, InflationResult::tangent_shift): the README's
// "How fine a mesh" finds the example tyre unstable already when inflated on meshes too coarse round the
// circumference (a mesh-scale mode; 40 × 12 with refinement 4: 12 negative eigenvalues) and stable on
// finer ones (64 × 16 with equal elements: none). Each inflation says which, also when its Newton solve
// took no step (a full model from its half model's mirror image), and a static contact study seeking stable
// equilibria (contact.equilibrium = "stable") on an unstable inflated mesh stops at once, saying why.
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "contact_support.hpp"

namespace tirefem::verification {
namespace {

TEST(InflationStability, ACoarseMeshIsFoundUnstableAndAFineOneStable) {
  const Case& c = example_case();
  const TyreMesh coarse = build_tyre_mesh(c.tyre, coarse_mesh(32, 12));
  const InflationResult unstable = run_inflation(coarse, c.inflation);
  ASSERT_TRUE(unstable.converged);
  std::printf("  32 x 12 half (refinement 4): shift %.1e, %s\n", unstable.tangent_shift, unstable.instability.c_str());
  EXPECT_GT(unstable.tangent_shift, 0.0);
  EXPECT_NE(unstable.instability.find("unstable on the 32 x 12 half mesh"), std::string::npos);
  // Refinement 4 on 32 columns: the longest, opposite the patch, spans just under 2π/32 · (1 + 3/5) of the
  // station map's steepest slope, at the carcass radius of the equator (272 mm).
  const double steepest = 2 * std::numbers::pi / 32 * 1.6 * 272.0;
  EXPECT_LE(longest_circumferential_element_mm(coarse), steepest);
  EXPECT_GE(longest_circumferential_element_mm(coarse), 0.99 * steepest);

  const TyreMesh fine = build_tyre_mesh(c.tyre, coarse_mesh(64, 16, true, 1.0));
  const InflationResult stable = run_inflation(fine, c.inflation);
  ASSERT_TRUE(stable.converged);
  std::printf("  64 x 16 half (equal elements): shift %.1e\n", stable.tangent_shift);
  EXPECT_EQ(stable.tangent_shift, 0.0);
  EXPECT_TRUE(stable.instability.empty());
}

// The full model started from its half model's mirror image converges without a Newton step, so its
// solve tests no state: the inflation tests it itself.
TEST(InflationStability, AFullModelStartedFromItsHalfIsTestedToo) {
  const Case& c = example_case();
  const TyreMesh half = build_tyre_mesh(c.tyre, coarse_mesh(32, 12, true));
  const TyreMesh full = build_tyre_mesh(c.tyre, coarse_mesh(32, 12, false));
  const InflationResult h = run_inflation(half, c.inflation);
  ASSERT_TRUE(h.converged);
  const InflationResult f = run_inflation_from(full, c.inflation, half, h.displacement);
  ASSERT_TRUE(f.converged);
  std::printf("  32 x 12 full from its half: %d Newton iterations, shift %.1e\n", f.counters.newton_iterations,
              f.tangent_shift);
  EXPECT_GT(f.tangent_shift, 0.0);
}

// A static contact study seeking stable equilibria refuses an unstable inflated state at once, with the
// inflation's message and the way out; one seeking the nearest equilibrium solves on it.
TEST(InflationStability, StableEquilibriaAreNotSoughtFromAnUnstableInflatedState) {
  const Case& c = example_case();
  const TyreMesh tm = build_tyre_mesh(c.tyre, coarse_mesh(32, 12));
  const InflationResult inflated = inflate_for_contact(tm, c.inflation);
  ASSERT_GT(inflated.tangent_shift, 0.0);
  const LoadCurveStudy study = load_curve("plane", plane_support(), 4.0, 1);
  ContactSettings stable = test_contact_settings(ContactSettings::Iteration::single_loop);
  stable.equilibrium = ContactSettings::Equilibrium::stable;
  try {
    run_load_curve(tm, c.tyre, c.inflation, stable, study, {}, &inflated);
    ADD_FAILURE() << "a study seeking stable equilibria started from an unstable inflated state";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("unstable on the 32 x 12 half mesh"), std::string::npos) << what;
    EXPECT_NE(what.find("\"nearest\""), std::string::npos) << what;
  }
  const StaticContactResult nearest = run_load_curve(tm, c.tyre, c.inflation,
                                                     test_contact_settings(ContactSettings::Iteration::single_loop),
                                                     study, {}, &inflated);
  EXPECT_TRUE(nearest.completed);
}

}  // namespace
}  // namespace tirefem::verification
