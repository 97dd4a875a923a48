// Reports of a rolling result, on a hand-made result: a half model's tread points on an (s, φ) grid with a
// 2-line × 6-point contact patch whose points stick first, then slip; no solver runs.
#include "tirefem/report/rolling_report.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>

#include <unistd.h>

#include "tirefem/io/json_summary.hpp"

namespace tirefem {
namespace {
namespace fs = std::filesystem;

constexpr double kDegree = 180.0 / std::numbers::pi;
constexpr int kColumns = 6, kRows = 14;  // tread point grid: s = 1.5 (i + 0.5), φ = 0.01 (j − 6.5)
constexpr double kWeight = 2.0;          // mm² per point

bool in_contact(int i, int j) { return i < 2 && j >= 4 && j <= 9; }
// Line 0 slips from row 7 on, line 1 from row 8 on.
bool slips(int i, int j) { return in_contact(i, j) && j >= 7 + i; }
double qy_of(int i, int j) { return in_contact(i, j) ? 0.01 * j + 0.001 * i : 0.0; }

RollingStateResult state(const std::string& name, RollingStateSpec::Kind kind, std::optional<double> slip,
                         std::optional<double> radius, bool converged = true) {
  RollingStateResult s;
  s.spec.kind = kind;
  s.name = name;
  s.converged = converged;
  if (!converged) s.failure = "no convergence";
  s.slip = slip;
  s.rolling_radius_mm = radius;
  s.figures.Qz_N = 3700.0;
  s.figures.Qy_N = 1000.0 * slip.value_or(1.0);
  s.figures.Mx_Nmm = -50.0;
  s.figures.contact_area_mm2 = 12000.0;
  s.figures.stick_area_fraction = 0.5;
  s.figures.max_traction_MPa = 0.15;
  s.counts = {3, 17, 18, 2, 1.5};
  for (int j = 0; j < kRows; ++j)
    for (int i = 0; i < kColumns; ++i) {
      TreadPointState n;
      const double phi = 0.01 * (j - 6.5);
      n.position = Eigen::Vector3d(1.5 * (i + 0.5), 280.0 * std::sin(phi), 280.0 * (1 - std::cos(phi)));
      n.penetration = in_contact(i, j) ? 0.1 : -0.5 - 0.01 * i;
      n.pressure = std::max(n.penetration, 0.0) * 2.0;
      TreadTraction t;
      t.status = !in_contact(i, j) ? TreadContact::out
                 : slips(i, j)     ? TreadContact::slip
                                   : TreadContact::stick;
      t.force = Eigen::Vector3d(0.5, qy_of(i, j) * kWeight, 0.0);
      t.traction = -qy_of(i, j);  // the support moves in −y
      t.shear = in_contact(i, j) ? 0.1 * j : 0.0;
      s.normal.push_back(n);
      s.tangential.push_back(t);
    }
  return s;
}

RollingResult rolling(bool half = true) {
  RollingResult r;
  r.name = "rolling_3700N";
  r.support.kind = SupportDescription::Kind::drum;
  r.support.drum_diameter = 1830.0;
  r.friction = 0.7;
  r.half_model = half;
  r.completed = true;
  r.footprint.target_Qz_N = 3700.0;
  r.deflection_mm = 21.5;
  r.loaded_radius_mm = 268.5;
  r.effective_rolling_radius_mm = 280.0;
  r.slip_stiffness_N = 52000.0;
  for (int j = 0; j < kRows; ++j)
    for (int i = 0; i < kColumns; ++i) {
      TreadPoint p;
      p.u = 1.5 * (i + 0.5);
      p.v = 0.01 * (j - 6.5);
      p.weight = kWeight;
      r.tread_points.push_back(p);
    }
  r.states = {state("free", RollingStateSpec::Kind::free, 0.0, 280.0),
              state("spin", RollingStateSpec::Kind::full_slip, std::nullopt, 0.0),
              state("lock", RollingStateSpec::Kind::full_slip, -1.0, std::nullopt),
              state("brake", RollingStateSpec::Kind::given_slip, -0.05, 280.0 / 0.95, false)};
  r.states[2].spec.braking = true;
  for (int k = 0; k < 3; ++k) {
    SweepPoint p;
    p.slip = -0.02 + 0.02 * k;
    p.rolling_radius_mm = 280.0 / (1 + p.slip);
    p.figures.Qz_N = k == 2 ? 0.0 : 3700.0 + k;
    p.figures.Qy_N = 50000.0 * p.slip;
    p.counts = {2, 5 + k, 6 + k, 1, 0.5};
    r.sweep.push_back(p);
  }
  return r;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string s;
  for (const auto& l : lines) s += l + "\n";
  return s;
}

TEST(RollingReport, KindNames) {
  EXPECT_EQ(rolling_state_kind_name(RollingStateSpec::Kind::free), "free");
  EXPECT_EQ(rolling_state_kind_name(RollingStateSpec::Kind::given_slip), "given_slip");
  EXPECT_EQ(rolling_state_kind_name(RollingStateSpec::Kind::given_radius), "given_radius");
  EXPECT_EQ(rolling_state_kind_name(RollingStateSpec::Kind::full_stick), "full_stick");
  EXPECT_EQ(rolling_state_kind_name(RollingStateSpec::Kind::full_slip), "full_slip");
}

TEST(RollingReport, StatesTableMarksUndefinedAndFailedValuesNaN) {
  const CsvTable t = rolling_states_table(rolling());
  EXPECT_EQ(t.columns,
            (std::vector<std::string>{"state", "slip", "rolling_radius_mm", "loaded_radius_mm", "Qz_N",
                                      "Qy_N", "Mx_Nmm", "stick_area_fraction", "contact_area_mm2",
                                      "max_traction_MPa", "contact_iterations", "newton_iterations",
                                      "factorizations", "solves", "time_s", "converged", "slip_angle_deg",
                                      "camber_deg", "Fx_N", "Fy_N", "Fz_N", "Mz_Nmm", "overturning_moment_Nmm",
                                      "pneumatic_trail_mm", "flange_axial_force_N", "flange_contact_fraction"}));
  ASSERT_EQ(t.rows.size(), 4u);
  const std::vector<double> first(t.rows[0].begin(), t.rows[0].begin() + 23);
  EXPECT_EQ(first, (std::vector<double>{0, 0, 280, 268.5, 3700, 0, -50, 0.5, 12000, 0.15, 3, 17, 18, 2, 1.5, 1,
                                        0, 0, 0, 0, 0, 0, 0}));
  EXPECT_TRUE(std::isnan(t.rows[0][23]));  // no lateral force: no trail
  EXPECT_EQ(t.rows[1][0], 4.0);
  EXPECT_TRUE(std::isnan(t.rows[1][1]));  // spinning: no slip
  EXPECT_EQ(t.rows[1][2], 0.0);
  EXPECT_EQ(t.rows[2][1], -1.0);
  EXPECT_TRUE(std::isnan(t.rows[2][2]));  // locked: no Rk
  const auto& failed = t.rows[3];
  EXPECT_EQ(failed[0], 1.0);
  EXPECT_EQ(failed[1], -0.05);
  EXPECT_EQ(failed[3], 268.5);
  for (int c = 4; c <= 9; ++c) EXPECT_TRUE(std::isnan(failed[c])) << t.columns[c];
  for (int c = 18; c <= 23; ++c) EXPECT_TRUE(std::isnan(failed[c])) << t.columns[c];
  EXPECT_EQ(failed[11], 17.0);
  EXPECT_EQ(failed[15], 0.0);
  for (const auto& row : t.rows) EXPECT_EQ(row.size(), t.columns.size());
  const std::string c = joined(t.comments);
  for (const char* text :
       {"rolling_3700N", "drum 1830 mm", "mu = 0.7", "travel +y", "deflection 21.5 mm", "Re = 280 mm",
        "52000 N", "nan", "row 1: 'free' (free", "row 2: 'spin' (full_slip, spinning",
        "row 3: 'lock' (full_slip, locked", "row 4: 'brake' (given_slip", "not converged, no convergence"})
    EXPECT_NE(c.find(text), std::string::npos) << text << "\n" << c;
}

TEST(RollingReport, SweepTableAndPlot) {
  const RollingResult r = rolling();
  const CsvTable t = slip_sweep_table(r);
  EXPECT_EQ(t.columns, (std::vector<std::string>{"slip", "rolling_radius_mm", "deflection_mm", "Qz_N", "Qy_N",
                                                 "Mx_Nmm", "Qy_over_Qz", "stick_area_fraction", "contact_iterations",
                                                 "newton_iterations", "factorizations", "time_s",
                                                 "flange_axial_force_N", "flange_contact_fraction"}));
  ASSERT_EQ(t.rows.size(), 3u);
  EXPECT_EQ(t.rows[0][0], -0.02);
  EXPECT_EQ(t.rows[0][2], r.sweep[0].deflection_mm);
  EXPECT_DOUBLE_EQ(t.rows[0][6], -1000.0 / 3700.0);
  EXPECT_TRUE(std::isnan(t.rows[2][6]));  // Qz = 0
  EXPECT_EQ(t.rows[1][9], 6.0);

  const Plot p = slip_sweep_plot(r);
  ASSERT_EQ(p.series.size(), 2u);
  EXPECT_EQ(p.series[0].x, (std::vector<double>{-0.02, 0.0, 0.02}));
  EXPECT_EQ(p.series[0].y, (std::vector<double>{-1000.0, 0.0, 1000.0}));
  EXPECT_EQ(p.series[1].title, "±μ Qz");
  ASSERT_EQ(p.series[1].y.size(), 7u);  // +μ Qz, a gap, −μ Qz
  EXPECT_DOUBLE_EQ(p.series[1].y[1], 0.7 * 3701.0);
  EXPECT_TRUE(std::isnan(p.series[1].x[3]) && std::isnan(p.series[1].y[3]));
  EXPECT_DOUBLE_EQ(p.series[1].y[4], -0.7 * 3700.0);
  EXPECT_NE(p.series[1].style.find("dt 2"), std::string::npos);

  RollingResult none = r;
  none.sweep.clear();
  for (const auto& s : slip_sweep_plot(none).series) EXPECT_TRUE(s.x.empty());
}

TEST(RollingReport, TreadTableListsTheWindow) {
  const RollingResult r = rolling();
  const CsvTable t = rolling_tread_table(r, r.states[0]);
  EXPECT_EQ(t.columns, (std::vector<std::string>{"s_mm", "phi_deg", "x_mm", "y_mm", "z_mm", "pressure_MPa",
                                                 "traction_MPa", "qy_MPa", "shear_mm", "status"}));
  // Columns 0..1 + 3, rows 4..9 ± 3: 5 × 12 of the model's own points.
  ASSERT_EQ(t.rows.size(), 60u);
  int stick = 0, slip = 0;
  for (std::size_t k = 0; k < t.rows.size(); ++k) {
    const auto& row = t.rows[k];
    const int i = static_cast<int>(std::lround(row[0] / 1.5 - 0.5));
    const int j = static_cast<int>(std::lround(row[1] / kDegree / 0.01 + 6.5));
    EXPECT_EQ(k, static_cast<std::size_t>((j - 1) * 5 + i));  // by φ, then s
    EXPECT_NEAR(row[7], qy_of(i, j), 1e-15);
    EXPECT_NEAR(row[6], -qy_of(i, j), 1e-15);
    EXPECT_EQ(row[9], !in_contact(i, j) ? 0.0 : slips(i, j) ? 2.0 : 1.0);
    EXPECT_EQ(row[5], in_contact(i, j) ? 0.2 : 0.0);
    stick += row[9] == 1.0, slip += row[9] == 2.0;
  }
  EXPECT_EQ(stick, 7);
  EXPECT_EQ(slip, 5);

  RollingStateResult broken = r.states[0];
  broken.tangential.pop_back();
  EXPECT_THROW(rolling_tread_table(r, broken), std::invalid_argument);
  EXPECT_THROW(traction_map_s_phi(r, broken), std::invalid_argument);
  EXPECT_THROW(tread_points_vtu(r, broken), std::invalid_argument);
}

TEST(RollingReport, TractionMapMirrorsAndMarksSlip) {
  const RollingResult r = rolling();
  const HeatMap m = traction_map_s_phi(r, r.states[0]);
  ASSERT_EQ(m.x.size(), 10u);  // 5 columns and their mirror images
  ASSERT_EQ(m.y.size(), 12u);
  EXPECT_DOUBLE_EQ(m.x.front(), -6.75);
  EXPECT_DOUBLE_EQ(m.x.back(), 6.75);
  EXPECT_NEAR(m.y.front(), 0.01 * (1 - 6.5) * kDegree, 1e-12);
  for (std::size_t iy = 0; iy < m.y.size(); ++iy)
    for (std::size_t ix = 0; ix < m.x.size(); ++ix) {
      const int i = static_cast<int>(std::lround(std::abs(m.x[ix]) / 1.5 - 0.5)),
                j = static_cast<int>(iy) + 1;
      EXPECT_NEAR(m.values[iy][ix], qy_of(i, j), 1e-15);
      EXPECT_EQ(m.values[iy][ix], m.values[iy][m.x.size() - 1 - ix]);
    }
  ASSERT_EQ(m.overlays.size(), 1u);
  const PlotSeries& slip = m.overlays[0];
  EXPECT_EQ(slip.title, "slip");
  EXPECT_NE(slip.style.find("pt 7"), std::string::npos);
  ASSERT_EQ(slip.x.size(), 10u);  // 5 slipping points, each twice
  for (std::size_t k = 0; k < slip.x.size(); ++k) {
    const int i = static_cast<int>(std::lround(std::abs(slip.x[k]) / 1.5 - 0.5));
    const int j = static_cast<int>(std::lround(slip.y[k] / kDegree / 0.01 + 6.5));
    EXPECT_TRUE(slips(i, j)) << slip.x[k] << ", " << slip.y[k];
  }

  const HeatMap full = traction_map_s_phi(rolling(false), r.states[0]);  // not mirrored
  EXPECT_EQ(full.x.size(), 5u);
  EXPECT_EQ(full.overlays[0].x.size(), 5u);
}

TEST(RollingReport, TractionMapRendersWithOverlays) {
  if (std::system("command -v gnuplot > /dev/null 2>&1") != 0) GTEST_SKIP() << "gnuplot is not on PATH";
  const fs::path dir = fs::temp_directory_path() / ("tirefem_rolling_report_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const RollingResult r = rolling();
  EXPECT_TRUE(write_heatmap(dir / "traction", traction_map_s_phi(r, r.states[0])));
  EXPECT_GT(fs::file_size(dir / "traction.png"), 1000u);
  EXPECT_GT(fs::file_size(dir / "traction.svg"), 1000u);
  std::ifstream gp(dir / "traction.gp");
  const std::string script(std::istreambuf_iterator<char>(gp), {});
  EXPECT_NE(script.find("title 'slip'"), std::string::npos) << script;
  fs::remove_all(dir);
}

TEST(RollingReport, TreadPointsVtuIsAPointCloud) {
  const RollingResult r = rolling();
  const VtuMesh v = tread_points_vtu(r, r.states[0]);
  const std::size_t n = kColumns * kRows;
  ASSERT_EQ(v.points.size(), n);
  EXPECT_TRUE(v.quads.empty());
  ASSERT_EQ(v.vertices.size(), n);
  EXPECT_EQ(v.vertices[17], 17);
  EXPECT_EQ(v.points[7], r.states[0].normal[7].position);
  ASSERT_EQ(v.point_scalars.size(), 5u);
  const std::vector<std::string> names{"pressure_MPa", "traction_MPa", "qy_MPa", "shear_mm", "status"};
  for (std::size_t k = 0; k < names.size(); ++k) {
    EXPECT_EQ(v.point_scalars[k].first, names[k]);
    EXPECT_EQ(v.point_scalars[k].second.size(), n);
  }
  const int p = 8 * kColumns + 1;  // i = 1, j = 8: slipping
  EXPECT_NEAR(v.point_scalars[2].second[p], qy_of(1, 8), 1e-15);
  EXPECT_EQ(v.point_scalars[3].second[p], 0.8);
  EXPECT_EQ(v.point_scalars[4].second[p], 2.0);
  const fs::path file =
      fs::temp_directory_path() / ("tirefem_rolling_" + std::to_string(::getpid()) + ".vtu");
  EXPECT_NO_THROW(write_vtu(file, v));
  fs::remove(file);
}

TEST(RollingReport, SummaryKeys) {
  RollingResult r = rolling();
  toml::table s = rolling_summary(r);
  EXPECT_EQ(s["name"].value<std::string>(), "rolling_3700N");
  EXPECT_EQ(s["support"].value<std::string>(), "drum");
  EXPECT_EQ(s["drum_diameter_mm"].value<double>(), 1830.0);
  EXPECT_EQ(s["friction"].value<double>(), 0.7);
  EXPECT_EQ(s["travel"].value<std::string>(), "+y");
  EXPECT_EQ(s["completed"].value<bool>(), true);
  EXPECT_FALSE(s.contains("failure"));
  EXPECT_EQ(s["target_Qz_N"].value<double>(), 3700.0);
  EXPECT_EQ(s["deflection_mm"].value<double>(), 21.5);
  EXPECT_EQ(s["loaded_radius_mm"].value<double>(), 268.5);
  EXPECT_EQ(s["effective_rolling_radius_mm"].value<double>(), 280.0);
  EXPECT_EQ(s["slip_stiffness_N"].value<double>(), 52000.0);
  const toml::array& states = *s["states"].as_array();
  ASSERT_EQ(states.size(), 4u);
  const toml::table& free = *states[0].as_table();
  EXPECT_EQ(free["state"].value<std::string>(), "free");
  EXPECT_EQ(free["slip"].value<double>(), 0.0);
  EXPECT_EQ(free["Qz_N"].value<double>(), 3700.0);
  EXPECT_EQ(free["contact_area_mm2"].value<double>(), 12000.0);
  EXPECT_EQ(free["newton_iterations"].value<int64_t>(), 17);
  EXPECT_EQ(free["converged"].value<bool>(), true);
  EXPECT_FALSE(free.contains("failure"));
  EXPECT_FALSE(states[1].as_table()->contains("slip"));
  EXPECT_FALSE(states[2].as_table()->contains("rolling_radius_mm"));
  const toml::table& failed = *states[3].as_table();
  EXPECT_EQ(failed["converged"].value<bool>(), false);
  EXPECT_EQ(failed["failure"].value<std::string>(), "no convergence");
  EXPECT_FALSE(failed.contains("Qz_N"));
  EXPECT_EQ(failed["slip"].value<double>(), -0.05);
  const toml::array& sweep = *s["sweep"].as_array();
  ASSERT_EQ(sweep.size(), 3u);
  EXPECT_EQ((*sweep[2].as_table())["Qy_N"].value<double>(), 1000.0);
  EXPECT_EQ((*sweep[1].as_table())["factorizations"].value<int64_t>(), 7);
  const fs::path file =
      fs::temp_directory_path() / ("tirefem_rolling_" + std::to_string(::getpid()) + ".json");
  EXPECT_NO_THROW(write_json(file, s));  // nothing NaN
  fs::remove(file);

  r.support.kind = SupportDescription::Kind::plane;
  r.reverse = true;
  r.completed = false;
  r.failure = "free rolling not found";
  r.footprint.target_Qz_N.reset();
  r.effective_rolling_radius_mm.reset();
  r.slip_stiffness_N.reset();
  r.sweep.clear();
  s = rolling_summary(r);
  EXPECT_EQ(s["travel"].value<std::string>(), "-y");
  EXPECT_EQ(s["failure"].value<std::string>(), "free rolling not found");
  for (const char* key :
       {"drum_diameter_mm", "target_Qz_N", "effective_rolling_radius_mm", "slip_stiffness_N", "sweep"})
    EXPECT_FALSE(s.contains(key)) << key;
}

// A full model's two flanges: each state's summary lists them, its table row carries the larger axial
// force and the smaller contact fraction; without flanges there is neither key nor figure.
TEST(RollingReport, RimFlangeLoads) {
  RollingResult r = rolling(false);
  RimFlangeLoad left{-1, 2000.0, 150.0, 0.8, 1.0}, right{1, 2500.0, 90.0, 0.6, 0.75};
  // Named by the W-axis side of the travel: forward, +Y (left) is x < 0; reversed, x > 0.
  EXPECT_EQ(rim_flange_side(left, false, false), "left");
  EXPECT_EQ(rim_flange_side(right, false, false), "right");
  EXPECT_EQ(rim_flange_side(right, false, true), "left");
  EXPECT_EQ(rim_flange_side(right, true, false), "each");
  const RollingFigures mirror = mirrored_figures(RollingFigures{.rim_flanges = {{"left", left}}});
  EXPECT_EQ(mirror.rim_flanges[0].side, "right");
  EXPECT_EQ(mirror.rim_flanges[0].load.side, 1);
  r.states[0].figures.rim_flanges = {{"left", left}, {"right", right}};
  r.sweep[0].figures.rim_flanges = r.states[0].figures.rim_flanges;
  const toml::table s = rolling_summary(r);
  const toml::table& free = *(*s["states"].as_array())[0].as_table();
  const toml::array& flanges = *free["rim_flanges"].as_array();
  ASSERT_EQ(flanges.size(), 2u);
  const toml::table& second = *flanges[1].as_table();
  EXPECT_EQ(second["side"].value<std::string>(), "right");
  EXPECT_EQ(second["axial_force_N"].value<double>(), 2500.0);
  EXPECT_EQ(second["radial_force_N"].value<double>(), 90.0);
  EXPECT_EQ(second["peak_pressure_MPa"].value<double>(), 0.6);
  EXPECT_EQ(second["contact_fraction"].value<double>(), 0.75);
  EXPECT_FALSE((*(*s["states"].as_array())[1].as_table()).contains("rim_flanges"));
  EXPECT_TRUE((*(*s["sweep"].as_array())[0].as_table()).contains("rim_flanges"));

  const CsvTable t = rolling_states_table(r);
  const auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(t.columns.begin(), t.columns.end(), name) - t.columns.begin());
  };
  ASSERT_LT(column("flange_axial_force_N"), t.columns.size());
  ASSERT_LT(column("flange_contact_fraction"), t.columns.size());
  EXPECT_EQ(t.rows[0][column("flange_axial_force_N")], 2500.0);
  EXPECT_EQ(t.rows[0][column("flange_contact_fraction")], 0.75);
  EXPECT_TRUE(std::isnan(t.rows[1][column("flange_axial_force_N")])) << "no flange: no figure";
  const CsvTable sweep = slip_sweep_table(r);
  EXPECT_EQ(sweep.rows[0][sweep.columns.size() - 2], 2500.0);
  EXPECT_TRUE(std::isnan(sweep.rows[1].back()));
}

}  // namespace
}  // namespace tirefem
