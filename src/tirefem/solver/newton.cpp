#include "tirefem/solver/newton.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace tirefem {

NewtonSolver::NewtonSolver(NonlinearProblem& problem, NewtonSettings settings)
    : problem_(problem), settings_(settings), linear_(problem.symmetric(), /*sticky_lu=*/!settings.reuse_factorization) {}

NewtonOutcome NewtonSolver::solve(Eigen::VectorXd& u, double load_factor) {
  const DofMap& dofs = problem_.dofs();
  const double reference = std::max(std::abs(load_factor), 1e-12) * problem_.load_scale();
  NewtonOutcome out;
  double increment_norm = 0.0;
  double first_residual = -1.0;
  double energy = 0.0, first_energy = 0.0;  // |Δu·R| of the last and of the first iteration
  double previous_residual = 0.0;
  for (int it = 0;; ++it) {
    problem_.evaluate(u, load_factor, true);
    const Eigen::VectorXd r = dofs.gather(problem_.system().residual());
    const double rn = r.norm();
    out.relative_residual = reference > 0 ? rn / reference : rn;
    if (!std::isfinite(rn)) return out;
    if (first_residual < 0) first_residual = rn;
    out.residual_history.push_back(out.relative_residual);
    const bool residual_ok = out.relative_residual <= settings_.residual_tolerance ||
                             (it > 0 && energy <= settings_.energy_tolerance * first_energy);
    const bool increment_ok = it > 0 && increment_norm <= settings_.increment_tolerance * u.norm();
    if (residual_ok && (increment_ok || it == 0 ||
                        out.relative_residual <= 0.01 * settings_.residual_tolerance)) {
      out.converged = true;
      return out;
    }
    if (it >= settings_.max_iterations) return out;
    if (it >= 3 && rn > 1e4 * first_residual) return out;  // diverging
    Eigen::VectorXd du;
    // A step from a reused factorisation that made the residual grow was too inexact for this
    // nonlinearity (e.g. the preconditioner came from a very different state): factorise afresh.
    const bool fresh = it > 0 && rn > previous_residual;
    previous_residual = rn;
    if (!solve_linear(-r, du, fresh)) return out;
    // Line search: far from the solution (an unstressed membrane under follower pressure) a full
    // Newton step can overshoot by orders of magnitude; halve it while the residual grows.
    for (int halving = 0; halving < settings_.max_line_search_halvings; ++halving) {
      Eigen::VectorXd trial = u;
      dofs.scatter_add(du, trial);
      problem_.evaluate(trial, load_factor, false);
      const double trial_norm = dofs.gather(problem_.system().residual()).norm();
      if (std::isfinite(trial_norm) && trial_norm < rn) break;
      du *= 0.5;
    }
    dofs.scatter_add(du, u);
    increment_norm = du.norm();
    energy = std::abs(du.dot(r));
    if (it == 0) first_energy = energy;
    ++out.iterations;
    ++total_iterations_;
  }
}

bool NewtonSolver::solve_linear(const Eigen::VectorXd& rhs, Eigen::VectorXd& du, bool fresh) {
  const SparseMatrix& tangent = problem_.system().tangent();
  const auto direct = [&] {
    linear_.factorize(tangent);
    du = linear_.solve(rhs);
    return du.allFinite();
  };
  try {
    const bool lu = linear_.uses_lu();
    if (!settings_.reuse_factorization || (lu && (fresh || refresh_))) {
      refresh_ = false;
      return direct();
    }
    // Reuse the last factorisation as a preconditioner; refactorise when that no longer converges fast.
    const int before = linear_.stats().krylov_iterations;
    if (linear_.solve_preconditioned(tangent, rhs, du, settings_.krylov_tolerance,
                                     settings_.max_krylov_iterations)) {
      refresh_ = lu && linear_.stats().krylov_iterations - before > settings_.refresh_after_krylov_iterations;
      return true;
    }
    if (lu) return direct();  // unsymmetric: a fresh LU of the current tangent
    if (linear_.factorize_shifted(tangent) == 0.0) {
      du = linear_.solve(rhs);
      return du.allFinite();
    }
    // Indefinite tangent: the shifted factorisation preconditions GMRES; LU if even that fails.
    if (linear_.solve_preconditioned(tangent, rhs, du, settings_.krylov_tolerance,
                                     4 * settings_.max_krylov_iterations))
      return true;
    return direct();
  } catch (const std::runtime_error&) {
    return false;
  }
}

LoadPathResult follow_load_path(
    NewtonSolver& newton, Eigen::VectorXd& u, const LoadSteppingSettings& settings,
    const std::function<void(const LoadStepRecord&, const Eigen::VectorXd&)>& on_step,
    const ProgressSink& progress) {
  LoadPathResult result;
  double lambda = 0.0;
  double increment = std::min(settings.first_increment, settings.max_increment);
  Eigen::VectorXd previous = u;  // converged state before the last one
  double previous_lambda = 0.0;
  while (lambda < 1.0 - 1e-12) {
    increment = std::min(increment, 1.0 - lambda);
    const double target = lambda + increment;
    Eigen::VectorXd trial = u;
    if (lambda > previous_lambda)  // secant predictor from the last two converged states
      trial += (target - lambda) / (lambda - previous_lambda) * (u - previous);
    const NewtonOutcome outcome = newton.solve(trial, target);
    if (!outcome.converged) {
      ++result.cutbacks;
      increment *= 0.5;
      if (progress)
        progress(fmt::format("  load factor {:.4f}: no convergence, increment cut to {:.4g}", target,
                             increment));
      if (increment < settings.min_increment) return result;
      continue;
    }
    previous = u;
    previous_lambda = lambda;
    u = trial;
    lambda = target;
    const LoadStepRecord record{lambda, outcome.iterations, outcome.relative_residual};
    result.steps.push_back(record);
    if (progress)
      progress(fmt::format("  load factor {:.4f}: {} Newton iterations, residuals {:.1e}", lambda,
                           outcome.iterations, fmt::join(outcome.residual_history, " ")));
    if (on_step) on_step(record, u);
    if (outcome.iterations < settings.easy_iterations)
      increment = std::min(1.5 * increment, settings.max_increment);
  }
  result.completed = true;
  return result;
}

}  // namespace tirefem
