// Global equilibrium of the loaded tyre (MODEL.md §4, eq. 14): the vertical force of the support on the
// tread, Qz = ∫Ωc qz dΩ as patch_figures integrates it, equals the axle load, i.e. minus the vertical
// reaction of the rim — the residual of the shell + pressure forms at the fixed bead DOFs.
// Reference: statics. The internal forces sum to zero (translation invariance of the strains); the
// follower pressure's resultant on the carcass is ∫ n dA = ½∮ x × dx over its boundary (Stokes, exact for
// the 2 × 2 rule on bilinear faces), and that boundary is the bead circle (fixed, in a plane x = const) and,
// in the half model, the equator line (x held at 0): both area vectors lie along x, so the pressure has no
// vertical resultant. What is left is the Newton residual at the free DOFs, ~1e-10 of the inflation load
// here (tolerance tightened to 1e-10 for this test), ≪ 1e-6 of Qz: tolerance 1e-6 relative.
// The half model's reaction is that of half the tyre: doubled before the comparison (patch_figures
// doubles Qz itself).
#include <cstdio>

#include <gtest/gtest.h>

#include "contact_support.hpp"

namespace tirefem::verification {
namespace {

struct Reactions {
  Eigen::Vector3d fixed = Eigen::Vector3d::Zero();  // Σ residual at the fixed DOFs (the rim on the tyre)
  Eigen::Vector3d free = Eigen::Vector3d::Zero();   // Σ residual at the free DOFs (the Newton remainder)
};

Reactions reactions(NonlinearProblem& problem, const Eigen::VectorXd& u) {
  problem.evaluate(u, 1.0, false);
  const Eigen::VectorXd& r = problem.system().residual();
  Reactions out;
  for (int d = 0; d < problem.dofs().dof_count(); ++d)
    (problem.dofs().is_fixed(d) ? out.fixed : out.free)[d % 3] += r[d];
  return out;
}

void check_equilibrium(const char* label, const SupportDescription& support, bool half_model,
                       ContactSettings::Iteration iteration = ContactSettings::Iteration::two_level) {
  const Stopwatch clock;
  const Case& c = example_case();
  const TyreMesh tm = build_tyre_mesh(c.tyre, coarse_mesh(36, 8, half_model));
  ContactSettings settings = test_contact_settings(iteration);
  settings.residual_tolerance = 1e-10;
  ManualContactRun run(tm, c.tyre, c.inflation, settings, support);
  for (double delta : {5.0, 10.0, 15.0}) {
    const DeflectionPath::Step step = run.path->advance_to(delta);
    ASSERT_TRUE(step.converged) << label << ": " << step.failure;
  }
  const Eigen::VectorXd& u = run.path->displacement();
  run.contact->set_deflection(15.0);
  const PatchFigures f = patch_figures(run.tread_points, run.contact->evaluate(u), tm.half_model);
  const Reactions r = reactions(*run.problem, u);
  const double factor = tm.half_model ? 2.0 : 1.0;
  const double axle_load = -factor * r.fixed.z();
  const double error = std::abs(axle_load - f.Qz_N) / f.Qz_N;
  std::printf("  %s (%s), δz 15 mm: Qz (contact integral) %.6f N, axle load (rim reaction) %.6f N, relative "
              "difference %.2e; Σ free-DOF residual z %.2e N; rim reaction y %.2e N (%.1f s)\n",
              label, iteration_name(iteration), f.Qz_N, axle_load, error, r.free.z(), factor * r.fixed.y(), clock.seconds());
  EXPECT_GT(f.Qz_N, 500.0) << "the tyre must be visibly loaded";
  EXPECT_LT(error, 1e-6) << label << ": Qz must equal the axle load (statics), tol 1e-6";
  // The support force is symmetric fore and aft: no net longitudinal reaction (same tolerance).
  EXPECT_LT(std::abs(factor * r.fixed.y()), 1e-6 * f.Qz_N) << label;
}

TEST(ContactEquilibrium, QzEqualsAxleLoadHalfModelPlane) {
  check_equilibrium("half model, plane", plane_support(), true);
}

TEST(ContactEquilibrium, QzEqualsAxleLoadHalfModelPlaneSingleLoop) {
  check_equilibrium("half model, plane", plane_support(), true, ContactSettings::Iteration::single_loop);
}

TEST(ContactEquilibrium, QzEqualsAxleLoadHalfModelDrum) {
  check_equilibrium("half model, drum 1830", drum_support(1830.0), true);
}

TEST(ContactEquilibrium, QzEqualsAxleLoadFullModelPlane) {
  check_equilibrium("full model, plane", plane_support(), false);
}

}  // namespace
}  // namespace tirefem::verification
