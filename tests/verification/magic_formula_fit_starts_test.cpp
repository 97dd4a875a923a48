// The fit of a Coulomb tread's rig table does not depend on round-off in the table: two runs of the example
// tyre's rig whose forces differ by at most 0.09% give the same coefficients. With one start, the lateral
// group of the second run found another minimum of the least-squares function (PKY1 -26.9 against -24.0,
// PDY1 0.67 against 0.85, Fy RMS 1.02% against 0.57% of the peak). Since the fit groups the loads into
// levels (fit_points.hpp: load_levels) both runs give PKY1 −15.5 with PKY2 2.0, Fy RMS 0.37%.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace tirefem
