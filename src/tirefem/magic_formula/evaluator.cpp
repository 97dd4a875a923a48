#include "tirefem/magic_formula/evaluator.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tirefem {
namespace {

constexpr double b_epsilon = 1e-3;  // keeps B = K/(C D) finite when C D = 0 (MFeval's epsilon)

double sign(double x) { return x > 0 ? 1.0 : (x < 0 ? -1.0 : 0.0); }
double sign_not_zero(double x) { return x < 0 ? -1.0 : 1.0; }
double at_most_one(double e) { return std::min(e, 1.0); }

// The Magic Formula sine/cosine argument C atan(B x - E (B x - atan(B x))).
double magic_angle(double B, double C, double E, double x) {
  const double Bx = B * x;
  return C * std::atan(Bx - E * (Bx - std::atan(Bx)));
}

struct LoadTerms {
  double Fz0_prime;  // FNOMIN LFZO (4.E1)
  double dfz;        // (Fz - Fz0')/Fz0' (4.E2)
};

LoadTerms load_terms(const MagicFormulaCoefficients& c, double Fz) {
  const double Fz0_prime = c.FNOMIN * c.LFZO;
  return {Fz0_prime, (Fz - Fz0_prime) / Fz0_prime};
}

}  // namespace

PureLongitudinalForce pure_longitudinal_force(const MagicFormulaCoefficients& c, double Fz, double kappa, double gamma) {
  const auto [Fz0_prime, dfz] = load_terms(c, Fz);
  const double gamma_x = gamma * c.LGAX;
  PureLongitudinalForce f;
  f.Cx = c.PCX1 * c.LCX;                                                          // (4.E11)
  f.mux = (c.PDX1 + c.PDX2 * dfz) * (1 - c.PDX3 * gamma_x * gamma_x) * c.LMUX;    // (4.E13)
  f.Dx = f.mux * Fz;                                                              // (4.E12)
  f.Kxk = Fz * (c.PKX1 + c.PKX2 * dfz) * std::exp(c.PKX3 * dfz) * c.LKX;          // (4.E15)
  f.Bx = f.Kxk / (f.Cx * f.Dx + b_epsilon * sign_not_zero(f.Dx));                 // (4.E16)
  f.SHx = (c.PHX1 + c.PHX2 * dfz) * c.LHX;                                        // (4.E17)
  f.SVx = Fz * (c.PVX1 + c.PVX2 * dfz) * c.LVX * c.LMUX;                          // (4.E18)
  const double kappa_x = kappa + f.SHx;                                           // (4.E10)
  f.Ex = at_most_one((c.PEX1 + c.PEX2 * dfz + c.PEX3 * dfz * dfz) * (1 - c.PEX4 * sign(kappa_x)) * c.LEX);  // (4.E14)
  f.Fx0 = f.Dx * std::sin(magic_angle(f.Bx, f.Cx, f.Ex, kappa_x)) + f.SVx;        // (4.E9)
  return f;
}

PureLateralForce pure_lateral_force(const MagicFormulaCoefficients& c, double Fz, double alpha, double gamma) {
  const auto [Fz0_prime, dfz] = load_terms(c, Fz);
  const double gamma_y = gamma * c.LGAY;                                                    // (4.E31)
  PureLateralForce f;
  f.Cy = c.PCY1 * c.LCY;                                                                    // (4.E21)
  f.muy = (c.PDY1 + c.PDY2 * dfz) * (1 - c.PDY3 * gamma_y * gamma_y) * c.LMUY;              // (4.E23)
  f.Dy = f.muy * Fz;                                                                        // (4.E22)
  const double Kya0 = c.PKY1 * Fz0_prime * std::sin(2 * std::atan(Fz / (c.PKY2 * Fz0_prime))) * c.LKY;
  f.Kya = Kya0 * (1 - c.PKY3 * std::abs(gamma_y));                                          // (4.E25)
  f.By = f.Kya / (f.Cy * f.Dy + b_epsilon * sign_not_zero(f.Dy));                           // (4.E26)
  f.SHy = (c.PHY1 + c.PHY2 * dfz) * c.LHY + c.PHY3 * gamma_y;                               // (4.E27)
  f.SVy = Fz * ((c.PVY1 + c.PVY2 * dfz) * c.LVY + (c.PVY3 + c.PVY4 * dfz) * gamma_y) * c.LMUY;  // (4.E29)
  const double alpha_y = alpha + f.SHy;                                                     // (4.E20)
  f.Ey = at_most_one((c.PEY1 + c.PEY2 * dfz) * (1 - (c.PEY3 + c.PEY4 * gamma_y) * sign(alpha_y)) * c.LEY);  // (4.E24)
  f.Fy0 = f.Dy * std::sin(magic_angle(f.By, f.Cy, f.Ey, alpha_y)) + f.SVy;                  // (4.E19)
  return f;
}

AligningMomentTerms pure_aligning_moment(const MagicFormulaCoefficients& c, double Fz, double alpha, double gamma,
                                         const PureLateralForce& lateral) {
  const auto [Fz0_prime, dfz] = load_terms(c, Fz);
  const double R0 = c.UNLOADED_RADIUS;
  const double gamma_z = gamma * c.LGAZ;
  AligningMomentTerms m;
  m.SHt = c.QHZ1 + c.QHZ2 * dfz + (c.QHZ3 + c.QHZ4 * dfz) * gamma_z;                               // (4.E35)
  const double Kya = lateral.Kya + b_epsilon * sign_not_zero(lateral.Kya);
  m.SHf = lateral.SHy + lateral.SVy / Kya;                                                          // (4.E38)
  const double alpha_t = alpha + m.SHt;                                                             // (4.E34)
  const double alpha_r = alpha + m.SHf;                                                             // (4.E37)
  m.Bt = (c.QBZ1 + c.QBZ2 * dfz + c.QBZ3 * dfz * dfz) * (1 + c.QBZ4 * gamma_z + c.QBZ5 * std::abs(gamma_z)) *
         c.LKY / c.LMUY;                                                                            // (4.E40)
  m.Ct = c.QCZ1;                                                                                    // (4.E41)
  m.Dt = Fz * (c.QDZ1 + c.QDZ2 * dfz) * (1 + c.QDZ3 * gamma_z + c.QDZ4 * gamma_z * gamma_z) * (R0 / Fz0_prime) *
         c.LTR;                                                                                     // (4.E42)
  m.Et = at_most_one((c.QEZ1 + c.QEZ2 * dfz + c.QEZ3 * dfz * dfz) *
                     (1 + (c.QEZ4 + c.QEZ5 * gamma_z) * (2 / std::numbers::pi) * std::atan(m.Bt * m.Ct * alpha_t)));  // (4.E44)
  m.Br = c.QBZ9 * c.LKY / c.LMUY + c.QBZ10 * lateral.By * lateral.Cy;                               // (4.E45)
  m.Dr = Fz * ((c.QDZ6 + c.QDZ7 * dfz) * c.LRES + (c.QDZ8 + c.QDZ9 * dfz) * gamma_z) * R0 * c.LMUY;  // (4.E47)
  m.trail = m.Dt * std::cos(magic_angle(m.Bt, m.Ct, m.Et, alpha_t)) * std::cos(alpha);             // (4.E33)
  m.residual_moment = m.Dr * std::cos(std::atan(m.Br * alpha_r)) * std::cos(alpha);                 // (4.E36), Cr = 1
  m.Mz0 = -m.trail * lateral.Fy0 + m.residual_moment;                                              // (4.E31)
  return m;
}

TyreForcesAndMoments evaluate_magic_formula(const MagicFormulaCoefficients& c, const WheelSlipState& state,
                                            SlipCombination combination) {
  const double Fz = state.Fz, kappa = state.kappa, alpha = state.alpha, gamma = state.gamma;
  const auto [Fz0_prime, dfz] = load_terms(c, Fz);
  const PureLongitudinalForce lon = pure_longitudinal_force(c, Fz, kappa, gamma);
  const PureLateralForce lat = pure_lateral_force(c, Fz, alpha, gamma);
  const AligningMomentTerms mz = pure_aligning_moment(c, Fz, alpha, gamma, lat);

  TyreForcesAndMoments out;
  out.Kxk = lon.Kxk;
  out.Kya = lat.Kya;
  out.mux = lon.mux;
  out.muy = lat.muy;
  if (combination == SlipCombination::pure) {
    out.Fx = lon.Fx0;
    out.Fy = lat.Fy0;
    out.Mz = mz.Mz0;
    out.trail = mz.trail;
    out.residual_moment = mz.residual_moment;
  } else {
    // Fx: (4.E50)-(4.E57).
    const double SHxa = c.RHX1;
    const double alpha_s = alpha + SHxa;
    const double Bxa = (c.RBX1 + c.RBX3 * gamma * gamma) * std::cos(std::atan(c.RBX2 * kappa)) * c.LXAL;
    const double Cxa = c.RCX1;
    const double Exa = at_most_one(c.REX1 + c.REX2 * dfz);
    out.Gxa = std::cos(magic_angle(Bxa, Cxa, Exa, alpha_s)) / std::cos(magic_angle(Bxa, Cxa, Exa, SHxa));
    out.Fx = out.Gxa * lon.Fx0;
    // Fy: (4.E58)-(4.E67).
    const double SHyk = c.RHY1 + c.RHY2 * dfz;
    const double kappa_s = kappa + SHyk;
    const double Byk = c.RBY1 * std::cos(std::atan(c.RBY2 * (alpha - c.RBY3))) * c.LYKA;
    const double Cyk = c.RCY1;
    const double Eyk = at_most_one(c.REY1 + c.REY2 * dfz);
    const double DVyk = lat.muy * Fz * (c.RVY1 + c.RVY2 * dfz + c.RVY3 * gamma) * std::cos(std::atan(c.RVY4 * alpha));
    out.SVyk = DVyk * std::sin(c.RVY5 * std::atan(c.RVY6 * kappa)) * c.LVYKA;
    out.Gyk = std::cos(magic_angle(Byk, Cyk, Eyk, kappa_s)) / std::cos(magic_angle(Byk, Cyk, Eyk, SHyk));
    out.Fy = out.Gyk * lat.Fy0 + out.SVyk;
    // Mz: (4.E71)-(4.E78), equivalent slip angles with the ratio of the slip stiffnesses.
    const double Kya = lat.Kya + b_epsilon * sign_not_zero(lat.Kya);
    const double stiffness_ratio_kappa = lon.Kxk / Kya * kappa;
    const double alpha_t = alpha + mz.SHt;
    const double alpha_r = alpha + mz.SHf;
    const double tan_t = std::tan(alpha_t), tan_r = std::tan(alpha_r);
    const double alpha_t_eq =
        std::atan(std::sqrt(tan_t * tan_t + stiffness_ratio_kappa * stiffness_ratio_kappa)) * sign(alpha_t);
    const double alpha_r_eq =
        std::atan(std::sqrt(tan_r * tan_r + stiffness_ratio_kappa * stiffness_ratio_kappa)) * sign(alpha_r);
    const double R0 = c.UNLOADED_RADIUS;
    const double gamma_z = gamma * c.LGAZ;
    const double s = R0 * (c.SSZ1 + c.SSZ2 * (out.Fy / Fz0_prime) + (c.SSZ3 + c.SSZ4 * dfz) * gamma_z) * c.LS;
    out.trail = mz.Dt * std::cos(magic_angle(mz.Bt, mz.Ct, mz.Et, alpha_t_eq)) * std::cos(alpha);
    out.residual_moment = mz.Dr * std::cos(std::atan(mz.Br * alpha_r_eq)) * std::cos(alpha);
    out.Mz = -out.trail * (out.Fy - out.SVyk) + out.residual_moment + s * out.Fx;
  }
  const double R0 = c.UNLOADED_RADIUS;
  out.Mx = R0 * Fz * (c.QSX1 * c.LVMX - c.QSX2 * gamma + c.QSX3 * out.Fy / Fz0_prime) * c.LMX;
  const double Vx = state.Vx < 0 ? c.LONGVL : state.Vx;
  const double speed_ratio = c.LONGVL > 0 ? Vx / c.LONGVL : 0.0;
  out.My = -R0 * Fz * c.LMY *
           (c.QSY1 + c.QSY2 * out.Fx / c.FNOMIN + c.QSY3 * std::abs(speed_ratio) + c.QSY4 * std::pow(speed_ratio, 4));
  return out;
}

double effective_rolling_radius(const MagicFormulaCoefficients& c, double Fz) {
  const double rho = Fz / c.FNOMIN;
  return c.UNLOADED_RADIUS * c.Q_RE0 -
         c.FNOMIN / c.VERTICAL_STIFFNESS * (c.DREFF * std::atan(c.BREFF * rho) + c.FREFF * rho);
}

RelaxationLengths relaxation_lengths(const MagicFormulaCoefficients& c, double Fz, double gamma) {
  const double Fz0 = c.FNOMIN * c.LFZO, dfz = (Fz - Fz0) / Fz0, R0 = c.UNLOADED_RADIUS;
  RelaxationLengths r;
  r.sigma_kappa = Fz * (c.PTX1 + c.PTX2 * dfz) * std::exp(-c.PTX3 * dfz) * (R0 / Fz0) * c.LSGKP;
  const double gamma_y = gamma * c.LGAY;
  r.sigma_alpha = c.PTY2 != 0 ? c.PTY1 * std::sin(2 * std::atan(Fz / (c.PTY2 * Fz0))) * (1 - c.PKY3 * std::abs(gamma_y)) *
                                    R0 * c.LFZO * c.LSGAL
                              : 0.0;
  return r;
}

}  // namespace tirefem
