#include "tirefem/solver/newton.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace tirefem {
namespace {
// The exact step on an indefinite tangent by GMRES on the shifted factorisation: worth trying up to this
// shift (the roll-up cantilever's 1e-5 needed ~20 iterations); beyond it LU is cheaper.
constexpr int kMaxExactStepIterations = 25;
constexpr double kMaxShiftForKrylov = 1e-4;
constexpr double kMaxExtension = 16.0;  // Π'(1) > this × |Π'(0)|: the step overshot the energy's minimum
}  // namespace

NewtonSolver::NewtonSolver(NonlinearProblem& problem, NewtonSettings settings)
    : problem_(problem), settings_(settings), linear_(problem.symmetric(), /*sticky_lu=*/!settings.reuse_factorization),
      inertia_corrected_(settings.inertia_correction && problem.symmetric()) {}

NewtonOutcome NewtonSolver::solve(Eigen::VectorXd& u, double load_factor) {
  const DofMap& dofs = problem_.dofs();
  const double reference = std::max(std::abs(load_factor), 1e-12) * problem_.load_scale();
  const bool potential = problem_.has_potential();
  NewtonOutcome out;
  out.final_shift = shift_;
  lu_only_ = false;
  double increment_norm = 0.0;
  double first_residual = -1.0;
  double energy = 0.0, first_energy = 0.0;  // |Δu·R| of the last and of the first iteration
  double previous_residual = 0.0;
  // The last step, kept until the residual at its end is known: a step that made the residual grow (or
  // came from a shifted tangent) is checked against the energy and cut back if it does not lower it.
  Eigen::VectorXd base, step;
  double slope = 0.0, step_shift = 0.0;
  bool pending = false;
  for (int it = 0;; ++it) {
    problem_.evaluate(u, load_factor, true);
    Eigen::VectorXd r = dofs.gather(problem_.system().residual());
    double rn = r.norm();
    if (pending && potential) {
      // A step from a positive definite tangent is a full Newton step (unless it left the domain of the
      // energy: a non-finite residual): thin shells leaving a flat or unstressed state overshoot the
      // residual and the energy for a step or two while Newton converges, and cutting those steps back
      // slows it down badly (measured on the roll-up cantilever and the inflated tyre). When a stable
      // equilibrium is sought, a step from a shifted (indefinite) tangent must lower the energy.
      const bool finite = std::isfinite(rn);
      const bool descend = settings_.stable_equilibrium && step_shift > 0;
      double fraction = 1.0;
      // A shifted step that still descends steeply at its end (an indefinite tangent: the energy falls
      // away along a direction of negative curvature, towards a state beyond an instability) is extended
      // to the secant estimate of the line minimum, at most kMaxExtension times, if the energy agrees.
      const double end_slope = finite ? step.dot(r) : std::numeric_limits<double>::infinity();
      if (descend && end_slope < 0 && end_slope > slope) {
        const double extended = std::min(slope / (slope - end_slope), kMaxExtension);
        Eigen::VectorXd trial = base;
        dofs.scatter_add(extended * step, trial);
        const std::optional<EnergyChange> e = problem_.energy_change(base, trial, load_factor);
        if (extended > 1.5 && e && e->change <= settings_.armijo * extended * slope) {
          u = trial;
          fraction = extended;
          ++out.extensions;
        }
      }
      // Otherwise a shifted step, or one whose end has no finite residual, is cut back to lower the
      // energy by the Armijo amount.
      else if (descend || !finite)
        fraction *= energy_line_search(base, fraction * step, fraction * slope, load_factor, u, out.backtracks);
      if (fraction != 1.0) {
        problem_.evaluate(u, load_factor, true);
        r = dofs.gather(problem_.system().residual());
        rn = r.norm();
        increment_norm *= fraction;
        energy *= fraction;
      }
    }
    pending = false;
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
      out.final_shift = shift_;
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
    out.max_shift = std::max(out.max_shift, shift_);
    out.final_shift = shift_;
    // Line search on ‖R‖ (problems without a potential, when enabled): far from the solution (an
    // unstressed membrane under follower pressure) a full step can overshoot by orders of magnitude.
    for (int halving = 0; !potential && halving < settings_.max_line_search_halvings; ++halving) {
      Eigen::VectorXd trial = u;
      dofs.scatter_add(du, trial);
      problem_.evaluate(trial, load_factor, false);
      const double trial_norm = dofs.gather(problem_.system().residual()).norm();
      if (std::isfinite(trial_norm) && trial_norm < rn) break;
      du *= 0.5;
    }
    if (potential) {
      base = u;
      step = du;
      slope = du.dot(r);
      step_shift = shift_;
      pending = true;
    }
    dofs.scatter_add(du, u);
    increment_norm = du.norm();
    energy = std::abs(du.dot(r));
    if (it == 0) first_energy = energy;
    ++out.iterations;
    ++total_iterations_;
  }
}

double NewtonSolver::energy_line_search(const Eigen::VectorXd& base, const Eigen::VectorXd& du, double slope,
                                        double load_factor, Eigen::VectorXd& u, int& backtracks) {
  const DofMap& dofs = problem_.dofs();
  double alpha = 1.0;
  for (int k = 0;; ++k) {
    Eigen::VectorXd trial = base;
    dofs.scatter_add(alpha * du, trial);
    const std::optional<EnergyChange> e = problem_.energy_change(base, trial, load_factor);
    if (!e) return alpha;
    const double change = e->change;
    // A change at round-off level cannot be judged: accept (Newton is then close to the solution).
    const bool round_off = std::isfinite(change) && std::abs(change) <= 1e-12 * e->magnitude;
    const bool decrease = std::isfinite(change) &&
                          (slope < 0 ? change <= settings_.armijo * alpha * slope : change < 0);
    if (round_off || decrease || k >= settings_.max_energy_backtracks) {
      if (alpha < 1.0) u = trial;
      return alpha;
    }
    ++backtracks;
    // Minimum of the quadratic through Π(0), Π'(0) = slope and Π(α), kept within [0.1α, 0.5α].
    double next = 0.5 * alpha;
    if (std::isfinite(change) && slope < 0) {
      const double curvature = change - slope * alpha;
      if (curvature > 0) next = -slope * alpha * alpha / (2.0 * curvature);
    }
    alpha = std::clamp(next, 0.1 * alpha, 0.5 * alpha);
  }
}

bool NewtonSolver::solve_inertia_corrected(const Eigen::VectorXd& rhs, Eigen::VectorXd& du) {
  const SparseMatrix& tangent = problem_.system().tangent();
  if (lu_only_) {  // strongly indefinite at the last iteration of this solve: exact steps by LU directly
    linear_.factorize_lu(tangent);
    du = linear_.solve(rhs);
    return du.allFinite();
  }
  shift_ = linear_.factorize_inertia_corrected(tangent);
  du = linear_.solve(rhs);
  if (shift_ == 0.0 || !du.allFinite()) return du.allFinite();
  // Indefinite tangent. The exact Newton step heads for the nearest equilibrium and converges fast (far
  // from a stable state, e.g. an unstressed membrane under follower pressure, the shifted step only
  // creeps): found by GMRES on the shifted factorisation, or by LU when that does not converge (a
  // strongly indefinite tangent). When a stable equilibrium is sought it is taken only if it descends
  // the energy (rhs = −R), else the shifted step, always a descent direction; the energy line search
  // checks either.
  Eigen::VectorXd exact;
  bool ok = shift_ <= kMaxShiftForKrylov &&
            linear_.solve_preconditioned(tangent, rhs, exact, settings_.krylov_tolerance, kMaxExactStepIterations);
  if (!ok) {
    linear_.factorize_lu(tangent);
    exact = linear_.solve(rhs);
    ok = exact.allFinite();
    // The shifted factorisation cannot serve this tangent: LU for the rest of this solve (the shift
    // found stays the stability figure), unless a stable equilibrium is sought (it needs the shift).
    lu_only_ = !settings_.stable_equilibrium;
  }
  if (ok && (!settings_.stable_equilibrium || !problem_.has_potential() || exact.dot(rhs) > 0)) du = exact;
  return true;
}

bool NewtonSolver::solve_linear(const Eigen::VectorXd& rhs, Eigen::VectorXd& du, bool fresh) {
  const SparseMatrix& tangent = problem_.system().tangent();
  const auto direct = [&] {
    if (inertia_corrected_) return solve_inertia_corrected(rhs, du);
    shift_ = 0.0;
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
      // With a potential the step must descend (rhs = −R): an exact step towards a saddle is replaced
      // by the inertia-corrected one.
      if (!(inertia_corrected_ && problem_.has_potential() && du.dot(rhs) <= 0)) {
        shift_ = 0.0;
        return true;
      }
    }
    if (lu || inertia_corrected_) return direct();
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
