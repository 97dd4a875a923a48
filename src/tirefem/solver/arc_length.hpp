#pragma once
// Arc-length path following for R(u, λ) = 0 (Riks 1979; Crisfield 1981, "A fast incremental/iterative
// solution procedure that handles snap-through"): u and λ advance together along the equilibrium path
// by steps of fixed length Δl, so the path is followed through limit points (load maxima, snap-through)
// where load stepping at fixed λ stops. Constraint ‖Δu‖² + ψ²Δλ²‖q‖² = Δl² with q = ∂R/∂λ
// (ψ = 0: cylindrical, ψ = 1: spherical). Newton corrector by the bordering method.
#include <functional>
#include <string>
#include <vector>

#include "tirefem/solver/linear_solver.hpp"
#include "tirefem/solver/nonlinear_problem.hpp"

namespace tirefem {

struct ArcLengthSettings {
  // The first step: its arc length, or (when initial_arc_length ≤ 0) the load increment of its tangent
  // predictor, Δl = Δλ₀ ‖K⁻¹q‖.
  double initial_arc_length = 0.0;
  double initial_load_increment = 0.1;
  // Bounds of the arc length; ≤ 0: 1/1024 and 16 times the first step's.
  double min_arc_length = 0.0;
  double max_arc_length = 0.0;
  double psi = 0.0;  // weight of the load term in the constraint: 0 cylindrical, 1 spherical
  // The next arc length is Δl·√(desired_iterations / iterations) (Crisfield), within [½, 2] × Δl.
  int desired_iterations = 4;
  int max_iterations = 15;  // corrector iterations of one step before it is halved
  // Convergence: ‖R_free‖ ≤ tol · max(|λ|, reference_load_factor) · ‖F‖ (‖F‖ = problem.load_scale()).
  // The floor keeps the test meaningful where the path crosses λ = 0.
  double residual_tolerance = 1e-8;
  double reference_load_factor = 0.01;
  // Load levels to land on exactly (sorted or not): when a converged step crosses λ* (λa < λ* ≤ λb or
  // λb ≤ λ* < λa), Newton at fixed λ* from the linear interpolation of the two states gives that point.
  std::vector<double> target_load_factors;
  // The path ends (completed) on landing at λ = max_load_factor (first crossing from below).
  double max_load_factor = 1.0;
  int max_steps = 200;  // converged arc-length steps; reaching it ends the run as not completed
};

struct ArcLengthPoint {
  double load_factor = 0.0;
  int iterations = 0;              // corrector (or landing Newton) iterations
  double relative_residual = 0.0;  // ‖R_free‖ / (max(|λ|, reference) ‖F‖)
  bool landing = false;            // a solve at fixed λ on a target level (or on max_load_factor)
  double arc_length = 0.0;         // of the step (0 for a landing)
};

struct ArcLengthResult {
  bool completed = false;  // reached max_load_factor
  std::vector<ArcLengthPoint> points;  // in path order: the landings of a step precede its end point
  int steps = 0;           // converged arc-length steps
  int cutbacks = 0;        // steps halved
  int iterations = 0;      // all corrector and landing iterations
  int factorizations = 0;  // of the tangent (SparseDirectSolver::stats())
  double max_load_factor_seen = 0.0;
  std::string failure;  // why the run stopped early
};

// Follows the path from the equilibrium (u, λ = 0) (u normally zero). On return u is the last
// reported state. `on_point` sees each reported point with its full-length displacement.
ArcLengthResult follow_arc_length(
    NonlinearProblem& problem, Eigen::VectorXd& u, const ArcLengthSettings& settings,
    const std::function<void(const ArcLengthPoint&, const Eigen::VectorXd&)>& on_point = {});

}  // namespace tirefem
