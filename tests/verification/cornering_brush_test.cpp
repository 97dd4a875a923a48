// Brush-model limit of cornering (issue 11; MODEL.md §7; Pacejka, Tyre and Vehicle Dynamics, ch. 3): with a
// nearly rigid carcass and belt, the FE lateral force Fy(α) and aligning moment Mz(α) are those of the brush
// model built on the FE pressure, and the pneumatic trail tends to a third of the half patch length a.
//
// Set-up: the example tyre with every structural stiffness ×1000 (as RollingBrush.*; tread kp = 1 N/mm³,
// G = 0.9 MPa, hp = 10 mm unchanged), the full model 60 × 24 (12 per half, mirrored), 8 × 8 tread points per
// element, plane, μ = 0.7, footprint of 2000 N, κ = 0 (Rk = Re of straight-ahead free rolling), planar
// tread shear, α = 0.1° … 4° (nearly all stick), 12° and 25° (sliding over much of the patch) and −1°.
//
// Reference per state, from the FE pressure alone: circumferential lines of tread points ordered from the
// leading edge (largest y), the leading edge y_A where the penetration crosses zero (linear between the
// last point out and the first in); the road carries a bristle tip sideways by tan α per unit of travel
// (+x for α > 0: the road moves right under a wheel that moves left of its heading), so the lateral stick
// stress is c tan α (y_A − y), c = G/hp; the traction min(c tan α (y_A − y), μ qn), sliding to the exit
// once it has started. Fy_brush = −Σ q w (W axes: Y = −x), Mz_brush = −Σ y q w (about the contact centre).
// Pacejka's closed form: as α → 0 every point sticks, the stress grows linearly from the leading edge
// whatever the pressure, and the trail of a line of half length a is a/3; over the patch the lines'
// a_l/3 (about each line's mid-point) weighted by their forces ∝ a_l² × width.
//
// Where the FE model departs from the brush, and the tolerances: the FE shear is a 2-vector, its
// longitudinal part the free-rolling shear D = O(a³/R²) of the rigid crown (RollingBrush.*: c|D| ≤ 0.5% of
// μ qn,max), which takes part of the friction budget where the point slides and adds longitudinal
// tractions whose moments about z cancel between the lines left and right of the centre only to the
// extent the patch is symmetric; the crown is not perfectly rigid (its lateral stretch along a line
// c|Δu| ≈ 0.05% of μ qn,max). Fy: 2% of |Fy| (a few %; measured below). Mz: 5% (a difference of two
// close moment arms near full sliding). Trail at α = 0.1°: within 5% of the brush trail on the FE pressure
// and of the closed form (the sampled lines end between tread points: O(h/2a), as in RollingBrush.*).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

#include <gtest/gtest.h>

#include "contact_support.hpp"
#include "rolling_support.hpp"
#include "tirefem/analysis/rolling.hpp"

namespace tirefem::verification {
namespace {

constexpr double kStiffening = 1000.0;
constexpr double kLoad = 2000.0;
constexpr double kFriction = 0.7;
const std::vector<double> kAngles = {0.1, 0.5, 1.0, 2.0, 4.0, 12.0, 25.0, -1.0};

const TyreDescription& tyre() {
  static const TyreDescription t = stiffened_tyre(kStiffening);
  return t;
}

const TyreMesh& mesh() {
  static const TyreMesh tm = build_tyre_mesh(tyre(), coarse_mesh(60, 12, false));
  return tm;
}

const RollingResult& run() {
  static const RollingResult r = [] {
    const Stopwatch clock;
    ContactSettings s = test_contact_settings(ContactSettings::Iteration::single_loop);
    s.quadrature = 8;
    s.residual_tolerance = 1e-8;  // the ×1000 structure's round-off floor, as in RollingBrush.*
    RollingStudy st;
    st.name = "brush";
    st.target_load = kLoad;
    st.friction = kFriction;
    for (double a : kAngles) {
      RollingStateSpec spec;
      spec.kind = RollingStateSpec::Kind::given_slip;
      spec.slip_angle_deg = a;
      spec.name = std::to_string(a);
      st.states.push_back(spec);
    }
    const Case& c = example_case();
    RollingResult res = run_rolling(mesh(), tyre(), c.inflation, s, st);
    std::printf("  nearly rigid tyre (x%.0f), full 60 x 24, quadrature 8, %.0f N, mu %.1f: %.1f s (%d factorisations, "
                "%d Newton iterations)\n", kStiffening, kLoad, kFriction, clock.seconds(), res.counters.factorizations,
                res.counters.newton_iterations);
    return res;
  }();
  return r;
}

struct Brush {
  double fy = 0.0, mz = 0.0, a_centre = 0.0;
  double closed_trail = 0.0;  // all stick: Σ_l F_l (a_l/3 − y_mid,l) / Σ_l F_l, F_l ∝ a_l² × the line's width
  // The mean distance from the leading edge, Σ c w (y_A − y) / Σ c w over the points in contact (c = G/hp):
  // the brush's relaxation length Kyα/Cy, Kyα = Σ c w (y_A − y) and Cy = Σ c w.
  double mean_distance = 0.0;
};

// The brush model on the FE pressure of state s (see the top).
Brush brush(const RollingResult& r, const RollingStateResult& s, double alpha_deg) {
  const auto& pts = r.tread_points;
  const double c = tyre().tread_shear_modulus, tan_a = std::tan(alpha_deg * M_PI / 180.0);
  std::map<double, std::vector<int>> by_u;
  for (int q = 0; q < static_cast<int>(pts.size()); ++q)
    if (std::cos(pts[q].v) > 0.5) by_u[pts[q].u].push_back(q);
  Brush b;
  double centre_u = 1e300, weight_sum = 0.0, trail_sum = 0.0, spring_sum = 0.0;
  for (auto& [u, all] : by_u) {
    std::sort(all.begin(), all.end(), [&](int i, int j) { return pts[i].reference.y() > pts[j].reference.y(); });
    int k0 = -1, k1 = -1;
    for (int k = 0; k < static_cast<int>(all.size()); ++k)
      if (s.normal[all[k]].pressure > 0) {
        if (k0 < 0) k0 = k;
        k1 = k;
      }
    if (k0 <= 0) continue;
    const int out = all[k0 - 1], in = all[k0];
    const double g0 = s.normal[out].penetration, g1 = s.normal[in].penetration, w = -g0 / (g1 - g0);
    const double ya = pts[out].reference.y() + w * (pts[in].reference.y() - pts[out].reference.y());
    bool sliding = false;
    for (int k = k0; k <= k1; ++k) {
      const int q = all[k];
      const double hp = pts[q].height, limit = kFriction * s.normal[q].pressure;
      const double stick = c / hp * std::abs(tan_a) * (ya - pts[q].reference.y());
      sliding = sliding || stick > limit;
      const double traction = (tan_a >= 0 ? 1.0 : -1.0) * (sliding ? limit : stick);  // along +x
      b.fy -= traction * pts[q].weight;
      b.mz -= s.normal[q].position.y() * traction * pts[q].weight;
      spring_sum += c / hp * pts[q].weight;
      b.mean_distance += c / hp * pts[q].weight * (ya - pts[q].reference.y());
    }
    const int out_b = all[k1 + 1], in_b = all[k1];
    const double h0 = s.normal[out_b].penetration, h1 = s.normal[in_b].penetration, wb = -h0 / (h1 - h0);
    const double yb = pts[out_b].reference.y() + wb * (pts[in_b].reference.y() - pts[out_b].reference.y());
    const double a = 0.5 * (ya - yb);
    double line_area = 0.0;
    for (int k = k0; k <= k1; ++k) line_area += pts[all[k]].weight;
    const double force = a * line_area;  // ∝ a² × width: the triangle of stick stress over 2a
    weight_sum += force;
    trail_sum += force * (a / 3.0 - 0.5 * (ya + yb));
    if (std::abs(u) < std::abs(centre_u)) centre_u = u, b.a_centre = a;
  }
  b.closed_trail = trail_sum / weight_sum;
  b.mean_distance /= spring_sum;
  return b;
}

const RollingStateResult& state(const RollingResult& r, int i) {
  EXPECT_TRUE(r.states.at(i).converged) << r.states.at(i).name << ": " << r.states.at(i).failure;
  return r.states.at(i);
}

TEST(CorneringBrush, LateralForceAndAligningMomentMatchTheBrushModel) {
  const RollingResult& r = run();
  ASSERT_TRUE(r.completed) << r.failure;
  for (std::size_t i = 0; i < kAngles.size(); ++i) {
    const RollingStateResult& s = state(r, static_cast<int>(i));
    const Brush b = brush(r, s, kAngles[i]);
    const RollingFigures& f = s.figures;
    std::printf("  α %+5.1f°: Fy FE %9.2f / brush %9.2f N (%+.2f%%), Mz FE %10.1f / brush %10.1f N·mm (%+.2f%%), "
                "stick %.2f\n", kAngles[i], f.Fy_N, b.fy, 100 * (f.Fy_N / b.fy - 1), f.aligning_moment_Nmm, b.mz,
                100 * (f.aligning_moment_Nmm / b.mz - 1), f.stick_area_fraction);
    EXPECT_NEAR(f.Fy_N, b.fy, 0.02 * std::abs(b.fy)) << "α " << kAngles[i];
    EXPECT_NEAR(f.aligning_moment_Nmm, b.mz, 0.05 * std::abs(b.mz)) << "α " << kAngles[i];
  }
}

TEST(CorneringBrush, PneumaticTrailTendsToAThirdOfTheHalfLength) {
  const RollingResult& r = run();
  const RollingStateResult& s = state(r, 0);  // α = 0.1°
  const Brush b = brush(r, s, kAngles[0]);
  ASSERT_TRUE(s.figures.pneumatic_trail_mm.has_value());
  const double trail = *s.figures.pneumatic_trail_mm, brush_trail = -b.mz / b.fy;
  std::printf("  α 0.1°: trail FE %.3f mm, brush on the FE pressure %.3f mm, closed form Σ a_l/3 %.3f mm (centre "
              "line a/3 = %.3f mm)\n", trail, brush_trail, b.closed_trail, b.a_centre / 3);
  EXPECT_NEAR(trail, brush_trail, 0.05 * brush_trail);
  EXPECT_NEAR(trail, b.closed_trail, 0.05 * b.closed_trail);
}

TEST(CorneringBrush, StandingStiffnessIsTheTreadsAndTheRelaxationLengthTheMeanDistanceFromTheLeadingEdge) {
  // With the carcass rigid the glued tread alone resists the road's motion: Cx = Cy = Σ (G/hp) w over the
  // patch; and σα = Kyα/Cy (Kyα from the α = 0.1° state, all stick) is the brush's mean distance of the
  // contact area from the leading edge (a for a rectangle of length 2a). Tolerances: 2% for Cx and Cy, as
  // for Fy above (the structure ×1000 leaves a carcass compliance in series with the tread, whose share
  // is Ct/Cc: observed −0.27% and −1.23%, the lateral one larger as the sidewalls bend; with the structure
  // ×10 000 a tenth of that, −0.027% and −0.124%, checked: 8–12 times less, below 0.2%); 2% for σα, where
  // that compliance lowers Kyα and Cy alike (observed +0.78%).
  const RollingResult& r = run();
  ASSERT_TRUE(r.standing_stiffness.has_value());
  const StandingStiffness& c = *r.standing_stiffness;
  ASSERT_TRUE(c.lateral_N_per_mm.has_value());
  const RollingStateResult& s = state(r, 0);  // α = 0.1°
  const Brush b = brush(r, s, kAngles[0]);
  const double k_alpha = std::abs(s.figures.Fy_N) / std::tan(kAngles[0] * M_PI / 180.0);
  const double sigma = k_alpha / *c.lateral_N_per_mm;
  std::printf("  rigid carcass: Cx %.2f, Cy %.2f N/mm against the tread's %.2f N/mm (%+.2f%%, %+.2f%%); σα = Kyα/Cy "
              "%.2f mm against the mean distance from the leading edge %.2f mm (%+.2f%%)\n", c.longitudinal_N_per_mm,
              *c.lateral_N_per_mm, c.tread_shear_N_per_mm, 100 * (c.longitudinal_N_per_mm / c.tread_shear_N_per_mm - 1),
              100 * (*c.lateral_N_per_mm / c.tread_shear_N_per_mm - 1), sigma, b.mean_distance,
              100 * (sigma / b.mean_distance - 1));
  // The deficit is the carcass's, in series: ten times stiffer again, it is ten times less.
  const auto deficit = [](double stiffness, double tread) { return 1.0 - stiffness / tread; };
  {
    const TyreDescription stiffer = stiffened_tyre(10 * kStiffening);
    const TyreMesh tm = build_tyre_mesh(stiffer, coarse_mesh(60, 12, false));
    ContactSettings cs = test_contact_settings(ContactSettings::Iteration::single_loop);
    cs.quadrature = 8;
    cs.residual_tolerance = 1e-8;
    FootprintStudy fs;
    fs.name = "stiffer";
    fs.target_load = kLoad;
    const StaticContactResult fp = run_footprint(tm, stiffer, example_case().inflation, cs, fs);
    ASSERT_TRUE(fp.completed) << fp.failure;
    const RoadPlane plane;
    const auto c10 = standing_stiffness(tm, stiffer, example_case().inflation.pressure, plane,
                                        fp.final_state.deflection_mm, fp.tread_points, fp.final_state.displacement);
    ASSERT_TRUE(c10 && c10->lateral_N_per_mm);
    std::printf("  x%.0f: Cx %.3f, Cy %.3f N/mm against the tread's %.3f (%+.3f%%, %+.3f%%)\n", 10 * kStiffening,
                c10->longitudinal_N_per_mm, *c10->lateral_N_per_mm, c10->tread_shear_N_per_mm,
                100 * (c10->longitudinal_N_per_mm / c10->tread_shear_N_per_mm - 1),
                100 * (*c10->lateral_N_per_mm / c10->tread_shear_N_per_mm - 1));
    const double dx = deficit(c.longitudinal_N_per_mm, c.tread_shear_N_per_mm),
                 dy = deficit(*c.lateral_N_per_mm, c.tread_shear_N_per_mm),
                 dx10 = deficit(c10->longitudinal_N_per_mm, c10->tread_shear_N_per_mm),
                 dy10 = deficit(*c10->lateral_N_per_mm, c10->tread_shear_N_per_mm);
    EXPECT_GT(dx10, 0.0);
    EXPECT_GT(dy10, 0.0);
    for (double ratio : {dx / dx10, dy / dy10}) {
      EXPECT_GT(ratio, 8.0);
      EXPECT_LT(ratio, 12.0);
    }
    EXPECT_LT(dy10, 0.002);
  }
  EXPECT_NEAR(c.longitudinal_N_per_mm, c.tread_shear_N_per_mm, 0.02 * c.tread_shear_N_per_mm);
  EXPECT_NEAR(*c.lateral_N_per_mm, c.tread_shear_N_per_mm, 0.02 * c.tread_shear_N_per_mm);
  EXPECT_LT(*c.lateral_N_per_mm, c.tread_shear_N_per_mm);  // in series with the carcass: never above the tread's
  EXPECT_NEAR(sigma, b.mean_distance, 0.02 * b.mean_distance);
}

}  // namespace
}  // namespace tirefem::verification
