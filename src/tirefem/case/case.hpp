#pragma once
// A case: the tyre, its mesh and the analyses to run, as plain data. Read from TOML by case_reader.hpp;
// units mm, N, MPa (N/mm²), N/mm³, degrees.
#include <Eigen/Dense>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "tirefem/tyre/table.hpp"

namespace tirefem {

// One cord–rubber ply.
struct Ply {
  std::string name;
  double cord_modulus = 0.0;    // Young's modulus of the cord, MPa
  double cord_area = 0.0;       // cross-section area of one cord, mm²
  double ends_per_mm = 0.0;     // cords per mm of ply width (measured across the cords), 1/mm
  double angle_deg = 90.0;      // cord angle to the circumferential direction; 90 = radial, sign = hand
  double thickness = 0.0;       // ply thickness (cords + skim rubber), mm
  double rubber_modulus = 0.0;  // Young's modulus of the skim rubber, MPa
  double rubber_poisson = 0.49;
  double cord_poisson = 0.3;  // only for ν12 of the Halpin–Tsai rule (rule of mixtures)
  // Young's modulus of the cord in compression, MPa; unset: as in tension. A textile cord twisted from
  // thousands of filaments buckles inside the rubber under a small compressive load.
  std::optional<double> cord_compression_modulus;
  double compression_modulus() const { return cord_compression_modulus.value_or(cord_modulus); }
};

enum class CordRubberRule { halpin_tsai, gough_tangorra };

// A membrane face: plies (laminated) plus an optional directly given orthotropic stiffness (which is also
// where isotropic rubber layers end up). face_stiffness() in tyre/ply_stiffness.hpp sums both.
struct FaceLayup {
  std::vector<Ply> plies;
  CordRubberRule rule = CordRubberRule::halpin_tsai;
  // A (N/mm), Voigt [11, 22, 12] with engineering shear; axis 1 meridional, axis 2 circumferential.
  std::optional<Eigen::Matrix3d> direct_stiffness;
  // The share of the `rubber` layers in direct_stiffness (Σ of their isotropic membranes) and their Σ μ t
  // (N/mm), which TyreDescription::rubber_law may give a large-strain law.
  Eigen::Matrix3d rubber_stiffness = Eigen::Matrix3d::Zero();
  double rubber_shear_stiffness = 0.0;
  // The face's own bending stiffness D (N·mm), [meridional, circumferential]; zero in the paper's membrane
  // faces (forms/face_bending_form.hpp).
  Eigen::Vector2d bending_stiffness = Eigen::Vector2d::Zero();
  // Its cords' bending stiffness within the face's plane (N·mm), [meridional, circumferential]: what
  // gives a ply compressed along its cords a kink width of its own (element/line_bending.hpp).
  Eigen::Vector2d in_plane_bending_stiffness = Eigen::Vector2d::Zero();
};

// A stretch of the meridian with one construction. Runs from the previous zone's s_end (or 0) to s_end.
struct Zone {
  std::string name;
  double s_end = 0.0;                // mm from the equator
  FaceLayup inner;                   // carcass face
  FaceLayup outer;                   // breaker / sidewall face
  double core_shear_modulus = 0.0;   // interlayer transverse shear modulus, MPa
  double core_normal_modulus = 0.0;  // interlayer through-thickness modulus, MPa
};

// The rim flange's curl (road/rim_flange.hpp): a rigid torus tangent to the outer face at the bead, on
// which the lower sidewall leans when it bends over the rim.
struct RimFlangeDescription {
  double radius = 9.5;      // curl radius, mm (typical of a passenger J flange)
  double stiffness = 20.0;  // Winkler stiffness of the rubber between the outer face and the flange, N/mm³
};

// The law of the faces' rubber layers (`rubber = { E, nu, thickness }`), nonlinear theory:
// saint_venant_kirchhoff: linear in the Green–Lagrange strain, the paper's; neo_hookean: incompressible
// neo-Hookean membranes of μ = E / 2(1 + ν), which keep their stiffness in large compression
// (element/rubber_membrane.hpp). The plies' skim rubber stays in the ply's linear law either way.
enum class RubberLaw { saint_venant_kirchhoff, neo_hookean };

struct TyreDescription {
  std::string name;
  RubberLaw rubber_law = RubberLaw::saint_venant_kirchhoff;
  std::vector<Eigen::Vector2d> profile;  // carcass line (x, r), equator (x = 0) → bead, x ≥ 0
  std::vector<Zone> zones;
  Table interlayer_thickness;        // h(s), mm: distance of the outer face from the carcass along the normal
  Table tread_height;                // hp(s), mm, measured from the outer face; only for s ≤ tread_end_s
  double tread_end_s = 0.0;          // tread edge, mm from the equator; no tread beyond
  double tread_stiffness = 0.0;      // Winkler stiffness kp, N/mm³ (per unit area of the outer face)
  double tread_shear_modulus = 0.0;  // effective tread rubber shear modulus G, MPa
  std::optional<RimFlangeDescription> rim_flange;  // none: the outer face is free up to the clamped bead
};

struct MeshSettings {
  int circumferential_elements = 120;
  // Along the meridian, equator to bead: the full model has twice as many (bead to bead).
  int meridional_elements = 46;
  bool half_model = true;
  // Ratio of the element length at φ = ±π to the one at φ = 0 (the patch); 1 = uniform.
  double circumferential_refinement = 4.0;
  // Where the meridional node lines go (tyre/tyre_mesh.hpp). zones: the meridian is cut at the zone ends
  // and the tread edge and the elements shared out over the pieces (every element in one zone).
  // uniform_arc_length: equal elements in s from equator to bead, across zone ends; each element takes
  // the zone of its centre.
  enum class MeridionalGrading { zones, uniform_arc_length };
  MeridionalGrading meridional_grading = MeridionalGrading::zones;
  // The faces' in-plane strains: compatible (the paper's bilinear faces, the default) or enhanced (EAS-4: no
  // parasitic shear when a face bends in its plane; see README, "How fine a mesh").
  enum class Faces { compatible, enhanced };
  Faces faces = Faces::compatible;
};

struct InflationSettings {
  bool enabled = true;
  double pressure = 0.2;  // MPa
  bool linear = false;
  int max_newton_iterations = 25;
  double residual_tolerance = 1e-8;
};

// A rigid support surface, moved towards the fixed axle by the deflection δz (road/support_surface.hpp).
struct SupportDescription {
  enum class Kind { plane, drum, surface };
  Kind kind = Kind::plane;
  double drum_diameter = 1830.0;  // mm (kind drum): a cylinder with its axis parallel to the wheel axis
  // Kind surface: z = f(x, y) = Σ coefficient · x^x_power · y^y_power (mm), a smooth shallow road.
  struct Term {
    double coefficient = 0.0;
    int x_power = 0;
    int y_power = 0;
  };
  std::vector<Term> terms;
};

// How the tread–road contact is solved (forms/winkler_contact_form.hpp, analysis/footprint.hpp).
struct ContactSettings {
  int quadrature = 4;  // Gauss points per direction on each element's breaker face (n × n)
  // two_level: the paper's scheme, an outer loop revising the contact region around a Newton solve with
  // the region frozen. single_loop: the region follows the iterate inside one Newton loop.
  enum class Iteration { two_level, single_loop };
  Iteration iteration = Iteration::two_level;
  int max_contact_iterations = 30;  // outer loop
  int region_tolerance = 0;         // the region is settled when at most this many points changed
  int max_newton_iterations = 25;   // inner loop (per outer iteration)
  // Rolling: a state's continuation from its start state (its stages, failed ones included) gives up
  // after this many Newton iterations in all (RollingModel::continuation).
  int max_state_iterations = 250;
  double residual_tolerance = 1e-8; // Newton: ‖R‖ relative to the size of the inflation load
  // Two-level: Newton tolerance while the region is still changing; the final solve (region settled)
  // uses residual_tolerance.
  double provisional_tolerance = 1e-5;
  // Newton systems solved by GMRES preconditioned with an earlier factorisation while that converges
  // fast (NewtonSettings::reuse_factorization, with Eisenstat–Walker tolerances); false: every Newton
  // iteration factorises.
  bool reuse_factorizations = true;
  // Which equilibrium each load point converges to (NewtonSettings::stable_equilibrium): nearest (exact
  // Newton steps from the prediction; the stability of each point is reported) or stable (every step
  // lowers the energy, so an unstable equilibrium is left for a stable one: a wrinkled or buckled state).
  enum class Equilibrium { nearest, stable };
  Equilibrium equilibrium = Equilibrium::nearest;
};

// Where a study's deflections are measured from. undeformed: the undeformed tyre touching the support
// (MODEL.md §2, the paper's origin; the inflated tyre, ~0.5 mm larger, already presses at δz = 0).
// first_touch: the inflated tyre touching it (δz = the first-touch deflection, analysis/first_touch.hpp).
enum class DeflectionOrigin { undeformed, first_touch };

// Load characteristic Qz(δz): the support pressed onto the inflated tyre in equal deflection steps.
struct LoadCurveStudy {
  std::string name;  // used in file names and the summary; unique, [A-Za-z0-9_-]
  SupportDescription support;
  bool linear = false;          // geometrically linear theory (inflation and contact)
  double max_deflection = 40.0; // mm, from deflection_from
  int points = 20;              // load points after the unloaded one (equal steps in δz)
  DeflectionOrigin deflection_from = DeflectionOrigin::undeformed;
};

// The footprint at a target vertical load (δz is found so that Qz, full tyre, equals target_load) or at
// a given deflection.
struct FootprintStudy {
  std::string name;  // as LoadCurveStudy::name
  SupportDescription support;
  bool linear = false;
  double target_load = 3700.0;    // N, full tyre (unless `deflection` is set)
  double load_tolerance = 1e-3;   // |Qz − target| ≤ tolerance · target
  std::optional<double> deflection;  // mm, from deflection_from: the footprint at this δz, no load target
  DeflectionOrigin deflection_from = DeflectionOrigin::undeformed;
};

// One steady slow-rolling state (MODEL.md §5). The longitudinal slip is κ = (Ω Re − V)/V = Re/Rk − 1
// (Re the free-rolling effective radius, Rk = V/Ω the rolling radius): κ > 0 traction (the wheel turns
// faster than it would roll freely), κ < 0 braking, κ = −1 a locked wheel.
struct RollingStateSpec {
  enum class Kind {
    free,          // Rk such that Qy = 0: the effective rolling radius
    given_slip,    // Rk from the slip κ
    given_radius,  // Rk given
    full_stick,    // no slip anywhere (friction unlimited), at the slip κ
    full_slip,     // the whole patch slides: a spinning (traction) or locked (braking) wheel
  };
  Kind kind = Kind::free;
  std::string name;             // for tables, plots and the summary; defaults to the kind's name
  double slip = 0.0;            // κ (given_slip, full_stick)
  double rolling_radius = 0.0;  // Rk, mm (given_radius)
  bool braking = false;         // full_slip: locked wheel (true) or spinning wheel (false)
  // Cornering (MODEL.md §7; full model only), degrees, ISO 8855 / TYDEX W-axis signs (README): the slip
  // angle α from the wheel's heading to its direction of travel, positive counter-clockwise seen from
  // above (α > 0 gives Fy < 0); the camber (inclination) γ, positive with the top of the wheel leaning to
  // the right of the heading (ISO −Y).
  double slip_angle_deg = 0.0;
  double camber_deg = 0.0;
  // hold = "load": the deflection δz adjusted so that Qz stays at the study's target load (as a sweep's
  // hold = "load"; free rolling then finds Rk again at each δz); not for full slip.
  bool hold_load = false;
};

// The longitudinal force–slip curve Qy(κ): `points` slips evenly from `from` to `to`, at the footprint's
// deflection (the paper's fixed axle; Qz drifts a little with the slip) or, with hold_load, with the
// deflection of each point adjusted so that Qz stays at the study's target load.
// How sweep points are spread over [from, to]: evenly, or quadratically denser near zero (each side
// from 0 to its end as (i/n)², so that small slips, which fix the slope at zero, are sampled finely).
// (analysis/rolling.hpp: sweep_values.)
enum class SweepSpacing { even, quadratic };

struct SlipSweep {
  double from = -0.1;
  double to = 0.1;
  int points = 15;
  bool hold_load = false;
  SweepSpacing spacing = SweepSpacing::even;
};

// The lateral force and aligning moment curves Fy(α), Mz(α): `points` slip angles (degrees) evenly from
// `from` to `to`, at the longitudinal slip κ = `slip` (0: the free-rolling Re of α = 0, the Magic
// Formula's pure side slip) and camber `camber_deg`, the load held as for SlipSweep.
struct SlipAngleSweep {
  double from = -12.0;
  double to = 12.0;
  int points = 13;
  double slip = 0.0;
  double camber_deg = 0.0;
  bool hold_load = false;
  SweepSpacing spacing = SweepSpacing::even;
  // Solve only α ≥ 0 and take each point at −α as the mirror image (in the wheel plane) of the point at
  // +α, where that is exact: a full model of a tyre that is its own mirror image (tyre/tyre_mesh.hpp,
  // mirror_symmetric) at camber 0; elsewhere every point is solved. Case file: angle_sweep.mirror
  // (default true); the virtual rig always mirrors.
  bool mirror_negative_angles = true;
};

// Combined slip: every (κ, α) pair of the two lists, the load held as for SlipSweep.
struct CombinedSlipGrid {
  std::vector<double> slips;
  std::vector<double> slip_angles_deg;
  bool hold_load = false;
};

// Steady slow rolling at the deflection of a footprint: the footprint at target_load is found first
// (static, as a FootprintStudy), then the axle is held there and the states are solved. The wheel
// travels in +y (the road moves in −y under it) unless `reverse`.
struct RollingStudy {
  std::string name;  // as LoadCurveStudy::name
  SupportDescription support;  // plane or drum (or a surface that does not depend on y)
  double target_load = 3700.0;   // N, full tyre, of the static footprint that sets the deflection
  double load_tolerance = 1e-3;
  double friction = 0.7;         // Coulomb coefficient μ between tread and support
  bool reverse = false;          // travel in −y
  std::vector<RollingStateSpec> states;
  std::optional<SlipSweep> sweep;
  // The tread shear of eq. (16): along the support's motion only (the paper's), or as a 2-vector in the
  // support's plane (MODEL.md §7; needed for slip angle and camber). Unset: planar on the full model,
  // longitudinal on the half model (the paper's).
  enum class TreadShear { longitudinal, planar };
  std::optional<TreadShear> tread_shear;
  std::optional<SlipAngleSweep> angle_sweep;
  std::optional<CombinedSlipGrid> combined;
  // Its own mesh (the paper rolls on 80 × 46 while its static studies use 120 × 46); unset: the case's.
  std::optional<MeshSettings> mesh;
  // The standing tyre's stiffness at the footprint (on a plane; analysis/standing_stiffness.hpp). Not a case
  // field: a tyre test measures it once per load, in its lateral series on the full model.
  bool standing_stiffness = true;
};

// A virtual flat-track tyre test (issue 12): at each load of `load_factors` × `nominal_load` the static
// footprint, free rolling, a longitudinal slip sweep and a slip-angle sweep with Qz held, and free rolling
// at each camber of `cambers`; plus the load–deflection curve (on the half model of the same mesh, where
// vertical loading is symmetric). Its table is the measurement a Magic Formula fit reads. Always a plane
// road; the mesh must be the full model (slip angle and camber need it).
struct TyreTestStudy {
  std::string name;  // as LoadCurveStudy::name
  double nominal_load = 3700.0;            // FNOMIN, N
  std::vector<double> load_factors{0.5, 1.0, 1.5};
  double load_tolerance = 1e-3;
  double friction = 0.7;
  // Quadratic spacing by default: the Magic Formula's slip stiffnesses come from the small slips.
  SlipSweep slip_sweep{-0.15, 0.15, 15, true, SweepSpacing::quadratic};
  SlipAngleSweep angle_sweep{-12.0, 12.0, 15, 0.0, 0.0, true, SweepSpacing::quadratic};
  std::vector<double> cambers_deg;         // free-rolling states at each load (camber thrust)
  // A (κ, α) grid at each load, Fz held, on the full model after the α sweep: the combined-slip
  // weighting functions (RBX1-2, RCX1, RBY1-2, RCY1). Unset: none, and those keys stay neutral.
  std::optional<CombinedSlipGrid> combined;
  double vertical_max_deflection = 40.0;   // mm, the load–deflection curve from the undeformed tyre
  int vertical_points = 10;
  std::optional<MeshSettings> mesh;        // unset: the case's
};

struct Case {
  std::filesystem::path source;  // the file it came from (for messages and relative paths)
  std::string title;
  TyreDescription tyre;
  MeshSettings mesh;
  InflationSettings inflation;
  ContactSettings contact;
  std::vector<LoadCurveStudy> load_curves;  // [[load_curve]] tables, run in order after inflation
  std::vector<FootprintStudy> footprints;   // [[footprint]] tables
  std::vector<RollingStudy> rolling;        // [[rolling]] tables
  std::vector<TyreTestStudy> tyre_tests;    // [[tyre_test]] tables
};

}  // namespace tirefem
