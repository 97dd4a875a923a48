#pragma once
// Newton–Raphson for R(u, λ) = 0 at a fixed load factor, and load stepping with automatic cut-back.
#include <functional>
#include <optional>
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
  // At or below this relative residual an LU is kept to the end of the solve (0: never): not refreshed
  // after many GMRES iterations, and a GMRES solve on it that meets its tolerance with too large a true
  // residual goes on a few iterations (as on a Cholesky) before a new LU is made. Near convergence one or
  // two steps are left, and GMRES on the LU held costs far less than a new one.
  double keep_lu_below_residual = 0.0;
  double krylov_tolerance = 1e-3;  // relative to the preconditioned residual (inexact Newton)
  // Eisenstat–Walker forcing terms instead of the fixed krylov_tolerance: loose (up to max_forcing_term)
  // while the residual is far from converged, tight where Newton converges fast, never tighter than the
  // Newton tolerance needs. (At most 0.1, so their safeguard against a sudden tightening, which acts
  // only above 0.1, is not needed.) Larger than 1e-2 measured worse on the load curve of the example: GMRES on the
  // factorisation of another load point then often meets its preconditioned tolerance with a true
  // residual above 0.1, the step is refused and the tangent factorised.
  bool adaptive_krylov_tolerance = false;
  double max_forcing_term = 1e-2;
  // Symmetric problems are factorised by Cholesky, an indefinite tangent with a diagonal shift (inertia
  // correction). Which equilibrium Newton converges to, for problems with a potential (MODEL.md §8):
  //  - false (nearest): exact Newton steps (found on the inertia-corrected factorisation by GMRES, or by
  //    LU when the tangent is strongly indefinite), so Newton converges to the equilibrium next to its
  //    start, stable or not; the stability of the result is reported (NewtonOutcome::final_shift).
  //  - true (stable): every step must lower the energy. On an indefinite tangent the exact step is kept
  //    only if it descends, else the shifted one is taken; a shifted step must lower the energy by at
  //    least armijo × its first-order prediction (cut back by quadratic interpolation, at most
  //    max_energy_backtracks times) and is extended while the energy keeps falling steeply along it.
  //    Newton then cannot settle on a saddle: it leaves an unstable equilibrium for a stable one (a
  //    wrinkled or snapped-through state), the way a quasi-static structure does.
  bool stable_equilibrium = false;
  // The problem's tangent is positive definite at every state (a linearised tyre, stable when inflated,
  // with contact springs): the converged states need no stability test.
  bool known_stable = false;
  int max_energy_backtracks = 12;
  // Stable equilibrium with reused factorisations: the tangent of the first iterate whose relative residual
  // is below this is factorised (Cholesky, no shift). Positive definite, it stands for the converged state's
  // (whose own factorisation, the stability test, is then spared) and preconditions the last iterations.
  // Measured on the example's plane load curve (20 points, 120 × 46): GMRES iterations 746 → 456,
  // factorisations 53 → 65 (failed attempts next to the instability), wall time 43.8 → 40.6 s (medians of
  // 3 paired runs), the same states to 2e-9. 0 turns it off.
  double near_solution_residual = 1e-2;
  double armijo = 1e-4;
};

struct NewtonOutcome {
  bool converged = false;
  int iterations = 0;              // linear solves
  double relative_residual = 0.0;  // final ‖R_free‖ / (λ‖F‖)
  std::vector<double> residual_history;  // relative residual before each iteration
  // Relative diagonal shift the last factorisation needed (of the converged state's tangent when it was
  // tested): > 0 means an indefinite tangent, an unstable equilibrium (after LU steps, 1e-5 stands for
  // "indefinite" without its size).
  double final_shift = 0.0;
  int backtracks = 0;        // energy line-search cut-backs
  int extensions = 0;        // shifted steps extended along a falling energy
  int escapes = 0;           // unstable equilibria left (stable-equilibrium mode)
  double escaped_shift = 0.0;  // the largest shift of the tangent at an equilibrium left
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
  // Solves K x = rhs over the free DOFs, K the tangent the problem last assembled (after solve(): the
  // converged state's), as a Newton step is solved (GMRES on a reused factorisation, else a new one), to
  // `tolerance` relative to the preconditioned residual. False when that fails: a derivative of the
  // solution along a parameter (a tangent predictor) costs one such solve.
  bool solve_with_tangent(const Eigen::VectorXd& rhs, Eigen::VectorXd& x, double tolerance);
  // The stability of the state the problem last assembled (symmetric problems): 0 when its tangent is
  // positive definite, else a shift as NewtonOutcome::final_shift. One or two Cholesky attempts; solve()
  // makes this test itself only on states it stepped to.
  double stability_shift();

 private:
  // `fresh`: factorise the current tangent even if a reused factorisation would do. `near_convergence`:
  // the iterate's residual is at or below keep_lu_below_residual (an LU held is kept).
  bool solve_linear(const Eigen::VectorXd& rhs, Eigen::VectorXd& du, bool fresh, double krylov_tolerance,
                    bool near_convergence = false);
  // At an unstable equilibrium (the last factorisation, of its tangent, needed a shift): moves u along
  // the direction of negative curvature to the side that lowers the energy. False when none is found.
  bool push_off_saddle(Eigen::VectorXd& u, double load_factor);
  // Nearest-equilibrium mode with reused factorisations: factorises the converged state's tangent to
  // tell its stability (shift_ 0, round-off, or indefinite: then LU steps follow, as without reuse).
  void test_stability_nearest();
  // Inertia-corrected factorisation of the current tangent and the step from it.
  // `first_shift`: where the shift scan starts (by default next to the last shift that worked).
  bool solve_inertia_corrected(const Eigen::VectorXd& rhs, Eigen::VectorXd& du,
                               std::optional<double> first_shift = {});
  // Cuts back the step base → base + du (residual r_base there) until the energy falls by the Armijo
  // amount; sets u to the accepted point. Returns the accepted fraction of the step.
  double energy_line_search(const Eigen::VectorXd& base, const Eigen::VectorXd& du, double slope,
                            double load_factor, Eigen::VectorXd& u, int& backtracks);

  NonlinearProblem& problem_;
  NewtonSettings settings_;
  SparseDirectSolver linear_;
  int total_iterations_ = 0;
  bool refresh_ = false;  // the last reused factorisation needed many GMRES iterations: factorise next
  bool inertia_corrected_ = false;  // a symmetric problem: Cholesky with inertia correction
  double shift_ = 0.0;              // relative shift of the factorisation behind the last step
  bool lu_mode_ = false;  // nearest-equilibrium steps on an indefinite tangent: LU until a stable state
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
  double tangent_shift = 0.0;  // NewtonOutcome::final_shift of the converged state
};

struct LoadPathResult {
  bool completed = false;
  std::vector<LoadStepRecord> steps;
  int cutbacks = 0;
  LoadStepRecord last_failure;  // the last attempt that did not converge (its target λ and residual)
};

// Drives λ from 0 to 1. Each step starts from a secant prediction of the last two converged states; an
// increment that does not converge is halved (down to min_increment). `on_step` sees each converged state.
LoadPathResult follow_load_path(NewtonSolver& newton, Eigen::VectorXd& u,
                                const LoadSteppingSettings& settings,
                                const std::function<void(const LoadStepRecord&, const Eigen::VectorXd&)>&
                                    on_step = {},
                                const ProgressSink& progress = {});

}  // namespace tirefem
