// Brush-model limit of steady rolling (issue item; VERIFICATION.md §5, Pacejka, Tyre and Vehicle Dynamics,
// ch. 3; MODEL.md §5): with a nearly rigid carcass and belt, the FE tangential stresses and Qy(κ) are those
// of the brush model built on the FE pressure.
//
// Set-up: the example tyre with every structural stiffness ×1000 (plies' cord and rubber moduli, direct face
// stiffnesses, core shear and normal moduli; the tread's kp = 1 N/mm³, G = 0.9 MPa, hp = 10 mm unchanged),
// 60 × 12 half model, 8 × 8 tread points per element (40 points, 1–2.2 mm apart, along the centre line of
// the patch), plane, μ = 0.7, footprint of 2000 N: patch 2a ≈ 60 mm, a/R ≈ 0.105. The crown barely deforms:
// the pressure is kp × the overlap of the rigid tread surface with the road (≈ parabolic along each
// circumferential line, 1.58 MPa at the centre) and the tread's shear is the only tangential compliance.
//
// Reference, built per state from the FE pressure alone: circumferential lines of tread points (equal s),
// ordered from the leading edge (largest y; the support moves −y); y the tread point's undeformed coordinate
// (the brush's rigid, straight base); leading edge y_A where the penetration crosses zero (linear
// interpolation between the last point out and the first in); brush slip σ = κ/(1 + κ) (base at Re Ω, road
// at V, Re the FE free-rolling radius); stick stress c σ (y_A − y), c = G/hp per unit area; traction
// sgn σ · min(c|σ|(y_A − y), μ qn), the bristle sliding to the exit once it has started (the pressure falls
// monotonically behind the slip point). FE traction along the travel: TreadTraction::force.y() / weight.
// Also Pacejka's closed form for a parabolic pressure per line (θ = 2ca²/(3μFz'), Fx = μFz(3θσ − 3θ²σ² +
// θ³σ³) below full sliding), with a and Fz' (per unit width) of a least-squares parabola through the FE
// line and Fz the line's force.
//
// Where the FE model departs from the brush model, and the tolerances:
// - The rigid crown's tread moves on a circle, not a straight line, and the crown's lines have different
//   radii r. In stick the FE stress is c[(y_A − y)' − Rk(φ_A − φ)] (' : deformed positions) with
//   Rk = Re(1 − σ), so exactly
//       qt_FE − qt_brush = (1 − σ) c D + σ c Δu,   D = (y_A − y)' − Re (φ_A − φ),   Δu = (y_A − y)' − (y_A − y),
//   D the free-rolling shear, ≈ (r − Re)(φ_A − φ) − r(φ_A³ − φ³)/6 = O(a³/R²), Δu the crown's remaining
//   stretch along the patch. Here r − Re ≈ 0.73 mm on the centre line (crown curvature a²/6R ≈ 0.5 mm,
//   plus the smaller radius of the outer lines, which lowers Re), φ_A ≈ 0.105: |D| ≤ 0.065 mm, c|D| ≤
//   0.006 MPa = 0.5% of μ qn,max = 1.11 MPa (against the brush's own largest stick stress c σ 2a that is
//   ≈ 0.001/σ: 1% at σ = 0.1, half of it at κ = 0.002, hence the comparison against μ qn). c|Δu| ≈ 5.5e-4
//   MPa (Δu ≈ 6e-3 mm: the ×1000 crown still stretches by 1e-4).
//   Checks (b): on the centre line max |qt_FE − qt_brush| ≤ (1 − σ) c|D|max + |σ| c|Δu|max (the estimate,
//   + 1e-5 MPa; equality where the worst point sticks in both) and ≤ 2% of μ qn,max (4× the estimate: "a
//   few %"); the worst point over all lines ≤ 2% of the centre line's μ qn,max as well.
// - Qy: D has (almost) no resultant — free rolling, Qy = 0, sticks up to the trailing-edge points — so D
//   acts through the sliding points only: |ΔQy| ≤ (1 − σ)(|Σ c D dA| + c|D|max · slip area) + |σ| c|Δu|max
//   · stick area, printed per state as "bound" (≤ 1.13% of Qy here, largest at κ = −0.3 and 0.002).
//   Checks (a): |ΔQy| ≤ bound + 0.1% of Qy, and ≤ 1.5% relative (measured ≤ 0.08%).
// - The crown is rigid enough: c|Δu|max < 0.1% of μ qn,max (measured 0.05%).
// - Stick/slip transition on the centre line (c): first sliding point of FE and brush within one point
//   spacing (D shifts it by c|D| / |d(μqn − c|σ|(y_A − y))/dy|, a fraction of a spacing: measured, the same
//   point in every state); stick area fractions within 0.02 (measured 0.004); the closed form's
//   x_s = a(2θ|σ| − 1) within one spacing of the brush transition.
// - Closed form against the point-wise brush sum (a cross-check of the reference, not of the FE): the
//   patch edges fall between tread points, so the sampled sum departs from the integral by O(h/2a) of the
//   stick stress near the trailing edge (h the point spacing): measured 2.2% at h ≈ 3.5 mm (40 × 12, 6 × 6
//   points), ≤ 0.72% here (h ≈ 1.5–2 mm); checked to 2%.
// The κ range: with the rigid crown's high pressure θ ≈ 1.24 on the centre line (more on the outer lines),
// full sliding needs σ ≈ 0.8; κ = 0.002 … 0.08 (and −0.03) is the near-linear range, κ = 0.3, 1 and −0.3
// (σ = 0.23, 0.5, −0.43; stick 23–63% of the area) the brush model's nonlinear one.
// Runtime ≈ 3 s on 2 cores (printed).
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
const std::vector<double> kSlips = {0.002, 0.01, 0.03, 0.08, 0.3, 1.0, -0.03, -0.3};

const TyreDescription& tyre() {
  static const TyreDescription t = stiffened_tyre(kStiffening);
  return t;
}

const TyreMesh& mesh() {
  static const TyreMesh tm = build_tyre_mesh(tyre(), coarse_mesh(60, 12));
  return tm;
}

const RollingResult& run() {
  static const RollingResult r = [] {
    const Stopwatch clock;
    ContactSettings s = test_contact_settings(ContactSettings::Iteration::single_loop);
    s.quadrature = 8;  // 40 points along the centre line of the patch
    // (1e-10 is below the round-off floor of the ×1000 structure: the inflation stalls at 3e-10.)
    s.residual_tolerance = 1e-8;
    RollingStudy st;
    st.name = "brush";
    st.target_load = kLoad;
    st.friction = kFriction;
    for (double k : kSlips) {
      RollingStateSpec spec;
      spec.kind = RollingStateSpec::Kind::given_slip;
      spec.slip = k;
      st.states.push_back(spec);
    }
    const Case& c = example_case();
    RollingResult res = run_rolling(mesh(), tyre(), c.inflation, s, st);
    std::printf("  nearly rigid tyre (x%.0f), 60 x 12, quadrature 8, %.0f N, mu %.1f: rolling study %.1f s "
                "(%d factorisations, %d Newton iterations)\n", kStiffening, kLoad, kFriction, clock.seconds(),
                res.counters.factorizations, res.counters.newton_iterations);
    return res;
  }();
  return r;
}

// One circumferential line of tread points in the patch, from the leading edge backwards.
struct Line {
  double u = 0.0;
  std::vector<int> points;  // in contact, leading first
  double yA = 0.0, vA = 0.0;  // leading edge: undeformed y (the brush's rigid base) and φ
  double yA_now = 0.0;        // leading edge in the deformed state (for the error estimate only)
  double yB = 0.0;            // trailing edge (undeformed y)
};

// Per state: the brush reference and the comparison.
struct Comparison {
  double kappa = 0.0, sigma = 0.0;
  double qy_fe = 0.0, qy_brush = 0.0, qy_parabolic = 0.0;
  double stick_fe = 0.0, stick_brush = 0.0;  // area fractions
  double bound = 0.0;          // |Qy_FE − Qy_brush| from the kinematic estimate (see the top), N
  double centre_bound = 0.0;   // max |qt_FE − qt_brush| on the centre line from the same estimate, MPa
  double stretch = 0.0;        // c |Δu|max: the crown's deformation along the lines, MPa
  // Centre line.
  double centre_worst = 0.0, centre_mu_qmax = 0.0;
  double all_lines_worst = 0.0, all_lines_worst_rel = 0.0;  // MPa; relative to each line's μ qn,max
  int fe_slip_index = -1, brush_slip_index = -1;  // first sliding point along the centre line (−1: none)
  double fe_slip_y = 0.0, brush_slip_y = 0.0, spacing = 0.0;
  double closed_form_xs = 0.0;  // parabolic closed form's transition (centre line), y
  double theta_centre = 0.0;
};

std::vector<Line> patch_lines(const RollingResult& r, const RollingStateResult& s) {
  const auto& pts = r.tread_points;
  std::map<double, std::vector<int>> by_u;
  for (int q = 0; q < static_cast<int>(pts.size()); ++q)
    if (std::cos(pts[q].v) > 0.5) by_u[pts[q].u].push_back(q);  // the lower part of the tyre only
  std::vector<Line> lines;
  for (auto& [u, all] : by_u) {
    std::sort(all.begin(), all.end(), [&](int a, int b) { return pts[a].reference.y() > pts[b].reference.y(); });
    int k0 = -1, k1 = -1;
    for (int k = 0; k < static_cast<int>(all.size()); ++k)
      if (s.normal[all[k]].pressure > 0) {
        if (k0 < 0) k0 = k;
        k1 = k;
      }
    if (k0 < 0) continue;
    EXPECT_GT(k0, 0);
    EXPECT_LT(k1 + 1, static_cast<int>(all.size()));
    for (int k = k0; k <= k1; ++k) EXPECT_GT(s.normal[all[k]].pressure, 0) << "one contact stretch per line";
    Line line;
    line.u = u;
    line.points.assign(all.begin() + k0, all.begin() + k1 + 1);
    // Where the penetration crosses zero between the last point out and the first in (linear).
    auto crossing = [&](int out, int in, double& y, double& v, double& y_now) {
      const double g0 = s.normal[out].penetration, g1 = s.normal[in].penetration, w = -g0 / (g1 - g0);
      y = pts[out].reference.y() + w * (pts[in].reference.y() - pts[out].reference.y());
      v = pts[out].v + w * (pts[in].v - pts[out].v);
      y_now = s.normal[out].position.y() + w * (s.normal[in].position.y() - s.normal[out].position.y());
    };
    double vB, yB_now;
    crossing(all[k0 - 1], all[k0], line.yA, line.vA, line.yA_now);
    crossing(all[k1 + 1], all[k1], line.yB, vB, yB_now);
    lines.push_back(std::move(line));
  }
  return lines;
}

// Pacejka's parabolic-pressure brush force, per unit μ Fz: 3x − 3x² + x³, x = θ|σ| (1 beyond full sliding).
double parabolic_ratio(double x) {
  x = std::min(x, 1.0);
  return 3 * x - 3 * x * x + x * x * x;
}

Comparison compare(const RollingResult& r, const RollingStateResult& s, bool print_centre) {
  Comparison out;
  out.kappa = *s.slip;
  out.sigma = out.kappa / (1.0 + out.kappa);
  out.qy_fe = s.figures.Qy_N;
  out.stick_fe = s.figures.stick_area_fraction;
  const double sigma = out.sigma, sign = sigma >= 0 ? 1.0 : -1.0;
  const double re = *r.effective_rolling_radius_mm;
  const double G = tyre().tread_shear_modulus;
  const auto& pts = r.tread_points;
  const std::vector<Line> lines = patch_lines(r, s);
  // The centre line: smallest |u|.
  const Line* centre = &lines.front();
  for (const Line& l : lines)
    if (std::abs(l.u) < std::abs(centre->u)) centre = &l;
  double area = 0.0, stick_area = 0.0, slip_area = 0.0;
  double d_max = 0.0, d_sum = 0.0;  // c|D|max, Σ c D dA (half model)
  for (const Line& line : lines) {
    const double c = G / pts[line.points.front()].height;
    bool sliding = false;
    double fz_line = 0.0, worst = 0.0, qmax = 0.0, line_d_max = 0.0;
    // Least-squares parabola qn = p0 + p1 y + p2 y² through the line (for the closed form).
    Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
    Eigen::Vector3d atb = Eigen::Vector3d::Zero();
    for (std::size_t k = 0; k < line.points.size(); ++k) {
      const int q = line.points[k];
      const double y = pts[q].reference.y(), qn = s.normal[q].pressure, w = pts[q].weight;
      // Brush model on the FE pressure, rigid straight base: y is the undeformed coordinate.
      const double stick = c * std::abs(sigma) * (line.yA - y);
      if (!sliding && stick > kFriction * qn) sliding = true;
      const double brush = sign * (sliding ? kFriction * qn : stick);
      out.qy_brush += 2.0 * brush * w;
      area += w;
      (sliding ? slip_area : stick_area) += w;
      // The error estimate (see the top): D on the deformed crown, Δu its deformation along the line.
      const double travel = line.yA_now - s.normal[q].position.y();
      const double D = travel - re * (line.vA - pts[q].v);
      line_d_max = std::max(line_d_max, c * std::abs(D));
      d_sum += c * D * w;
      out.stretch = std::max(out.stretch, c * std::abs(travel - (line.yA - y)));
      const double fe = s.tangential[q].force.y() / w;  // along the direction of travel
      worst = std::max(worst, std::abs(fe - brush));
      qmax = std::max(qmax, qn);
      fz_line += qn * w;
      const Eigen::Vector3d row(1.0, y, y * y);
      ata += row * row.transpose();
      atb += row * qn;
      if (&line == centre) {
        const bool fe_slip = s.tangential[q].status == TreadContact::slip;
        if (fe_slip && out.fe_slip_index < 0) out.fe_slip_index = static_cast<int>(k), out.fe_slip_y = y;
        if (sliding && out.brush_slip_index < 0) out.brush_slip_index = static_cast<int>(k), out.brush_slip_y = y;
        if (print_centre)
          std::printf("      y %8.3f  qn %.4f  qt FE %+.5f (%s)  brush %+.5f (%s)  mu qn %.4f\n", y, qn, fe,
                      fe_slip ? "slip " : "stick", brush, sliding ? "slip " : "stick", kFriction * qn);
      }
    }
    d_max = std::max(d_max, line_d_max);
    // Closed form for a parabolic pressure: a and Fz' (per unit width) from the fitted parabola (≥ 5 points),
    // else from the edges and a fitted amplitude.
    double a, ym, fz_unit;
    if (line.points.size() >= 5) {
      const Eigen::Vector3d p = ata.ldlt().solve(atb);
      const double q0 = p[0] - p[1] * p[1] / (4 * p[2]);
      a = std::sqrt(-q0 / p[2]);
      ym = -p[1] / (2 * p[2]);
      fz_unit = 4.0 / 3.0 * q0 * a;
    } else {
      a = 0.5 * (line.yA - line.yB);
      ym = 0.5 * (line.yA + line.yB);
      double num = 0, den = 0;
      for (int q : line.points) {
        const double shape = 1 - std::pow((pts[q].reference.y() - ym) / a, 2);
        num += shape * s.normal[q].pressure, den += shape * shape;
      }
      fz_unit = 4.0 / 3.0 * (num / den) * a;
    }
    const double theta = 2 * c * a * a / (3 * kFriction * fz_unit);
    out.qy_parabolic += 2.0 * sign * kFriction * fz_line * parabolic_ratio(theta * std::abs(sigma));
    if (&line == centre) {
      out.centre_worst = worst;
      out.centre_mu_qmax = kFriction * qmax;
      out.centre_bound = (1.0 - sigma) * line_d_max;  // + |σ| stretch, added below
      out.theta_centre = theta;
      out.closed_form_xs = ym + a * std::min(1.0, 2 * theta * std::abs(sigma) - 1);  // stick from +a down to x_s
      for (std::size_t k = 0; k + 1 < line.points.size(); ++k) {
        const int idx = std::max(out.fe_slip_index, 0);
        if (static_cast<int>(k) == idx || static_cast<int>(k) + 1 == idx)
          out.spacing = std::max(out.spacing, std::abs(pts[line.points[k]].reference.y() -
                                                       pts[line.points[k + 1]].reference.y()));
      }
    }
    out.all_lines_worst = std::max(out.all_lines_worst, worst);
    out.all_lines_worst_rel = std::max(out.all_lines_worst_rel, worst / (kFriction * qmax));
  }
  out.stick_brush = stick_area / area;
  out.centre_bound += std::abs(sigma) * out.stretch;
  // In stick qt_FE − qt_brush = (1 − σ) c D + σ c Δu. Σ c D dA over the patch is what free rolling leaves
  // (its few slip points), so the stick points' share of the D term is bounded by |Σ c D dA| + c|D|max ×
  // slip area; a point whose status differs is off by less than the point-wise bound too. ×2: half model.
  out.bound = 2.0 * ((1.0 - sigma) * (std::abs(d_sum) + d_max * slip_area) + std::abs(sigma) * out.stretch * stick_area);
  return out;
}

const std::vector<Comparison>& comparisons() {
  static const std::vector<Comparison> all = [] {
    const RollingResult& r = run();
    std::vector<Comparison> v;
    for (const RollingStateResult& s : r.states)
      if (s.converged) v.push_back(compare(r, s, false));
    return v;
  }();
  return all;
}

TEST(RollingBrush, StudyCompletesOnANearlyRigidCrown) {
  const RollingResult& r = run();
  ASSERT_TRUE(r.completed) << r.failure;
  ASSERT_EQ(comparisons().size(), kSlips.size());
  const double re = *r.effective_rolling_radius_mm;
  const RollingStateResult& s0 = r.states.front();
  const std::vector<Line> lines = patch_lines(r, s0);
  const Line* centre = &lines.front();
  for (const Line& l : lines)
    if (std::abs(l.u) < std::abs(centre->u)) centre = &l;
  const double a = 0.5 * (centre->yA - centre->yB), rc = centre->yA / std::sin(centre->vA);
  std::printf("  Re %.3f mm, Rd %.3f mm, axle %.3f mm; centre line: %zu points, a %.2f mm, r %.3f mm, "
              "a/R %.4f, a^2/R^2 %.5f, phi_A^2/6 %.5f, r - Re %.3f mm; %zu lines in contact\n",
              re, r.loaded_radius_mm, r.axle_z, centre->points.size(), a, rc, a / rc, a * a / (rc * rc),
              centre->vA * centre->vA / 6, rc - re, lines.size());
  EXPECT_GE(centre->points.size(), 16u);
  // The structure hardly deforms: along the patch, the tread points' travel differs from the rigid crown's
  // by a stretch Δu whose stress c|Δu| is below 0.1% of the friction stress μ qn,max.
  for (const Comparison& c : comparisons()) {
    std::printf("  kappa %+.3f: c |du|max %.2e MPa = %.4f%% of mu qn,max\n", c.kappa, c.stretch,
                100 * c.stretch / c.centre_mu_qmax);
    EXPECT_LT(c.stretch, 1e-3 * c.centre_mu_qmax);
  }
}

TEST(RollingBrush, LongitudinalForceMatchesBrushModel) {
  ASSERT_TRUE(run().completed) << run().failure;
  std::printf("  %7s %8s | %9s %9s %7s | %9s %7s | %6s | %6s %6s | %5s\n", "kappa", "sigma", "Qy FE", "brush",
              "err %", "parabol.", "vs br %", "bound%", "stickF", "stickB", "theta");
  for (const Comparison& c : comparisons()) {
    const double err = c.qy_fe / c.qy_brush - 1, par = c.qy_parabolic / c.qy_brush - 1;
    std::printf("  %+7.3f %+8.5f | %9.3f %9.3f %+7.3f | %9.3f %+7.3f | %6.3f | %6.3f %6.3f | %5.3f\n", c.kappa,
                c.sigma, c.qy_fe, c.qy_brush, 100 * err, c.qy_parabolic, 100 * par,
                100 * c.bound / std::abs(c.qy_brush), c.stick_fe, c.stick_brush, c.theta_centre);
    EXPECT_NEAR(err, 0.0, 0.015) << "kappa " << c.kappa;
    EXPECT_NEAR(par, 0.0, 0.02) << "kappa " << c.kappa;
    EXPECT_LT(std::abs(c.qy_fe - c.qy_brush), c.bound + 1e-3 * std::abs(c.qy_brush)) << "kappa " << c.kappa;
    EXPECT_NEAR(c.stick_fe, c.stick_brush, 0.02) << "kappa " << c.kappa;
  }
  // Qy grows with the slip.
  for (std::size_t i = 1; i < comparisons().size(); ++i)
    if (comparisons()[i].kappa > comparisons()[i - 1].kappa)
      EXPECT_GT(comparisons()[i].qy_fe, comparisons()[i - 1].qy_fe);
}

TEST(RollingBrush, CentreLineTractionMatchesBrushModel) {
  const RollingResult& r = run();
  ASSERT_TRUE(r.completed) << r.failure;
  for (std::size_t i = 0; i < r.states.size(); ++i) {
    const Comparison& c = comparisons()[i];
    std::printf("  kappa %+.3f: centre line max |qt FE - brush| %.5f MPa = %.3f%% of mu qn,max %.4f MPa (estimate "
                "%.5f MPa); all lines %.5f MPa (%.2f%% of the line's own mu qn,max at worst); first slip "
                "point FE #%d y %.2f, brush #%d y %.2f (spacing %.2f mm), closed form x_s %.2f mm\n", c.kappa,
                c.centre_worst, 100 * c.centre_worst / c.centre_mu_qmax, c.centre_mu_qmax,
                c.centre_bound, c.all_lines_worst, 100 * c.all_lines_worst_rel, c.fe_slip_index,
                c.fe_slip_y, c.brush_slip_index, c.brush_slip_y, c.spacing, c.closed_form_xs);
    if (std::abs(c.kappa - 0.3) < 1e-9) compare(r, r.states[i], true);  // the distribution, for the record
    EXPECT_LT(c.centre_worst, 0.02 * c.centre_mu_qmax) << "kappa " << c.kappa;
    EXPECT_LT(c.centre_worst, c.centre_bound + 1e-5) << "kappa " << c.kappa;
    EXPECT_LT(c.all_lines_worst, 0.02 * c.centre_mu_qmax) << "kappa " << c.kappa;
    ASSERT_EQ(c.fe_slip_index < 0, c.brush_slip_index < 0) << "kappa " << c.kappa;
    if (c.fe_slip_index >= 0) {
      EXPECT_LE(std::abs(c.fe_slip_y - c.brush_slip_y), c.spacing + 1e-9) << "kappa " << c.kappa;
      EXPECT_LE(std::abs(c.closed_form_xs - c.brush_slip_y), c.spacing + 1e-9) << "kappa " << c.kappa;
    }
  }
}

}  // namespace
}  // namespace tirefem::verification
