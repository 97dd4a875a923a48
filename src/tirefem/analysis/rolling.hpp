#pragma once
// Steady slow rolling with stick and slip (MODEL.md §5): the static footprint at the study's load fixes
// the axle height (deflection δz); the support then moves under the tyre and the rolling radius Rk = V/Ω
// sets traction or braking. Each state is solved like a static load point (two-level iteration, the
// outer loop now revising the contact region and the stick/slip plan, or the single loop) with the
// tread's tangential forces of forms/tread_friction_form.hpp; the tangent is unsymmetric (UMFPACK).
//
// Free rolling is found first (secant iteration on Rk for Qy = 0): its Rk is the effective rolling radius
// Re that defines the slip κ = Re/Rk − 1 of all other states. States and sweep points start from the
// converged state nearest in Rk (secant predictor through the two nearest).
//
// Signs: Qy is the longitudinal force of the support on the tyre along the direction of travel (+y, or
// −y when the study is reversed): > 0 traction. Mx is the moment about the axle (x axis) of all contact
// forces, Σ (y Fz − (z − z_axle) Fy) (for a reversed study the mirror image's, so that it keeps its sign
// with Qy); Rd = axle height above the support.
#include <optional>
#include <string>
#include <vector>

#include "tirefem/analysis/contact_iteration.hpp"
#include "tirefem/analysis/footprint.hpp"
#include "tirefem/forms/tread_friction_form.hpp"

namespace tirefem {

// Axle loads and patch figures of a rolling state (full tyre: a half model's are doubled).
struct RollingFigures {
  double Qz_N = 0.0;
  double Qy_N = 0.0;    // along the direction of travel
  double Mx_Nmm = 0.0;
  Eigen::Vector3d force_N = Eigen::Vector3d::Zero();  // total contact force in the model's axes
  double contact_area_mm2 = 0.0;
  double stick_area_fraction = 0.0;  // stick area / contact area
  double max_traction_MPa = 0.0;     // largest |qt|
};

RollingFigures rolling_figures(const std::vector<TreadPoint>& points, const std::vector<TreadPointState>& normal,
                               const std::vector<TreadTraction>& tangential, double axle_z, bool half_model,
                               bool reverse);

struct RollingSolveCounts {
  int contact_iterations = 0;  // outer iterations of the last solve (1 for the single loop)
  int newton_iterations = 0;   // all solves to reach the state (including the free-rolling search)
  int factorizations = 0;
  int solves = 0;              // nonlinear solves (several for free rolling or after cut-backs)
  double time_s = 0.0;
};

struct RollingStateResult {
  RollingStateSpec spec;
  std::string name;
  bool converged = false;
  std::string failure;
  // Rk, mm, and κ = Re/Rk − 1; not defined for a spinning wheel (Rk → 0) nor Rk for a locked one (κ = −1).
  std::optional<double> rolling_radius_mm;
  std::optional<double> slip;
  RollingFigures figures;
  RollingSolveCounts counts;
  Eigen::VectorXd displacement;
  std::vector<TreadPointState> normal;       // per tread point
  std::vector<TreadTraction> tangential;     // per tread point
};

struct SweepPoint {
  double slip = 0.0;
  double rolling_radius_mm = 0.0;
  double deflection_mm = 0.0;  // δz: the footprint's, or adjusted to hold Qz (SlipSweep::hold_load)
  RollingFigures figures;
  RollingSolveCounts counts;
};

struct RollingResult {
  std::string name;
  SupportDescription support;
  double friction = 0.7;
  bool reverse = false;
  bool half_model = true;
  bool completed = false;
  std::string failure;            // why it stopped, when not completed
  StaticContactResult footprint;  // the static state at the study's load (inflation included)
  double deflection_mm = 0.0;     // δz, held in all states
  double loaded_radius_mm = 0.0;  // Rd: axle to support
  double axle_z = 0.0;
  std::optional<double> effective_rolling_radius_mm;  // Re (free rolling)
  std::optional<double> slip_stiffness_N;             // dQy/dκ at κ = 0
  std::vector<TreadPoint> tread_points;               // in the order of the states' vectors
  std::vector<RollingStateResult> states;             // as listed in the study (converged or not)
  std::vector<SweepPoint> sweep;                      // converged points, by slip
  SolveCounters counters;                             // rolling phase (after the footprint)
};

// From `inflated` when given (see run_footprint), else from its own inflation. `footprint`, when given, is
// the completed static footprint of this mesh on the study's support at its target load (shared by the
// studies at that load); else the study solves its own.
RollingResult run_rolling(const TyreMesh& tyre_mesh, const TyreDescription& tyre, const InflationSettings& inflation,
                          const ContactSettings& contact, const RollingStudy& study, const ProgressSink& progress = {},
                          const InflationResult* inflated = nullptr,
                          const StaticContactResult* footprint = nullptr);

// Solves the rolling problem at the forms' current settings from u (overwritten). Two-level: the contact
// region and the friction plan are frozen together in each outer iteration; single loop: both follow
// the iterate, with a two-level retry from the start when the single loop fails.
ContactSolveOutcome solve_rolling_state(NewtonSolver& newton, WinklerContactForm& contact,
                                        TreadFrictionForm& friction, Eigen::VectorXd& u,
                                        const ContactSettings& settings);

}  // namespace tirefem
