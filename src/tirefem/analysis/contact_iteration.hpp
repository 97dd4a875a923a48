#pragma once
// Solving one load point of a contact problem (MODEL.md §4): the two-level iteration of the paper (outer
// loop revises the contact region Ωc by eq. 5, inner Newton loop solves eq. 13 with Ωc frozen, until Ωc
// repeats) or the single-loop variant (Ωc = {g > 0} at every Newton iterate), and the path of load points
// in the deflection δz with prediction and cut-back.
#include <functional>
#include <string>
#include <vector>

#include "tirefem/case/case.hpp"
#include "tirefem/forms/winkler_contact_form.hpp"
#include "tirefem/solver/newton.hpp"

namespace tirefem {

struct ContactSolveOutcome {
  bool converged = false;
  int contact_iterations = 0;  // outer iterations = Newton solves (1 for the single loop)
  int newton_iterations = 0;   // linear solves
  int region_changes = 0;      // points whose membership of Ωc changed in the last outer iteration
  // Relative diagonal shift the tangent needed at the last factorisation (NewtonOutcome::final_shift):
  // 0 for a positive definite tangent, a stable equilibrium; > 0 an indefinite one, an unstable state.
  double tangent_shift = 0.0;
  // Unstable equilibria Newton left for a stable state (ContactSettings::Equilibrium::stable), and the
  // largest shift their tangents needed.
  int escapes = 0;
  double escaped_shift = 0.0;
  std::string failure;
};

// The outer loop of the two-level iteration over whatever the inner Newton loop holds frozen (the
// contact region; in rolling also the stick/slip plan): freeze(u) fixes it from u, revise(u) proposes the
// next one from the solution and returns how many points it changes. While it still changes, Newton stops
// at the provisional tolerance; once it has settled (≤ region_tolerance changes), a final solve to the
// full tolerance (usually one or two iterations) confirms it.
ContactSolveOutcome two_level_iteration(NewtonSolver& newton, Eigen::VectorXd& u, const ContactSettings& settings,
                                        const std::function<void(const Eigen::VectorXd&)>& freeze,
                                        const std::function<int(const Eigen::VectorXd&)>& revise);

// Solves at the contact form's current deflection, starting from u (overwritten by the solution; left at
// the last iterate on failure).
ContactSolveOutcome solve_contact(NewtonSolver& newton, WinklerContactForm& contact, Eigen::VectorXd& u,
                                  const ContactSettings& settings);

// Converged states along δz, with a predictor from the nearest two of them and halving cut-back.
class DeflectionPath {
 public:
  DeflectionPath(NewtonSolver& newton, WinklerContactForm& contact, const ContactSettings& settings,
                 Eigen::VectorXd start, double start_deflection = 0.0);

  struct Step {
    bool converged = false;
    int increments = 0;          // solves that converged on the way (1 without cut-back)
    int cutbacks = 0;
    ContactSolveOutcome last;    // the solve that reached the target
    int newton_iterations = 0;   // over all solves, failed ones included
    std::string failure;
  };
  // Moves the support to `deflection` from the nearest converged state, cutting the increment back by
  // halving (at most `max_cutbacks` times) when a solve fails. On success the state is recorded.
  static constexpr int kMaxCutbacks = 6;
  Step advance_to(double deflection, int max_cutbacks = kMaxCutbacks);

  // A converged state found elsewhere (a load curve's), for the predictor only: the current state stays.
  void add_known_state(double deflection, Eigen::VectorXd u) {
    states_.insert(states_.end() - 1, {deflection, std::move(u)});
  }
  const Eigen::VectorXd& displacement() const { return states_.back().u; }
  double deflection() const { return states_.back().deflection; }

 private:
  struct State {
    double deflection;
    Eigen::VectorXd u;
  };
  Eigen::VectorXd predict(double deflection) const;
  const State& nearest(double deflection) const;

  NewtonSolver& newton_;
  WinklerContactForm& contact_;
  ContactSettings settings_;
  std::vector<State> states_;  // converged; the last one is the current state
};

}  // namespace tirefem
