// Reports of a static contact result, on hand-made results (a grid of tread points carrying a known
// elliptic pressure field) and on a coarse mesh of the example tyre.
#include "tirefem/report/footprint_report.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tirefem/case/case_reader.hpp"
#include "tirefem/report/inflation_report.hpp"

namespace tirefem {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kQ0 = 0.3, kA = 40.0, kB = 60.0, kR = 280.0;

// q = q0 (1 − (x/a)² − (y/b)²)₊, the pressure field the synthetic results carry.
double ellipse(double x, double y) {
  return kQ0 * std::max(0.0, 1.0 - (x / kA) * (x / kA) - (y / kB) * (y / kB));
}

// Tread points on a (u, v) grid: u = s every 1.5 mm (a half model: s > 0 only), v = φ every 0.005 rad
// over ±0.3; current position x = s + skew·y, y = R sin φ, z = R (1 − cos φ); penetration = the
// unclamped ellipse (kp = 1).
StaticContactResult ellipse_result(bool half, double skew = 0.0) {
  StaticContactResult r;
  r.name = half ? "half" : "full";
  r.half_model = half;
  r.support.kind = SupportDescription::Kind::plane;
  r.final_state.deflection_mm = 10.0;
  r.completed = true;
  int element = 0;
  for (int j = -60; j < 60; ++j) {
    const double phi = 0.005 * (j + 0.5);
    for (int i = half ? 0 : -40; i < 40; ++i) {
      const double s = 1.5 * (i + 0.5);
      TreadPoint p;
      p.element = element++;
      p.u = s;
      p.v = phi;
      p.weight = 1.0;
      TreadPointState st;
      const double y = kR * std::sin(phi);
      st.position = Eigen::Vector3d(s + skew * y, y, kR * (1 - std::cos(phi)));
      const double x = st.position.x();
      st.penetration = kQ0 * (1.0 - (x / kA) * (x / kA) - (y / kB) * (y / kB));
      st.pressure = std::max(0.0, st.penetration);
      p.reference = st.position;
      r.tread_points.push_back(p);
      r.final_state.tread.push_back(st);
    }
  }
  return r;
}

LoadPoint load_point(double deflection, double qz) {
  LoadPoint p;
  p.deflection_mm = deflection;
  p.patch.Qz_N = qz;
  p.patch.contact_area_mm2 = 10 * qz;
  p.patch.patch_length_mm = 2 * deflection;
  p.patch.patch_width_mm = deflection;
  p.patch.max_pressure_MPa = 0.01 * deflection;
  p.patch.mean_pressure_MPa = 0.005 * deflection;
  p.contact_iterations = 3;
  p.newton_iterations = 7;
  p.factorizations = 8;
  p.increments = 1;
  p.time_s = 0.25;
  return p;
}

StaticContactResult curve(SupportDescription::Kind kind, Kinematics kinematics) {
  StaticContactResult r;
  r.name = "curve";
  r.support.kind = kind;
  r.support.drum_diameter = 1830.0;
  r.kinematics = kinematics;
  r.completed = true;
  r.points = {load_point(0, 0), load_point(2, 700), load_point(4, 1500)};
  r.final_state.deflection_mm = 4;
  return r;
}

const Case& example() {
  static const Case c = read_case(std::filesystem::path(TIREFEM_SOURCE_DIR) / "tests/data/example_175-70R13_before_revision.toml");
  return c;
}

TyreMesh coarse_mesh(int circumferential, int meridional, bool half) {
  MeshSettings s;
  s.circumferential_elements = circumferential;
  s.meridional_elements = meridional;
  s.half_model = half;
  s.circumferential_refinement = 4.0;
  return build_tyre_mesh(example().tyre, s);
}

// Resampled map against the exact field: close well inside, small at the kinked edge, 0 outside.
void expect_ellipse(const HeatMap& m, int min_inside) {
  ASSERT_EQ(m.values.size(), m.y.size());
  int inside = 0;
  for (std::size_t iy = 0; iy < m.y.size(); ++iy) {
    ASSERT_EQ(m.values[iy].size(), m.x.size());
    for (std::size_t ix = 0; ix < m.x.size(); ++ix) {
      const double x = m.x[ix], y = m.y[iy], exact = ellipse(x, y), value = m.values[iy][ix];
      ASSERT_TRUE(std::isfinite(value));
      const double rho = std::hypot(x / kA, y / kB);
      if (exact >= 0.05) {
        EXPECT_NEAR(value, exact, 5e-4) << "x " << x << " y " << y;
        ++inside;
      } else if (rho > 1.1) {
        EXPECT_EQ(value, 0.0) << "x " << x << " y " << y;
      } else {
        EXPECT_NEAR(value, exact, 0.02) << "x " << x << " y " << y;
      }
    }
  }
  EXPECT_GT(inside, min_inside);
}

TEST(FootprintReport, FootprintMapResamplesEllipse) {
  const StaticContactResult r = ellipse_result(false, 0.05);  // skewed cells: a real inverse map
  const HeatMap m = footprint_map_xy(r, 1.0);
  EXPECT_TRUE(m.equal_axes);
  expect_ellipse(m, 4000);
  // Window: the contact extent (just inside the ellipse) plus 10 mm, on multiples of the cell.
  EXPECT_LE(m.x.front(), -kA - 10 + 2.5);
  EXPECT_GE(m.x.front(), -kA - 10 - 4.0);  // the skew shifts the extent by up to 60 · 0.05 · (x/a)…
  EXPECT_LE(m.y.front(), -kB - 10 + 2.5);
  EXPECT_GE(m.y.front(), -kB - 10 - 1.0);
  for (double x : m.x) EXPECT_NEAR(x, std::round(x), 1e-9);
  for (std::size_t k = 1; k < m.y.size(); ++k) EXPECT_NEAR(m.y[k] - m.y[k - 1], 1.0, 1e-9);
  // Coarser cells: nodes on multiples of 2.5 mm.
  const HeatMap coarse = footprint_map_xy(r, 2.5);
  for (double x : coarse.x) EXPECT_NEAR(x / 2.5, std::round(x / 2.5), 1e-9);
  expect_ellipse(coarse, 600);
  EXPECT_THROW(footprint_map_xy(r, 0.0), std::invalid_argument);
}

TEST(FootprintReport, FootprintMapMirrorsHalfModel) {
  const StaticContactResult r = ellipse_result(true);
  const HeatMap m = footprint_map_xy(r, 1.0);
  expect_ellipse(m, 4000);  // includes the strip |x| < 0.75 between the first point column and its image
  ASSERT_GE(m.x.size(), 2u);
  EXPECT_DOUBLE_EQ(m.x.front(), -m.x.back());
  const std::size_t nx = m.x.size();
  for (std::size_t iy = 0; iy < m.y.size(); ++iy)
    for (std::size_t ix = 0; ix < nx; ++ix) EXPECT_NEAR(m.values[iy][ix], m.values[iy][nx - 1 - ix], 1e-12);
  const auto ix0 = std::find(m.x.begin(), m.x.end(), 0.0) - m.x.begin();
  const auto iy0 = std::find(m.y.begin(), m.y.end(), 0.0) - m.y.begin();
  ASSERT_LT(ix0, static_cast<long>(nx));
  ASSERT_LT(iy0, static_cast<long>(m.y.size()));
  EXPECT_NEAR(m.values[iy0][ix0], kQ0, 1e-3);
}

TEST(FootprintReport, PressureMapSPhiWindowAndMirror) {
  for (bool half : {true, false}) {
    SCOPED_TRACE(half ? "half model" : "full model");
    const StaticContactResult r = ellipse_result(half);
    // Contact columns (s) and rows (φ) of the model's own points.
    std::vector<double> s_contact, phi_contact;
    for (std::size_t n = 0; n < r.tread_points.size(); ++n)
      if (r.final_state.tread[n].pressure > 0) {
        s_contact.push_back(r.tread_points[n].u);
        phi_contact.push_back(r.tread_points[n].v);
      }
    std::sort(s_contact.begin(), s_contact.end());
    std::sort(phi_contact.begin(), phi_contact.end());
    const double s_max = s_contact.back(), phi_min = phi_contact.front(), phi_max = phi_contact.back();
    const int columns = static_cast<int>(std::lround((s_max - (half ? 0.75 : -s_max)) / 1.5)) + 1;
    const int rows = static_cast<int>(std::lround((phi_max - phi_min) / 0.005)) + 1;

    const HeatMap m = pressure_map_s_phi(r);
    EXPECT_FALSE(m.equal_axes);
    ASSERT_EQ(static_cast<int>(m.x.size()), half ? 2 * (columns + 3) : columns + 6);
    ASSERT_EQ(static_cast<int>(m.y.size()), rows + 6);
    EXPECT_NEAR(m.x.back(), s_max + 3 * 1.5, 1e-9);
    EXPECT_NEAR(m.x.front(), -(s_max + 3 * 1.5), 1e-9);  // mirrored in the half model
    EXPECT_NEAR(m.y.front(), (phi_min - 3 * 0.005) * 180 / kPi, 1e-9);
    EXPECT_NEAR(m.y.back(), (phi_max + 3 * 0.005) * 180 / kPi, 1e-9);
    const std::size_t nx = m.x.size(), ny = m.y.size();
    for (std::size_t iy = 0; iy < ny; ++iy) {
      EXPECT_EQ(m.values[iy].front(), 0.0);
      EXPECT_EQ(m.values[iy].back(), 0.0);
      for (std::size_t ix = 0; ix < nx; ++ix) {
        const double phi = m.y[iy] * kPi / 180, y = kR * std::sin(phi);
        EXPECT_NEAR(m.values[iy][ix], ellipse(m.x[ix], y), 1e-12);  // the points' own pressure
        EXPECT_NEAR(m.values[iy][ix], m.values[iy][nx - 1 - ix], 1e-12);
      }
    }
    for (std::size_t ix = 0; ix < nx; ++ix) EXPECT_EQ(m.values.front()[ix], 0.0);

    const CsvTable t = tread_points_table(r);
    EXPECT_EQ(t.columns, (std::vector<std::string>{"s_mm", "phi_deg", "x_mm", "y_mm", "z_mm",
                                                   "penetration_mm", "pressure_MPa"}));
    EXPECT_EQ(static_cast<int>(t.rows.size()), (half ? columns + 3 : columns + 6) * (rows + 6));
    int loaded = 0;
    for (const auto& row : t.rows) {
      if (half) EXPECT_GT(row[0], 0.0);
      EXPECT_LE(std::abs(row[0]), s_max + 3 * 1.5 + 1e-9);
      loaded += row[6] > 0;
    }
    EXPECT_EQ(loaded, static_cast<int>(s_contact.size()));  // every loaded point is listed
  }
}

TEST(FootprintReport, NoContactGivesZeroMapsAroundTheNearestPoints) {
  StaticContactResult r = ellipse_result(true);
  for (auto& s : r.final_state.tread) s.penetration -= 1.0, s.pressure = 0.0;
  const HeatMap m = pressure_map_s_phi(r);
  EXPECT_EQ(m.x.size(), 8u);  // the point nearest the support (s = ±0.75, φ = ±0.0025) ± 3
  EXPECT_EQ(m.y.size(), 8u);
  for (const auto& row : m.values)
    for (double v : row) EXPECT_EQ(v, 0.0);
  const HeatMap f = footprint_map_xy(r);
  for (const auto& row : f.values)
    for (double v : row) EXPECT_EQ(v, 0.0);
}

TEST(FootprintReport, LoadCurveTableColumnsAndRows) {
  const StaticContactResult r = curve(SupportDescription::Kind::drum, Kinematics::nonlinear);
  const CsvTable t = load_curve_table(r);
  EXPECT_EQ(t.columns, (std::vector<std::string>{
                           "deflection_mm", "Qz_N", "contact_area_mm2", "patch_length_mm", "patch_width_mm",
                           "max_pressure_MPa", "mean_pressure_MPa", "contact_iterations", "newton_iterations",
                           "factorizations", "increments", "time_s", "tangent_shift"}));
  ASSERT_EQ(t.rows.size(), 3u);
  EXPECT_EQ(t.rows[2], (std::vector<double>{4, 1500, 15000, 8, 4, 0.04, 0.02, 3, 7, 8, 1, 0.25, 0}));
  std::string comments;
  for (const auto& c : t.comments) comments += c + "\n";
  EXPECT_NE(comments.find("curve"), std::string::npos);
  EXPECT_NE(comments.find("drum, diameter 1830 mm"), std::string::npos);
  EXPECT_NE(comments.find("nonlinear"), std::string::npos);
}

TEST(FootprintReport, LoadCharacteristicPlotSeries) {
  const StaticContactResult a = curve(SupportDescription::Kind::plane, Kinematics::nonlinear);
  const StaticContactResult b = curve(SupportDescription::Kind::drum, Kinematics::nonlinear);
  const StaticContactResult c = curve(SupportDescription::Kind::plane, Kinematics::linear);
  const Plot p = load_characteristic_plot({&a, &b, nullptr, &c});
  ASSERT_EQ(p.series.size(), 3u);
  EXPECT_EQ(p.series[0].title, "plane, nonlinear");
  EXPECT_EQ(p.series[1].title, "drum 1830 mm, nonlinear");
  EXPECT_EQ(p.series[2].title, "plane, linear");
  EXPECT_EQ(p.series[1].x, (std::vector<double>{0, 2, 4}));
  EXPECT_EQ(p.series[1].y, (std::vector<double>{0, 700, 1500}));
  EXPECT_NE(p.x_label.find("mm"), std::string::npos);
  EXPECT_NE(p.y_label.find("Qz"), std::string::npos);
}

TEST(FootprintReport, SummariesHaveRequiredKeys) {
  StaticContactResult r = curve(SupportDescription::Kind::drum, Kinematics::linear);
  r.iteration = ContactSettings::Iteration::single_loop;
  const toml::table s = load_curve_summary(r);
  EXPECT_EQ(s["name"].value<std::string>(), "curve");
  EXPECT_EQ(s["support"].value<std::string>(), "drum");
  EXPECT_EQ(s["drum_diameter_mm"].value<double>(), 1830.0);
  EXPECT_EQ(s["theory"].value<std::string>(), "linear");
  EXPECT_EQ(s["iteration"].value<std::string>(), "single_loop");
  EXPECT_EQ(s["completed"].value<bool>(), true);
  const toml::array* points = s["points"].as_array();
  ASSERT_NE(points, nullptr);
  ASSERT_EQ(points->size(), 3u);
  const toml::table& p = *(*points)[2].as_table();
  EXPECT_EQ(p["deflection_mm"].value<double>(), 4.0);
  EXPECT_EQ(p["Qz_N"].value<double>(), 1500.0);
  EXPECT_EQ(p["contact_area_mm2"].value<double>(), 15000.0);
  EXPECT_EQ(p["patch_length_mm"].value<double>(), 8.0);
  EXPECT_EQ(p["patch_width_mm"].value<double>(), 4.0);
  EXPECT_EQ(p["max_pressure_MPa"].value<double>(), 0.04);
  EXPECT_EQ(p["mean_pressure_MPa"].value<double>(), 0.02);
  EXPECT_EQ(p["contact_iterations"].value<int64_t>(), 3);
  EXPECT_EQ(p["newton_iterations"].value<int64_t>(), 7);

  StaticContactResult f = curve(SupportDescription::Kind::plane, Kinematics::nonlinear);
  f.name = "footprint_3700N";
  f.target_Qz_N = 1500.0;
  const toml::table fs = footprint_summary(f);
  EXPECT_EQ(fs["name"].value<std::string>(), "footprint_3700N");
  EXPECT_EQ(fs["support"].value<std::string>(), "plane");
  EXPECT_FALSE(fs.contains("drum_diameter_mm"));
  EXPECT_EQ(fs["theory"].value<std::string>(), "nonlinear");
  EXPECT_EQ(fs["target_Qz_N"].value<double>(), 1500.0);
  EXPECT_EQ(fs["deflection_mm"].value<double>(), 4.0);
  EXPECT_EQ(fs["Qz_N"].value<double>(), 1500.0);
  for (const char* key :
       {"contact_area_mm2", "patch_length_mm", "patch_width_mm", "max_pressure_MPa", "mean_pressure_MPa"})
    EXPECT_TRUE(fs[key].is_floating_point()) << key;

  f.completed = false;
  f.failure = "no convergence";
  EXPECT_EQ(footprint_summary(f)["failure"].value<std::string>(), "no convergence");
}

TEST(FootprintReport, SupportVtuPlaneAndDrum) {
  const StaticContactResult plane = curve(SupportDescription::Kind::plane, Kinematics::nonlinear);
  const VtuMesh v = support_vtu(plane, 150.0);
  ASSERT_EQ(v.points.size(), 61u * 61u);
  ASSERT_EQ(v.quads.size(), 60u * 60u);
  EXPECT_EQ(v.points.front(), Eigen::Vector3d(-150, -150, 4));
  EXPECT_EQ(v.points.back(), Eigen::Vector3d(150, 150, 4));
  const StaticContactResult drum = curve(SupportDescription::Kind::drum, Kinematics::nonlinear);
  const VtuMesh d = support_vtu(drum, 150.0);
  const double R = 915.0;
  EXPECT_NEAR(d.points[30 * 61 + 10].z(), 4.0, 1e-12);                             // y = 0
  EXPECT_NEAR(d.points[0].z(), 4.0 - R + std::sqrt(R * R - 150.0 * 150.0), 1e-9);  // y = −150
  // Quads counter-clockwise seen from above: (x, y) cross product > 0.
  const auto& q = d.quads[0];
  const Eigen::Vector3d a = d.points[q[1]] - d.points[q[0]], b = d.points[q[3]] - d.points[q[0]];
  EXPECT_GT(a.cross(b).z(), 0.0);
}

// Fake element results: outer ply k of element e carries 100 (k + 1) + e N and strain 1e-5 e.
std::vector<ElementResult> fake_elements(const TyreMesh& tm, double offset) {
  std::vector<ElementResult> r(tm.mesh.element_count());
  for (int e = 0; e < tm.mesh.element_count(); ++e) {
    const std::size_t plies = example().tyre.zones[tm.element_zone[e]].outer.plies.size();
    for (std::size_t k = 0; k < plies; ++k) {
      r[e].outer_cords.force_N.push_back(100.0 * (k + 1) + e + offset);
      r[e].outer_cords.strain.push_back(1e-5 * e + offset);
    }
  }
  return r;
}

TEST(FootprintReport, CircumferentialBeltTableEquatorialColumn) {
  for (bool half : {true, false}) {
    SCOPED_TRACE(half ? "half model" : "full model");
    const TyreMesh tm = coarse_mesh(24, 8, half);
    const ShellMesh& m = tm.mesh;
    const auto inflated = fake_elements(tm, 0.0), loaded = fake_elements(tm, 0.5);
    const CsvTable t =
        circumferential_belt_table(tm, example().tyre, {{"inflated", &inflated}, {"loaded", &loaded}});
    EXPECT_EQ(t.columns, (std::vector<std::string>{
                             "phi_deg", "inflated_belt1_force_N", "inflated_belt1_strain",
                             "inflated_belt2_force_N", "inflated_belt2_strain", "loaded_belt1_force_N",
                             "loaded_belt1_strain", "loaded_belt2_force_N", "loaded_belt2_strain"}));
    ASSERT_EQ(static_cast<int>(t.rows.size()), m.v_elements());
    const int col = half ? 0 : m.u_elements() / 2;  // full model: the column just on the s > 0 side
    EXPECT_GT(tm.element_s[m.element_index(col, 0)], 0.0);
    for (int j = 0; j < m.v_elements(); ++j) {
      const int e = m.element_index(col, j);
      const auto& row = t.rows[j];
      EXPECT_NEAR(row[0], 90.0 * (m.v_values[j] + m.v_values[j + 1]) / kPi, 1e-12);
      if (j > 0) EXPECT_GT(row[0], t.rows[j - 1][0]);
      EXPECT_EQ(row[1], 100.0 + e);
      EXPECT_EQ(row[2], 1e-5 * e);
      EXPECT_EQ(row[3], 200.0 + e);
      EXPECT_EQ(row[5], 100.5 + e);
      EXPECT_EQ(row[7], 200.5 + e);
    }
    const Plot p = circumferential_belt_plot(t);
    ASSERT_EQ(p.series.size(), 4u);
    EXPECT_EQ(p.series[0].title, "inflated_belt1");
    EXPECT_EQ(p.series[3].title, "loaded_belt2");
    EXPECT_EQ(p.series[2].y.size(), t.rows.size());
    EXPECT_EQ(p.series[2].x.front(), t.rows.front()[0]);

    std::vector<ElementResult> short_vector(3);
    EXPECT_THROW(circumferential_belt_table(tm, example().tyre, {{"bad", &short_vector}}),
                 std::invalid_argument);
  }
}

TEST(FootprintReport, MeridianCordStrainPlotFromMeridianTables) {
  const TyreMesh tm = coarse_mesh(24, 8, true);
  const Eigen::VectorXd u = Eigen::VectorXd::Zero(tm.mesh.dof_count());
  const auto elements = evaluate_element_results(tm, example().tyre, u, Kinematics::nonlinear);
  const CsvTable table = meridian_table(tm, example().tyre, u, elements);
  const Plot p = meridian_cord_strain_plot({{"inflated", &table}, {"loaded", &table}});
  std::vector<std::string> titles;
  for (const auto& s : p.series) {
    titles.push_back(s.title);
    EXPECT_EQ(s.x.size(), table.rows.size());
    EXPECT_EQ(s.y.size(), table.rows.size());
  }
  EXPECT_EQ(titles, (std::vector<std::string>{"inflated, carcass carcass", "inflated, breaker belt1",
                                              "inflated, breaker belt2", "loaded, carcass carcass",
                                              "loaded, breaker belt1", "loaded, breaker belt2"}));
  EXPECT_EQ(p.series[0].x.front(), table.rows.front()[0]);
}

StaticContactResult on_support(SupportDescription::Kind kind, double deflection) {
  StaticContactResult r;
  r.name = "nodal";
  r.support.kind = kind;
  r.support.drum_diameter = 1830.0;
  r.final_state.deflection_mm = deflection;
  return r;
}

TEST(FootprintReport, NodalContactPressureOnPlaneAndDrum) {
  const TyreMesh tm = coarse_mesh(24, 8, true);
  const ShellMesh& m = tm.mesh;
  const TyreDescription& tyre = example().tyre;
  const double kp = tyre.tread_stiffness;
  ASSERT_EQ(m.v_values[12], 0.0);  // a node row at φ = 0
  const int centre = m.pair_index(0, 12), next = m.pair_index(0, 13);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(m.dof_count());

  const StaticContactResult plane = on_support(SupportDescription::Kind::plane, 2.0);
  const std::vector<double> q = nodal_contact_pressure(tm, tyre, plane, u);
  ASSERT_EQ(static_cast<int>(q.size()), m.pair_count());
  EXPECT_NEAR(q[centre], 2.0 * kp, 1e-6);  // the tread surface touches z = 0 there: g = δ
  // Equator, next row: the tread point on the circle of radius axis_z, z = axis_z (1 − cos φ).
  const double phi = m.v_values[13], g = 2.0 - tm.axis_z * (1 - std::cos(phi));
  ASSERT_GT(g, 0.0);
  EXPECT_NEAR(q[next], kp * g, 1e-6);
  int loaded = 0;
  for (int p = 0; p < m.pair_count(); ++p) {
    EXPECT_GE(q[p], 0.0);
    const double phi_p = m.v_values[p / m.u_nodes()];
    if (std::abs(tm.pair_s(p)) > tyre.tread_end_s || std::abs(phi_p) > 0.5) EXPECT_EQ(q[p], 0.0);
    loaded += q[p] > 0;
  }
  EXPECT_GT(loaded, 2);

  // Outer nodes moved down by 1 mm: 1 mm deeper.
  for (int p = 0; p < m.pair_count(); ++p) u[outer_dof(p, 2)] = -1.0;
  EXPECT_NEAR(nodal_contact_pressure(tm, tyre, plane, u)[centre], 3.0 * kp, 1e-6);
  u.setZero();

  const StaticContactResult drum = on_support(SupportDescription::Kind::drum, 2.0);
  const std::vector<double> qd = nodal_contact_pressure(tm, tyre, drum, u);
  EXPECT_NEAR(qd[centre], 2.0 * kp, 1e-6);
  EXPECT_LT(qd[next], q[next]);  // the drum curves away from the tyre

  EXPECT_THROW(nodal_contact_pressure(tm, tyre, plane, Eigen::VectorXd::Zero(6)), std::invalid_argument);
}

TEST(FootprintReport, LoadedShellVtuAppendsContactPressure) {
  const TyreMesh tm = coarse_mesh(24, 8, true);
  const int np = tm.mesh.pair_count();
  StaticContactResult r = on_support(SupportDescription::Kind::plane, 2.0);
  r.final_state.displacement = Eigen::VectorXd::Zero(tm.mesh.dof_count());
  const auto elements =
      evaluate_element_results(tm, example().tyre, r.final_state.displacement, Kinematics::nonlinear);
  const VtuMesh v = loaded_shell_vtu(tm, example().tyre, r, elements);
  const VtuMesh plain = shell_vtu(tm, example().tyre, r.final_state.displacement, elements);
  ASSERT_EQ(v.point_scalars.size(), plain.point_scalars.size() + 1);
  const auto& [name, field] = v.point_scalars.back();
  EXPECT_EQ(name, "contact_pressure_MPa");
  ASSERT_EQ(static_cast<int>(field.size()), 2 * np);
  const std::vector<double> q = nodal_contact_pressure(tm, example().tyre, r, r.final_state.displacement);
  for (int p = 0; p < np; ++p) {
    EXPECT_EQ(field[p], 0.0);  // inner face
    EXPECT_EQ(field[np + p], q[p]);
    EXPECT_EQ(v.points[np + p], tm.mesh.outer_nodes[p]);
  }
}

// The undeformed example tyre against a plane at δz = 10 mm, tread points from the real mesh.
TEST(FootprintReport, RealTreadGridOfUndeformedTyre) {
  const TyreMesh tm = coarse_mesh(72, 8, true);
  const ShellMesh& m = tm.mesh;
  const TyreDescription& tyre = example().tyre;
  std::vector<int> elements;
  for (int j = 0; j < m.v_elements(); ++j)
    for (int i = 0; i < m.u_elements(); ++i) {
      const int e = m.element_index(i, j);
      if (tm.element_s[e] <= tyre.tread_end_s &&
          std::abs(0.5 * (m.v_values[j] + m.v_values[j + 1])) <= kPi / 2)
        elements.push_back(e);
    }
  StaticContactResult r = on_support(SupportDescription::Kind::plane, 10.0);
  r.tread_points = make_tread_points(m, elements, 4, [&](double s) { return tread_height_at(tyre, s); });
  const auto support = make_support(r.support);
  for (const TreadPoint& p : r.tread_points) {
    TreadPointState s;
    s.position = p.reference;
    s.penetration = support->penetration(s.position, 10.0).value;
    s.pressure = tyre.tread_stiffness * std::max(s.penetration, 0.0);
    r.final_state.tread.push_back(s);
  }
  const HeatMap f = footprint_map_xy(r, 1.0);
  const auto ix0 = std::find(f.x.begin(), f.x.end(), 0.0) - f.x.begin();
  const auto iy0 = std::find(f.y.begin(), f.y.end(), 0.0) - f.y.begin();
  ASSERT_LT(ix0, static_cast<long>(f.x.size()));
  ASSERT_LT(iy0, static_cast<long>(f.y.size()));
  EXPECT_NEAR(f.values[iy0][ix0], 10.0 * tyre.tread_stiffness, 0.1);
  // Length of the patch along x = 0: the chord of the tread circle 2 sqrt(2 R δ − δ²).
  double y_lo = 0, y_hi = 0;
  for (std::size_t iy = 0; iy < f.y.size(); ++iy)
    if (f.values[iy][ix0] > 0) y_lo = std::min(y_lo, f.y[iy]), y_hi = std::max(y_hi, f.y[iy]);
  const double chord = 2 * std::sqrt(2 * tm.axis_z * 10.0 - 100.0);
  EXPECT_NEAR(y_hi - y_lo, chord, 10.0);
  EXPECT_NEAR(y_hi, -y_lo, 2.0);
  const HeatMap sp = pressure_map_s_phi(r);
  EXPECT_DOUBLE_EQ(sp.x.front(), -sp.x.back());
  EXPECT_GT(sp.x.size(), 6u);
  EXPECT_GT(sp.y.size(), 6u);
}

}  // namespace
}  // namespace tirefem
