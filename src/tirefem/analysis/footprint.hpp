#pragma once
// Static loading of the inflated tyre by a rigid support (MODEL.md §4): the support is moved towards the
// fixed axle by δz; each load point is solved by the two-level iteration (outer loop: contact region,
// eq. 5; inner loop: Newton with the region frozen, eq. 13) or by the single-loop variant. Load curves
// step δz in equal steps (eq. 14 gives Qz); a footprint study finds δz for a target Qz.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "tirefem/analysis/inflation.hpp"
#include "tirefem/forms/winkler_contact_form.hpp"

namespace tirefem {

// Patch figures of the full tyre (a half model's are doubled / mirrored).
struct PatchFigures {
  double Qz_N = 0.0;               // vertical force of the support on the tyre (= axle load)
  Eigen::Vector3d force_N = Eigen::Vector3d::Zero();  // total contact force on the tyre
  double contact_area_mm2 = 0.0;   // breaker-face area with qn > 0
  double patch_length_mm = 0.0;    // extent along y (travel) of the contact, interpolated to qn = 0
  double patch_width_mm = 0.0;     // extent along x (lateral), interpolated to qn = 0
  double max_pressure_MPa = 0.0;
  double mean_pressure_MPa = 0.0;  // ∫ qn dΩ / contact area
};

PatchFigures patch_figures(const std::vector<TreadPoint>& points, const std::vector<TreadPointState>& states,
                           bool half_model);

// A converged state whose tangent is not positive definite (it needed a shift) is an unstable
// equilibrium. (A relative shift says little of the size of the instability: the bending modes of a
// thin wall are ~1e-6 of the diagonal, so a buckling mode needs only a tiny shift.)
inline bool stable(double tangent_shift) { return tangent_shift <= 0.0; }

struct LoadPoint {
  double deflection_mm = 0.0;
  PatchFigures patch;
  int contact_iterations = 0;  // outer iterations (Newton solves) of the last increment to this point
  int newton_iterations = 0;   // Newton iterations (linear solves) of all increments to this point
  int factorizations = 0;
  int increments = 0;          // > 1 when the step was cut back
  // Stability of the converged state: the relative diagonal shift its tangent needed to be positive
  // definite (0: stable; > 0: unstable).
  double tangent_shift = 0.0;
  double time_s = 0.0;
  // > 0: on the way to this point Newton left unstable equilibria (their tangent needed escaped_shift)
  // for this stable state: the path passed an instability here (a wrinkle, a snap-through).
  int escapes = 0;
  double escaped_shift = 0.0;
};

// The converged state at one deflection, with what the reports need.
struct ContactState {
  double deflection_mm = 0.0;
  Eigen::VectorXd displacement;
  std::vector<TreadPointState> tread;
};

// A converged state of a load curve, kept for a footprint study on the same support to start from.
struct PathState {
  double deflection_mm = 0.0;
  double Qz_N = 0.0;
  Eigen::VectorXd displacement;
};
// The states of a load curve's path on either side of `load`: the last below it and the first at or above
// it; both nullptr unless they bracket it (the second at a larger δz).
std::pair<const PathState*, const PathState*> states_around_load(const std::vector<PathState>& path, double load);

struct StaticContactResult {
  std::string name;
  SupportDescription support;
  Kinematics kinematics = Kinematics::nonlinear;
  ContactSettings::Iteration iteration = ContactSettings::Iteration::two_level;
  bool half_model = true;            // the figures are for the full tyre either way
  bool completed = false;
  std::string failure;               // why it stopped, when not completed
  std::vector<LoadPoint> points;     // converged points only, the unloaded one first
  std::vector<TreadPoint> tread_points;
  ContactState final_state;          // at the last converged point
  InflationResult inflation;         // the state the loading started from
  std::optional<double> target_Qz_N; // footprint studies at a load
  std::optional<double> given_deflection_mm;  // footprint studies at a deflection (from deflection_from)
  SolveCounters counters;            // contact phase only
  // δz (from the undeformed tyre) at which the inflated tyre first touches the support
  // (analysis/first_touch.hpp): < 0 when it already presses at δz = 0.
  double first_touch_deflection_mm = 0.0;
  // The origin of the deflections the study was given and reports. LoadPoint::deflection_mm and
  // ContactState::deflection_mm are always from the undeformed tyre; deflection_from_origin converts.
  DeflectionOrigin deflection_from = DeflectionOrigin::undeformed;
  // Every converged state of a load curve, when asked for (run_load_curve's keep_path).
  std::vector<PathState> path;
};

// A deflection from the undeformed tyre, measured from the result's origin.
inline double deflection_from_origin(const StaticContactResult& r, double deflection_mm) {
  return r.deflection_from == DeflectionOrigin::first_touch ? deflection_mm - r.first_touch_deflection_mm
                                                            : deflection_mm;
}

// Runs the load curve from the nonlinear inflated state: `inflated` when given (a converged nonlinear
// inflation of this mesh at inflation.pressure, shared by the studies of a run), else its own.
StaticContactResult run_load_curve(const TyreMesh& tyre_mesh, const TyreDescription& tyre,
                                   const InflationSettings& inflation, const ContactSettings& contact,
                                   const LoadCurveStudy& study, const ProgressSink& progress = {},
                                   const InflationResult* inflated = nullptr, bool keep_path = false);
// Finds δz with Qz = target (points: the deflections tried on the way, all converged), or solves at the
// study's given deflection, from `inflated` as above. `along`: a load curve of this mesh on the same
// support, in the same theory and from the same origin, with its path kept: the search starts from its
// states (the bracket of the target from their Qz, the prediction from the nearest two), instead of
// stepping there from the unloaded tyre. `nearby` (without `along`): two states of another mesh's such load
// curve on either side of the target load, carried onto this mesh (interpolated_onto): the search's first
// step goes to where their Qz meets the target, predicted from them; its bracket comes from this mesh's own
// solves (the other mesh's Qz differs by its discretisation).
StaticContactResult run_footprint(const TyreMesh& tyre_mesh, const TyreDescription& tyre,
                                  const InflationSettings& inflation, const ContactSettings& contact,
                                  const FootprintStudy& study, const ProgressSink& progress = {},
                                  const InflationResult* inflated = nullptr,
                                  const StaticContactResult* along = nullptr,
                                  const std::vector<PathState>* nearby = nullptr);

// The nonlinear inflated state the contact studies start from (both theories: the linear one is
// linearised about it).
InflationResult inflate_for_contact(const TyreMesh& tyre_mesh, const InflationSettings& inflation,
                                    const ProgressSink& progress = {});

// The tread points of a tyre mesh: elements within the tread (|s| ≤ tread end) on the lower half of the
// tyre (|φ| ≤ 90°, the only part a support within the 40 mm range can reach), hp from the tread table.
std::vector<TreadPoint> tyre_tread_points(const TyreMesh& tyre_mesh, const TyreDescription& tyre,
                                          int quadrature);

}  // namespace tirefem
