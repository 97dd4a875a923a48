#pragma once
// The virtual flat-track rig (issue 12): a [[tyre_test]] study turned into rolling studies, one per load
// (footprint at the load, free rolling, κ and α sweeps with Qz held, cambered free rolling), and a
// load–deflection curve; their results gathered into one measurement table in SI units and the TYDEX /
// ISO 8855 W-axis signs (README, *Conventions*): the data a Magic Formula fit reads.
#include <chrono>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "tirefem/analysis/footprint.hpp"
#include "tirefem/analysis/rolling.hpp"
#include "tirefem/case/case.hpp"

namespace tirefem {

// The rig's two series at a load, independent experiments as on a flat track: the longitudinal one (free
// rolling, the cambered free rolling unless this series runs on the half model, the κ sweep) and the
// lateral one (the cambered free rolling when the other is on the half model, the α sweep, the cornering
// stiffness). Each is a rolling study of its own, so the two run side by side.
enum class TyreTestSeries { longitudinal, lateral };

// Where the longitudinal series runs. Straight ahead (α = γ = 0) a tyre that is its own mirror image in the
// wheel plane (tyre_mesh.hpp, mirror_symmetric) deforms symmetrically, so its κ states are the half
// model's with the planar tread shear (test Cornering.StraightAheadTheFullModelReproducesTheHalfModel):
// about a third of the full model's cost per Newton iteration (80 × 46 at 5550 N: free rolling 12
// iterations in 3.9 s against 12.6 s), and Fy, Mz, Mx 0 to round-off (the full model's rig: |Fy| up to
// 3.6 N). Otherwise the full model, from the lateral series' footprint and free rolling.
enum class TyreTestLongitudinalModel { full, half };
TyreTestLongitudinalModel tyre_test_longitudinal_model(const TyreMesh& rig_full_mesh);

// The rolling study of one series at the rig's load number `load_index` (name "<rig>_Fz<N>", the lateral
// series "<rig>_Fz<N>_alpha"). The rig's mesh is the study's; a longitudinal series on the half model has
// its half (tyre_test_half_mesh) as `mesh`, and the cambered states move to the lateral series.
RollingStudy tyre_test_rolling_study(const TyreTestStudy& study, std::size_t load_index, TyreTestSeries series,
                                     const MeshSettings& rig_mesh,
                                     TyreTestLongitudinalModel longitudinal = TyreTestLongitudinalModel::full);
// The load–deflection curve: a plane pressed from the undeformed tyre, on the half model.
LoadCurveStudy tyre_test_vertical_study(const TyreTestStudy& study);
// The half model of the rig's mesh: vertical loading, and straight-ahead rolling of a tyre that is its own
// mirror image, are symmetric about the equatorial plane.
MeshSettings tyre_test_half_mesh(const MeshSettings& rig_mesh);

// The states and sweep points of the whole test (all loads and both series; each series solves its own
// free rolling), as run_rolling counts them finished.
int tyre_test_points(const TyreTestStudy& study);

// Counts the finished points of a test whose series run side by side, and estimates the time left from
// the share of the test's expected work done so far. The points differ in cost by far more than the pace
// of the points alone can tell (the rig runs its heaviest series first, and half its α points are mirror
// images that cost nothing): measured on the tyre-test example (80 × 46), seconds per solved point at
// 1850 / 3700 / 5550 N were 2.9 / 6.8 / 15.6 in the α series and 0.6 / 1.2 / 4.3 in the κ series on the
// half model, and the time left estimated from the points alone was 2–4 times too long for most of the
// run. So a point's expected work is (Fz / FNOMIN)^1.5, a quarter of that on the half model, three times
// that for a series' first point (its footprint and free rolling), and none for a mirror image.
class TyreTestProgress {
 public:
  // `longitudinal`: where the κ series run (a half model also means the α sweep mirrors its negative angles).
  TyreTestProgress(const TyreTestStudy& study, TyreTestLongitudinalModel longitudinal);
  // One more point of the series `series` at load number `load_index` finished (solved, failed or
  // skipped; a series reports its points in run_rolling's order, the mirror images last). Returns a
  // progress line at every tenth of the test's points, else an empty string.
  std::string point_done(std::size_t load_index, TyreTestSeries series);
  // Share of the expected work done, 0 … 1.
  double work_done() const;

 private:
  struct Series {
    int points = 0, solved = 0, done = 0;  // solved: the points that are not mirror images
    double weight = 0.0;                   // expected work of each solved point
  };
  static double point_work(const Series& s, int index);
  mutable std::mutex mutex_;
  std::string name_;
  std::vector<Series> series_;  // by load, longitudinal then lateral
  int total_ = 0, done_ = 0;
  double total_work_ = 0.0, done_work_ = 0.0;
  std::chrono::steady_clock::time_point start_;
};

// One measured point, as a flat-track rig would record it. SI units, W axes: FX along the heading,
// FY to the left, MZ the aligning moment, MX the overturning moment, all at the contact centre;
// ALPHA > 0 gives FY < 0; GAMMA > 0 leans the wheel's top to the right.
struct TyreTestRow {
  enum class Kind { free, slip_sweep, angle_sweep, camber, combined };
  Kind kind = Kind::free;
  double target_load_N = 0.0;
  double Fz_N = 0.0, kappa = 0.0, alpha_rad = 0.0, gamma_rad = 0.0;
  double Fx_N = 0.0, Fy_N = 0.0, Mz_Nm = 0.0, Mx_Nm = 0.0;
  double loaded_radius_m = 0.0;     // axle above the road at this point
  double effective_radius_m = 0.0;  // Re of free rolling at this load
  int newton_iterations = 0;
  int factorizations = 0;
  double time_s = 0.0;
  bool mirrored = false;  // the mirror image of the point at −ALPHA, not solved (SweepPoint::mirrored)
};

// What the rig found at one load.
struct TyreTestLoad {
  double target_load_N = 0.0;
  bool completed = false;
  std::string failure;
  double Fz_N = 0.0;                  // of the static footprint
  double deflection_mm = 0.0;         // δz from the undeformed tyre
  double loaded_radius_mm = 0.0;      // Rd
  std::optional<double> effective_rolling_radius_mm;
  double patch_length_mm = 0.0, patch_width_mm = 0.0;
  std::optional<double> slip_stiffness_N;              // dFx/dκ at κ = 0
  std::optional<double> cornering_stiffness_N_per_deg;  // dFy/dα at α = 0 (< 0 in W axes)
  std::optional<double> pneumatic_trail_mm;
  // The standing tyre at the footprint (analysis/standing_stiffness.hpp): Cx, Cy and Cψ, and the relaxation
  // lengths σκ = Kxκ/Cx and σα = Kyα/Cy (Kyα per radian).
  std::optional<double> longitudinal_stiffness_N_per_mm, lateral_stiffness_N_per_mm, yaw_stiffness_Nmm_per_rad;
  std::optional<double> longitudinal_relaxation_length_mm, lateral_relaxation_length_mm;
};

struct TyreTestResult {
  std::string name;
  double nominal_load_N = 0.0;
  double unloaded_radius_mm = 0.0;
  std::vector<TyreTestLoad> loads;
  // By load, then by series: free, κ sweep, cambers, α sweep (the cambers before the κ sweep when the
  // longitudinal series has them).
  std::vector<TyreTestRow> rows;
  std::optional<StaticContactResult> vertical;  // the load–deflection curve (half model)
  bool completed = false;
  std::vector<std::string> failures;
};

// One load's rolling results, a series each (longitudinal, then lateral); a null one is a series whose
// study threw, with its message at the same place in `errors`.
struct TyreTestLoadRuns {
  std::vector<const RollingResult*> series;
  std::vector<std::string> errors;
};

// Gathers the per-load rolling results (in the study's load order) and the vertical curve.
TyreTestResult assemble_tyre_test(const TyreTestStudy& study, double unloaded_radius_mm,
                                  const std::vector<TyreTestLoadRuns>& loads,
                                  std::optional<StaticContactResult> vertical, const std::string& vertical_error);

}  // namespace tirefem
