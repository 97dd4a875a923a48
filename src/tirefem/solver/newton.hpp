#pragma once
// Newton–Raphson for R(u, λ) = 0 at a fixed load factor, and load stepping with automatic cut-back.
#include <functional>
#include <string>

#include "tirefem/solver/linear_solver.hpp"
#include "tirefem/solver/nonlinear_problem.hpp"

namespace tirefem {

using ProgressSink = std::function<void(const std::string&)>;

struct NewtonSettings {
  double residual_tolerance = 1e-8;   // ‖R_free‖ ≤ tol · λ‖F‖ (‖F‖ = size of the full applied load)
  double increment_tolerance = 1e-7;  // ‖Δu‖ ≤ tol · ‖u‖
  // |Δu·R| ≤ tol · |Δu₁·R₁| (first iteration): accepted instead of the residual test, so an
  // ill-conditioned system whose residual stalls at round-off above residual_tolerance still converges.
  double energy_tolerance = 1e-16;
  int max_iterations = 25;
  // Backtracking on ‖R‖: the step is halved (at most this many times) while it increases the residual.
  // Off by default: on the inflated tyre it saved 2 of 10 factorisations but cost 15 more assemblies.
  int max_line_search_halvings = 0;
  // Reuse factorisations: each Newton system is first solved by GMRES preconditioned with the last
  // factorisation (of an earlier tangent); only when that does not converge within max_krylov_iterations
  // is the current tangent factorised. Along a load path the tangent changes little between iterations
  // and steps, so most iterations cost a few triangular solves instead of a factorisation.
  bool reuse_factorization = false;
  int max_krylov_iterations = 12;
  // An LU (unsymmetric problems) that needed more GMRES iterations than this is replaced by a fresh one
  // at the next iteration: measured on the rolling sweep of the example (80 × 46), 8 gave 80 Newton
  // iterations and 17 s against 99 iterations and 27 s without the refresh (many-iteration inexact steps
  // also slow Newton down).
  int refresh_after_krylov_iterations = 8;
  double krylov_tolerance = 1e-3;  // relative to the preconditioned residual (inexact Newton)
};

struct NewtonOutcome {
  bool converged = false;
  int iterations = 0;              // linear solves
  double relative_residual = 0.0;  // final ‖R_free‖ / (λ‖F‖)
  std::vector<double> residual_history;  // relative residual before each iteration
};

class NewtonSolver {
 public:
  NewtonSolver(NonlinearProblem& problem, NewtonSettings settings);
  // On failure u is left at the last iterate; the caller restores its own copy.
  NewtonOutcome solve(Eigen::VectorXd& u, double load_factor);
  NonlinearProblem& problem() { return problem_; }
  const LinearSolverStats& linear_stats() const { return linear_.stats(); }
  int total_iterations() const { return total_iterations_; }
  double residual_tolerance() const { return settings_.residual_tolerance; }
  void set_residual_tolerance(double tolerance) { settings_.residual_tolerance = tolerance; }
  int max_iterations() const { return settings_.max_iterations; }
  void set_max_iterations(int iterations) { settings_.max_iterations = iterations; }

 private:
  // `fresh`: factorise the current tangent even if a reused factorisation would do.
  bool solve_linear(const Eigen::VectorXd& rhs, Eigen::VectorXd& du, bool fresh);

  NonlinearProblem& problem_;
  NewtonSettings settings_;
  SparseDirectSolver linear_;
  int total_iterations_ = 0;
  bool refresh_ = false;  // the last reused factorisation needed many GMRES iterations: factorise next
};

struct LoadSteppingSettings {
  double first_increment = 1.0;
  double min_increment = 1.0 / 1024;
  double max_increment = 1.0;
  int easy_iterations = 4;  // fewer Newton iterations than this: the next increment grows
};

struct LoadStepRecord {
  double load_factor = 0.0;
  int iterations = 0;
  double relative_residual = 0.0;
};

struct LoadPathResult {
  bool completed = false;
  std::vector<LoadStepRecord> steps;
  int cutbacks = 0;
};

// Drives λ from 0 to 1. Each step starts from a secant prediction of the last two converged states; an
// increment that does not converge is halved (down to min_increment). `on_step` sees each converged state.
LoadPathResult follow_load_path(NewtonSolver& newton, Eigen::VectorXd& u,
                                const LoadSteppingSettings& settings,
                                const std::function<void(const LoadStepRecord&, const Eigen::VectorXd&)>&
                                    on_step = {},
                                const ProgressSink& progress = {});

}  // namespace tirefem
