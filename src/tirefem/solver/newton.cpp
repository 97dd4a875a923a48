#include "tirefem/solver/newton.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace tirefem {
namespace {
// The exact step on an indefinite tangent by GMRES on the shifted factorisation: worth trying up to this
// shift (the roll-up cantilever's 1e-5 needed ~20 iterations); beyond it LU is cheaper.
constexpr int kMaxExactStepIterations = 25;
constexpr double kMaxShiftForKrylov = 1e-4;
// Nearest-equilibrium steps on a tangent that a relative shift this small makes positive definite (a
// slightly indefinite or singular one, e.g. the roll-up cantilever past 0.8 of a turn) are found by
// GMRES on that factorisation rather than by LU.
constexpr double kRoundOffShift = 1e-6;
// Leaving a saddle: inverse iterations for the direction of negative curvature, its largest nodal
// displacement (mm), and how many saddles one solve may leave.
constexpr int kInverseIterations = 40;
constexpr double kPushSize = 0.05;
constexpr int kMaxEscapes = 3;
constexpr double kNegativeCurvature = 1e-10;
constexpr double kMaxExtension = 16.0;  // at most this many times a shifted step along a falling energy
constexpr double kConvergingResidual = 1e-3;  // see the iteration limit in solve()
constexpr int kExtraIterations = 5;
}  // namespace

NewtonSolver::NewtonSolver(NonlinearProblem& problem, NewtonSettings settings)
    : problem_(problem), settings_(settings), linear_(problem.symmetric()),
      inertia_corrected_(problem.symmetric()) {}

NewtonOutcome NewtonSolver::solve(Eigen::VectorXd& u, double load_factor) {
  const DofMap& dofs = problem_.dofs();
  const double reference = std::max(std::abs(load_factor), 1e-12) * problem_.load_scale();
  const bool potential = problem_.has_potential();
  // A stable equilibrium is sought and this solve must tell whether the converged state is one.
  const bool tests_stability =
      settings_.stable_equilibrium && potential && inertia_corrected_ && !settings_.known_stable;
  NewtonOutcome out;
  out.final_shift = shift_;
  double increment_norm = 0.0;
  double first_residual = -1.0;
  double energy = 0.0, first_energy = 0.0;  // |Δu·R| of the last and of the first iteration
  double previous_residual = 0.0;
  // The last step, kept until the residual at its end is known: a step that made the residual grow (or
  // came from a shifted tangent) is checked against the energy and cut back if it does not lower it.
  Eigen::VectorXd base, step;
  double slope = 0.0, step_shift = 0.0;
  bool pending = false;
  bool restart = false;  // the last iteration pushed u off a saddle: the next step is a first step
  bool near_tested = false, near_stable = false;  // see near_test below
  // The tangent near the solution was indefinite (the near test failed since the last push): Newton is
  // converging to an unstable equilibrium.
  bool saddle_ahead = false;
  double last_step_shift = 0.0;  // of the factorisation behind the last step that needed one
  bool step_factorised = false;  // the last step came with a factorisation made for it
  // The first shift the converged state's stability test tries: with a saddle ahead, one decade below
  // the shift a tangent of this solve last needed, since the converged state's is alike (measured on the
  // example's load curve: the scan from 0 took 6 factorisations at 30 mm, for the 1e-2 found two
  // iterations before). Found positive definite there, the state is stable only if σ = 0 also is.
  const auto final_test_shift = [&] { return saddle_ahead && last_step_shift > 0 ? 0.1 * last_step_shift : 0.0; };
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
      // The energy falls ever faster along the step (negative curvature: the state is moving off an
      // instability towards the buckled or wrinkled one): the secant has no minimum to aim at, so the
      // step is doubled while the energy keeps falling. Without this the heavily shifted steps only
      // creep down the slope and Newton runs out of iterations before it reaches the stable state.
      else if (descend && end_slope < 0 && end_slope <= slope) {
        const std::optional<EnergyChange> at_end = problem_.energy_change(base, u, load_factor);
        double best = at_end ? at_end->change : 0.0;
        for (double t = 2.0; at_end && t <= kMaxExtension; t *= 2.0) {
          Eigen::VectorXd trial = base;
          dofs.scatter_add(t * step, trial);
          const std::optional<EnergyChange> e = problem_.energy_change(base, trial, load_factor);
          if (!e || !std::isfinite(e->change) || e->change >= best) break;
          best = e->change;
          u = std::move(trial);
          fraction = t;
        }
        if (fraction > 1.0) ++out.extensions;
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
    // The error left in u is about the next increment, which Newton's contraction makes the last one
    // times the residual's reduction since (a converging step that cut the residual 1e4-fold leaves an
    // error 1e4 times smaller than itself): measured against the tolerance, this saves the confirming
    // iteration the last increment alone would ask for.
    const double contraction = previous_residual > 0 ? std::min(1.0, rn / previous_residual) : 1.0;
    const bool increment_ok =
        it > 0 && increment_norm * contraction <= settings_.increment_tolerance * u.norm();
    if (residual_ok && (increment_ok || it == 0 ||
                        out.relative_residual <= 0.01 * settings_.residual_tolerance)) {
      out.converged = true;
      // After LU steps the converged state's stability is not known yet: one Cholesky attempt on its
      // tangent tells (and lets the next solve start with Cholesky again if it is stable).
      // (GMRES steps on the LU have reset shift_: an indefinite tangent must be reported as such, 1e-5
      // standing for "indefinite" without its size.)
      if (lu_mode_ && it > 0) {
        lu_mode_ = !linear_.factorize_cholesky(problem_.system().tangent(), 0.0);
        shift_ = lu_mode_ ? 10 * kRoundOffShift : 0.0;
      }
      // Steps by GMRES on an earlier factorisation say nothing of this state's tangent: one Cholesky
      // attempt on it tells whether the state is stable, and preconditions the next solve.
      else if (settings_.reuse_factorization && inertia_corrected_ && !settings_.stable_equilibrium && it > 0 &&
               !settings_.known_stable)
        test_stability_nearest();
      // A stable equilibrium is sought: test the converged state's own tangent; at a saddle (the
      // prediction kept the symmetry of the state, so the exact steps never felt the unstable mode)
      // push off along the direction of negative curvature, to the side that lowers the energy, and
      // go on descending.
      // (A positive definite tangent near the solution has already told: the state is stable.)
      // When the tangent of the iterate near the solution (or a later one) was indefinite, the shifted
      // factorisation held serves the push: its inverse iteration finds this state's direction of
      // negative curvature too (push_off_saddle checks the curvature on this state's tangent), and the
      // test's own factorisations are spared (measured on the example's load curve: 6 at 30 mm, 4 at 32).
      if (tests_stability && !near_stable) {
        const double held = linear_.held_cholesky_shift();
        bool pushed = false;
        if (saddle_ahead && held > 0 && out.escapes < kMaxEscapes) {
          shift_ = held;
          pushed = push_off_saddle(u, load_factor);
        }
        if (!pushed) {
          const SparseMatrix& tangent = problem_.system().tangent();
          const double first = final_test_shift();
          shift_ = linear_.factorize_inertia_corrected(tangent, first);
          if (shift_ > 0 && shift_ == first)  // positive definite at once: is it without a shift too?
            shift_ = linear_.factorize_cholesky(tangent, 0.0) ? 0.0
                                                              : (linear_.factorize_cholesky(tangent, first), first);
          pushed = shift_ > 0 && out.escapes < kMaxEscapes && push_off_saddle(u, load_factor);
        }
        if (pushed) {
          ++out.escapes;
          out.escaped_shift = std::max(out.escaped_shift, shift_);
          out.converged = false;
          pending = false;
          saddle_ahead = false;
          increment_norm = std::numeric_limits<double>::infinity();
          // The pushed state is the start of a new descent: the divergence test and the energy criterion
          // measure from it, not from the residual of the saddle (round-off small: any later iterate
          // would look 1e4 times larger and be taken for divergence).
          first_residual = -1.0;
          previous_residual = 0.0;
          restart = true;
          continue;
        }
      }
      out.final_shift = shift_;
      return out;
    }
    // A solve that is converging fast when it reaches its iteration limit (the residual fell more than
    // tenfold in the last iteration and is below kConvergingResidual) is let finish, within
    // kExtraIterations more: cutting it off throws the work away, and the caller then retries from
    // scratch with a smaller step. Measured on the 80 × 46 full model, α 4° → 6°: a frozen-plan solve
    // went 7e-5 → 1.1e-6 at its 25th iteration and was cut off; let finish, it reached 1.7e-8 at its 26th.
    const bool converging = it > 0 && rn < 0.1 * previous_residual && out.relative_residual < kConvergingResidual;
    if (it >= settings_.max_iterations && !(converging && it < settings_.max_iterations + kExtraIterations))
      return out;
    // Diverging. Not when a stable state is sought on a potential: after leaving a saddle, the energy-checked
    // descent towards the buckled (wrinkled) state can raise the residual by orders of magnitude (the
    // coarse example mesh's inflated saddle: to 1e2 relative); max_iterations bounds it.
    if (it >= 3 && rn > 1e4 * first_residual && !(settings_.stable_equilibrium && potential)) return out;
    Eigen::VectorXd du;
    const int factorizations_before = linear_.stats().factorizations;
    // A step from a reused factorisation that made the residual grow was too inexact for this
    // nonlinearity (e.g. the preconditioner came from a very different state): factorise afresh. Not after
    // a step from a factorisation of its own iterate: that step was as exact as a new one would be, the
    // growth is the nonlinearity's, and GMRES on that recent factorisation serves the next step.
    const bool fresh = it > 0 && rn > previous_residual && !step_factorised;
    double eta = settings_.krylov_tolerance;
    if (settings_.adaptive_krylov_tolerance) {
      // Eisenstat–Walker forcing term (their choice 2, γ = 0.9, α = 2): loose while the residual falls
      // slowly, tight once Newton converges fast; between krylov_tolerance and max_forcing_term, and no
      // tighter than what brings the residual to a tenth of the Newton tolerance.
      const double eta_max = std::min(settings_.max_forcing_term, 0.1);
      eta = previous_residual > 0 && !restart ? 0.9 * std::pow(rn / previous_residual, 2.0) : eta_max;
      eta = std::clamp(eta, settings_.krylov_tolerance, eta_max);
      eta = std::max(eta, std::min(eta_max, 0.1 * settings_.residual_tolerance * reference / rn));
    }
    previous_residual = rn;
    // Near the solution (stable mode with reused factorisations): factorise this iterate's tangent once.
    // Its inertia tells the converged state's stability (the final test is then spared when it is
    // positive definite), and the last iterations' GMRES runs on a factorisation of nearly their own
    // tangent.
    bool factorised_here = false, indefinite_here = false;
    if (tests_stability && settings_.reuse_factorization && !near_tested && it > 0 && !lu_mode_ &&
        out.relative_residual <= settings_.near_solution_residual) {
      near_tested = true;
      near_stable = factorised_here = linear_.factorize_cholesky(problem_.system().tangent(), 0.0);
      saddle_ahead = indefinite_here = !near_stable;
    }
    if (factorised_here) {
      shift_ = 0.0;
      du = linear_.solve(-r);
      if (!du.allFinite()) return out;
    } else if (indefinite_here) {
      // Newton converges to an unstable equilibrium: the step comes from an inertia-corrected
      // factorisation, whose scan need not try σ = 0 again.
      if (!solve_inertia_corrected(-r, du, SparseDirectSolver::kFirstShift)) return out;
    } else if (!solve_linear(-r, du, fresh, eta, out.relative_residual <= settings_.keep_lu_below_residual)) {
      return out;
    }
    step_factorised = linear_.stats().factorizations > factorizations_before;
    if (shift_ > 0 || lu_mode_) near_stable = false;  // a later tangent was indefinite: test the end state
    if (shift_ > 0) last_step_shift = shift_;
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
    if (it == 0 || restart) first_energy = energy;
    restart = false;
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

bool NewtonSolver::push_off_saddle(Eigen::VectorXd& u, double load_factor) {
  const DofMap& dofs = problem_.dofs();
  const SparseMatrix& tangent = problem_.system().tangent();
  // Inverse iteration with the shifted factorisation (A + σD)⁻¹D: the eigenvector of the most negative
  // eigenvalue of D⁻¹A (D = diag|A|) grows fastest, since σ only just exceeds it.
  const Eigen::VectorXd d = tangent.diagonal().cwiseAbs().cwiseMax(1e-8 * tangent.diagonal().cwiseAbs().mean());
  Eigen::VectorXd v(tangent.cols());
  std::uint64_t seed = 88172645463325252ull;  // a fixed start: the same push on every run
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    seed ^= seed << 13, seed ^= seed >> 7, seed ^= seed << 17;
    v[i] = static_cast<double>(seed % 2001) / 1000.0 - 1.0;
  }
  bool negative = false;
  for (int k = 0; k < kInverseIterations && !negative; ++k) {
    v = linear_.solve(Eigen::VectorXd(d.cwiseProduct(v)));
    v /= v.cwiseAbs().maxCoeff();
    // Negative curvature beyond round-off (relative to the diagonal's measure of v): a saddle.
    negative = v.allFinite() && v.dot(tangent * v) < -kNegativeCurvature * v.dot(d.cwiseProduct(v));
  }
  if (!negative) return false;
  const Eigen::VectorXd base = u;
  double best = 0.0;
  // The push is sized down until the energy falls (at a saddle it falls ∝ t² along v, until the
  // nonlinear terms take over).
  for (double size = kPushSize; size >= 1e-4 * kPushSize && best == 0.0; size *= 0.1)
    for (double sign : {1.0, -1.0}) {
      Eigen::VectorXd trial = base;
      dofs.scatter_add(sign * size * v, trial);
      const std::optional<EnergyChange> e = problem_.energy_change(base, trial, load_factor);
      if (e && e->change < best && std::abs(e->change) > 1e-12 * e->magnitude) best = e->change, u = trial;
    }
  return best < 0.0;
}

void NewtonSolver::test_stability_nearest() {
  const SparseMatrix& tangent = problem_.system().tangent();
  if (linear_.factorize_cholesky(tangent, 0.0)) {
    shift_ = 0.0;
    return;
  }
  // Singular up to round-off (the shift that makes it positive definite is this small) or indefinite.
  shift_ = linear_.factorize_cholesky(tangent, kRoundOffShift) ? kRoundOffShift : 10 * kRoundOffShift;
  if (shift_ > kRoundOffShift) lu_mode_ = true;
}

double NewtonSolver::stability_shift() {
  if (!inertia_corrected_) throw std::logic_error("NewtonSolver::stability_shift: the problem is not symmetric");
  test_stability_nearest();
  return shift_;
}

bool NewtonSolver::solve_inertia_corrected(const Eigen::VectorXd& rhs, Eigen::VectorXd& du,
                                           std::optional<double> first_shift) try {
  const SparseMatrix& tangent = problem_.system().tangent();
  const auto lu_step = [&] {
    linear_.factorize_lu(tangent);
    du = linear_.solve(rhs);
    return du.allFinite();
  };
  if (!settings_.stable_equilibrium) {
    // Nearest equilibrium: exact steps. Cholesky when the tangent is positive definite, or nearly so (a
    // shift at round-off level, with GMRES for the exact step); LU otherwise, and from then on until a
    // converged state is found stable again (solve() checks that).
    if (lu_mode_) return lu_step();
    if (linear_.factorize_cholesky(tangent, 0.0)) {
      shift_ = 0.0;
      du = linear_.solve(rhs);
      return du.allFinite();
    }
    shift_ = kRoundOffShift;
    if (linear_.factorize_cholesky(tangent, kRoundOffShift) &&
        linear_.solve_preconditioned(tangent, rhs, du, settings_.krylov_tolerance, kMaxExactStepIterations))
      return true;
    shift_ = 10 * kRoundOffShift;  // a lower bound: the tangent is indefinite beyond round-off
    lu_mode_ = true;
    return lu_step();
  }
  // Stable equilibrium: the smallest shift that makes the tangent positive definite gives a descent
  // step; the exact step (GMRES on that factorisation while the shift is small, else LU) is taken
  // instead when it also descends the energy (rhs = −R), since far from a stable state (an unstressed
  // membrane under follower pressure) the shifted step only creeps. The energy line search checks either.
  shift_ = linear_.factorize_inertia_corrected(tangent, first_shift);
  du = linear_.solve(rhs);
  if (shift_ == 0.0 || !du.allFinite() || !problem_.has_potential()) return du.allFinite();
  const Eigen::VectorXd shifted = du;
  Eigen::VectorXd exact;
  bool ok = shift_ <= kMaxShiftForKrylov &&
            linear_.solve_preconditioned(tangent, rhs, exact, settings_.krylov_tolerance, kMaxExactStepIterations);
  if (!ok) {
    linear_.factorize_lu(tangent);
    exact = linear_.solve(rhs);
    ok = exact.allFinite();
  }
  du = ok && exact.dot(rhs) > 0 ? exact : shifted;
  return true;
} catch (const std::runtime_error&) {
  return false;
}

bool NewtonSolver::solve_linear(const Eigen::VectorXd& rhs, Eigen::VectorXd& du, bool fresh,
                                double krylov_tolerance, bool near_convergence) {
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
    if (!settings_.reuse_factorization || (lu && (fresh || (refresh_ && !near_convergence)))) {
      refresh_ = false;
      return direct();
    }
    // Reuse the last factorisation as a preconditioner; refactorise when that no longer converges fast.
    const int before = linear_.stats().krylov_iterations;
    if (linear_.solve_preconditioned(tangent, rhs, du, krylov_tolerance, settings_.max_krylov_iterations,
                                     near_convergence)) {
      refresh_ = lu && linear_.stats().krylov_iterations - before > settings_.refresh_after_krylov_iterations;
      // When a stable equilibrium is sought the step must descend (rhs = −R): an exact step towards a
      // saddle is replaced by the inertia-corrected one.
      const bool ascends = settings_.stable_equilibrium && problem_.has_potential() && du.dot(rhs) <= 0;
      if (!ascends) {
        shift_ = 0.0;
        return true;
      }
    }
    return direct();
  } catch (const std::runtime_error&) {
    return false;
  }
}

bool NewtonSolver::solve_with_tangent(const Eigen::VectorXd& rhs, Eigen::VectorXd& x, double tolerance) {
  return solve_linear(rhs, x, false, tolerance) && x.allFinite();
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
      result.last_failure = {target, outcome.iterations, outcome.relative_residual};
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
    const LoadStepRecord record{lambda, outcome.iterations, outcome.relative_residual, outcome.final_shift};
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
