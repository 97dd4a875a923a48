#pragma once
// The static contact problem of a load curve or footprint study (internal to analysis/footprint*.cpp and
// static_contact_run.cpp): the inflated tyre with the tread's Winkler contact on a support, its Newton
// solver and the deflection path; each converged load point recorded in the study's result.
#include <chrono>
#include <memory>
#include <vector>

#include "tirefem/analysis/contact_iteration.hpp"
#include "tirefem/analysis/footprint.hpp"

namespace tirefem {

using StaticContactClock = std::chrono::steady_clock;
inline double seconds_since(StaticContactClock::time_point t0) {
  return std::chrono::duration<double>(StaticContactClock::now() - t0).count();
}

// Inflated tyre + contact: the forms, the Newton solver and the deflection path over them.
class StaticContactRun {
 public:
  StaticContactRun(const TyreMesh& tm, const TyreDescription& tyre, const InflationSettings& inflation,
                   const ContactSettings& settings, const SupportDescription& support_description,
                   Kinematics kinematics, DeflectionOrigin origin, StaticContactResult& result,
                   const ProgressSink& progress, const InflationResult* inflated);

  // δz (from the undeformed tyre) of the first load point: 0, or the first touch.
  double start() const { return start_; }
  // States of another study of this problem (a load curve's) for the predictor.
  void add_known_states(const std::vector<PathState>& states) {
    for (const PathState& p : states) path_->add_known_state(p.deflection_mm, p.displacement);
  }
  // The current converged state, to keep as a PathState.
  PathState current_state() const {
    return {path_->deflection(), result_.points.back().patch.Qz_N, path_->displacement()};
  }
  const std::vector<Eigen::Vector3d>& inflated_tread() const { return inflated_tread_; }
  const SupportSurface& support() const { return *support_; }

  // Solves at δz and records the load point; false (and result_.failure) when it does not converge after
  // at most `max_cutbacks` halvings of the increment.
  bool solve_at(double deflection, int max_cutbacks = DeflectionPath::kMaxCutbacks);
  // The final state and the solver's counters into the result.
  void finish();

  double last_Qz() const { return result_.points.back().patch.Qz_N; }

 private:
  void record(double deflection, const DeflectionPath::Step& step, double time, int factorizations);

  const TyreMesh& tm_;
  ContactSettings settings_;
  StaticContactResult& result_;
  ProgressSink progress_;
  std::unique_ptr<SupportSurface> support_;
  WinklerContactForm* contact_ = nullptr;
  std::unique_ptr<NonlinearProblem> problem_;
  std::unique_ptr<NewtonSolver> newton_;
  std::unique_ptr<DeflectionPath> path_;
  double start_ = 0.0;
  std::vector<Eigen::Vector3d> inflated_tread_;  // tread point positions in the inflated state
};

template <class Study>
StaticContactResult empty_result(const TyreMesh& tm, const ContactSettings& contact, const Study& study) {
  StaticContactResult result;
  result.name = study.name;
  result.support = study.support;
  result.kinematics = study.linear ? Kinematics::linear : Kinematics::nonlinear;
  result.iteration = contact.iteration;
  result.half_model = tm.half_model;
  result.deflection_from = study.deflection_from;
  return result;
}

inline const char* origin_label(DeflectionOrigin origin) {
  return origin == DeflectionOrigin::first_touch ? " from the inflated tyre's first touch" : "";
}

}  // namespace tirefem
