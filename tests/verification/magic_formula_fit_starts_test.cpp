// The fit of a Coulomb tread's rig table does not depend on round-off in the table: two runs of the example
// tyre's rig whose forces differ by at most 0.09% give the same coefficients. With one start, the lateral
// group of the second run found another minimum of the least-squares function (PKY1 -26.9 against -24.0,
// PDY1 0.67 against 0.85, Fy RMS 1.02% against 0.57% of the peak). Since the fit groups the loads into
// levels (fit_points.hpp: load_levels) both runs give PKY1 −15.5 with PKY2 2.0, Fy RMS 0.37%.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tirefem/magic_formula/evaluator.hpp"
#include "tirefem/magic_formula/fitter.hpp"

namespace tirefem {
namespace {

// Points of one run of tests/verification/data/magic_formula/rig_175-70R13_two_runs.csv.
std::vector<TyreTestPoint> rig_run(int run) {
  std::ifstream in(std::string(TIREFEM_SOURCE_DIR) +
                   "/tests/verification/data/magic_formula/rig_175-70R13_two_runs.csv");
  std::vector<TyreTestPoint> points;
  std::string line;
  bool header = true;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (header) {
      header = false;
      continue;
    }
    std::istringstream row(line);
    std::vector<double> v;
    for (std::string field; std::getline(row, field, ',');) v.push_back(std::stod(field));
    if (v.size() == 8 && static_cast<int>(v[0]) == run) points.push_back({v[1], v[2], v[3], v[4], v[5], v[6], v[7]});
  }
  return points;
}

MagicFormulaFit fit_run(int run) {
  MagicFormulaCoefficients start;
  start.FNOMIN = 3700;
  start.UNLOADED_RADIUS = 0.285;
  const auto points = rig_run(run);
  EXPECT_EQ(points.size(), 93u) << "run " << run;
  return fit_magic_formula(points, start);
}

TEST(MagicFormulaFitStarts, TwoRunsOfTheRigGiveTheSameCoefficients) {
  const MagicFormulaFit a = fit_run(1), b = fit_run(2);
  ASSERT_EQ(a.groups.size(), 3u);
  ASSERT_EQ(b.groups.size(), 3u);
  for (std::size_t g = 0; g < 3; ++g) {
    std::printf("%s: RMS %.4f%% and %.4f%% of the peak, %.3f s and %.3f s\n", a.groups[g].error.channel.c_str(),
                100 * a.groups[g].error.relative_rms, 100 * b.groups[g].error.relative_rms, a.groups[g].seconds,
                b.groups[g].seconds);
    // The same minimum: RMS errors within 2% of each other (0.09% data changes).
    EXPECT_NEAR(a.groups[g].error.relative_rms, b.groups[g].error.relative_rms,
                0.02 * a.groups[g].error.relative_rms)
        << a.groups[g].error.channel;
  }
  const MagicFormulaCoefficients &x = a.coefficients, &y = b.coefficients;
  // The coefficients that set the curves' slope, peak and shape: within 1% (the data differ by 0.09%; the
  // two minima differed by 12% in PKY1, 22% in PDY1 and a factor 2 in PCY1).
  for (auto [p, q, name] : {std::tuple{x.PKX1, y.PKX1, "PKX1"}, {x.PDX1, y.PDX1, "PDX1"}, {x.PCX1, y.PCX1, "PCX1"},
                            {x.PKY1, y.PKY1, "PKY1"}, {x.PDY1, y.PDY1, "PDY1"}, {x.PCY1, y.PCY1, "PCY1"},
                            {x.QBZ1, y.QBZ1, "QBZ1"}, {x.QCZ1, y.QCZ1, "QCZ1"}, {x.QDZ1, y.QDZ1, "QDZ1"}}) {
    std::printf("%s %.6g %.6g\n", name, p, q);
    EXPECT_LE(std::abs(p - q), 0.01 * std::abs(p)) << name;
  }
}

// The number a vehicle model takes most from the file, the cornering stiffness, is the FE tyre's: at FNOMIN
// the fitted curve's secant at the rig's smallest slip angle equals the table's within 2%. (With the load
// levels split by the rig's ±0.2% load scatter the start values were spoiled and PKY2 ran to its bound 4:
// 731 against 813 N/deg.)
TEST(MagicFormulaFitStarts, TheFittedCorneringStiffnessIsTheTables) {
  const auto points = rig_run(1);
  const MagicFormulaFit fit = fit_run(1);
  const TyreTestPoint* smallest = nullptr;
  for (const TyreTestPoint& p : points)
    if (p.kappa == 0 && p.gamma == 0 && p.alpha > 0 && std::abs(p.Fz - 3700) < 0.01 * 3700 &&
        (!smallest || p.alpha < smallest->alpha))
      smallest = &p;
  ASSERT_NE(smallest, nullptr);
  const auto f = evaluate_magic_formula(fit.coefficients, {smallest->Fz, 0.0, smallest->alpha, 0.0}, SlipCombination::pure);
  const double table = smallest->Fy / smallest->alpha, fitted = f.Fy / smallest->alpha;
  std::printf("cornering stiffness at %.0f N, alpha %.3f deg: table %.1f, fit %.1f N/deg\n", smallest->Fz,
              smallest->alpha * 180 / M_PI, table * M_PI / 180, fitted * M_PI / 180);
  EXPECT_LT(table, 0.0);  // W axes: alpha > 0 gives Fy < 0
  EXPECT_NEAR(fitted, table, 0.02 * std::abs(table));
}

// Sweeps of one sign (κ ≥ 0, α ≥ 0) do not determine the curves' shifts, which then trade against each
// other and the slope: they are flagged and kept at 0, and the file's curves stay the FE tyre's mirror
// image on the side the test did not run (this tyre is its own mirror image: Fy(−α) = −Fy(α)). Before,
// fitted from one side, its example's quick rig gave Fy(−6°) = +774 N against −1183 N at +6°.
TEST(MagicFormulaFitStarts, OneSidedSweepsLeaveTheShiftsOut) {
  const auto all = rig_run(1);
  std::vector<TyreTestPoint> positive;
  for (const TyreTestPoint& p : all)
    if (p.kappa >= 0 && p.alpha >= 0) positive.push_back(p);
  MagicFormulaCoefficients start;
  start.FNOMIN = 3700;
  start.UNLOADED_RADIUS = 0.285;
  const MagicFormulaFit fit = fit_magic_formula(positive, start);
  const std::vector<std::vector<const char*>> shifts{
      {"PHX1", "PHX2", "PVX1", "PVX2"}, {"PHY1", "PHY2", "PVY1", "PVY2"}, {"QHZ1", "QHZ2"}};
  for (std::size_t g = 0; g < 3; ++g)
    for (const char* key : shifts[g])
      EXPECT_NE(std::find(fit.groups[g].not_determined.begin(), fit.groups[g].not_determined.end(), key),
                fit.groups[g].not_determined.end())
          << key;
  const MagicFormulaCoefficients& c = fit.coefficients;
  for (double v : {c.PHX1, c.PHX2, c.PVX1, c.PVX2, c.PHY1, c.PHY2, c.PVY1, c.PVY2, c.QHZ1, c.QHZ2}) EXPECT_EQ(v, 0.0);
  // Fy and Mz against the whole table, the negative slip angles included (the tyre's mirror image); Fx, whose
  // braking side is not the driving side's mirror image (5550 N: −3786 N at κ −0.15, +3604 N at +0.15),
  // against the driving side it was fitted to. Within the 3% of the peak the issue asks of the fit for Fx
  // and Fy, 10% for Mz.
  double peak[3] = {0, 0, 0}, squares[3] = {0, 0, 0};
  int n[3] = {0, 0, 0};
  for (const TyreTestPoint& p : all) {
    if (p.gamma != 0 || (p.kappa != 0 && p.alpha != 0)) continue;
    const auto f = evaluate_magic_formula(c, {p.Fz, p.kappa, p.alpha, 0.0}, SlipCombination::pure);
    const double fitted[3] = {f.Fx, f.Fy, f.Mz}, table[3] = {p.Fx, p.Fy, p.Mz};
    const bool used[3] = {p.alpha == 0 && p.kappa >= 0, p.kappa == 0, p.kappa == 0};
    for (int k = 0; k < 3; ++k) {
      if (!used[k]) continue;
      peak[k] = std::max(peak[k], std::abs(table[k]));
      squares[k] += (fitted[k] - table[k]) * (fitted[k] - table[k]);
      ++n[k];
    }
  }
  const double bound[3] = {0.03, 0.03, 0.10};
  for (int k = 0; k < 3; ++k) {
    const double rms = std::sqrt(squares[k] / n[k]) / peak[k];
    std::printf("%s: fitted to one side, RMS %.2f%% of the peak against %d points\n",
                k == 0 ? "Fx" : (k == 1 ? "Fy" : "Mz"), 100 * rms, n[k]);
    EXPECT_LE(rms, bound[k]) << k;
  }
}

}  // namespace
}  // namespace tirefem
