// The virtual rig's measurement table (analysis/tyre_test.cpp, results/tyre_test_report.cpp): the rolling
// results of each load become rows in SI units and W-axis signs, with the radius of each held-load point,
// and a load whose study failed is named, not silently dropped.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "tirefem/analysis/tyre_test.hpp"
#include "tirefem/report/tyre_test_report.hpp"

namespace tirefem {
namespace {

RollingFigures figures(double fx, double fy, double fz, double mz_nmm, double mx_nmm) {
  RollingFigures f;
  f.Fx_N = fx, f.Fy_N = fy, f.Fz_N = fz;
  f.aligning_moment_Nmm = mz_nmm;
  f.overturning_moment_Nmm = mx_nmm;
  return f;
}

// One load's rolling result: footprint at δz = 20 mm (Rd 265 mm), free rolling, one κ point held at a
// deflection 0.5 mm smaller, one α point held at 0.25 mm more.
RollingResult load_result(double fz) {
  RollingResult r;
  r.completed = true;
  LoadPoint p;
  p.deflection_mm = 20.0;
  p.patch.Qz_N = fz;
  p.patch.patch_length_mm = 150.0;
  p.patch.patch_width_mm = 120.0;
  r.footprint.points = {p};
  r.footprint.completed = true;
  r.deflection_mm = 20.0;
  r.loaded_radius_mm = 265.0;
  r.effective_rolling_radius_mm = 280.0;
  r.slip_stiffness_N = 60000.0;
  r.cornering_stiffness_N_per_deg = -700.0;
  RollingStateResult free;
  free.converged = true;
  free.slip = 0.0;
  free.figures = figures(0.0, 0.0, fz, 0.0, 0.0);
  free.counts.newton_iterations = 5;
  r.states = {free};
  SweepPoint k;
  k.slip = -0.05, k.deflection_mm = 19.5, k.figures = figures(-2000.0, 0.0, fz, 0.0, 0.0);
  r.sweep = {k};
  SweepPoint a;
  a.slip_angle_deg = 2.0, a.deflection_mm = 20.25, a.figures = figures(-10.0, -900.0, fz, 15000.0, 4000.0);
  a.counts.factorizations = 3;
  r.angle_sweep = {a};
  return r;
}

TEST(TyreTestReport, RowsInSiUnitsAndWAxisSigns) {
  TyreTestStudy s;
  s.name = "rig";
  s.nominal_load = 4000.0;
  s.load_factors = {1.0};
  const RollingResult r = load_result(4000.0);
  const TyreTestResult t = assemble_tyre_test(s, 285.0, {{{&r}, {""}}}, std::nullopt, "");
  EXPECT_TRUE(t.completed);
  ASSERT_EQ(t.rows.size(), 3u);
  const CsvTable table = tyre_test_table(t);
  ASSERT_EQ(table.columns.size(), 17u);
  const std::vector<std::string> first{"FZ", "KAPPA", "ALPHA", "GAMMA", "FX", "FY", "MZ", "MX"};
  EXPECT_EQ(std::vector<std::string>(table.columns.begin(), table.columns.begin() + 8), first);
  const auto col = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(table.columns.begin(), table.columns.end(), name) - table.columns.begin());
  };
  ASSERT_EQ(table.rows.size(), 3u);
  const auto& kappa_row = table.rows[1];
  EXPECT_EQ(kappa_row[col("KAPPA")], -0.05);
  EXPECT_EQ(kappa_row[col("FX")], -2000.0);
  EXPECT_DOUBLE_EQ(kappa_row[col("RL")], 0.2655);  // 0.5 mm less deflection: the axle 0.5 mm higher
  EXPECT_DOUBLE_EQ(kappa_row[col("RE")], 0.280);
  EXPECT_EQ(kappa_row[col("SERIES")], 1.0);
  const auto& alpha_row = table.rows[2];
  EXPECT_DOUBLE_EQ(alpha_row[col("ALPHA")], 2.0 * std::numbers::pi / 180.0);
  EXPECT_EQ(alpha_row[col("FY")], -900.0);
  EXPECT_DOUBLE_EQ(alpha_row[col("MZ")], 15.0);  // N·mm → N·m
  EXPECT_DOUBLE_EQ(alpha_row[col("MX")], 4.0);
  EXPECT_DOUBLE_EQ(alpha_row[col("RL")], 0.26475);
  EXPECT_DOUBLE_EQ(alpha_row[col("PATCH_LENGTH")], 0.150);
  EXPECT_DOUBLE_EQ(alpha_row[col("PATCH_WIDTH")], 0.120);
  EXPECT_EQ(alpha_row[col("FACTORIZATIONS")], 3.0);
  EXPECT_EQ(alpha_row[col("SERIES")], 2.0);
  EXPECT_EQ(table.rows[0][col("NEWTON_ITERATIONS")], 5.0);
}

TEST(TyreTestReport, AFailedLoadIsNamedAndTheRestKept) {
  TyreTestStudy s;
  s.name = "rig";
  s.nominal_load = 4000.0;
  s.load_factors = {0.5, 1.0};
  RollingResult r = load_result(4000.0);
  r.completed = false;
  r.failure = "α sweep κ +0.0000, α +6°: Newton: residual 1e-3";
  const TyreTestResult t =
      assemble_tyre_test(s, 285.0, {{{nullptr}, {"tyre test 'rig_Fz2000' failed: singular"}}, {{&r}, {""}}},
                         std::nullopt, "");
  EXPECT_FALSE(t.completed);
  ASSERT_EQ(t.failures.size(), 2u);
  EXPECT_NE(t.failures[0].find("load 2000 N: tyre test 'rig_Fz2000' failed: singular"), std::string::npos);
  EXPECT_NE(t.failures[1].find("load 4000 N: α sweep"), std::string::npos);
  EXPECT_EQ(t.rows.size(), 3u);  // the converged points of the second load
  const toml::table summary = tyre_test_summary(t);
  EXPECT_EQ(summary["completed"].value<bool>(), false);
  EXPECT_EQ(summary["loads"].as_array()->size(), 2u);
}

// The two series of a load (tyre_test_rolling_study) make one load: the longitudinal series' rows, then
// the lateral ones; Re and the slip stiffness from the first, the cornering stiffness from the second; a
// failed lateral series fails the load and keeps the longitudinal rows.
TEST(TyreTestReport, TheTwoSeriesOfALoadMakeOneLoad) {
  TyreTestStudy s;
  s.name = "rig";
  s.nominal_load = 4000.0;
  s.load_factors = {1.0};
  RollingResult longitudinal = load_result(4000.0);
  longitudinal.angle_sweep.clear();
  longitudinal.cornering_stiffness_N_per_deg.reset();
  RollingResult lateral = load_result(4000.0);
  lateral.states.clear();
  lateral.sweep.clear();
  lateral.effective_rolling_radius_mm = 281.0;  // solved alike in both: the first series' is taken
  lateral.cornering_stiffness_N_per_deg = -750.0;
  lateral.pneumatic_trail_at_zero_mm = 30.0;
  TyreTestResult t = assemble_tyre_test(s, 285.0, {{{&longitudinal, &lateral}, {"", ""}}}, std::nullopt, "");
  EXPECT_TRUE(t.completed);
  ASSERT_EQ(t.rows.size(), 3u);
  EXPECT_EQ(t.rows[0].kind, TyreTestRow::Kind::free);
  EXPECT_EQ(t.rows[1].kind, TyreTestRow::Kind::slip_sweep);
  EXPECT_EQ(t.rows[2].kind, TyreTestRow::Kind::angle_sweep);
  EXPECT_DOUBLE_EQ(t.rows[2].effective_radius_m, 0.280);
  ASSERT_EQ(t.loads.size(), 1u);
  EXPECT_EQ(t.loads[0].effective_rolling_radius_mm, 280.0);
  EXPECT_EQ(t.loads[0].slip_stiffness_N, 60000.0);
  EXPECT_EQ(t.loads[0].cornering_stiffness_N_per_deg, -750.0);
  EXPECT_EQ(t.loads[0].pneumatic_trail_mm, 30.0);
  // No standing stiffness measured: no relaxation lengths; the loads table says nan, the plot has nothing.
  EXPECT_FALSE(t.loads[0].longitudinal_relaxation_length_mm || t.loads[0].lateral_relaxation_length_mm);
  EXPECT_TRUE(std::isnan(tyre_test_loads_table(t).rows.at(0).back()));
  EXPECT_TRUE(tyre_test_relaxation_plot(t).series.empty());
  // The lateral series measured it (full model): σκ = Kxκ/Cx, σα = |Kyα| (per radian)/Cy, in the table.
  StandingStiffness c;
  c.longitudinal_N_per_mm = 200.0;
  c.lateral_N_per_mm = 100.0;
  c.yaw_Nmm_per_rad = 2e6;
  lateral.standing_stiffness = c;
  t = assemble_tyre_test(s, 285.0, {{{&longitudinal, &lateral}, {"", ""}}}, std::nullopt, "");
  EXPECT_EQ(t.loads[0].longitudinal_stiffness_N_per_mm, 200.0);
  EXPECT_DOUBLE_EQ(*t.loads[0].longitudinal_relaxation_length_mm, 60000.0 / 200.0);
  EXPECT_DOUBLE_EQ(*t.loads[0].lateral_relaxation_length_mm, 750.0 * 180.0 / std::numbers::pi / 100.0);
  const CsvTable loads = tyre_test_loads_table(t);
  ASSERT_EQ(loads.rows.size(), 1u);
  EXPECT_DOUBLE_EQ(loads.rows[0].back(), *t.loads[0].lateral_relaxation_length_mm);
  EXPECT_NEAR(loads.rows[0][12], 2e3 * std::numbers::pi / 180.0, 1e-12);  // yaw, N·m per degree
  EXPECT_EQ(tyre_test_relaxation_plot(t).series.size(), 2u);  // the points, without a fit

  t = assemble_tyre_test(s, 285.0, {{{&longitudinal, nullptr}, {"", "tyre test 'rig_Fz4000_alpha' failed: singular"}}},
                         std::nullopt, "");
  EXPECT_FALSE(t.completed);
  EXPECT_FALSE(t.loads[0].completed);
  ASSERT_EQ(t.failures.size(), 1u);
  EXPECT_NE(t.failures[0].find("load 4000 N: tyre test 'rig_Fz4000_alpha' failed"), std::string::npos);
  EXPECT_EQ(t.rows.size(), 2u);
  EXPECT_FALSE(t.loads[0].cornering_stiffness_N_per_deg);
}

TEST(TyreTestReport, PointCountAndStudiesPerLoad) {
  TyreTestStudy s;
  s.name = "rig";
  s.nominal_load = 3000.0;
  s.cambers_deg = {2.0};
  EXPECT_EQ(tyre_test_points(s), 3 * (2 + 1 + 15 + 15));  // free rolling in each series
  MeshSettings full;
  full.half_model = false;
  full.circumferential_elements = 64;
  const MeshSettings half = tyre_test_half_mesh(full);
  EXPECT_TRUE(half.half_model);
  EXPECT_EQ(half.circumferential_elements, 64);
  // A tyre that is not its own mirror image: both series on the full model, the cambered state in the
  // longitudinal one.
  const RollingStudy r = tyre_test_rolling_study(s, 2, TyreTestSeries::longitudinal, full);
  EXPECT_EQ(r.name, "rig_Fz4500");
  EXPECT_EQ(r.target_load, 4500.0);
  ASSERT_EQ(r.states.size(), 2u);
  EXPECT_EQ(r.states[1].camber_deg, 2.0);
  ASSERT_TRUE(r.sweep && !r.angle_sweep);
  EXPECT_TRUE(r.sweep->hold_load);
  EXPECT_EQ(r.tread_shear, RollingStudy::TreadShear::planar);
  ASSERT_TRUE(r.mesh);
  EXPECT_FALSE(r.mesh->half_model);
  const RollingStudy a = tyre_test_rolling_study(s, 2, TyreTestSeries::lateral, full);
  EXPECT_EQ(a.name, "rig_Fz4500_alpha");
  EXPECT_EQ(a.target_load, 4500.0);
  EXPECT_TRUE(a.states.empty());  // its free rolling is the longitudinal series' row
  ASSERT_TRUE(a.angle_sweep && !a.sweep);
  EXPECT_TRUE(a.angle_sweep->hold_load && a.angle_sweep->mirror_negative_angles);
  EXPECT_EQ(a.tread_shear, RollingStudy::TreadShear::planar);
  ASSERT_TRUE(a.mesh);
  EXPECT_FALSE(a.mesh->half_model);
  // Its own mirror image: the longitudinal series on the half model, the cambered state moved to the
  // lateral series on the full one.
  const RollingStudy rh =
      tyre_test_rolling_study(s, 2, TyreTestSeries::longitudinal, full, TyreTestLongitudinalModel::half);
  ASSERT_TRUE(rh.mesh);
  EXPECT_TRUE(rh.mesh->half_model);
  EXPECT_EQ(rh.mesh->circumferential_elements, 64);
  ASSERT_EQ(rh.states.size(), 1u);
  EXPECT_EQ(rh.states[0].camber_deg, 0.0);
  ASSERT_TRUE(rh.sweep);
  EXPECT_EQ(rh.tread_shear, RollingStudy::TreadShear::planar);
  const RollingStudy ah =
      tyre_test_rolling_study(s, 2, TyreTestSeries::lateral, full, TyreTestLongitudinalModel::half);
  ASSERT_TRUE(ah.mesh);
  EXPECT_FALSE(ah.mesh->half_model);
  ASSERT_EQ(ah.states.size(), 1u);
  EXPECT_EQ(ah.states[0].camber_deg, 2.0);
  ASSERT_TRUE(ah.angle_sweep);
}

// The time left is estimated from the share of the expected work done (TyreTestProgress): a point's work
// grows with its load, a half-model point costs a quarter, a mirror image nothing.
TEST(TyreTestProgress, ShareOfWorkFollowsLoadModelAndMirrorImages) {
  TyreTestStudy s;  // loads 0.5, 1, 1.5 × FNOMIN; 15 slips, 15 angles (7 of them mirror images)
  s.name = "rig";
  TyreTestProgress p(s, TyreTestLongitudinalModel::half);
  EXPECT_EQ(p.work_done(), 0.0);
  const auto finish = [&](std::size_t load, TyreTestSeries series, int points) {
    const double before = p.work_done();
    for (int k = 0; k < points; ++k) p.point_done(load, series);
    return p.work_done() - before;
  };
  using enum TyreTestSeries;
  // The first point of a series (footprint and free rolling) counts three; then, per solved point:
  const double first_heavy = finish(2, lateral, 1);
  const double alpha_heavy = finish(2, lateral, 1);  // α = 0
  EXPECT_NEAR(first_heavy, 3 * alpha_heavy, 1e-12);
  EXPECT_NEAR(finish(2, lateral, 7), 7 * alpha_heavy, 1e-12);  // the other 7 of the 8 angles ≥ 0
  EXPECT_EQ(finish(2, lateral, 7), 0.0);                       // the 7 mirror images
  finish(1, lateral, 1);
  const double alpha_nominal = finish(1, lateral, 1);
  EXPECT_NEAR(alpha_heavy, std::pow(1.5, 1.5) * alpha_nominal, 1e-12);
  finish(2, longitudinal, 1);
  const double kappa_heavy = finish(2, longitudinal, 1);  // on the half model
  EXPECT_NEAR(kappa_heavy, 0.25 * alpha_heavy, 1e-12);
  // Every point of the test done: all the work.
  finish(1, lateral, 14);
  finish(2, longitudinal, 14);
  for (const std::size_t load : {0, 1}) finish(load, longitudinal, 16);
  finish(0, lateral, 16);
  EXPECT_NEAR(p.work_done(), 1.0, 1e-12);
  // A tyre that is not its own mirror image: every angle solved, the κ series on the full model.
  TyreTestProgress full(s, TyreTestLongitudinalModel::full);
  for (int k = 0; k < 16; ++k) full.point_done(2, lateral);
  for (int k = 0; k < 16; ++k) full.point_done(2, longitudinal);
  const double heavy = full.work_done();
  EXPECT_NEAR(heavy, 2 * std::pow(1.5, 1.5) / (2 * (std::pow(0.5, 1.5) + 1 + std::pow(1.5, 1.5))), 1e-12);
}

}  // namespace
}  // namespace tirefem
