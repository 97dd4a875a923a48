// The stability each converged load point reports (MODEL.md §8) must be the stability of that state's own
// tangent, whichever way Newton got there. Regression: in nearest-equilibrium mode with reused
// factorisations, a point reached by LU steps on an indefinite tangent was reported stable (its GMRES steps
// had reset the shift to 0). Checked independently: a Cholesky attempt on the tangent assembled at each
// converged state, on the example tyre's 80 × 24 half model, whose tangent turns indefinite near δz = 21 mm.
#include <gtest/gtest.h>

#include "contact_support.hpp"
#include "tirefem/solver/linear_solver.hpp"

namespace tirefem::verification {
namespace {

TEST(StabilityReport, NearestModeReportsTheInertiaOfEachConvergedTangent) {
  const TyreMesh tm = build_tyre_mesh(example_case().tyre, coarse_mesh(80, 24));
  ContactSettings settings = test_contact_settings(ContactSettings::Iteration::single_loop);
  settings.reuse_factorizations = true;  // the regression needs GMRES steps after LU ones
  ManualContactRun run(tm, example_case().tyre, example_case().inflation, settings, plane_support());
  int unstable = 0;
  for (double deflection = 2.0; deflection <= 24.0 + 1e-9; deflection += 2.0) {
    const DeflectionPath::Step step = run.path->advance_to(deflection);
    ASSERT_TRUE(step.converged) << "δz " << deflection << ": " << step.failure;
    run.problem->evaluate(run.path->displacement(), 1.0, true);
    SparseDirectSolver independent(true);
    const bool positive_definite = independent.factorize_cholesky(run.problem->system().tangent(), 0.0);
    const double reported = step.last.tangent_shift;
    std::printf("  δz %4.1f mm: reported shift %.0e, own tangent %s\n", deflection, reported,
                positive_definite ? "positive definite" : "indefinite");
    if (positive_definite) {
      EXPECT_EQ(reported, 0.0) << "δz " << deflection << ": a stable state reported unstable";
    } else {
      ++unstable;
      // 1e-6: singular up to round-off (a shift that small makes it positive definite); 1e-5: indefinite.
      const bool round_off = independent.factorize_cholesky(run.problem->system().tangent(), 1e-6);
      EXPECT_GT(reported, round_off ? 0.5e-6 : 5e-6) << "δz " << deflection << ": an unstable state reported stable";
    }
  }
  EXPECT_GT(unstable, 0) << "the path is expected to pass this tyre's instability (onset about 21 mm on 80 × 24)";
}

}  // namespace
}  // namespace tirefem::verification
