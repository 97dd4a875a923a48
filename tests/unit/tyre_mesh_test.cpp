// The tyre mesh of the example case: sizes, constraints, the axis height and the geometry of the faces.
#include "tirefem/tyre/tyre_mesh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "tirefem/analysis/footprint.hpp"
#include "tirefem/case/case_reader.hpp"
#include "tirefem/tyre/ply_stiffness.hpp"

namespace tirefem {
namespace {

const Case& example() {
  static const Case c = read_case(std::filesystem::path(TIREFEM_SOURCE_DIR) / "tests/data/example_175-70R13_before_revision.toml");
  return c;
}

MeshSettings settings(int n_circ, int n_mer, bool half) {
  MeshSettings m;
  m.circumferential_elements = n_circ;
  m.meridional_elements = n_mer;
  m.half_model = half;
  m.circumferential_refinement = 4.0;
  return m;
}

TEST(TyreMesh, HalfModelSizesAndConstraints) {
  const TyreMesh tm = build_tyre_mesh(example().tyre, example().mesh);  // 120 × 46
  const ShellMesh& m = tm.mesh;
  EXPECT_EQ(m.element_count(), 120 * 46);
  EXPECT_EQ(m.pair_count(), 120 * 47);
  EXPECT_EQ(m.u_elements(), 46);
  EXPECT_EQ(m.v_elements(), 120);
  EXPECT_EQ(tm.sections.size(), 5520u);
  EXPECT_EQ(tm.element_zone.size(), 5520u);
  EXPECT_EQ(tm.element_s.size(), 5520u);
  EXPECT_EQ(tm.pressure_elements.size(), 5520u);
  // bead: 6 DOFs × 120 pairs; equator: inner and outer x displacement × 120 pairs
  EXPECT_EQ(tm.fixed_dofs.size(), 120u * 6 + 120u * 2);
  EXPECT_TRUE(std::is_sorted(tm.fixed_dofs.begin(), tm.fixed_dofs.end()));
  EXPECT_EQ(std::set<int>(tm.fixed_dofs.begin(), tm.fixed_dofs.end()).size(), tm.fixed_dofs.size());
  for (int p : m.edge_pairs(GridEdge::u_min)) {
    EXPECT_TRUE(std::binary_search(tm.fixed_dofs.begin(), tm.fixed_dofs.end(), inner_dof(p, 0)));
    EXPECT_TRUE(std::binary_search(tm.fixed_dofs.begin(), tm.fixed_dofs.end(), outer_dof(p, 0)));
    EXPECT_FALSE(std::binary_search(tm.fixed_dofs.begin(), tm.fixed_dofs.end(), inner_dof(p, 2)));
    EXPECT_NEAR(m.inner_nodes[p].x(), 0.0, 1e-12);
  }
  EXPECT_TRUE(tm.half_model);
}

TEST(TyreMesh, FullModelSizesAndConstraints) {
  const TyreMesh tm = build_tyre_mesh(example().tyre, settings(40, 46, false));
  const ShellMesh& m = tm.mesh;
  EXPECT_EQ(m.u_elements(), 92);
  EXPECT_EQ(m.element_count(), 40 * 92);
  EXPECT_EQ(m.pair_count(), 40 * 93);
  EXPECT_EQ(tm.fixed_dofs.size(), 2u * 40 * 6);
  EXPECT_TRUE(tm.profile.is_mirrored());
  // Mirror symmetry of stations, zones and nodes.
  const int nu = m.u_nodes();
  for (int i = 0; i < nu; ++i) EXPECT_NEAR(m.u_values[i], -m.u_values[nu - 1 - i], 1e-12);
  for (int i = 0; i < m.u_elements(); ++i) {
    const int mirror = m.u_elements() - 1 - i;
    EXPECT_EQ(tm.element_zone[i], tm.element_zone[mirror]);
    EXPECT_NEAR(tm.element_s[i], -tm.element_s[mirror], 1e-12);
    EXPECT_EQ(tm.sections[i].inner_face, tm.sections[mirror].inner_face);
  }
  for (int i = 0; i < nu; ++i) {
    const Eigen::Vector3d a = m.outer_nodes[m.pair_index(i, 7)],
                          b = m.outer_nodes[m.pair_index(nu - 1 - i, 7)];
    EXPECT_NEAR(a.x(), -b.x(), 1e-9);
    EXPECT_NEAR(a.y(), b.y(), 1e-9);
    EXPECT_NEAR(a.z(), b.z(), 1e-9);
  }
}

TEST(TyreMesh, AxisHeightPutsTheTreadOnTheRoad) {
  const TyreMesh tm = build_tyre_mesh(example().tyre, settings(24, 46, true));
  EXPECT_NEAR(tm.axis_z, 272.0 + 3.0 + 10.0, 1e-9);
  const ShellMesh& m = tm.mesh;
  // φ = 0 is the middle station of the closed mesh (stations run −π … π).
  const int j0 = m.v_nodes() / 2;
  ASSERT_NEAR(m.v_values[j0], 0.0, 1e-12);
  const int p = m.pair_index(0, j0);
  EXPECT_LT((m.inner_nodes[p] - Eigen::Vector3d(0, 0, 13.0)).norm(), 1e-9);
  EXPECT_LT((m.outer_nodes[p] - Eigen::Vector3d(0, 0, 10.0)).norm(), 1e-9);  // hp = 10 below, the road
  // Every outer node is above the road by at least the tread height there.
  for (int q = 0; q < m.pair_count(); ++q)
    EXPECT_GE(m.outer_nodes[q].z(), tread_height_at(example().tyre, tm.pair_s(q)) - 1e-9);
}

TEST(TyreMesh, OuterFaceSitsAtTheInterlayerThicknessAlongTheNormal) {
  const TyreMesh tm = build_tyre_mesh(example().tyre, settings(16, 46, true));
  const ShellMesh& m = tm.mesh;
  for (int q = 0; q < m.pair_count(); ++q) {
    const double s = tm.pair_s(q);
    const Eigen::Vector3d d = m.outer_nodes[q] - m.inner_nodes[q];
    EXPECT_NEAR(d.norm(), example().tyre.interlayer_thickness.at(s), 1e-9);
    // along the meridian normal, away from the axis: the radial distance grows where n_r > 0
    const int j = q / m.u_nodes();
    const Eigen::Vector3d n = revolution_normal(tm.profile.tangent(s), m.v_values[j]);
    EXPECT_NEAR(d.normalized().dot(n), 1.0, 1e-12);
  }
}

TEST(TyreMesh, ZoneEndsAndTreadEdgeAreElementEdges) {
  const TyreMesh tm = build_tyre_mesh(example().tyre, example().mesh);
  const std::vector<double>& u = tm.mesh.u_values;
  for (double edge : {60.0, 78.0, 82.0, 130.0}) {
    const bool found = std::any_of(u.begin(), u.end(), [&](double s) { return std::abs(s - edge) < 1e-12; });
    EXPECT_TRUE(found) << edge;
  }
  EXPECT_NEAR(u.back(), tm.profile.length(), 1e-12);
  // Zones and sections follow the element centres.
  const TyreDescription& t = example().tyre;
  const MembraneStiffness belts = face_stiffness(t.zones[0].outer);
  for (int e = 0; e < tm.mesh.element_count(); ++e) {
    const double s = tm.element_s[e];
    const int z = tm.element_zone[e];
    EXPECT_LT(s, t.zones[z].s_end);
    EXPECT_GT(s, z == 0 ? 0.0 : t.zones[z - 1].s_end);
    EXPECT_EQ(tm.sections[e].core_shear_modulus, t.zones[z].core_shear_modulus);
    EXPECT_EQ(tm.sections[e].core_normal_modulus, t.zones[z].core_normal_modulus);
    if (z == 0) EXPECT_EQ(tm.sections[e].outer_face, belts);
  }
  // Element lengths stay within a factor 1.5 of the mean (proportional allocation).
  const double mean = tm.profile.length() / 46;
  for (std::size_t i = 0; i + 1 < u.size(); ++i) {
    EXPECT_GT(u[i + 1] - u[i], mean / 1.5);
    EXPECT_LT(u[i + 1] - u[i], mean * 1.5);
  }
}

TEST(TyreMesh, MeridionalStationsShareElementsByLength) {
  const std::vector<double> s = meridional_stations(100.0, {10.0, 90.0}, 10);
  ASSERT_EQ(s.size(), 11u);
  EXPECT_EQ(s.front(), 0.0);
  EXPECT_EQ(s.back(), 100.0);
  EXPECT_EQ(std::count(s.begin(), s.end(), 10.0), 1);
  EXPECT_EQ(std::count(s.begin(), s.end(), 90.0), 1);
  EXPECT_NEAR(s[1], 10.0, 1e-12);  // 1 + 8 + 1
  EXPECT_NEAR(s[2], 20.0, 1e-12);
  // a tiny zone still gets one element
  const std::vector<double> t = meridional_stations(100.0, {0.5}, 4);
  EXPECT_EQ(t.size(), 5u);
  EXPECT_EQ(t[1], 0.5);
  EXPECT_THROW(meridional_stations(100.0, {10.0, 20.0, 30.0}, 3), std::invalid_argument);
}

TEST(TyreMesh, TreadHeightEndsAtTheTreadEdge) {
  const TyreDescription& t = example().tyre;
  EXPECT_DOUBLE_EQ(tread_height_at(t, 0.0), 10.0);
  EXPECT_DOUBLE_EQ(tread_height_at(t, 62.5), 9.0);
  EXPECT_DOUBLE_EQ(tread_height_at(t, -62.5), 9.0);
  EXPECT_DOUBLE_EQ(tread_height_at(t, 78.0), 8.0);
  EXPECT_DOUBLE_EQ(tread_height_at(t, 78.5), 0.0);
  EXPECT_EQ(zone_at(t, 59.0), 0);
  EXPECT_EQ(zone_at(t, -61.0), 1);
  EXPECT_EQ(zone_at(t, 200.0), 3);
}

}  // namespace
}  // namespace tirefem

namespace tirefem {
namespace {

// meridional_grading = "uniform_arc_length": equal elements in s across the zone ends; each element takes
// the zone of its centre, and an element across the tread edge keeps the tread points on the tread side.
TEST(TyreMesh, UniformArcLengthGradingHasEqualElementsAcrossZones) {
  const TyreDescription& t = example().tyre;
  for (bool half : {true, false}) {
    MeshSettings m = settings(24, 25, half);
    m.meridional_grading = MeshSettings::MeridionalGrading::uniform_arc_length;
    const TyreMesh tm = build_tyre_mesh(t, m);
    const std::vector<double>& u = tm.mesh.u_values;
    const double length = tm.profile.length() / (half ? 1.0 : 2.0);
    ASSERT_EQ(static_cast<int>(u.size()), (half ? 1 : 2) * 25 + 1);
    const double h = length / 25;
    for (std::size_t i = 0; i + 1 < u.size(); ++i) EXPECT_NEAR(u[i + 1] - u[i], h, 1e-12 * length) << i;
    // 25 equal elements (h ≈ 6.16 mm) put no edge near the zone ends 60 and 82 mm (60/h ≈ 9.75, 82/h ≈ 13.3).
    for (double edge : {60.0, 82.0})
      EXPECT_FALSE(std::any_of(u.begin(), u.end(), [&](double s) { return std::abs(std::abs(s) - edge) < 0.5; }));
    for (int e = 0; e < tm.mesh.element_count(); ++e) {
      EXPECT_EQ(tm.element_zone[e], zone_at(t, tm.element_s[e]));
      EXPECT_EQ(tm.sections[e].core_shear_modulus, t.zones[tm.element_zone[e]].core_shear_modulus);
    }
  }
}

TEST(TyreMesh, UniformGradingKeepsTheTreadUpToItsEdge) {
  const TyreDescription& t = example().tyre;
  MeshSettings m = settings(24, 25, true);
  m.meridional_grading = MeshSettings::MeridionalGrading::uniform_arc_length;
  const TyreMesh tm = build_tyre_mesh(t, m);
  const std::vector<TreadPoint> points = tyre_tread_points(tm, t, 4);
  ASSERT_FALSE(points.empty());
  double s_max = 0.0;
  for (const TreadPoint& p : points) {
    EXPECT_LE(p.u, t.tread_end_s);
    s_max = std::max(s_max, p.u);
  }
  // The element across the tread edge (78 mm; edges at ≈ 73.9 and 80.0 mm) has points beyond its inner edge.
  const double h = tm.profile.length() / 25;
  const double inner_edge = std::floor(t.tread_end_s / h) * h;
  EXPECT_GT(s_max, inner_edge);
  EXPECT_GT(s_max, t.tread_end_s - h / 2);
}

}  // namespace
}  // namespace tirefem
