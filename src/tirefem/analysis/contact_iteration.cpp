#include "tirefem/analysis/contact_iteration.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include <fmt/format.h>

namespace tirefem {

namespace {
int count_changes(const std::vector<char>& a, const std::vector<char>& b) {
  int n = 0;
  for (std::size_t k = 0; k < a.size(); ++k) n += (a[k] != 0) != (b[k] != 0);
  return n;
}
}  // namespace

ContactSolveOutcome solve_contact(NewtonSolver& newton, WinklerContactForm& contact, Eigen::VectorXd& u,
                                  const ContactSettings& settings) {
  ContactSolveOutcome out;
  if (settings.iteration == ContactSettings::Iteration::single_loop) {
    contact.release_region();
    const NewtonOutcome n = newton.solve(u, 1.0);
    out.contact_iterations = 1;
    out.newton_iterations = n.iterations;
    out.converged = n.converged;
    out.tangent_shift = n.final_shift;
    out.escapes = n.escapes;
    out.escaped_shift = n.escaped_shift;
    if (!n.converged) out.failure = fmt::format("Newton: residual {:.1e} after {} iterations", n.relative_residual, n.iterations);
    return out;
  }
  // Two-level iteration: Ωc from the starting state (the prediction), then revised after each solve.
  std::vector<char> region;
  const auto freeze = [&](const Eigen::VectorXd& v) {
    if (region.empty()) region = contact.region(v);
    contact.freeze_region(region);
  };
  const auto revise = [&](const Eigen::VectorXd& v) {
    std::vector<char> revised = contact.region(v);
    const int changes = count_changes(region, revised);
    region = std::move(revised);
    return changes;
  };
  return two_level_iteration(newton, u, settings, freeze, revise);
}

ContactSolveOutcome two_level_iteration(NewtonSolver& newton, Eigen::VectorXd& u, const ContactSettings& settings,
                                        const std::function<void(const Eigen::VectorXd&)>& freeze,
                                        const std::function<int(const Eigen::VectorXd&)>& revise) {
  ContactSolveOutcome out;
  const double final_tolerance = newton.residual_tolerance();
  const double provisional = std::max(settings.provisional_tolerance, final_tolerance);
  bool settled = false;
  for (int outer = 1; outer <= settings.max_contact_iterations; ++outer) {
    freeze(u);
    newton.set_residual_tolerance(settled ? final_tolerance : provisional);
    const NewtonOutcome n = newton.solve(u, 1.0);
    newton.set_residual_tolerance(final_tolerance);
    out.contact_iterations = outer;
    out.newton_iterations += n.iterations;
    out.tangent_shift = n.final_shift;
    out.escapes += n.escapes;
    out.escaped_shift = std::max(out.escaped_shift, n.escaped_shift);
    if (!n.converged) {
      out.failure = fmt::format("Newton in contact iteration {}: residual {:.1e} after {} iterations", outer,
                                n.relative_residual, n.iterations);
      return out;
    }
    out.region_changes = revise(u);
    if (out.region_changes <= settings.region_tolerance) {
      if (settled || provisional <= final_tolerance) {
        out.converged = true;
        return out;
      }
      settled = true;  // polish with the full tolerance, then check once more
    } else {
      settled = false;
    }
  }
  out.failure = fmt::format("contact region not settled after {} iterations ({} points still changing)",
                            settings.max_contact_iterations, out.region_changes);
  return out;
}

DeflectionPath::DeflectionPath(NewtonSolver& newton, WinklerContactForm& contact,
                               const ContactSettings& settings, Eigen::VectorXd start, double start_deflection)
    : newton_(newton), contact_(contact), settings_(settings) {
  states_.push_back({start_deflection, std::move(start)});
}

const DeflectionPath::State& DeflectionPath::nearest(double deflection) const {
  return *std::min_element(states_.begin(), states_.end(), [deflection](const State& a, const State& b) {
    return std::abs(a.deflection - deflection) < std::abs(b.deflection - deflection);
  });
}

Eigen::VectorXd DeflectionPath::predict(double deflection) const {
  // Linear in δz through the two converged states nearest to the target (secant predictor).
  const State& a = nearest(deflection);
  const State* b = nullptr;
  for (const State& s : states_)
    if (&s != &a && std::abs(s.deflection - a.deflection) > 1e-12 &&
        (!b || std::abs(s.deflection - deflection) < std::abs(b->deflection - deflection)))
      b = &s;
  if (!b) return a.u;
  const double t = (deflection - a.deflection) / (b->deflection - a.deflection);
  return a.u + t * (b->u - a.u);
}

DeflectionPath::Step DeflectionPath::advance_to(double deflection, int max_cutbacks) {
  Step step;
  double from = nearest(deflection).deflection;
  double increment = deflection - from;
  const bool stable_mode = settings_.equilibrium == ContactSettings::Equilibrium::stable;
  // A solve to resume (stable mode): its target and its last iterate.
  std::optional<std::pair<double, Eigen::VectorXd>> resume;
  int escapes = 0;
  double escaped_shift = 0.0;
  while (true) {
    const bool last = std::abs(increment) >= std::abs(deflection - from) - 1e-12;
    const double target = last ? deflection : from + increment;
    const bool resuming = resume && resume->first == target;
    Eigen::VectorXd u = resuming ? std::move(resume->second) : predict(target);
    resume.reset();
    const Eigen::VectorXd start = u;
    contact_.set_deflection(target);
    const ContactSolveOutcome outcome = solve_contact(newton_, contact_, u, settings_);
    step.newton_iterations += outcome.newton_iterations;
    // Instabilities passed on the way to the point count, whichever solve passed them.
    escapes += outcome.escapes;
    escaped_shift = std::max(escaped_shift, outcome.escaped_shift);
    if (!outcome.converged) {
      if (step.cutbacks >= max_cutbacks) {
        // Having left unstable equilibria for a stable state it did not reach, the tyre lost its stability
        // here: more iterations are not the remedy (on a coarse mesh, a mesh-scale mode).
        const std::string remedy =
            escapes > 0 ? fmt::format("the tyre lost its stability on the way ({} unstable equilibria left for a "
                                      "stable state not reached): on a coarse mesh a mesh-scale mode (README, \"How "
                                      "fine a mesh\"): refine the mesh, or seek the nearest equilibrium "
                                      "(contact.equilibrium = \"nearest\")",
                                      escapes)
                        : std::string("try more load points, a larger contact.max_newton_iterations or "
                                      "contact.max_contact_iterations");
        step.failure = fmt::format("δz = {:.4g} mm: {} (after {} cut-backs); {}", target, outcome.failure,
                                   step.cutbacks, remedy);
        contact_.set_deflection(states_.back().deflection);
        return step;
      }
      ++step.cutbacks;
      // Seeking a stable state, Newton lowers the energy at every shifted step. A solve that left an
      // unstable equilibrium runs down a long slope towards the buckled (wrinkled) state, and may run
      // out of iterations on the way: it is resumed from its last iterate when that lies lower than its
      // start. Halving the increment instead would repeat the same escape from a state next to the same
      // saddle (or, at the first load point, the very same solve: its increment from the start is 0).
      if (stable_mode && outcome.escapes > 0 && u.allFinite()) {
        const std::optional<EnergyChange> e = newton_.problem().energy_change(start, u, 1.0);
        if (e && std::isfinite(e->change) && e->change < 0) {
          resume.emplace(target, std::move(u));
          continue;
        }
      }
      increment *= 0.5;
      continue;
    }
    ++step.increments;
    states_.push_back({target, std::move(u)});
    from = target;
    if (last) {
      step.converged = true;
      step.last = outcome;
      step.last.escapes = escapes;
      step.last.escaped_shift = escaped_shift;
      return step;
    }
  }
}

}  // namespace tirefem
