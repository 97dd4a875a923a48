// NewtonSolver on one-equation problems whose Newton iterates are known: when it stops and why.
#include <cmath>
#include <functional>
#include <memory>

#include <gtest/gtest.h>

#include "tirefem/solver/newton.hpp"

namespace tirefem {
namespace {

// R(u) = f(u) on a single DOF (its load scale ‖R(0)‖ = |f(0)|), tangent f'(u).
class ScalarForm : public Form {
 public:
  ScalarForm(std::function<double(double)> f, std::function<double(double)> df) : f_(std::move(f)), df_(std::move(df)) {}
  void add_pattern(PatternBuilder& pattern) const override {
    const int dof = 0;
    pattern.add_block(std::span<const int>(&dof, 1));
  }
  void assemble(const FormInput& input, SparseSystem& system) const override {
    const int dof = 0;
    const Eigen::Matrix<double, 1, 1> r(f_(input.displacement[0])), k(df_(input.displacement[0]));
    system.add(std::span<const int>(&dof, 1), r, k, input.with_tangent);
  }

 private:
  std::function<double(double)> f_, df_;
};

NewtonOutcome solve_scalar(std::function<double(double)> f, std::function<double(double)> df, double start,
                           int max_iterations, double& u_out) {
  std::vector<std::unique_ptr<Form>> forms;
  forms.push_back(std::make_unique<ScalarForm>(std::move(f), std::move(df)));
  NonlinearProblem problem(DofMap(1), std::move(forms));
  NewtonSettings settings;
  settings.max_iterations = max_iterations;
  NewtonSolver newton(problem, settings);
  Eigen::VectorXd u(1);
  u[0] = start;
  const NewtonOutcome out = newton.solve(u, 1.0);
  u_out = u[0];
  return out;
}

// u³ = 1 from u = 10: Newton's steps shrink u by about a third while it is large, then converge
// quadratically; it needs 10 iterations to a relative residual of 1e-8.
NewtonOutcome solve_cube_root_of_one(int max_iterations, double& u) {
  return solve_scalar([](double x) { return x * x * x - 1.0; }, [](double x) { return 3.0 * x * x; }, 10.0,
                      max_iterations, u);
}

// With a limit of 25 it converges in those 10. With a limit of 8 it is converging quadratically when it
// reaches the limit (the residual falls more than tenfold per iteration and is below 1e-3): it is let
// finish, in the same 10.
TEST(NewtonSolver, AConvergingSolveIsLetFinishPastItsLimit) {
  for (const int limit : {25, 8}) {
    SCOPED_TRACE(limit);
    double u = 0.0;
    const NewtonOutcome out = solve_cube_root_of_one(limit, u);
    ASSERT_TRUE(out.converged);
    EXPECT_EQ(out.iterations, 10);
    EXPECT_NEAR(u, 1.0, 1e-9);
  }
}

// ... but not one still far from converged at the limit: at 5 iterations the residual is about 1.9
// relative (u ≈ 1.43), so the solve fails there.
TEST(NewtonSolver, ASolveFarFromConvergedStopsAtItsLimit) {
  double u = 0.0;
  const NewtonOutcome out = solve_cube_root_of_one(5, u);
  EXPECT_FALSE(out.converged);
  EXPECT_EQ(out.iterations, 5);
}

// Newton on atan(u) − atan(0.5) from u = 5 overshoots further at every step (to −18.7, then beyond):
// it is not let run on past its limit.
TEST(NewtonSolver, ADivergingSolveFails) {
  double u = 0.0;
  const NewtonOutcome out = solve_scalar([](double x) { return std::atan(x) - std::atan(0.5); },
                                         [](double x) { return 1.0 / (1.0 + x * x); }, 5.0, 25, u);
  EXPECT_FALSE(out.converged);
  EXPECT_LE(out.iterations, 25);
}

// Π(u) = u⁴/4 − u²/2 − 0.1 u: R = u³ − u − 0.1, K = 3u² − 1. Equilibria: a maximum (unstable) at
// u ≈ −0.101 and minima (stable) at u ≈ −0.946 and u ≈ 1.047.
class DoubleWellForm : public Form {
 public:
  void add_pattern(PatternBuilder& pattern) const override {
    const int dof = 0;
    pattern.add_block(std::span<const int>(&dof, 1));
  }
  void assemble(const FormInput& input, SparseSystem& system) const override {
    const int dof = 0;
    const double u = input.displacement[0];
    const Eigen::Matrix<double, 1, 1> r(u * u * u - u - 0.1), k(3.0 * u * u - 1.0);
    system.add(std::span<const int>(&dof, 1), r, k, input.with_tangent);
  }
  bool has_potential() const override { return true; }
  std::optional<EnergyChange> energy_change(const Eigen::VectorXd& from, const Eigen::VectorXd& to,
                                            double) const override {
    const auto pi = [](double u) { return 0.25 * u * u * u * u - 0.5 * u * u - 0.1 * u; };
    return EnergyChange{pi(to[0]) - pi(from[0]), std::abs(pi(to[0])) + std::abs(pi(from[0]))};
  }
};

struct StableSolve {
  NewtonOutcome outcome;
  double u = 0.0;
  int factorizations = 0;
  int gmres_solves = 0;  // on a reused factorisation, given up ones included
};

StableSolve solve_double_well(double start, double near_solution_residual) {
  std::vector<std::unique_ptr<Form>> forms;
  forms.push_back(std::make_unique<DoubleWellForm>());
  NonlinearProblem problem(DofMap(1), std::move(forms));
  NewtonSettings settings;
  settings.stable_equilibrium = true;
  settings.reuse_factorization = true;
  settings.near_solution_residual = near_solution_residual;
  NewtonSolver newton(problem, settings);
  Eigen::VectorXd u(1);
  u[0] = start;
  StableSolve s;
  s.outcome = newton.solve(u, 1.0);
  s.u = u[0];
  s.factorizations = newton.linear_stats().factorizations;
  s.gmres_solves = newton.linear_stats().krylov_solves + newton.linear_stats().krylov_failures;
  return s;
}

// Stable mode with reused factorisations: the positive definite tangent factorised near the solution
// stands for the converged state's stability test (the same count of factorisations, not one more), and
// the solution is the one found without it (near_solution_residual 0: never). From next to the unstable
// maximum as well, the solve ends on a minimum.
TEST(NewtonSolver, ATangentFactorisedNearTheSolutionStandsForTheStabilityTest) {
  for (const double start : {2.0, -0.3}) {
    SCOPED_TRACE(start);
    const StableSolve near = solve_double_well(start, 1e-2);
    const StableSolve off = solve_double_well(start, 0.0);
    ASSERT_TRUE(near.outcome.converged);
    ASSERT_TRUE(off.outcome.converged);
    EXPECT_NEAR(near.u, off.u, 1e-10);
    EXPECT_GT(3.0 * near.u * near.u - 1.0, 0.0);
    EXPECT_EQ(near.outcome.final_shift, 0.0);
    // The near test took the place of the final one, and its iteration was solved on it directly.
    EXPECT_EQ(near.factorizations, off.factorizations);
    EXPECT_EQ(near.gmres_solves, off.gmres_solves - 1);
  }
  const double root = solve_double_well(2.0, 1e-2).u;  // the minimum on the right
  EXPECT_GT(root, 1.0);
  EXPECT_NEAR(root * root * root - root - 0.1, 0.0, 1e-9);
}

}  // namespace
}  // namespace tirefem
