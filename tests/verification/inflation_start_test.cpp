// The inflated state of one mesh as the start of another's (analysis/inflation.hpp run_inflation_from):
// the same state as the pressure ramp on that mesh, in fewer Newton iterations; and the interpolation of a
// state round the axis (analysis/mesh_transfer.hpp).
#include <cstdio>

#include <gtest/gtest.h>

#include "contact_support.hpp"

namespace tirefem::verification {
namespace {

// The inflation of `to` started from `from`'s inflated state, against the pressure ramp on `to`.
struct StartedAgainstRamp {
  InflationResult source, ramp, started;
  double scale = 0.0;       // largest displacement of the ramp's state (mm)
  double difference = 0.0;  // largest difference of the started solution from it (mm)
};

StartedAgainstRamp started_against_ramp(const TyreMesh& from, const TyreMesh& to) {
  const Case& c = example_case();
  StartedAgainstRamp r;
  r.source = run_inflation(from, c.inflation);
  r.ramp = run_inflation(to, c.inflation);
  r.started = run_inflation_from(to, c.inflation, from, r.source.displacement);
  r.scale = r.ramp.displacement.cwiseAbs().maxCoeff();
  r.difference = (r.started.displacement - r.ramp.displacement).cwiseAbs().maxCoeff();
  std::printf("  %d Newton iterations (ramp %d), %d factorisations (ramp %d); largest difference %.1e mm of %.3f mm\n",
              r.started.counters.newton_iterations, r.ramp.counters.newton_iterations,
              r.started.counters.factorizations, r.ramp.counters.factorizations, r.difference, r.scale);
  return r;
}

TEST(InflationStart, FromAnotherMeshEqualsTheRampOnThisMesh) {
  const Case& c = example_case();
  const TyreMesh from = build_tyre_mesh(c.tyre, coarse_mesh(48, 12));
  const TyreMesh to = build_tyre_mesh(c.tyre, coarse_mesh(32, 12));
  std::printf("  32 x 12 from 48 x 12:\n");
  const StartedAgainstRamp r = started_against_ramp(from, to);
  ASSERT_TRUE(r.source.converged && r.ramp.converged && r.started.converged);
  // Both converged to the residual tolerance 1e-8: the same state well inside 1e-8 of its size.
  EXPECT_LE(r.difference, 1e-8 * r.scale);
  EXPECT_LT(r.started.counters.newton_iterations, r.ramp.counters.newton_iterations);
}

// A half model's inflated state and its mirror image start the full model of the same stations: the
// state of the full model's own pressure ramp (the inflated tyre is symmetric about the wheel plane), in
// fewer Newton iterations. The image itself is already that state (an image not mirrored would differ on
// the side s < 0 by twice the lateral displacement there).
TEST(InflationStart, FromTheHalfModelEqualsTheRampOnTheFullModel) {
  const Case& c = example_case();
  const TyreMesh half = build_tyre_mesh(c.tyre, coarse_mesh(32, 12, true));
  const TyreMesh full = build_tyre_mesh(c.tyre, coarse_mesh(32, 12, false));
  ASSERT_TRUE(turns_onto(half, full));
  EXPECT_FALSE(turns_onto(full, half));
  std::printf("  32 x 12 full from its half:\n");
  const StartedAgainstRamp r = started_against_ramp(half, full);
  ASSERT_TRUE(r.source.converged && r.ramp.converged && r.started.converged);
  const Eigen::VectorXd image = turned_onto(half, r.source.displacement, full);
  const double start_difference = (image - r.ramp.displacement).cwiseAbs().maxCoeff();
  std::printf("  the mirror image %.1e mm from the ramp's state\n", start_difference);
  EXPECT_LE(start_difference, 1e-6 * r.scale);  // the half model's own tolerance, 1e-8 in the residual
  EXPECT_LE(r.difference, 1e-8 * r.scale);
  EXPECT_LT(r.started.counters.newton_iterations, r.ramp.counters.newton_iterations);
}

TEST(InflationStart, OnlyBetweenMeshesWithTheSameMeridionalStations) {
  const Case& c = example_case();
  const TyreMesh a = build_tyre_mesh(c.tyre, coarse_mesh(24, 8));
  const TyreMesh b = build_tyre_mesh(c.tyre, coarse_mesh(24, 10));
  EXPECT_THROW(turned_onto(a, Eigen::VectorXd::Zero(a.mesh.dof_count()), b), std::invalid_argument);
  // On a mesh with equal elements round the circumference the inflated state is exactly axisymmetric: its
  // first node row turned onto every row is the state itself (this checks the sense of the turn). (With
  // refinement towards the patch it is not: there the rows' states differ by the elements' lengths.)
  const TyreMesh uniform = build_tyre_mesh(c.tyre, coarse_mesh(24, 8, true, 1.0));
  const InflationResult r = run_inflation(uniform, c.inflation);
  ASSERT_TRUE(r.converged);
  const Eigen::VectorXd same = turned_onto(uniform, r.displacement, uniform);
  EXPECT_LE((same - r.displacement).cwiseAbs().maxCoeff(), 1e-8 * r.displacement.cwiseAbs().maxCoeff());
}

// interpolated_onto (a deformed state onto another mesh of the same kind and meridional stations): onto
// its own mesh it is the state itself; a state that turns with the tyre (the inflated one on equal
// elements) it carries exactly, as turned_onto does; a half model's state onto a full model it refuses.
TEST(InflationStart, InterpolationRoundTheAxisKeepsWhatItShould) {
  const Case& c = example_case();
  const TyreMesh from = build_tyre_mesh(c.tyre, coarse_mesh(24, 8, true, 1.0));
  const TyreMesh to = build_tyre_mesh(c.tyre, coarse_mesh(36, 8, true, 1.0));
  const TyreMesh full = build_tyre_mesh(c.tyre, coarse_mesh(36, 8, false, 1.0));
  const InflationResult r = run_inflation(from, c.inflation);
  ASSERT_TRUE(r.converged);
  const double scale = r.displacement.cwiseAbs().maxCoeff();
  const Eigen::VectorXd same = interpolated_onto(from, r.displacement, from);
  EXPECT_LE((same - r.displacement).cwiseAbs().maxCoeff(), 1e-12 * scale);
  const Eigen::VectorXd interpolated = interpolated_onto(from, r.displacement, to);
  const Eigen::VectorXd turned = turned_onto(from, r.displacement, to);
  const double difference = (interpolated - turned).cwiseAbs().maxCoeff();
  std::printf("  24 x 8 inflated onto 36 x 8: interpolated and turned differ by %.1e mm of %.3f mm\n", difference,
              scale);
  EXPECT_LE(difference, 1e-8 * scale);  // the state's own departure from axisymmetry (see above)
  EXPECT_TRUE(interpolates_onto(from, to));
  EXPECT_FALSE(interpolates_onto(from, full));
  EXPECT_THROW(interpolated_onto(from, r.displacement, full), std::invalid_argument);
}

}  // namespace
}  // namespace tirefem::verification
