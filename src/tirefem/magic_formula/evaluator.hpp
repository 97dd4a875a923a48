#pragma once
// Steady-state forces and moments of the PAC2002 / MF-Tyre 5.2 Magic Formula (Pacejka, "Tire and Vehicle
// Dynamics", 2nd ed., sec. 4.3.2, eqs. (4.E1)-(4.E78); the MF 5.2 branches of MFeval; Chrono's ChPac02Tire).
//
// Variant implemented, precisely:
// - Axes: TYDEX/ISO W-axis system at the contact point (x forward along the wheel heading, z up, y left).
//   Inputs Fz > 0 (N), longitudinal slip kappa (-; < 0 braking), slip angle alpha (rad; positive when the
//   contact point slides to the right, so a file with PKY1 < 0 gives Fy < 0), inclination gamma (rad).
//   Forward rolling (Vx > 0) only: the sgn(Vx) factors of the book are +1.
// - alpha enters the formulas as the angle itself (alpha* = alpha, as Chrono's ChPac02Tire), not tan(alpha)
//   (MFeval's optional alpha* = tan alpha); the trail and residual moment carry the book's cos(alpha) factor
//   (4.E33, 4.E34, 4.E76, 4.E77). gamma* = gamma (small-camber form), scaled by LGAX, LGAY, LGAZ.
// - Fz0' = FNOMIN LFZO, dfz = (Fz - Fz0')/Fz0' (4.E1, 4.E2). No inflation-pressure terms (PAC2002 has none),
//   no turn slip (all zeta = 1), no speed dependence of friction (LMUV), no low-speed damping, no limits:
//   the ranges FZMIN..CAMMAX are not applied. The curvature factors Ex, Ey, Et, Exa, Eyk are limited to <= 1
//   (as MFeval with its limit check on).
// - B = K/(C D + eps sgn D) with eps = 1e-3 only to avoid 0/0 (MFeval's epsilon; 1e-7 relative at road loads).
// - Pure lateral, MF 5.2: Kya0 = PKY1 Fz0' sin(2 atan(Fz/(PKY2 Fz0'))) LKY, Kya = Kya0 (1 - PKY3 |gamma_y|),
//   SHy = (PHY1 + PHY2 dfz) LHY + PHY3 gamma_y, SVy = Fz ((PVY1 + PVY2 dfz) LVY + (PVY3 + PVY4 dfz) gamma_y)
//   LMUY, muy = (PDY1 + PDY2 dfz)(1 - PDY3 gamma_y^2) LMUY.
// - Combined slip with the cosine weighting functions Gxa (4.E50-4.E57) and Gyk (4.E58-4.E67) normalised by
//   their value at zero slip, the kappa-induced side force SVyk = DVyk sin(RVY5 atan(RVY6 kappa)) LVYKA,
//   DVyk = muy Fz (RVY1 + RVY2 dfz + RVY3 gamma) cos(atan(RVY4 alpha)); Mz = -t (Fy - SVyk) + Mzr + s Fx with
//   the equivalent slip angles alpha_eq = atan(sqrt(tan^2 alpha + (Kxk/Kya)^2 kappa^2)) sgn(alpha)
//   (4.E74-4.E78; the MF-Tyre 5.2 form, as MFeval's FITTYP 6 branch). Et keeps its pure-slip value.
// - Mx = R0 Fz (QSX1 LVMX - QSX2 gamma + QSX3 Fy/Fz0') LMX (MF 5.2, 4.E69);
//   My = -R0 Fz LMY (QSY1 + QSY2 Fx/FNOMIN + QSY3 |Vx/LONGVL| + QSY4 (Vx/LONGVL)^4) (MF-Tyre 5.2 manual).
#include "tirefem/magic_formula/coefficients.hpp"

namespace tirefem {

struct WheelSlipState {
  double Fz = 0;      // N, > 0 in compression
  double kappa = 0;   // longitudinal slip (-)
  double alpha = 0;   // slip angle (rad)
  double gamma = 0;   // inclination angle (rad)
  double Vx = -1;     // forward speed (m/s) for My; < 0: LONGVL
};

enum class SlipCombination { pure, combined };

struct PureLongitudinalForce {
  double Fx0 = 0, Kxk = 0, mux = 0, Bx = 0, Cx = 0, Dx = 0, Ex = 0, SHx = 0, SVx = 0;
};

struct PureLateralForce {
  double Fy0 = 0, Kya = 0, muy = 0, By = 0, Cy = 0, Dy = 0, Ey = 0, SHy = 0, SVy = 0;
};

struct AligningMomentTerms {
  double trail = 0;            // pneumatic trail t (m), pure slip
  double residual_moment = 0;  // Mzr (N m), pure slip
  double Mz0 = 0;              // -t Fy0 + Mzr
  double Bt = 0, Ct = 0, Dt = 0, Et = 0, SHt = 0, Br = 0, Dr = 0, SHf = 0;
};

struct TyreForcesAndMoments {
  double Fx = 0, Fy = 0, Mx = 0, My = 0, Mz = 0;
  double Kxk = 0;              // longitudinal slip stiffness dFx0/dkappa at kappa = -SHx (N)
  double Kya = 0;              // cornering stiffness dFy0/dalpha at alpha = -SHy (N/rad)
  double trail = 0;            // pneumatic trail of the returned Mz (m)
  double residual_moment = 0;  // Mzr of the returned Mz (N m)
  double mux = 0, muy = 0;     // peak friction coefficients
  double SVyk = 0;             // kappa-induced side force (combined slip only)
  double Gxa = 1, Gyk = 1;     // combined-slip weighting functions (1 in pure slip)
};

// Fx0 (4.E9-4.E18).
PureLongitudinalForce pure_longitudinal_force(const MagicFormulaCoefficients& c, double Fz, double kappa, double gamma);
// Fy0 (4.E19-4.E30, MF 5.2 form).
PureLateralForce pure_lateral_force(const MagicFormulaCoefficients& c, double Fz, double alpha, double gamma);
// Pure-slip aligning moment (4.E31-4.E49) given the pure lateral force at the same state.
AligningMomentTerms pure_aligning_moment(const MagicFormulaCoefficients& c, double Fz, double alpha, double gamma,
                                         const PureLateralForce& lateral);

// All forces and moments of one state; `pure` ignores the combined-slip weighting (USE_MODE 3).
TyreForcesAndMoments evaluate_magic_formula(const MagicFormulaCoefficients& c, const WheelSlipState& state,
                                            SlipCombination combination = SlipCombination::combined);

// Effective rolling radius (MF 5.2): Re = R0 Q_RE0 - (FNOMIN/Cz)(DREFF atan(BREFF Fz/FNOMIN) + FREFF Fz/FNOMIN),
// with Cz = VERTICAL_STIFFNESS, no speed terms.
double effective_rolling_radius(const MagicFormulaCoefficients& c, double Fz);

// Relaxation lengths of the transient model (MF-Tyre 5.2 / PAC2002), m:
//   sigma_kappa = Fz (PTX1 + PTX2 dfz) exp(-PTX3 dfz) (R0/Fz0') LSGKP,
//   sigma_alpha = PTY1 sin(2 atan(Fz/(PTY2 Fz0'))) (1 - PKY3 |gamma_y|) R0 LFZO LSGAL
// (PTX1: sigma_kappa/R0 at FNOMIN; PTY1: the peak of sigma_alpha/R0, reached at Fz/Fz0' = PTY2).
struct RelaxationLengths {
  double sigma_kappa = 0, sigma_alpha = 0;
};
RelaxationLengths relaxation_lengths(const MagicFormulaCoefficients& c, double Fz, double gamma = 0.0);

}  // namespace tirefem
