#pragma once
// Limits a case must respect to be solvable at all: plausibility bounds on material and geometry values
// (generous: any real tyre, passenger car to truck, lies well inside them; a value outside is a typo or a
// unit mistake, and the solve would fail late or silently give nonsense), and hard caps on sizes. The
// README's "Plausibility bounds" table states the same numbers; keep them in step.
namespace tirefem::case_reading {

// A closed range [lo, hi] of a value in `unit` (lo > 0 unless the value may be zero).
struct Bound {
  double lo;
  double hi;
  const char* unit;
};

// Moduli (MPa): cord (steel ~2e5, textile ~3e3), skim and layer rubber (~1..20), interlayer shear and
// through-thickness moduli, tread rubber shear modulus.
inline constexpr Bound kModulus{1e-3, 1e6, "MPa"};
// Thicknesses (mm): plies, rubber layers, the interlayer h(s).
inline constexpr Bound kThickness{0.01, 100.0, "mm"};
// Tread height hp(s) (mm): 0 is allowed (no tread there).
inline constexpr Bound kTreadHeight{0.0, 100.0, "mm"};
// Winkler tread stiffness kp (N/mm³, per unit area of the outer face): ~E_tread / hp ≈ 0.1 .. 5.
inline constexpr Bound kTreadStiffness{1e-3, 100.0, "N/mm³"};
// Rim flange curl radius (mm): a passenger J flange 9.5, a truck flange ~25.
inline constexpr Bound kFlangeRadius{1.0, 100.0, "mm"};
// Inflation pressure (MPa): passenger ~0.2, truck ~0.9, aircraft ~1.5.
inline constexpr Bound kPressure{0.0, 2.0, "MPa"};
// Diagonal terms of a directly given face stiffness A (N/mm): the modulus bound times the thickness bound.
inline constexpr double kMaxFaceStiffness = 1e8;
// A face's own bending stiffness D (N·mm): 0 (a membrane) up to a 25 mm steel plate's ~2.6e8.
inline constexpr Bound kFaceBendingStiffness{0.0, 1e9, "N·mm"};

// Drum diameter (mm): at least the tyre's outer diameter (see support_reader.hpp), at most 100 m.
inline constexpr double kMaxDrumDiameter = 1e5;

// Sizes.
inline constexpr int kMaxProfilePoints = 2000;          // tyre.profile.points
inline constexpr int kMaxCircumferentialElements = 10000;
inline constexpr int kMaxMeridionalElements = 2000;      // equator to bead
inline constexpr int kMaxLoadCurvePoints = 1000;         // load_curve.points
inline constexpr int kMaxSweepPoints = 200;              // rolling.sweep.points
inline constexpr int kMaxNameLength = 100;               // study and state names (they name files)
inline constexpr int kMaxIterations = 1000;              // Newton and contact-region iteration limits
// Target vertical loads (N, whole tyre): a truck tyre carries ~5e4 N, an aircraft tyre ~3e5 N.
inline constexpr double kMaxTargetLoad = 1e6;

// Other ranges.
inline constexpr int kMaxSurfacePower = 8;        // support surface terms: x^p y^q with p, q in [0, 8]
inline constexpr int kMaxQuadrature = 8;          // contact: Gauss points per direction
inline constexpr double kMaxLoadTolerance = 0.1;  // footprint: relative tolerance on the vertical load
inline constexpr double kMaxFriction = 5.0;       // rolling: Coulomb coefficient μ
inline constexpr double kMaxSlipAngleDeg = 45.0;  // rolling: slip angle α, degrees (a tyre slides fully long before)
inline constexpr double kMaxCamberDeg = 20.0;     // rolling: camber γ, degrees
inline constexpr double kMaxSlip = 10.0;          // rolling: longitudinal slip κ (> −1: −1 is a locked wheel)
// given_radius: the slip κ = R/Rk − 1 a rolling radius implies (R the tyre's outer radius, which the
// free-rolling radius Re is close to) must lie in [kMinImpliedSlip, kMaxSlip]. Below −0.99 (Rk > 100 R)
// the wheel is as good as locked: that is full_slip with wheel = "locked".
inline constexpr double kMinImpliedSlip = -0.99;

}  // namespace tirefem::case_reading
