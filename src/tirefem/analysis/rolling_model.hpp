#pragma once
// The model of a rolling study (internal to analysis/rolling*.cpp): the inflated, statically loaded tyre
// with the tread's friction (forms/tread_friction_form.hpp), its Newton solver (LU) and the converged
// states, from which each new state is predicted and continued.
//
// A state is set by the wheel's slip: the rolling radius Rk = V/Ω (longitudinal slip), the slip angle α
// and the camber γ (MODEL.md §7). In the model's frame the support moves along ∓y under the fixed axle
// and, at a slip angle, also sideways by tan α per unit of travel (ISO 8855: α > 0 when the wheel moves
// to the left of its heading, so the road moves to the right under it, towards +x, when the wheel
// travels in +y); camber tilts the road plane (road/cambered_plane.hpp).
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "tirefem/analysis/rolling.hpp"
#include "tirefem/road/cambered_plane.hpp"

namespace tirefem {

struct WheelSlip {
  double rolling_radius = 0.0;  // Rk, mm
  double slip_angle = 0.0;      // α, rad
  double camber = 0.0;          // γ, rad
};

class RollingModel {
 public:
  RollingModel(const TyreMesh& tm, const TyreDescription& tyre, const InflationSettings& inflation,
               const ContactSettings& settings, const RollingStudy& study, RollingResult& result);

  struct Solved {
    bool converged = false;
    std::string failure;
    RollingFigures figures;
    RollingSolveCounts counts;
    Eigen::VectorXd u;
    Eigen::Vector4d parameters = Eigen::Vector4d::Zero();  // of the state (see Parameters below)
    bool continued = false;  // a Coulomb state: kept for later states to start from and predict with
  };

  // Solves with the given law at the given slip. Coulomb and full stick: from the nearest converged
  // Coulomb state (predicted), continued in (1/Rk, tan α, γ) from it, the step halved when a solve fails.
  // Full slip (α = γ = 0): from the static footprint, continued in μ with a secant predictor; the whole
  // friction force at once is tried first.
  // `from_last`: continue from the state converged last instead of the nearest one. `along_tangent`: a stage
  // without a secant starts along du/dt (slip_rate) instead of from its start state.
  Solved solve(const FrictionLaw& law, const WheelSlip& slip, bool from_last = false, bool along_tangent = false);
  // Holds Qz at `target` by moving the support (δz): Newton steps in δz, each a rolling solve from the
  // last state predicted along its du/dδz (deflection_rate), until |Qz − target| ≤ tolerance · target;
  // `stiffness` (dQz/dδz) and then secants serve where du/dδz is not found. Leaves the model at the new
  // deflection.
  void hold_load(Solved& s, double target, double tolerance, double stiffness);
  void set_deflection(double deflection);
  double deflection() const { return deflection_; }
  RollingFigures figures(const Eigen::VectorXd& u) const;
  // Qy of a full-stick plan at the static state for Rk (no solve): affine in Rk, it estimates Re.
  double static_full_stick_Qy(double rolling_radius);
  // du/dδz at the converged state u (at the model's δz and slip): K du/dδz = −∂R/∂δz with the exact
  // tangent at u (one assembly, one linear solve), and dQz/dδz along it. False when the solve fails or the
  // stiffness is not positive. Leaves δz as it was.
  bool deflection_rate(const Eigen::VectorXd& u, Eigen::VectorXd& rate, double& stiffness);
  // du/dt at the converged state u (at the slip `from` and the model's δz) for the slip moving from `from`
  // (t = 0) towards `to` (t = 1) in (axle height / Rk, tan α, γ), and d(Fx, Fy)/dt along it (parameter_rate):
  // the tangent predictor of free rolling's secant steps (solve's along_tangent). Leaves the slip at `from`.
  bool slip_rate(const Eigen::VectorXd& u, const WheelSlip& from, const WheelSlip& to, Eigen::VectorXd& rate,
                 Eigen::Vector2d& force_rate);
  void fill(RollingStateResult& state, const Solved& s) const;
  // The converged Coulomb states later states start from (RollingStart::states), and the adoption of
  // such states solved by another model of the same study's tyre, mesh and support (at the same δz).
  const std::vector<RollingStartState>& converged_states() const { return known_; }
  void adopt(const std::vector<RollingStartState>& states) { known_.insert(known_.end(), states.begin(), states.end()); }
  void finish(SolveCounters& c) const;
  // A state that takes long (more than kQuietSeconds) reports each further stage of its continuation
  // and each δz step of hold_load here.
  void set_progress(ProgressSink progress) { progress_ = std::move(progress); }

 private:
  // (axle height / Rk, tan α, γ, δz / axle height): κ, α, γ and the support's deflection on comparable
  // scales. The deflection is one of them because states held at a load (hold_load) lie at other δz: a
  // secant through states at two deflections, read as if at one, predicts badly.
  using Parameters = Eigen::Vector4d;
  using Known = RollingStartState;
  Parameters parameters(const WheelSlip& slip) const;
  // One continuation to `target` from known_[from_index] (−1: the static footprint), in stages with
  // halving cut-back, within ContactSettings::max_state_iterations; counts its nonlinear solves.
  struct Attempt {
    bool converged = false;
    std::string failure;
    Eigen::VectorXd u;
    ContactSolveOutcome last;  // of the last stage
  };
  Attempt continuation(const FrictionLaw& law, const Parameters& target, int from_index, bool along_tangent,
                       int& solves);
  void apply(const Parameters& parameters);
  const Known* nearest(const Parameters& p, const Known* other = nullptr) const;
  // `path`: indices in known_ of the continuation under way (its start state, then its stages). False
  // (and `out` untouched) where no secant serves.
  bool predict(const Parameters& p, const std::vector<int>& path, Eigen::VectorXd& out) const;
  // du/dt at the converged state u for the parameters p(t) = at + t · direction (δz held): K du/dt = −∂R/∂t
  // with the exact tangent at u (one assembly, one linear solve), and d(Fx, Fy)/dt along it. False when
  // the solve fails. Leaves the parameters at `at`.
  bool parameter_rate(const Eigen::VectorXd& u, const Parameters& at, const Parameters& direction,
                      Eigen::VectorXd& rate, Eigen::Vector2d& force_rate);
  // Both rates: K du/dt = −∂R/∂t at u, ∂R/∂t by central differences over ±h of `move` (which puts the
  // support or the slip at t; move(0) is where u is).
  bool solution_rate(const Eigen::VectorXd& u, const std::function<void(double)>& move, double h, Eigen::VectorXd& rate);

  const TyreMesh& tm_;
  ContactSettings settings_;
  RollingResult& result_;
  std::unique_ptr<SupportSurface> support_;
  CamberedPlane* cambered_ = nullptr;  // the support when it is a plane (camber allowed)
  WinklerContactForm* contact_ = nullptr;
  TreadFrictionForm* friction_ = nullptr;
  const RimFlangeForm* flange_ = nullptr;  // the rim flange's contact, if the tyre has one
  std::unique_ptr<NonlinearProblem> problem_;
  std::unique_ptr<NewtonSolver> newton_;
  Eigen::VectorXd base_;  // the static footprint
  double deflection_ = 0.0;
  std::vector<Known> known_;
  ProgressSink progress_;
};

// Secant iteration on Rk for Qy = 0 (|Qy| ≤ 1e-4 Qz) at the given slip angle and camber, from `rk` with
// the first slope dQy/dRk `slope`. `tried` receives every converged (Rk, Qy).
RollingModel::Solved secant_free_rolling(RollingModel& model, const FrictionLaw& law, WheelSlip slip, double slope,
                                         std::vector<std::pair<double, double>>& tried, RollingSolveCounts& total,
                                         const ProgressSink& progress);

// Free rolling straight ahead (α = γ = 0), started from the rigid-tread estimate of the static state.
// Returns the state; sets Re and the slip stiffness dQy/dκ (least squares over the iterates within
// |κ| ≤ 0.003, else the last secant) in the result.
RollingStateResult free_rolling(RollingModel& model, const RollingStudy& study, RollingResult& result,
                                const ProgressSink& progress);

// A study's result before anything is solved (its name, support, friction, travel, model half or full).
RollingResult rolling_result_of(const RollingStudy& study, const TyreMesh& tm);
// δz, the axle height and the loaded radius of the result's footprint.
void place_axle_at_footprint(RollingResult& r, const TyreMesh& tm);

// The static footprint of a rolling study: `footprint` when given and completed (a copy under the study's
// name), else solved (from `nearby`, when given: see run_footprint).
StaticContactResult rolling_footprint(const TyreMesh& tm, const TyreDescription& tyre, const InflationSettings& inflation,
                                      const ContactSettings& contact, const RollingStudy& study,
                                      const ProgressSink& progress, const InflationResult* inflated,
                                      const StaticContactResult* footprint, const std::vector<PathState>* nearby);

}  // namespace tirefem
