// The rim flange (road/rim_flange.hpp, forms/rim_flange_form.hpp): the lower sidewall's outer face leaning
// on a rigid torus, the flange's curl, through a unilateral Winkler layer.
// - The curl's penetration, gradient and Hessian against central differences, on both flanges of the
//   full model.
// - Placement: the curl touches the outer face at the bead and clears every other outer node.
// - The form's tangent against central differences of its residual (released region, points on both
//   sides of g = 0), its symmetry, and that the curl's curvature term is large enough to be seen; its
//   energy's derivative is its residual.
// - A known answer: a band of the outer face concentric with the curl, inside it by δ all round, carries
//   the pressure kf δ, and its axial force is kf δ times the annulus it projects on a plane x = const,
//   π (ρ2² − ρ1²) (the radial forces cancel round the circle).
// - Equilibrium: rolling at a slip angle, the rim (beads and flanges) balances the contact's six components.
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "contact_support.hpp"
#include "form_fd_support.hpp"
#include "rolling_support.hpp"
#include "tirefem/analysis/rolling.hpp"
#include "tirefem/forms/rim_flange_form.hpp"

namespace tirefem::verification {
namespace {

constexpr double kAxis = 300.0;  // height of the wheel axis in the synthetic tests, mm

TEST(RimFlange, PenetrationDerivativesMatchFiniteDifferences) {
  const RimFlange flange(Eigen::Vector2d(75.0, 175.0), 9.5, kAxis, true);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> angle(-std::numbers::pi, std::numbers::pi), offset(-14.0, 14.0);
  double worst_gradient = 0.0, worst_hessian = 0.0;
  for (int k = 0; k < 60; ++k) {
    const double side = k % 2 ? -1.0 : 1.0, phi = angle(rng);
    const double a = side * (75.0 + offset(rng)), rho = 175.0 + offset(rng);
    const Eigen::Vector3d x(a, rho * std::sin(phi), kAxis - rho * std::cos(phi));
    const Penetration p = flange.penetration(x, 0.0);
    // The value is the distance to the circle in the meridian plane of the point's own side.
    EXPECT_NEAR(p.value, 9.5 - std::hypot(std::abs(a) - 75.0, rho - 175.0), 1e-11);
    Eigen::Vector3d grad;
    Eigen::Matrix3d hess;
    for (int i = 0; i < 3; ++i) {
      Eigen::Vector3d xp = x, xm = x;
      xp[i] += kFdStep, xm[i] -= kFdStep;
      const Penetration pp = flange.penetration(xp, 0.0), pm = flange.penetration(xm, 0.0);
      grad[i] = (pp.value - pm.value) / (2 * kFdStep);
      hess.col(i) = (pp.gradient - pm.gradient) / (2 * kFdStep);
    }
    worst_gradient = std::max(worst_gradient, (grad - p.gradient).norm() / p.gradient.norm());
    worst_hessian = std::max(worst_hessian, (hess - p.hessian).norm() / p.hessian.norm());
    EXPECT_NEAR(p.gradient.norm(), 1.0, 1e-12) << "the gradient is minus the curl's unit normal";
  }
  std::printf("  rim flange: gradient error %.2e, Hessian error %.2e\n", worst_gradient, worst_hessian);
  EXPECT_LT(worst_gradient, kFdTolerance);
  EXPECT_LT(worst_hessian, kFdTolerance);
}

TyreDescription tyre_on_flange() {
  TyreDescription t = example_case().tyre;
  t.rim_flange = RimFlangeDescription{9.5, 2.0};
  return t;
}

TEST(RimFlange, CurlTouchesTheOuterFaceAtTheBeadAndClearsTheRest) {
  for (const bool half : {true, false}) {
    const TyreMesh tm = build_tyre_mesh(tyre_on_flange(), coarse_mesh(16, 8, half));
    const RimFlange flange = place_rim_flange(tm.mesh, tm.axis_z, !half, 9.5);
    const ShellMesh& m = tm.mesh;
    double bead_worst = 0.0, others_least = 1e300;
    for (int j = 0; j < m.v_nodes(); ++j)
      for (int i = 0; i < m.u_nodes(); ++i) {
        const bool bead = i == m.u_nodes() - 1 || (!half && i == 0);
        const double c = flange.clearance(m.outer_nodes[m.pair_index(i, j)]);
        if (bead) bead_worst = std::max(bead_worst, std::abs(c));
        else others_least = std::min(others_least, c);
        // At the bead the inner face lies on the tyre's side of the outer face, away from the curl.
        if (bead) EXPECT_GT(flange.clearance(m.inner_nodes[m.pair_index(i, j)]), 1.0);
      }
    EXPECT_LT(bead_worst, 1e-9) << "the curl is tangent to the outer face at every bead node";
    EXPECT_GT(others_least, 0.05) << "the rest of the outer face is clear of the curl in the reference state";
    // The elements it may meet: the ones next to the bead (both beads on the full model).
    const std::vector<int> near = elements_near_flange(m, flange);
    EXPECT_EQ(static_cast<int>(near.size()) % m.v_elements(), 0);
    for (int e : near) {
      const int i = e % m.u_elements();
      EXPECT_TRUE(i >= m.u_elements() - 3 || (!half && i < 3)) << "element column " << i;
    }
  }
}

// A band of the outer face on tori concentric with the curl, over the meridian angles θ ∈ [θ1, θ2] from
// the axial direction and round the axis at the angles `phi` (the first 0, then up to but not including
// 2π): at angle φ its tube radius is R − depth(φ) (inside the curl by depth(φ)).
ShellMesh band_on_curl(const RimFlange& flange, const std::function<double(double)>& depth, double theta1,
                       double theta2, int n_theta, std::vector<double> phi) {
  const Eigen::Vector2d c = flange.centre();
  phi.push_back(2 * std::numbers::pi);
  std::vector<double> theta;
  for (int k = 0; k <= n_theta; ++k) theta.push_back(theta1 + (theta2 - theta1) * k / n_theta);
  return build_grid_mesh(theta, phi, true, [&](double t, double p) {
    const double r = flange.radius() - depth(p);
    const auto at = [&](double radius) {
      const double a = c.x() + radius * std::cos(t), rho = c.y() + radius * std::sin(t);
      return Eigen::Vector3d(a, rho * std::sin(p), kAxis - rho * std::cos(p));
    };
    return NodePairPosition{at(r - 3.0), at(r)};  // the inner face 3 mm further in
  });
}

std::vector<double> even_angles(int n) {
  std::vector<double> phi;
  for (int k = 0; k < n; ++k) phi.push_back(2 * std::numbers::pi * k / n);
  return phi;
}

// Uniformly pressed, the band carries kf δ everywhere, the axial force kf δ π(ρ2² − ρ1²) and no radial
// resultant, on a fine even mesh round the axis and on a coarse graded one alike: the points lie on the
// round wall, not on the elements' chords, whose sag (up to 3.4 mm on the coarse mesh, against δ = 2 mm)
// would otherwise press them into the curl unevenly.
TEST(RimFlange, ConcentricBandCarriesTheUniformPressureAndItsAxialForce) {
  const double depth = 2.0, kf = 2.0, t1 = -0.5, t2 = 2.0;
  const RimFlange flange(Eigen::Vector2d(75.0, 175.0), 9.5, kAxis, false);
  std::vector<double> graded;  // 24 elements from 0.5 to 1.5 times the even length
  for (int k = 0; k < 24; ++k) {
    const double even = 2 * std::numbers::pi * k / 24;
    graded.push_back(even + 0.5 * std::sin(even));  // d φ / d(even) = 1 + 0.5 cos
  }
  for (const auto& [name, phi] : {std::pair{"fine even", even_angles(720)}, std::pair{"coarse graded", graded}}) {
    const ShellMesh band = band_on_curl(flange, [&](double) { return depth; }, t1, t2, 40, phi);
    RimFlangeForm form(band, flange, kf);
    ASSERT_EQ(form.point_count(), 40 * static_cast<int>(phi.size()) * 9) << "every element lies near the curl";
    const Eigen::VectorXd u = Eigen::VectorXd::Zero(band.dof_count());
    const std::vector<TreadPointState> states = form.evaluate(u);
    Eigen::Vector3d force = Eigen::Vector3d::Zero();
    double least = 1e300, most = 0.0;
    for (const TreadPointState& s : states) {
      force += s.force;
      least = std::min(least, s.pressure), most = std::max(most, s.pressure);
    }
    // The Gauss points lie on the elements' meridian chords, inside the torus by at most their sag (h²/8r
    // with h = 2.5 r / 40: 0.004 mm here), so the pressure is kf δ within 0.5%.
    EXPECT_GT(least, kf * depth) << name;
    EXPECT_LT(most, kf * depth * 1.005) << name;
    const double r = 9.5 - depth, rho1 = 175.0 + r * std::sin(t1), rho2 = 175.0 + r * std::sin(t2);
    const double axial = kf * depth * std::numbers::pi * (rho2 * rho2 - rho1 * rho1);
    std::printf("  concentric band, %s: pressure %.5f .. %.5f MPa (kf δ = %.3f), axial force %.2f N (exact "
                "%.2f), radial resultant %.2e N\n",
                name, least, most, kf * depth, force.x(), axial, force.tail<2>().norm());
    EXPECT_NEAR(force.x(), axial, 5e-3 * std::abs(axial)) << name;
    // The radial forces cancel round the circle, to round-off on the even mesh and to the 3-point rule's
    // error on the graded one, whose lifted elements (15° on average) it integrates only approximately
    // (measured 7e-7; on the elements' chords, before the lift, it was 2e-3).
    EXPECT_LT(force.tail<2>().norm(), 1e-5 * std::abs(axial)) << name;
    // The flange's load as the outputs report it: the tyre's force on the flange, its push along the axis
    // counted outward (here the band lies on the curl's far side, so the push is inward: negative).
    const std::vector<RimFlangeLoad> loads = form.loads(u);
    ASSERT_EQ(loads.size(), 1u) << name;
    EXPECT_EQ(loads[0].side, 1);
    EXPECT_NEAR(loads[0].axial_force_N, -force.x(), 1e-9 * std::abs(axial));
    EXPECT_NEAR(loads[0].radial_force_N, force.tail<2>().norm(), 1e-9 * std::abs(axial));
    EXPECT_DOUBLE_EQ(loads[0].peak_pressure_MPa, most);
    EXPECT_DOUBLE_EQ(loads[0].contact_fraction, 1.0);
  }
}

// A band pressed into the curl over half its round (0 ≤ φ ≤ π) and clear of it elsewhere: the flange
// touches the 12 elements of that half and the 2 that straddle its ends, 14 of 24 columns.
TEST(RimFlange, LoadReportsTheShareOfTheRoundInContact) {
  const RimFlange flange(Eigen::Vector2d(75.0, 175.0), 9.5, kAxis, false);
  const auto depth = [](double phi) { return phi <= std::numbers::pi + 1e-9 ? 2.0 : -1.0; };
  const ShellMesh band = band_on_curl(flange, depth, -0.5, 2.0, 10, even_angles(24));
  const RimFlangeForm form(band, flange, 2.0);
  const std::vector<RimFlangeLoad> loads = form.loads(Eigen::VectorXd::Zero(band.dof_count()));
  ASSERT_EQ(loads.size(), 1u);
  EXPECT_DOUBLE_EQ(loads[0].contact_fraction, 14.0 / 24.0);
  EXPECT_GT(loads[0].radial_force_N, 0.1 * std::abs(loads[0].axial_force_N)) << "a one-sided contact has a radial resultant";
}

TEST(RimFlange, TangentAndEnergyMatchFiniteDifferences) {
  const SingleThread single_thread;
  const TyreMesh tm = build_tyre_mesh(tyre_on_flange(), coarse_mesh(8, 4, false, 1.0));
  const RimFlange flange = place_rim_flange(tm.mesh, tm.axis_z, true, 9.5);
  SingleFormProblem<RimFlangeForm> p(tm.mesh, std::make_unique<RimFlangeForm>(tm.mesh, flange, 2.0));
  // A random state of ±1.5 mm, redrawn until no point lies within 1e-3 mm of g = 0 (a step cannot cross
  // the kink) and there are points on both sides.
  Eigen::VectorXd u;
  int inside = 0, outside = 0;
  for (unsigned seed = 1; seed < 200; ++seed) {
    u = random_vector(tm.mesh.dof_count(), seed, 1.5);
    inside = outside = 0;
    double closest = 1e300;
    for (const TreadPointState& s : p.form->evaluate(u)) {
      (s.penetration > 0 ? inside : outside)++;
      closest = std::min(closest, std::abs(s.penetration));
    }
    if (closest > 1e-3 && inside > 10 && outside > 10) break;
  }
  ASSERT_GT(inside, 10);
  ASSERT_GT(outside, 10);
  const Eigen::MatrixXd k = p.tangent(u);
  const double error = max_relative_error(fd_tangent(p, u), k);
  EXPECT_LT(error, kFdTolerance);
  EXPECT_LT((k - k.transpose()).cwiseAbs().maxCoeff(), 1e-12 * k.cwiseAbs().maxCoeff());
  // The curl's curvature term kf g ∂²g is large enough for the check to see it (the same points on the
  // same curl with its Hessian dropped).
  const WithoutCurvature flat(flange);
  SingleFormProblem<WinklerContactForm> q(
      tm.mesh, std::make_unique<WinklerContactForm>(
                   tm.mesh, make_tread_points(tm.mesh, elements_near_flange(tm.mesh, flange), 3, [](double) { return 0.0; }),
                   2.0, flat));
  const double curvature_share = max_relative_error(q.tangent(u), k);
  EXPECT_GT(curvature_share, 1e3 * kFdTolerance);
  const double energy = energy_gradient_error(*p.problem, u, random_vector(tm.mesh.dof_count(), 17, 1.0), 1.0, 1e-5);
  EXPECT_LT(energy, 1e-6);
  std::printf("  rim flange form: %d points in contact, %d out; tangent error %.2e (curvature term %.2e of it), "
              "energy error %.2e\n", inside, outside, error, curvature_share, energy);
}

// The tyre leaning on its flanges, rolling at α = 4° on the plane (a coarse full model, 40 × 12 per half,
// kf = 20): the flanges carry part of the load, and the rim (the clamped beads and the flanges) balances
// all six force and moment components of the contact, 1e-6 of Fz (and of Fz × Rd for the moments).
RollingStateSpec cornering(double alpha_deg, const char* name) {
  RollingStateSpec s;
  s.kind = RollingStateSpec::Kind::given_slip;
  s.slip_angle_deg = alpha_deg;
  s.name = name;
  return s;
}

TEST(RimFlange, RimWithFlangesBalancesAllSixComponentsOfTheContact) {
  TyreDescription t = example_case().tyre;
  t.rim_flange = RimFlangeDescription{9.5, 20.0};
  const TyreMesh tm = build_tyre_mesh(t, coarse_mesh(40, 12, false));
  RollingStudy study;
  study.name = "flange";
  study.target_load = 3000.0;
  study.friction = 0.7;
  study.tread_shear = RollingStudy::TreadShear::planar;
  study.states = {cornering(4.0, "alpha+4")};
  ContactSettings settings = test_contact_settings(ContactSettings::Iteration::single_loop);
  settings.residual_tolerance = 1e-10;
  const RollingResult r = run_rolling(tm, t, example_case().inflation, settings, study);
  ASSERT_EQ(r.states.size(), 1u);
  const RollingStateResult& s = r.states[0];
  ASSERT_TRUE(s.converged) << s.failure;
  const Eigen::Vector3d centre(0.0, 0.0, tm.axis_z);
  RimReaction contact, flange;
  for (std::size_t q = 0; q < r.tread_points.size(); ++q) {
    const Eigen::Vector3d x = s.normal[q].position - r.tread_points[q].height * r.tread_points[q].normal;
    const Eigen::Vector3d f = s.normal[q].force + s.tangential[q].force;
    contact.force += f;
    contact.moment += (x - centre).cross(f);
  }
  const std::unique_ptr<RimFlangeForm> form = make_rim_flange_form(tm);
  ASSERT_TRUE(form);
  int touching = 0;
  for (const TreadPointState& p : form->evaluate(s.displacement)) {
    flange.force += p.force;
    touching += p.penetration > 0;
  }
  const RimReaction rim = rim_reaction(tm, example_case().inflation.pressure, s.displacement);
  const double fz = s.figures.Fz_N;
  std::printf("  α 4°: Fy %.1f N, Fz %.1f N; flange points touching %d of %d, flange force (%.1f, %.1f, %.1f) N\n",
              s.figures.Fy_N, fz, touching, form->point_count(), flange.force.x(), flange.force.y(), flange.force.z());
  EXPECT_GT(flange.force.norm(), 0.01 * fz) << "the flanges must carry a visible share for the balance to test them";
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(contact.force[i], -rim.force[i], 1e-6 * fz) << "force " << i;
    EXPECT_NEAR(contact.moment[i], -rim.moment[i], 1e-6 * fz * r.loaded_radius_mm) << "moment " << i;
  }
}

}  // namespace
}  // namespace tirefem::verification
