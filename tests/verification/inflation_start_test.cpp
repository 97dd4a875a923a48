// The inflated state of one mesh as the start of another's (analysis/inflation.hpp run_inflation_from):
// the same state as the pressure ramp on that mesh, in fewer Newton iterations.
#include <cstdio>

#include <gtest/gtest.h>

#include "contact_support.hpp"

namespace tirefem::verification {
namespace {

TEST(InflationStart, FromAnotherMeshEqualsTheRampOnThisMesh) {
  const Case& c = example_case();
  const TyreMesh from = build_tyre_mesh(c.tyre, coarse_mesh(48, 12));
  const TyreMesh to = build_tyre_mesh(c.tyre, coarse_mesh(32, 12));
  const InflationResult source = run_inflation(from, c.inflation);
  const InflationResult ramp = run_inflation(to, c.inflation);
  const InflationResult started = run_inflation_from(to, c.inflation, from, source.displacement);
  ASSERT_TRUE(source.converged && ramp.converged && started.converged);
  const double scale = ramp.displacement.cwiseAbs().maxCoeff();
  const double difference = (started.displacement - ramp.displacement).cwiseAbs().maxCoeff();
  std::printf("  32 x 12 from 48 x 12: %d Newton iterations (ramp %d), %d factorisations (ramp %d); largest "
              "difference %.1e mm of %.3f mm\n",
              started.counters.newton_iterations, ramp.counters.newton_iterations, started.counters.factorizations,
              ramp.counters.factorizations, difference, scale);
  // Both converged to the residual tolerance 1e-8: the same state well inside 1e-8 of its size.
  EXPECT_LE(difference, 1e-8 * scale);
  EXPECT_LT(started.counters.newton_iterations, ramp.counters.newton_iterations);
}

// A half model's inflated state and its mirror image start the full model of the same stations: the
// state of the full model's own pressure ramp (the inflated tyre is symmetric about the wheel plane), in
// fewer Newton iterations. The mirror sense is checked by the lateral displacement of the two beads'
// neighbourhood, which would not cancel if the image were not mirrored.
TEST(InflationStart, FromTheHalfModelEqualsTheRampOnTheFullModel) {
  const Case& c = example_case();
  const TyreMesh half = build_tyre_mesh(c.tyre, coarse_mesh(32, 12, true));
  const TyreMesh full = build_tyre_mesh(c.tyre, coarse_mesh(32, 12, false));
  ASSERT_TRUE(turns_onto(half, full));
  EXPECT_FALSE(turns_onto(full, half));
  const InflationResult source = run_inflation(half, c.inflation);
  const InflationResult ramp = run_inflation(full, c.inflation);
  const InflationResult started = run_inflation_from(full, c.inflation, half, source.displacement);
  ASSERT_TRUE(source.converged && ramp.converged && started.converged);
  const double scale = ramp.displacement.cwiseAbs().maxCoeff();
  const double difference = (started.displacement - ramp.displacement).cwiseAbs().maxCoeff();
  const Eigen::VectorXd image = turned_onto(half, source.displacement, full);
  const double start_difference = (image - ramp.displacement).cwiseAbs().maxCoeff();
  std::printf("  32 x 12 full from its half: %d Newton iterations (ramp %d), %d factorisations (ramp %d); the "
              "mirror image %.1e mm from the ramp's state, the solution %.1e mm, of %.3f mm\n",
              started.counters.newton_iterations, ramp.counters.newton_iterations, started.counters.factorizations,
              ramp.counters.factorizations, start_difference, difference, scale);
  EXPECT_LE(start_difference, 1e-6 * scale);  // the half model's own tolerance, 1e-8 in the residual
  EXPECT_LE(difference, 1e-8 * scale);
  EXPECT_LT(started.counters.newton_iterations, ramp.counters.newton_iterations);
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

}  // namespace
}  // namespace tirefem::verification
