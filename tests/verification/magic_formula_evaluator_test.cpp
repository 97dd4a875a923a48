// PAC2002 evaluator: values of the formulas at four states of a public file, limits that follow from the
// formulas (shifts, slopes, peaks), combined slip reducing to pure slip, and W-axis signs.
//
// No force values computed by an established reader (MFeval, MF-Tyre, Adams, Chrono) for a public .tir file
// were found in public material, so the reference values below are NOT published numbers: they were
// computed by an independent hand transcription of the book's equations (a separate Python script, the
// equations typed from Pacejka 2nd ed. 4.E1-4.E78 again), which checks the C++ transcription, not the
// interpretation of the equations. The limit tests check the interpretation.
#include <gtest/gtest.h>

#include <cmath>

#include "tirefem/magic_formula/evaluator.hpp"
#include "tirefem/magic_formula/tir_reader.hpp"

namespace tirefem {
namespace {

MagicFormulaCoefficients public_file(const char* name) {
  return read_tir_file(std::string(TIREFEM_SOURCE_DIR) + "/tests/verification/data/magic_formula/" + name).coefficients;
}

void expect_relative(double actual, double expected, double tolerance, const char* what) {
  EXPECT_LE(std::abs(actual - expected), tolerance * std::abs(expected)) << what << ": " << actual << " vs " << expected;
}

struct HandValues {
  WheelSlipState state;
  double Fx0, Fy0, Mz0, Fx, Fy, Mz, My, Kxk, Kya;
};

TEST(MagicFormulaEvaluator, MatchesHandEvaluatedFormulasOn185R14) {
  const MagicFormulaCoefficients c = public_file("mf_185_80R14.tir");
  const HandValues cases[] = {
      {{3800, -0.05, 0.0, 0.0}, -3042.56239050798, 6.90878516658987, -10.9263212151007, -3042.56239050798,
       6.60736294288841, -37.1214866669767, -14.288, 74985.4, -45211.0249074814},
      {{5000, 0.0, 0.08, 0.0}, -175.77724750091, -3076.1584591954, 127.786196383684, -110.335340602137,
       -3076.1584591954, 126.24775863194, -18.8, 102769.234589519, -47573.2156765484},
      {{2500, 0.1, -0.05, 0.03}, 2628.82854211961, 1590.66398411471, -58.559407054376, 2307.5848953918,
       1395.14929478293, 10.2730051499454, -9.4, 47201.6333998604, -37948.2848623611},
      {{4200, -0.08, 0.06, -0.02}, -4152.77039192263, -2347.9657809364, 105.545767340432, -3309.93355593899,
       -2104.16350064263, -9.88034799565781, -15.792, 84012.230362886, -47312.1563792331},
  };
  constexpr double tolerance = 1e-12;
  for (const HandValues& h : cases) {
    const TyreForcesAndMoments pure = evaluate_magic_formula(c, h.state, SlipCombination::pure);
    const TyreForcesAndMoments combined = evaluate_magic_formula(c, h.state, SlipCombination::combined);
    expect_relative(pure.Fx, h.Fx0, tolerance, "Fx0");
    expect_relative(pure.Fy, h.Fy0, tolerance, "Fy0");
    expect_relative(pure.Mz, h.Mz0, tolerance, "Mz0");
    expect_relative(combined.Fx, h.Fx, tolerance, "Fx");
    expect_relative(combined.Fy, h.Fy, tolerance, "Fy");
    expect_relative(combined.Mz, h.Mz, tolerance, "Mz");
    expect_relative(combined.My, h.My, tolerance, "My");
    expect_relative(combined.Kxk, h.Kxk, tolerance, "Kxk");
    expect_relative(combined.Kya, h.Kya, tolerance, "Kya");
  }
}

TEST(MagicFormulaEvaluator, ShiftsSlopesAndPeakFollowFromTheCoefficients) {
  for (const char* name : {"mf_185_80R14.tir", "Sedan_Pac02Tire.tir"}) {
    const MagicFormulaCoefficients c = public_file(name);
    for (double Fz : {0.6 * c.FNOMIN, c.FNOMIN, 1.4 * c.FNOMIN}) {
      const PureLongitudinalForce lon0 = pure_longitudinal_force(c, Fz, 0.0, 0.0);
      // Fx0(kappa = -SHx) = SVx (4.E9) and dFx0/dkappa there = Kxk = Bx Cx Dx (up to the 1e-3 epsilon).
      EXPECT_NEAR(pure_longitudinal_force(c, Fz, -lon0.SHx, 0.0).Fx0, lon0.SVx, 1e-9 * Fz) << name;
      const double h = 1e-7;
      const double slope = (pure_longitudinal_force(c, Fz, -lon0.SHx + h, 0.0).Fx0 -
                            pure_longitudinal_force(c, Fz, -lon0.SHx - h, 0.0).Fx0) / (2 * h);
      expect_relative(slope, lon0.Kxk, 1e-6, "dFx0/dkappa");
      // The peak of the sine is Dx + SVx (C > 1 here, so the curve passes its maximum).
      double peak = -1e300;
      for (int i = 0; i <= 200000; ++i) peak = std::max(peak, pure_longitudinal_force(c, Fz, i * 5e-6, 0.0).Fx0);
      expect_relative(peak, lon0.Dx + lon0.SVx, 1e-7, "peak Fx0");

      const PureLateralForce lat0 = pure_lateral_force(c, Fz, 0.0, 0.0);
      EXPECT_NEAR(pure_lateral_force(c, Fz, -lat0.SHy, 0.0).Fy0, lat0.SVy, 1e-9 * Fz) << name;
      const double slope_y = (pure_lateral_force(c, Fz, -lat0.SHy + h, 0.0).Fy0 -
                              pure_lateral_force(c, Fz, -lat0.SHy - h, 0.0).Fy0) / (2 * h);
      expect_relative(slope_y, lat0.Kya, 1e-6, "dFy0/dalpha");
      // Kya = PKY1 Fz0' sin(2 atan(Fz/(PKY2 Fz0'))), Fz0' = FNOMIN LFZO (LFZO = 0.81 in the Sedan file).
      const double Fz0 = c.FNOMIN * c.LFZO;
      expect_relative(lat0.Kya, c.PKY1 * Fz0 * std::sin(2 * std::atan(Fz / (c.PKY2 * Fz0))), 1e-14, "Kya");

      // Trail at alpha_t = 0 is Dt cos(alpha) (4.E33); Mz0 = -t Fy0 + Mzr.
      const AligningMomentTerms m0 = pure_aligning_moment(c, Fz, 0.0, 0.0, lat0);
      const double alpha_t0 = -m0.SHt;
      const PureLateralForce lat_t = pure_lateral_force(c, Fz, alpha_t0, 0.0);
      const AligningMomentTerms m_t = pure_aligning_moment(c, Fz, alpha_t0, 0.0, lat_t);
      expect_relative(m_t.trail, m0.Dt * std::cos(alpha_t0), 1e-14, "trail peak");
      expect_relative(m_t.Mz0, -m_t.trail * lat_t.Fy0 + m_t.residual_moment, 1e-14, "Mz0");
    }
  }
}

TEST(MagicFormulaEvaluator, CombinedSlipReducesToPureSlipWhenTheOtherSlipIsZero) {
  const MagicFormulaCoefficients c = public_file("mf_185_80R14.tir");
  for (double slip : {-0.2, -0.03, 0.05, 0.3}) {
    const WheelSlipState longitudinal{c.FNOMIN, slip, 0.0, 0.0};
    EXPECT_DOUBLE_EQ(evaluate_magic_formula(c, longitudinal).Fx, pure_longitudinal_force(c, c.FNOMIN, slip, 0.0).Fx0);
    const WheelSlipState lateral{c.FNOMIN, 0.0, slip, 0.0};
    const TyreForcesAndMoments f = evaluate_magic_formula(c, lateral);
    EXPECT_DOUBLE_EQ(f.Fy, pure_lateral_force(c, c.FNOMIN, slip, 0.0).Fy0);
    EXPECT_EQ(f.SVyk, 0.0);
  }
}

TEST(MagicFormulaEvaluator, WAxisSigns) {
  for (const char* name : {"mf_185_80R14.tir", "Sedan_Pac02Tire.tir"}) {
    const MagicFormulaCoefficients c = public_file(name);
    ASSERT_LT(c.PKY1, 0) << name;
    for (double Fz : {0.5 * c.FNOMIN, c.FNOMIN, 1.5 * c.FNOMIN}) {
      for (double kappa : {-0.02, -0.1, -0.5}) {
        EXPECT_LT(evaluate_magic_formula(c, {Fz, kappa, 0.0, 0.0}).Fx, 0) << name << " braking";
        EXPECT_GT(evaluate_magic_formula(c, {Fz, -kappa, 0.0, 0.0}).Fx, 0) << name << " driving";
      }
      for (double alpha : {0.02, 0.1, 0.3}) {
        EXPECT_LT(evaluate_magic_formula(c, {Fz, 0.0, alpha, 0.0}).Fy, 0) << name << " alpha > 0";
        EXPECT_GT(evaluate_magic_formula(c, {Fz, 0.0, -alpha, 0.0}).Fy, 0) << name << " alpha < 0";
      }
      // Small slip angle: the aligning moment turns the wheel towards the slip (Mz > 0 for alpha > 0).
      EXPECT_GT(evaluate_magic_formula(c, {Fz, 0.0, 0.03, 0.0}).Mz, 0) << name;
    }
  }
}

}  // namespace
}  // namespace tirefem
