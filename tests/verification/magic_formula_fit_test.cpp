// The fitter recovers the coefficients of a public PAC2002 file from data the evaluator generated:
// to 1e-6 relative on the curves without noise, and within stated bounds with 1% Gaussian noise.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "tirefem/magic_formula/combined_slip_fit.hpp"
#include "tirefem/magic_formula/evaluator.hpp"
#include "tirefem/magic_formula/fitter.hpp"
#include "tirefem/magic_formula/tir_reader.hpp"

namespace tirefem {
namespace {

using M = MagicFormulaCoefficients;

MagicFormulaCoefficients truth() {
  return read_tir_file(std::string(TIREFEM_SOURCE_DIR) + "/tests/verification/data/magic_formula/mf_185_80R14.tir")
      .coefficients;
}

// A virtual rig: 3 loads x (41 kappa + 41 alpha) states, no camber: 123 points per group.
std::vector<TyreTestPoint> rig_points(const MagicFormulaCoefficients& c) {
  std::vector<TyreTestPoint> points;
  for (double load : {0.5, 1.0, 1.5}) {
    const double Fz = load * c.FNOMIN;
    for (int i = -20; i <= 20; ++i) {
      const double kappa = 0.015 * i;
      const auto f = evaluate_magic_formula(c, {Fz, kappa, 0.0, 0.0}, SlipCombination::pure);
      points.push_back({Fz, kappa, 0.0, 0.0, f.Fx, f.Fy, f.Mz});
    }
    for (int i = -20; i <= 20; ++i) {
      if (i == 0) continue;  // alpha = kappa = 0 is already a point
      const double alpha = 0.0125 * i;
      const auto f = evaluate_magic_formula(c, {Fz, 0.0, alpha, 0.0}, SlipCombination::pure);
      points.push_back({Fz, 0.0, alpha, 0.0, f.Fx, f.Fy, f.Mz});
    }
  }
  return points;
}

// The rig's points at the given loads (x FNOMIN), each state's Fz off its load by up to ±0.2% as a rig that
// holds the load to its tolerance leaves it (tirefem's rig: 5544.6–5561.1 N at 5550 N).
std::vector<TyreTestPoint> held_load_points(const MagicFormulaCoefficients& c, std::initializer_list<double> loads) {
  std::vector<TyreTestPoint> points;
  int n = 0;
  const auto add = [&](double load, double kappa, double alpha) {
    const double Fz = load * c.FNOMIN * (1.0 + 0.002 * std::sin(1.7 * n++));
    const auto f = evaluate_magic_formula(c, {Fz, kappa, alpha, 0.0}, SlipCombination::pure);
    points.push_back({Fz, kappa, alpha, 0.0, f.Fx, f.Fy, f.Mz});
  };
  for (double load : loads) {
    for (int i = -20; i <= 20; ++i) add(load, 0.015 * i, 0.0);
    for (int i = -20; i <= 20; ++i)
      if (i != 0) add(load, 0.0, 0.0125 * i);
  }
  return points;
}

// max |fitted - true| over the rig's states, relative to the channel's peak.
// The fitted curve against the true one over the pure-slip states of `points`: the largest difference
// (or, with `rms`, the root mean square of the differences) relative to the true curve's peak.
double curve_error(FitGroup group, const MagicFormulaCoefficients& fitted, const MagicFormulaCoefficients& exact,
                   const std::vector<TyreTestPoint>& points, bool rms = false) {
  double worst = 0, peak = 0, squares = 0;
  int n = 0;
  for (const TyreTestPoint& p : points) {
    const bool lateral = group != FitGroup::pure_longitudinal;
    if ((lateral ? p.kappa : p.alpha) != 0) continue;
    const auto a = evaluate_magic_formula(fitted, {p.Fz, p.kappa, p.alpha, 0.0}, SlipCombination::pure);
    const auto b = evaluate_magic_formula(exact, {p.Fz, p.kappa, p.alpha, 0.0}, SlipCombination::pure);
    const double va = group == FitGroup::pure_longitudinal ? a.Fx : (group == FitGroup::pure_lateral ? a.Fy : a.Mz);
    const double vb = group == FitGroup::pure_longitudinal ? b.Fx : (group == FitGroup::pure_lateral ? b.Fy : b.Mz);
    worst = std::max(worst, std::abs(va - vb));
    squares += (va - vb) * (va - vb), ++n;
    peak = std::max(peak, std::abs(vb));
  }
  return (rms ? std::sqrt(squares / n) : worst) / peak;
}

MagicFormulaCoefficients start_from(const MagicFormulaCoefficients& exact) {
  MagicFormulaCoefficients start;
  start.FNOMIN = exact.FNOMIN;
  start.UNLOADED_RADIUS = exact.UNLOADED_RADIUS;
  return start;
}

bool contains(const std::vector<std::string>& list, const std::string& key) {
  return std::find(list.begin(), list.end(), key) != list.end();
}

TEST(MagicFormulaFit, RecoversTheCoefficientsFromNoiseFreeData) {
  const MagicFormulaCoefficients exact = truth();
  const auto points = rig_points(exact);
  const MagicFormulaFit fit = fit_magic_formula(points, start_from(exact));
  ASSERT_EQ(fit.groups.size(), 3u);
  for (const GroupFitResult& g : fit.groups) {
    const double error = curve_error(g.group, fit.coefficients, exact, points);
    std::printf("%s: %d points, %zu fitted, rms %.3g (%.3g of peak), curve error %.3g of peak, %.3f s, %d evaluations\n",
                g.error.channel.c_str(), g.error.points, g.fitted.size(), g.error.rms, g.error.relative_rms, error,
                g.seconds, g.function_evaluations);
    EXPECT_LE(error, 1e-6) << g.error.channel;
    EXPECT_LE(g.error.relative_rms, 1e-7) << g.error.channel;
    EXPECT_LT(g.seconds, 1.0) << g.error.channel;
  }
  // The coefficients that set the curves' main features, to 1e-6 relative.
  const MagicFormulaCoefficients& c = fit.coefficients;
  for (auto [fitted, expected, name] : {std::tuple{c.PCX1, exact.PCX1, "PCX1"}, {c.PDX1, exact.PDX1, "PDX1"},
                                        {c.PDX2, exact.PDX2, "PDX2"}, {c.PKX1, exact.PKX1, "PKX1"},
                                        {c.PKX3, exact.PKX3, "PKX3"}, {c.PEX1, exact.PEX1, "PEX1"},
                                        {c.PCY1, exact.PCY1, "PCY1"}, {c.PDY1, exact.PDY1, "PDY1"},
                                        {c.PDY2, exact.PDY2, "PDY2"}, {c.PKY1, exact.PKY1, "PKY1"},
                                        {c.PKY2, exact.PKY2, "PKY2"}, {c.QBZ1, exact.QBZ1, "QBZ1"},
                                        {c.QCZ1, exact.QCZ1, "QCZ1"}, {c.QDZ1, exact.QDZ1, "QDZ1"},
                                        {c.QBZ9, exact.QBZ9, "QBZ9"}, {c.QDZ6, exact.QDZ6, "QDZ6"}})
    EXPECT_LE(std::abs(fitted - expected), 1e-6 * std::abs(expected)) << name << " " << fitted << " vs " << expected;
  // Without camber points the camber terms are not determined and hold their neutral values.
  for (const char* key : {"PDX3"}) EXPECT_TRUE(contains(fit.groups[0].not_determined, key)) << key;
  for (const char* key : {"PDY3", "PEY4", "PKY3", "PHY3", "PVY3", "PVY4"})
    EXPECT_TRUE(contains(fit.groups[1].not_determined, key)) << key;
  for (const char* key : {"QBZ4", "QBZ5", "QBZ10", "QDZ3", "QDZ4", "QDZ8", "QDZ9", "QEZ5", "QHZ3", "QHZ4"})
    EXPECT_TRUE(contains(fit.groups[2].not_determined, key)) << key;
  EXPECT_EQ(c.PDX3, 0.0);
  EXPECT_EQ(c.PKY3, 0.0);
  EXPECT_EQ(c.QDZ8, 0.0);
}

TEST(MagicFormulaFit, StaysCloseWithOnePercentNoise) {
  const MagicFormulaCoefficients exact = truth();
  auto points = rig_points(exact);
  double peak_x = 0, peak_y = 0, peak_z = 0;
  for (const auto& p : points) {
    peak_x = std::max(peak_x, std::abs(p.Fx));
    peak_y = std::max(peak_y, std::abs(p.Fy));
    peak_z = std::max(peak_z, std::abs(p.Mz));
  }
  std::mt19937 random(20240612);
  std::normal_distribution<double> unit(0.0, 1.0);
  for (auto& p : points) {  // sigma = 1% of each channel's peak
    p.Fx += 0.01 * peak_x * unit(random);
    p.Fy += 0.01 * peak_y * unit(random);
    p.Mz += 0.01 * peak_z * unit(random);
  }
  const MagicFormulaFit fit = fit_magic_formula(points, start_from(exact));
  for (const GroupFitResult& g : fit.groups) {
    const double error = curve_error(g.group, fit.coefficients, exact, rig_points(exact), true);
    std::printf("%s with noise: rms %.3g of peak, rms curve error %.3g of peak, %.3f s\n", g.error.channel.c_str(),
                g.error.relative_rms, error, g.seconds);
    // The residual is the noise itself (1% of the peak); the fitted curve lies well inside it. For least
    // squares with p parameters on N points the fitted-minus-true curve has an expected RMS over the points
    // of σ·√(p/N): σ = 1% of the peak, p ≤ 15, N = 123 give 0.35%. The bound is 0.6%; measured with 12 other
    // seeds 0.22–0.43% in every channel, with this seed 0.33% (Fx), 0.48% (Fy), 0.31% (Mz). (A first bound on the
    // largest difference, 1%, was ill-posed: over 20 noise seeds that maximum ranged 0.5–1.5% for every
    // channel and fitter, above 1% for about a third of the seeds.)
    EXPECT_NEAR(g.error.relative_rms, 0.01, 0.002) << g.error.channel;
    EXPECT_LE(error, 0.006) << g.error.channel;
    EXPECT_LT(g.seconds, 1.0) << g.error.channel;
  }
  const MagicFormulaCoefficients& c = fit.coefficients;
  for (auto [fitted, expected, name] : {std::tuple{c.PDX1, exact.PDX1, "PDX1"}, {c.PKX1, exact.PKX1, "PKX1"},
                                        {c.PDY1, exact.PDY1, "PDY1"}, {c.PKY1, exact.PKY1, "PKY1"},
                                        {c.QDZ1, exact.QDZ1, "QDZ1"}})
    EXPECT_LE(std::abs(fitted - expected), 0.03 * std::abs(expected)) << name << " " << fitted << " vs " << expected;
}

// Free-rolling cambered points (alpha = 0, a small kappa of their own, as the rig's cambers give them) at
// every load determine the camber thrust and the residual moment's camber term (PVY3-4, QDZ8-9); the
// shifts they cannot tell apart from these (PHY3, QHZ3) and the sweep terms stay neutral. Observed: the
// camber thrust within 11.3 N of 337.5 N (3.3%), the moment 0.40 of 17.4 N m (2.3%); not exact, as the
// file's own camber thrust is partly PHY3's and its load dependence not linear. Before, the fit left out
// every point with kappa != 0 and the file had no camber thrust at all.
TEST(MagicFormulaFit, FreeRollingCamberedPointsGiveTheCamberThrust) {
  const MagicFormulaCoefficients exact = truth();
  auto points = rig_points(exact);
  std::vector<TyreTestPoint> cambered;
  for (double load : {0.5, 1.0, 1.5})
    for (double gamma_deg : {-4.0, -2.0, 2.0, 4.0}) {
      const double Fz = load * exact.FNOMIN, gamma = gamma_deg * M_PI / 180;
      const auto f = evaluate_magic_formula(exact, {Fz, 1e-4, 0.0, gamma}, SlipCombination::pure);
      cambered.push_back({Fz, 1e-4, 0.0, gamma, f.Fx, f.Fy, f.Mz});
    }
  points.insert(points.end(), cambered.begin(), cambered.end());
  const MagicFormulaFit fit = fit_magic_formula(points, start_from(exact));
  for (const char* key : {"PVY3", "PVY4"}) EXPECT_TRUE(contains(fit.groups[1].fitted, key)) << key;
  for (const char* key : {"QDZ8", "QDZ9"}) EXPECT_TRUE(contains(fit.groups[2].fitted, key)) << key;
  for (const char* key : {"PHY3", "PDY3", "PKY3", "PEY4"}) EXPECT_TRUE(contains(fit.groups[1].not_determined, key)) << key;
  for (const char* key : {"QHZ3", "QBZ4", "QDZ3"}) EXPECT_TRUE(contains(fit.groups[2].not_determined, key)) << key;
  double worst_fy = 0, worst_mz = 0, peak_fy = 0, peak_mz = 0;
  for (const TyreTestPoint& p : cambered) {
    const auto f = evaluate_magic_formula(fit.coefficients, {p.Fz, p.kappa, 0.0, p.gamma}, SlipCombination::pure);
    worst_fy = std::max(worst_fy, std::abs(f.Fy - p.Fy));
    worst_mz = std::max(worst_mz, std::abs(f.Mz - p.Mz));
    peak_fy = std::max(peak_fy, std::abs(p.Fy));
    peak_mz = std::max(peak_mz, std::abs(p.Mz));
  }
  std::printf("camber thrust: largest error %.2f N of %.1f N; camber moment %.3f of %.3f N m\n", worst_fy, peak_fy,
              worst_mz, peak_mz);
  EXPECT_LE(worst_fy, 0.05 * peak_fy);
  EXPECT_LE(worst_mz, 0.10 * peak_mz);
}

// A rig's combined-slip grid (kappa and alpha both non-zero) gives the weighting functions' slope, its fall
// and shape (RBX1-2, RCX1, RBY1-2, RCY1): recovered exactly from a file whose other combined-slip terms
// are neutral, and with the 185/80R14 file's own (curvature REX1 0.62, shifts, kappa-induced side force)
// the fitted surfaces stay within a few per cent of its forces.
TEST(MagicFormulaFit, CombinedSlipPointsGiveTheWeightingFunctions) {
  const auto grid = [](const MagicFormulaCoefficients& c) {
    std::vector<TyreTestPoint> points;
    for (double load : {0.5, 1.0, 1.5})
      for (double kappa : {-0.1, -0.05, -0.02, 0.02, 0.05, 0.1})
        for (double alpha_deg : {2.0, 4.0, 8.0}) {
          const double Fz = load * c.FNOMIN, alpha = alpha_deg * M_PI / 180;
          const auto f = evaluate_magic_formula(c, {Fz, kappa, alpha, 0.0}, SlipCombination::combined);
          points.push_back({Fz, kappa, alpha, 0.0, f.Fx, f.Fy, f.Mz});
        }
    return points;
  };
  const auto fit_with_grid = [&](const MagicFormulaCoefficients& exact) {
    auto points = rig_points(exact);
    const auto combined = grid(exact);
    points.insert(points.end(), combined.begin(), combined.end());
    MagicFormulaCoefficients c = fit_magic_formula(points, start_from(exact)).coefficients;
    const CombinedSlipFit fit = fit_combined_slip(points, c);
    double worst[2] = {0, 0}, peak[2] = {0, 0};
    for (const TyreTestPoint& p : combined) {
      const auto f = evaluate_magic_formula(c, {p.Fz, p.kappa, p.alpha, 0.0}, SlipCombination::combined);
      worst[0] = std::max(worst[0], std::abs(f.Fx - p.Fx)), peak[0] = std::max(peak[0], std::abs(p.Fx));
      worst[1] = std::max(worst[1], std::abs(f.Fy - p.Fy)), peak[1] = std::max(peak[1], std::abs(p.Fy));
    }
    return std::tuple{c, fit, worst[0] / peak[0], worst[1] / peak[1]};
  };
  MagicFormulaCoefficients plain = truth();
  for (double M::*m : {&M::REX1, &M::REX2, &M::RHX1, &M::RBY3, &M::REY1, &M::REY2, &M::RHY1, &M::RHY2, &M::RVY1,
                       &M::RVY2, &M::RVY3, &M::RVY4, &M::RVY5, &M::RVY6})
    plain.*m = 0;
  {
    const auto [c, fit, fx, fy] = fit_with_grid(plain);
    std::printf("combined slip, plain file: Fx %.2g, Fy %.2g of the peak; RBX1 %.6g RBX2 %.6g RCX1 %.6g RBY1 %.6g "
                "RBY2 %.6g RCY1 %.6g\n", fx, fy, c.RBX1, c.RBX2, c.RCX1, c.RBY1, c.RBY2, c.RCY1);
    for (const char* key : {"RBX1", "RBX2", "RCX1", "RBY1", "RBY2", "RCY1"}) EXPECT_TRUE(contains(fit.fitted, key)) << key;
    for (const char* key : {"REX1", "RHX1", "RVY1", "SSZ1"}) EXPECT_TRUE(contains(fit.not_determined, key)) << key;
    for (auto [fitted, expected, name] : {std::tuple{c.RBX1, plain.RBX1, "RBX1"}, {std::abs(c.RBX2), std::abs(plain.RBX2), "|RBX2|"},
                                          {c.RCX1, plain.RCX1, "RCX1"}, {c.RBY1, plain.RBY1, "RBY1"},
                                          {std::abs(c.RBY2), std::abs(plain.RBY2), "|RBY2|"}, {c.RCY1, plain.RCY1, "RCY1"}})
      EXPECT_LE(std::abs(fitted - expected), 1e-4 * std::abs(expected)) << name << " " << fitted << " vs " << expected;
  }
  {
    const auto [c, fit, fx, fy] = fit_with_grid(truth());
    std::printf("combined slip, the whole file: Fx %.3f, Fy %.3f of the peak\n", fx, fy);
    EXPECT_LE(fx, 0.05);
    EXPECT_LE(fy, 0.05);
  }
}

// A load held to its tolerance is one load level: the coefficients of the load's influence are not determined
// by one load (and those of its square not by two), whatever the scatter of Fz within each.
TEST(MagicFormulaFit, LoadsHeldToTheirToleranceAreOneLevelEach) {
  const MagicFormulaCoefficients exact = truth();
  const std::vector<std::vector<const char*>> by_one_load{
      {"PDX2", "PEX2", "PEX3", "PKX2", "PKX3", "PHX2", "PVX2"},
      {"PDY2", "PEY2", "PKY2", "PHY2", "PVY2"},
      {"QBZ2", "QBZ3", "QDZ2", "QDZ7", "QEZ2", "QEZ3", "QHZ2"}};
  const std::vector<std::vector<const char*>> by_two_loads{{"PEX3", "PKX3"}, {}, {"QBZ3", "QEZ3"}};
  {
    const auto points = held_load_points(exact, {1.0});
    const MagicFormulaFit fit = fit_magic_formula(points, start_from(exact));
    for (std::size_t g = 0; g < 3; ++g) {
      for (const char* key : by_one_load[g]) EXPECT_TRUE(contains(fit.groups[g].not_determined, key)) << key;
      // At FNOMIN the nominal coefficients alone describe the tyre: the fit passes through the points.
      EXPECT_LE(curve_error(fit.groups[g].group, fit.coefficients, exact, points, true), 2e-3) << g;
    }
    const MagicFormulaCoefficients& c = fit.coefficients;
    EXPECT_EQ(c.PKX2, 0.0);
    EXPECT_EQ(c.PEX3, 0.0);
    // PKY1 with PKY2 (held at an assumed value): the cornering stiffness at FNOMIN, PKY1 sin(2 atan(1/PKY2)).
    const auto Kya = [](const MagicFormulaCoefficients& m) { return m.PKY1 * std::sin(2 * std::atan(1 / m.PKY2)); };
    for (auto [fitted, expected, name] : {std::tuple{c.PDX1, exact.PDX1, "PDX1"}, {c.PKX1, exact.PKX1, "PKX1"},
                                          {c.PDY1, exact.PDY1, "PDY1"}, {Kya(c), Kya(exact), "Kya/Fz0"},
                                          {c.QDZ1, exact.QDZ1, "QDZ1"}})
      EXPECT_LE(std::abs(fitted - expected), 0.01 * std::abs(expected)) << name << " " << fitted << " vs " << expected;
  }
  {
    const auto points = held_load_points(exact, {0.5, 1.0});
    const MagicFormulaFit fit = fit_magic_formula(points, start_from(exact));
    for (std::size_t g = 0; g < 3; ++g) {
      for (const char* key : by_two_loads[g]) EXPECT_TRUE(contains(fit.groups[g].not_determined, key)) << key;
      for (const char* key : by_one_load[g])
        if (std::find_if(by_two_loads[g].begin(), by_two_loads[g].end(),
                         [&](const char* k) { return std::string(k) == key; }) == by_two_loads[g].end())
          EXPECT_TRUE(contains(fit.groups[g].fitted, key)) << key;
      EXPECT_LE(curve_error(fit.groups[g].group, fit.coefficients, exact, points, true), 0.01) << g;
    }
  }
}

}  // namespace
}  // namespace tirefem
