// NewtonSolver on one-equation problems whose Newton iterates are known: when it stops and why.
#include <array>
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

// A problem of the one form F on `dof_count` DOFs.
template <class F>
NonlinearProblem problem_of(int dof_count) {
  std::vector<std::unique_ptr<Form>> forms;
  forms.push_back(std::make_unique<F>());
  return NonlinearProblem(DofMap(dof_count), std::move(forms));
}

// Stable equilibrium with reused factorisations, as the static contact studies solve.
NewtonSettings stable_with_reuse() {
  NewtonSettings settings;
  settings.stable_equilibrium = true;
  settings.reuse_factorization = true;
  return settings;
}

StableSolve solve_double_well(double start, double near_solution_residual) {
  NonlinearProblem problem = problem_of<DoubleWellForm>(1);
  NewtonSettings settings = stable_with_reuse();
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

// Π(x, y) = x⁴/4 − x + y⁴/4 + (1/2 − x²) y²/2: R = (x³ − 1 − x y², y³ + (1/2 − x²) y), K =
// [[3x² − y², −2xy], [−2xy, 3y² + 1/2 − x²]], on the DOFs p = (x + y)/√2, q = (x − y)/√2 (so that the
// unstable mode is not a diagonal entry of K, as in a shell). Along p = q (y = 0, where R_y = 0: a
// symmetric state) Newton converges to the saddle (1, 0), stable only while x² < 1/2 (at x = 1: K's
// diagonal 1.25, eigenvalues 3 and −0.5, a relative shift σ > 0.4 makes it positive definite). The
// stable states are (x, ±y) with x³ − x y² = 1, y² = x² − 1/2.
class PitchforkForm : public Form {
 public:
  void add_pattern(PatternBuilder& pattern) const override { pattern.add_block(kDofs); }
  void assemble(const FormInput& input, SparseSystem& system) const override {
    const Eigen::Vector2d xy = kRotation * Eigen::Vector2d(input.displacement[0], input.displacement[1]);
    const double x = xy[0], y = xy[1];
    const Eigen::Vector2d r(x * x * x - 1.0 - x * y * y, y * y * y + (0.5 - x * x) * y);
    Eigen::Matrix2d k;
    k << 3.0 * x * x - y * y, -2.0 * x * y, -2.0 * x * y, 3.0 * y * y + 0.5 - x * x;
    const Eigen::Vector2d r_pq = kRotation * r;
    const Eigen::Matrix2d k_pq = kRotation * k * kRotation;
    system.add(kDofs, r_pq, k_pq, input.with_tangent);
  }
  bool has_potential() const override { return true; }
  std::optional<EnergyChange> energy_change(const Eigen::VectorXd& from, const Eigen::VectorXd& to,
                                            double) const override {
    const auto pi = [](const Eigen::VectorXd& u) {
      const Eigen::Vector2d xy = kRotation * Eigen::Vector2d(u[0], u[1]);
      const double x = xy[0], y = xy[1];
      return 0.25 * std::pow(x, 4) - x + 0.25 * std::pow(y, 4) + 0.5 * (0.5 - x * x) * y * y;
    };
    return EnergyChange{pi(to) - pi(from), std::abs(pi(to)) + std::abs(pi(from))};
  }

 private:
  static constexpr std::array<int, 2> kDofs{0, 1};
  // (p, q) ↔ (x, y): symmetric and orthogonal, its own inverse.
  static inline const Eigen::Matrix2d kRotation = (Eigen::Matrix2d() << 1, 1, 1, -1).finished() / std::sqrt(2.0);
};

// Stable mode with reused factorisations, from (x, y) = (1/2, 0): the tangent factorised near the
// solution is indefinite, the steps on to the saddle come from the inertia-corrected factorisation, and
// the saddle is left for a minimum. The shift scans do not start again from 0 at a tangent already found
// indefinite: up to the push, the failed Cholesky attempts are one at the near test, six in the scan to
// σ = 1 (1e-6 … 0.1), and one where the saddle's test starts a decade below that σ (scanning from 0 each
// time: fifteen); then one in the descent from the push.
TEST(NewtonSolver, ASaddleFoundIndefiniteNearTheSolutionIsLeftWithoutRescanningItsShift) {
  NonlinearProblem problem = problem_of<PitchforkForm>(2);
  NewtonSolver newton(problem, stable_with_reuse());
  Eigen::VectorXd u = Eigen::Vector2d::Constant(0.5 / std::sqrt(2.0));
  const NewtonOutcome out = newton.solve(u, 1.0);
  ASSERT_TRUE(out.converged);
  EXPECT_EQ(out.escapes, 1);
  EXPECT_EQ(out.final_shift, 0.0);
  const Eigen::Vector2d xy = (Eigen::Matrix2d() << 1, 1, 1, -1).finished() / std::sqrt(2.0) * u;
  const double x = xy[0], y = xy[1];
  EXPECT_NEAR(x * x * x - x * y * y, 1.0, 1e-8);
  EXPECT_NEAR(y * y, x * x - 0.5, 1e-8);
  const auto& stats = newton.linear_stats();
  EXPECT_EQ(stats.failed_cholesky, 8 + 1);
}

// R(u) = K u + u³ − f on 8 DOFs: K the second-difference matrix (2, −1) plus the identity, f = 3, and a
// skew coupling ±0.5 between the last two DOFs, so the tangent is unsymmetric (an LU, as rolling's).
class UnsymmetricCubicForm : public Form {
 public:
  static constexpr int kDofs = 8;
  void add_pattern(PatternBuilder& pattern) const override {
    std::array<int, kDofs> dofs{};
    for (int i = 0; i < kDofs; ++i) dofs[i] = i;
    pattern.add_block(dofs);
  }
  void assemble(const FormInput& input, SparseSystem& system) const override {
    std::array<int, kDofs> dofs{};
    for (int i = 0; i < kDofs; ++i) dofs[i] = i;
    using Matrix = Eigen::Matrix<double, kDofs, kDofs>;
    using Vector = Eigen::Matrix<double, kDofs, 1>;
    Matrix linear = Matrix::Zero();
    for (int i = 0; i < kDofs; ++i) {
      linear(i, i) = 3.0;
      if (i > 0) linear(i, i - 1) = linear(i - 1, i) = -1.0;
    }
    linear(kDofs - 2, kDofs - 1) += 0.5;
    linear(kDofs - 1, kDofs - 2) -= 0.5;
    const Vector u = input.displacement.head<kDofs>();
    const Vector r = linear * u + u.array().cube().matrix() - Vector::Constant(3.0);
    const Matrix k = linear + Matrix((3.0 * u.array().square()).matrix().asDiagonal());
    system.add(dofs, r, k, input.with_tangent);
  }
  bool symmetric() const override { return false; }
};

// An LU reused by GMRES is replaced once it needed more than refresh_after_krylov_iterations (here 0:
// after every GMRES solve), unless the iterate's residual is already at or below keep_lu_below_residual:
// near convergence the last steps run on the LU held. Fewer LUs, the same solution.
TEST(NewtonSolver, AnLuIsNotRefreshedNearConvergence) {
  const auto solve = [](double keep_lu_below_residual, Eigen::VectorXd& u) {
    NonlinearProblem problem = problem_of<UnsymmetricCubicForm>(UnsymmetricCubicForm::kDofs);
    NewtonSettings settings;
    settings.reuse_factorization = true;
    settings.refresh_after_krylov_iterations = 0;
    settings.keep_lu_below_residual = keep_lu_below_residual;
    NewtonSolver newton(problem, settings);
    u = Eigen::VectorXd::Zero(UnsymmetricCubicForm::kDofs);
    const NewtonOutcome out = newton.solve(u, 1.0);
    EXPECT_TRUE(out.converged);
    EXPECT_TRUE(newton.linear_stats().used_lu);
    return std::pair{out, newton.linear_stats().factorizations};
  };
  Eigen::VectorXd always, near;
  const auto [out_always, lus_always] = solve(0.0, always);
  const auto [out_near, lus_near] = solve(1e-2, near);
  // Every other step on a fresh LU, against none once the residual is below 1e-2.
  EXPECT_GE(lus_always, (out_always.iterations + 1) / 2);
  int above = 0;  // iterates above 1e-2 after the first
  for (std::size_t k = 1; k < out_near.residual_history.size(); ++k) above += out_near.residual_history[k] > 1e-2;
  EXPECT_LE(lus_near, 1 + above);
  EXPECT_LT(lus_near, lus_always);
  EXPECT_LT((near - always).norm(), 1e-8 * always.norm());
}

}  // namespace
}  // namespace tirefem
