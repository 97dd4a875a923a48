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
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "tirefem/analysis/contact_iteration.hpp"
#include "tirefem/analysis/footprint.hpp"
#include "tirefem/analysis/standing_stiffness.hpp"
#include "tirefem/forms/rim_flange_form.hpp"
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
  // Tyre practice (MODEL.md §7): the contact forces and moments on the tyre in the W-axis system of ISO 8855
  // / TYDEX, at the contact centre C (the point of the support under the axle, in the wheel plane x = 0):
  // X along the direction of travel in the support's plane, Z the support's normal (up), Y = Z × X (to the
  // left). Fx is Qy; Fz ≈ Qz (Qz is along the model's z, Fz along the support's normal: they differ under
  // camber). Moments about C: overturning Mx, rolling resistance My (from the tread's shear alone: the
  // model has no hysteresis), aligning Mz. The pneumatic trail −Mz/Fy (when |Fy| > 1e-3 Fz) and the centre
  // of pressure (X, Y of Σ x Fn / Σ Fn over the support's normal forces).
  double Fx_N = 0.0, Fy_N = 0.0, Fz_N = 0.0;
  double overturning_moment_Nmm = 0.0, rolling_moment_Nmm = 0.0, aligning_moment_Nmm = 0.0;
  std::optional<double> pneumatic_trail_mm;
  Eigen::Vector2d centre_of_pressure_mm = Eigen::Vector2d::Zero();
  // The rim flanges' loads (forms/rim_flange_form.hpp), when the tyre leans on flanges, each named by
  // rim_flange_side.
  struct Flange {
    std::string side;
    RimFlangeLoad load;
  };
  std::vector<Flange> rim_flanges;
};

// The W-axis frame of a rolling state: C and the unit axes, in the model's coordinates.
struct WheelFrame {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d x = Eigen::Vector3d::UnitY(), y = -Eigen::Vector3d::UnitX(), z = Eigen::Vector3d::UnitZ();
};
// C is the support's point under the axle at the given deflection, Z its normal there, X the direction
// of travel (+y, or −y when reversed) projected on the support's plane.
WheelFrame wheel_frame(const SupportSurface& support, double deflection, bool reverse);

RollingFigures rolling_figures(const std::vector<TreadPoint>& points, const std::vector<TreadPointState>& normal,
                               const std::vector<TreadTraction>& tangential, double axle_z, bool half_model,
                               bool reverse, const WheelFrame& frame);

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
  std::optional<double> deflection_mm;  // δz, where it was adjusted to hold Qz (RollingStateSpec::hold_load)
  RollingFigures figures;
  RollingSolveCounts counts;
  Eigen::VectorXd displacement;
  std::vector<TreadPointState> normal;       // per tread point
  std::vector<TreadTraction> tangential;     // per tread point
};

struct SweepPoint {
  double slip = 0.0;
  double slip_angle_deg = 0.0;
  double camber_deg = 0.0;
  double rolling_radius_mm = 0.0;
  double deflection_mm = 0.0;  // δz: the footprint's, or adjusted to hold Qz (SlipSweep::hold_load)
  RollingFigures figures;
  RollingSolveCounts counts;
  bool mirrored = false;  // not solved: the mirror image of the point at −α (SlipAngleSweep::mirror_negative_angles)
};

// A flange's name in the outputs: "each" on a half model (the one flange computed stands for both); on a
// full one its W-axis side for the travel, "left" (+Y) or "right" (forward travel: "left" is at x < 0).
// States without travel (inflation) are named as for forward travel.
std::string rim_flange_side(const RimFlangeLoad& load, bool half_model, bool reverse);

// The figures of the mirror image of a state in the wheel plane (α, γ → −α, −γ): the lateral force and
// the moments about X and Z change sign, the centre of pressure's Y too, and the flanges swap sides.
RollingFigures mirrored_figures(const RollingFigures& f);

struct RollingResult {
  std::string name;
  SupportDescription support;
  double friction = 0.7;
  bool reverse = false;
  bool half_model = true;
  bool completed = false;
  std::string failure;            // why it stopped, when not completed
  StaticContactResult footprint;  // the static state at the study's load (inflation included)
  double deflection_mm = 0.0;     // δz of the footprint (of every state not held at the load)
  double loaded_radius_mm = 0.0;  // Rd: axle to support, at that δz
  double axle_z = 0.0;
  std::optional<double> effective_rolling_radius_mm;  // Re (free rolling)
  std::optional<double> slip_stiffness_N;             // dQy/dκ at κ = 0
  std::vector<TreadPoint> tread_points;               // in the order of the states' vectors
  std::vector<RollingStateResult> states;             // as listed in the study (converged or not)
  std::vector<SweepPoint> sweep;                      // converged points, by slip
  std::vector<SweepPoint> angle_sweep;                // converged points, by slip angle
  std::vector<SweepPoint> combined;                   // converged (κ, α) points, by κ then α
  bool planar_shear = false;                          // the tread shear a 2-vector (MODEL.md §7)
  // With an α sweep: dFy/dα at α = 0 (N per degree; W axes, so < 0) and the pneumatic trail there, by
  // central differences over α = ±0.2° at the sweep's κ and γ.
  std::optional<double> cornering_stiffness_N_per_deg;
  std::optional<double> pneumatic_trail_at_zero_mm;
  // The same normalised as published for radial passenger tyres (about 0.11–0.19 Fz per degree; a trail
  // of about 1/6 of the patch length), on the static footprint's Qz and patch length.
  std::optional<double> cornering_stiffness_over_Fz_per_deg;
  std::optional<double> pneumatic_trail_over_patch_length;
  // On a plane: the standing tyre's tangential stiffness at the footprint (analysis/standing_stiffness.hpp)
  // and the relaxation lengths σκ = Kxκ/Cx (with the slip stiffness) and σα = Kyα/Cy (with the cornering
  // stiffness, Kyα per radian).
  std::optional<StandingStiffness> standing_stiffness;
  std::optional<double> longitudinal_relaxation_length_mm;
  std::optional<double> lateral_relaxation_length_mm;
  SolveCounters counters;                             // rolling phase (after the footprint)
};

// The loaded radius of a state at the deflection `deflection_mm` (one held at the load): the axle higher
// than the footprint's by the difference of the deflections.
inline double loaded_radius_at(const RollingResult& r, double deflection_mm) {
  return r.loaded_radius_mm + (r.deflection_mm - deflection_mm);
}

// A converged rolling state as later states start from it: its parameters (RollingModel's: axle height /
// Rk, tan α, γ, δz / axle height) and its displacement.
struct RollingStartState {
  Eigen::Vector4d parameters = Eigen::Vector4d::Zero();
  Eigen::VectorXd u;
};

// Where the rolling studies at one load on one mesh and support begin: the static footprint and free
// rolling straight ahead, solved once (solve_rolling_start) and shared by every study that begins there (a
// tyre test's two series at a load), which then solve neither. Valid for studies with the same friction
// and travel (`friction`, `reverse`).
struct RollingStart {
  StaticContactResult footprint;   // completed or not
  RollingStateResult free;         // free rolling (converged or not), with the counts of its solves
  std::optional<double> effective_rolling_radius_mm, slip_stiffness_N;
  std::vector<RollingStartState> states;  // every state free rolling converged to, in order
  double friction = 0.0;
  bool reverse = false;
};

// The footprint (as run_rolling finds it: `footprint` if given and completed, else solved, from `nearby`
// when given) and free rolling of `study`.
RollingStart solve_rolling_start(const TyreMesh& tyre_mesh, const TyreDescription& tyre,
                                 const InflationSettings& inflation, const ContactSettings& contact,
                                 const RollingStudy& study, const ProgressSink& progress = {},
                                 const InflationResult* inflated = nullptr,
                                 const StaticContactResult* footprint = nullptr,
                                 const std::vector<PathState>* nearby = nullptr);

// From `inflated` when given (see run_footprint), else from its own inflation. `footprint`, when given, is
// the completed static footprint of this mesh on the study's support at its target load (shared by the
// studies at that load); else the study solves its own (from `nearby`, when given: see run_footprint).
// `point_done` is called once per state and sweep point as it is finished (solved, failed or skipped), e.g.
// to estimate the time left.
// `start`, when given, is where the study begins (its friction and travel the study's): its footprint and
// free rolling, not solved again (the study's counters leave out their work; its free state keeps its counts).
RollingResult run_rolling(const TyreMesh& tyre_mesh, const TyreDescription& tyre, const InflationSettings& inflation,
                          const ContactSettings& contact, const RollingStudy& study, const ProgressSink& progress = {},
                          const InflationResult* inflated = nullptr,
                          const StaticContactResult* footprint = nullptr,
                          const std::function<void()>& point_done = {},
                          const std::vector<PathState>* nearby = nullptr, const RollingStart* start = nullptr);

// The `points` values of a sweep over [from, to] (SweepSpacing): evenly spaced, or each side of zero
// quadratically denser towards it (v = end·(t/end)² for t evenly spaced; from < 0 < to keeps 0 if even).
std::vector<double> sweep_values(double from, double to, int points, SweepSpacing spacing);
// The negative angles of `angles` whose opposite is among them too: the points an α sweep that mirrors
// its negative angles (SlipAngleSweep::mirror_negative_angles) takes as mirror images, not solved.
std::vector<double> mirrored_angles(const std::vector<double>& angles);

// Solves the rolling problem at the forms' current settings from u (overwritten). Two-level: the contact
// region and the friction plan are frozen together in each outer iteration; single loop: both follow
// the iterate, with a two-level retry from the start when the single loop fails.
ContactSolveOutcome solve_rolling_state(NewtonSolver& newton, WinklerContactForm& contact,
                                        TreadFrictionForm& friction, Eigen::VectorXd& u,
                                        const ContactSettings& settings);

}  // namespace tirefem
