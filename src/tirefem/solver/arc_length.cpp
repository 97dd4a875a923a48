#include "tirefem/solver/arc_length.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

namespace tirefem {
namespace {

using Eigen::VectorXd;

// Evaluations of one problem with one linear solver; all vectors over the free DOFs except states.
class PathSolver {
 public:
  PathSolver(NonlinearProblem& problem, const ArcLengthSettings& settings)
      : problem_(problem), dofs_(problem.dofs()), settings_(settings), linear_(problem.symmetric()),
        scale_(problem.load_scale()) {}

  double reference(double lambda) const {
    return std::max(std::abs(lambda), settings_.reference_load_factor) * scale_;
  }

  // R(u, λ) and, on request, q = ∂R/∂λ and the tangent (left in the problem's system, not factorised).
  // R is linear in λ for the loads of this library (dead loads, pressure at fixed u): q = R(u, λ+1) − R(u, λ).
  VectorXd evaluate(const VectorXd& u, double lambda, bool with_tangent, VectorXd* q = nullptr) {
    VectorXd shifted;
    if (q) {
      problem_.evaluate(u, lambda + 1.0, false);
      shifted = dofs_.gather(problem_.system().residual());
    }
    problem_.evaluate(u, lambda, with_tangent);
    VectorXd r = dofs_.gather(problem_.system().residual());
    if (q) *q = shifted - r;
    return r;
  }

  // Factorises the tangent of the last evaluation; false when it is singular.
  bool factorize() {
    try {
      linear_.factorize(problem_.system().tangent());
      return true;
    } catch (const std::runtime_error&) {
      return false;
    }
  }
  VectorXd solve(const VectorXd& rhs) { return linear_.solve(rhs); }
  const LinearSolverStats& stats() const { return linear_.stats(); }

  // Newton at fixed λ from u (full length): the landing on a target level. Returns the iterations, or
  // −1 without convergence; `residual` gets the final relative residual.
  int newton(VectorXd& u, double lambda, double& residual) {
    for (int it = 0;; ++it) {
      const VectorXd r = evaluate(u, lambda, true);
      residual = r.norm() / reference(lambda);
      if (!std::isfinite(residual)) return -1;
      if (residual <= settings_.residual_tolerance) return it;
      if (it >= settings_.max_iterations || !factorize()) return -1;
      dofs_.scatter_add(solve(-r), u);
    }
  }

  const DofMap& dofs() const { return dofs_; }

 private:
  NonlinearProblem& problem_;
  const DofMap& dofs_;
  const ArcLengthSettings& settings_;
  SparseDirectSolver linear_;
  double scale_;
};

struct StepOutcome {
  bool converged = false;
  int iterations = 0;
  double relative_residual = 0.0;
  VectorXd du;  // increment over the free DOFs
  double dlambda = 0.0;
  std::string failure;
};

// One arc-length step of length dl from the converged (u, λ). `previous_du`, `previous_dlambda`: the
// last converged increment (empty before the first step), which sets the predictor's direction.
StepOutcome arc_length_step(PathSolver& solver, const ArcLengthSettings& s, const VectorXd& u, double lambda,
                            double dl, const VectorXd& previous_du, double previous_dlambda) {
  StepOutcome out;
  const DofMap& dofs = solver.dofs();
  // Tangent predictor: K du/dλ = −q, Δλ = ±Δl / √(‖du/dλ‖² + ψ²‖q‖²).
  VectorXd q;
  solver.evaluate(u, lambda, true, &q);
  if (!solver.factorize()) {
    out.failure = "singular tangent at the start of the step";
    return out;
  }
  const VectorXd tangent = solver.solve(-q);
  const double psi2qq = s.psi * s.psi * q.squaredNorm();  // fixed over the step
  const double scale = std::sqrt(tangent.squaredNorm() + psi2qq);
  // Direction: the one making an acute angle (in the constraint's metric) with the previous increment.
  double sign = 1.0;
  if (previous_du.size() > 0 && tangent.dot(previous_du) + psi2qq * previous_dlambda < 0) sign = -1.0;
  out.dlambda = sign * dl / scale;
  out.du = out.dlambda * tangent;

  for (int it = 0;; ++it) {
    VectorXd trial = u;
    dofs.scatter_add(out.du, trial);
    const double trial_lambda = lambda + out.dlambda;
    const VectorXd r = solver.evaluate(trial, trial_lambda, true, &q);
    out.relative_residual = r.norm() / solver.reference(trial_lambda);
    out.iterations = it;
    if (!std::isfinite(out.relative_residual)) {
      out.failure = "non-finite residual";
      return out;
    }
    if (out.relative_residual <= s.residual_tolerance) {
      out.converged = true;
      return out;
    }
    if (it >= s.max_iterations) {
      out.failure = fmt::format("no convergence in {} iterations (residual {:.1e})", it, out.relative_residual);
      return out;
    }
    if (!solver.factorize()) {
      out.failure = "singular tangent";
      return out;
    }
    // Bordering: δu = δu_R + δλ δu_F with K δu_R = −R, K δu_F = −q; δλ from the constraint
    // ‖Δu + δu‖² + ψ²‖q‖²(Δλ + δλ)² = Δl², a quadratic a δλ² + b δλ + c = 0.
    const VectorXd du_r = solver.solve(-r);
    const VectorXd du_f = solver.solve(-q);
    const VectorXd base = out.du + du_r;
    const double a = du_f.squaredNorm() + psi2qq;
    const double b = 2.0 * (base.dot(du_f) + psi2qq * out.dlambda);
    const double c = base.squaredNorm() + psi2qq * out.dlambda * out.dlambda - dl * dl;
    const double disc = b * b - 4.0 * a * c;
    if (!(disc >= 0.0) || a <= 0.0) {
      out.failure = "no real root of the arc-length constraint";
      return out;
    }
    // Roots without cancellation; of the two, the one whose new increment makes the smaller angle with
    // the current one (Crisfield 1981), which keeps the iteration from turning back along the path.
    const double root = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    const double r1 = root / a, r2 = root != 0.0 ? c / root : r1;
    double best = -std::numeric_limits<double>::infinity(), chosen = r1;
    for (const double dlam : {r1, r2}) {
      const double cosine = (base + dlam * du_f).dot(out.du) + psi2qq * (out.dlambda + dlam) * out.dlambda;
      if (cosine > best) {
        best = cosine;
        chosen = dlam;
      }
    }
    out.du = base + chosen * du_f;
    out.dlambda += chosen;
  }
}

// The targets a step from λa to λb crosses (λa < λ* ≤ λb, or λb ≤ λ* < λa), in path order.
std::vector<double> crossed(const std::vector<double>& targets, double la, double lb) {
  std::vector<double> hit;
  for (const double t : targets)
    if (t != la && (t - la) * (t - lb) <= 0.0) hit.push_back(t);
  std::sort(hit.begin(), hit.end());
  if (lb < la) std::reverse(hit.begin(), hit.end());
  return hit;
}

}  // namespace

ArcLengthResult follow_arc_length(
    NonlinearProblem& problem, Eigen::VectorXd& u, const ArcLengthSettings& s,
    const std::function<void(const ArcLengthPoint&, const Eigen::VectorXd&)>& on_point) {
  ArcLengthResult result;
  PathSolver solver(problem, s);
  const DofMap& dofs = problem.dofs();
  double lambda = 0.0;

  // The first arc length, from the tangent at the start when a load increment is given.
  double dl = s.initial_arc_length;
  if (dl <= 0.0) {
    VectorXd q;
    solver.evaluate(u, lambda, true, &q);
    if (!solver.factorize()) {
      result.failure = "singular tangent at the start";
      return result;
    }
    dl = std::abs(s.initial_load_increment) * solver.solve(-q).norm();
  }
  const double min_dl = s.min_arc_length > 0 ? s.min_arc_length : dl / 1024.0;
  const double max_dl = s.max_arc_length > 0 ? s.max_arc_length : 16.0 * dl;

  VectorXd previous_du;
  double previous_dlambda = 0.0;
  while (result.steps < s.max_steps) {
    StepOutcome step = arc_length_step(solver, s, u, lambda, dl, previous_du, previous_dlambda);
    result.iterations += step.iterations;
    VectorXd end = u;
    const double end_lambda = lambda + step.dlambda;
    std::vector<std::pair<ArcLengthPoint, VectorXd>> landings;
    bool finished = false;
    if (step.converged) {
      dofs.scatter_add(step.du, end);
      // Landings on the target levels the step crossed, and on max_load_factor (which ends the run).
      std::vector<double> levels = crossed(s.target_load_factors, lambda, end_lambda);
      if (lambda < s.max_load_factor && end_lambda >= s.max_load_factor) {
        std::erase_if(levels, [&](double t) { return t >= s.max_load_factor; });
        levels.push_back(s.max_load_factor);
        finished = true;
      }
      for (const double level : levels) {
        const double w = (level - lambda) / step.dlambda;
        VectorXd state = u + w * (end - u);  // linear interpolation of the two converged states
        ArcLengthPoint point{level, 0, 0.0, true, 0.0};
        point.iterations = solver.newton(state, level, point.relative_residual);
        if (point.iterations < 0) {
          step.converged = false;
          step.failure = fmt::format("landing on load factor {} did not converge", level);
          break;
        }
        result.iterations += point.iterations;
        landings.emplace_back(point, std::move(state));
      }
    }
    if (!step.converged) {
      ++result.cutbacks;
      dl *= 0.5;
      if (dl < min_dl) {
        result.failure = fmt::format("at load factor {}: {}; arc length below its minimum", lambda, step.failure);
        break;
      }
      continue;
    }
    ++result.steps;
    for (auto& [point, state] : landings) {
      result.points.push_back(point);
      if (on_point) on_point(point, state);
    }
    if (finished) {
      u = std::move(landings.back().second);
      lambda = s.max_load_factor;
      result.max_load_factor_seen = std::max(result.max_load_factor_seen, lambda);
      result.completed = true;
      break;
    }
    const ArcLengthPoint point{end_lambda, step.iterations, step.relative_residual, false, dl};
    result.points.push_back(point);
    if (on_point) on_point(point, end);
    u = std::move(end);
    lambda = end_lambda;
    result.max_load_factor_seen = std::max(result.max_load_factor_seen, lambda);
    previous_du = std::move(step.du);
    previous_dlambda = step.dlambda;
    // Next arc length from the iteration count (Crisfield): Δl √(desired / iterations), within [½, 2].
    const double ratio = std::sqrt(static_cast<double>(s.desired_iterations) / std::max(step.iterations, 1));
    dl = std::clamp(dl * std::clamp(ratio, 0.5, 2.0), min_dl, max_dl);
  }
  if (!result.completed && result.failure.empty())
    result.failure = fmt::format("{} steps taken without reaching load factor {}", result.steps, s.max_load_factor);
  result.factorizations = solver.stats().factorizations;
  return result;
}

}  // namespace tirefem
