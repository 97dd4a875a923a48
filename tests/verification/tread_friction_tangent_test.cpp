// Consistency of the tread friction form of steady rolling (MODEL.md §5, eqs. 15–17) and of the supports'
// travel coordinate ξ: the form's tangent is the exact derivative of its residual (unsymmetric, with the
// coupling of a stick point to its anchor upstream on its line), ∂ξ/∂x and ∂²ξ/∂x² are the exact
// derivatives of ξ, and the tractions the form reports add up to its residual.
//
// Reference: central finite differences with h = 1e-5 mm (form_fd_support.hpp); tolerance: relative error
// 1e-6 of the largest entry, for the tangents with a frozen plan (Coulomb on the plane and on the drum
// R 915 with the support moving in −y and +y; full stick; full slip of both signs) and with a released plan
// at a state where no step of h changes the plan (no tread point within 1e-3 mm of g = 0, the plan's
// statuses, anchors and slip signs identical at every perturbed state), and for ∂ξ, ∂²ξ of the plane and
// the drum (|∇ξ| within 1e-3 of 1 within 0.5 mm of the drum's surface). The frozen Coulomb plans are built
// to contain every kind of point the form knows (asserted, so the checks cannot pass vacuously): stick
// points anchored at the entry (interpolated between two points, 0 < w < 1), slip points of both signs
// and stick points re-anchored on a slip point; their tangents must be unsymmetric
// (‖K − Kᵀ‖max > 1e-3 ‖K‖max). evaluate(): Σ force = −Σ residual per component to 1e-10 of Σ|force|;
// slip |qt| = μ kp g and stick qt = G s/hp, s recomputed here from eq. (16) and the plan, to 1e-12.
//
// State: the patch of form_fd_support.hpp (tread radius 290 mm, 3 × 3 tread points per element, lines of
// 30 points along the flow), δz = 4 mm, kp = 1.3 N/mm³, G = 0.9 MPa, hp = 7 mm, μ = 0.2, Rk 5 % below the tread
// radius (braking: the would-be stick shear grows against the flow and the tread slides near the exit),
// a random displacement of ±0.2 mm on every DOF, plus, in the middle of the patch, one row of nodes lifted
// by 3.5 mm (a dip in the pressure: the tread slides there and sticks again behind it) and pushed 5 mm
// against the flow (the would-be shear there changes sign: slip of the other sign).
#include <cstdio>
#include <random>

#include <gtest/gtest.h>

#include "form_fd_support.hpp"
#include "tirefem/forms/tread_friction_form.hpp"
#include "tirefem/road/support_surface.hpp"

namespace tirefem::verification {
namespace {

constexpr double kKp = 1.3;          // tread stiffness, N/mm³
constexpr double kShear = 0.9;       // tread rubber shear modulus G, MPa
constexpr double kMu = 0.2;          // friction coefficient
constexpr double kDrumRadius = 915.0;
constexpr double kTreadRadius = kAxisZ;  // undeformed tread surface about the axis
constexpr double kMargin = 1e-3;     // released plan: no tread point this close to g = 0

using FrictionOnly = SingleFormProblem<TreadFrictionForm>;

FrictionLaw coulomb(double mu = kMu) {
  FrictionLaw law;
  law.mode = FrictionLaw::Mode::coulomb;
  law.friction = mu;
  return law;
}

FrictionOnly friction_only(const ShellMesh& mesh, const SupportSurface& support, int direction, double deflection,
                           double rolling_radius, const FrictionLaw& law) {
  std::vector<TreadPoint> points = patch_points(mesh);
  std::vector<char> window(points.size(), 1);
  auto form = std::make_unique<TreadFrictionForm>(mesh, std::move(points), kKp, kShear, support, direction,
                                                  std::move(window));
  form->set_deflection(deflection);
  form->set_rolling_radius(rolling_radius);
  form->set_law(law);
  return FrictionOnly(mesh, std::move(form));
}

// Random ±amplitude on every DOF, plus a pressure dip across the patch: the node row at φ = 0 lifted by
// `lift` and moved by `push` in y.
Eigen::VectorXd random_state(const ShellMesh& mesh, std::mt19937& rng, double amplitude, double lift, double push) {
  std::uniform_real_distribution<double> uniform(-amplitude, amplitude);
  Eigen::VectorXd u(mesh.dof_count());
  for (int i = 0; i < u.size(); ++i) u[i] = uniform(rng);
  const int row = mesh.v_nodes() / 2;  // φ = 0
  for (int i = 0; i < mesh.u_nodes(); ++i) {
    const int p = mesh.pair_index(i, row);
    u[outer_dof(p, 1)] += push;
    u[outer_dof(p, 2)] += lift;
  }
  return u;
}

Eigen::Vector3d position(const TreadPoint& p, const Eigen::VectorXd& u) {
  Eigen::Vector3d x = p.reference;
  for (int a = 0; a < 4; ++a) x += p.shape[a] * u.segment<3>(outer_dof(p.pairs[a], 0));
  return x;
}

struct PlanCounts {
  int out = 0, stick = 0, stick_entry = 0, stick_on_slip = 0, slip_positive = 0, slip_negative = 0;
};

PlanCounts count(const FrictionPlan& plan) {
  PlanCounts c;
  for (const FrictionPlanPoint& p : plan) {
    if (p.status == TreadContact::out) {
      ++c.out;
    } else if (p.status == TreadContact::slip) {
      (p.sign > 0 ? c.slip_positive : c.slip_negative)++;
    } else {
      ++c.stick;
      if (p.anchored_on_slip) ++c.stick_on_slip;
      if (!p.anchored_on_slip && p.anchor_a != p.anchor_b && p.anchor_weight > 0 && p.anchor_weight < 1)
        ++c.stick_entry;
    }
  }
  return c;
}

// The discrete part of a plan (what a step of h must not change; the entry weights move with u).
bool same_decisions(const FrictionPlan& a, const FrictionPlan& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t q = 0; q < a.size(); ++q)
    if (a[q].status != b[q].status || a[q].anchor_a != b[q].anchor_a || a[q].anchor_b != b[q].anchor_b ||
        a[q].anchored_on_slip != b[q].anchored_on_slip || a[q].sign != b[q].sign)
      return false;
  return true;
}

double asymmetry(const Eigen::MatrixXd& k) {
  return (k - k.transpose()).cwiseAbs().maxCoeff() / k.cwiseAbs().maxCoeff();
}

// ---- 1. travel coordinate ------------------------------------------------------------------------------

struct TravelErrors {
  double gradient = 0.0, hessian = 0.0, unit = 0.0;
};

// ∂ξ vs central differences of ξ and ∂²ξ vs central differences of ∂ξ at points within 0.5 mm of the
// support's surface near its top (both signs of y).
TravelErrors travel_errors(const SupportSurface& s, double deflection, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> ux(-60, 60), uy(-120, 120), ud(-0.5, 0.5);
  TravelErrors e;
  for (int k = 0; k < 40; ++k) {
    const double y = k < 2 ? (k == 0 ? 1e-3 : -1e-3) : uy(rng);
    const Eigen::Vector3d x(ux(rng), y, s.height(0.0, y, deflection) + ud(rng));
    const TravelCoordinate t = s.travel(x, deflection);
    Eigen::Vector3d grad;
    Eigen::Matrix3d hess;
    for (int i = 0; i < 3; ++i) {
      Eigen::Vector3d a = x, b = x;
      a[i] += kFdStep, b[i] -= kFdStep;
      const TravelCoordinate ta = s.travel(a, deflection), tb = s.travel(b, deflection);
      grad[i] = (ta.value - tb.value) / (2 * kFdStep);
      hess.col(i) = (ta.gradient - tb.gradient) / (2 * kFdStep);
    }
    e.gradient = std::max(e.gradient, (grad - t.gradient).norm() / t.gradient.norm());
    const double scale = t.hessian.norm();
    e.hessian = std::max(e.hessian, scale == 0.0 ? hess.norm() : (hess - t.hessian).norm() / scale);
    e.unit = std::max(e.unit, std::abs(t.gradient.norm() - 1.0));
  }
  return e;
}

TEST(TreadFrictionTangent, TravelCoordinateDerivatives) {
  RoadPlane plane;
  TestDrum drum(kDrumRadius);
  for (double deflection : {0.0, 3.0, 8.0}) {
    const TravelErrors p = travel_errors(plane, deflection, 7);
    const TravelErrors d = travel_errors(drum, deflection, 8);
    EXPECT_LT(p.gradient, kFdTolerance) << "plane, δz " << deflection;
    EXPECT_LT(p.hessian, kFdTolerance) << "plane, δz " << deflection;
    EXPECT_LT(p.unit, 1e-3) << "plane, δz " << deflection;
    EXPECT_LT(d.gradient, kFdTolerance) << "drum, δz " << deflection;
    EXPECT_LT(d.hessian, kFdTolerance) << "drum, δz " << deflection;
    EXPECT_LT(d.unit, 1e-3) << "drum, δz " << deflection << ": |∇ξ| near the surface";
    std::printf("  δz %.0f: plane ξ gradient error %.2e, hessian %.2e, ||∇ξ| − 1| %.1e; drum R 915 gradient "
                "%.2e, hessian %.2e, ||∇ξ| − 1| %.1e\n",
                deflection, p.gradient, p.hessian, p.unit, d.gradient, d.hessian, d.unit);
  }
  // Values: ξ = y on the plane; on the drum the arc length from its top, R θ, counted in +y.
  EXPECT_DOUBLE_EQ(plane.travel(Eigen::Vector3d(3.0, -42.0, 1.0), 2.0).value, -42.0);
  const double theta = 0.05, zc = 3.0 - kDrumRadius;
  for (double sign : {1.0, -1.0}) {
    const Eigen::Vector3d on(1.0, sign * kDrumRadius * std::sin(theta), zc + kDrumRadius * std::cos(theta));
    EXPECT_NEAR(drum.travel(on, 3.0).value, sign * kDrumRadius * theta, 1e-9);
    EXPECT_NEAR(drum.travel(on, 3.0).gradient.norm(), 1.0, 1e-12);
  }
}

// ---- 2.–4. frozen plans --------------------------------------------------------------------------------

struct FrozenCase {
  const char* label;
  const SupportSurface& support;
  int direction;
  double deflection;
  double rolling_radius;
  FrictionLaw law;
  double amplitude = 0.2, lift = 3.5, push = 0.0;
  unsigned seed = 4711;
};

struct FrozenResult {
  PlanCounts counts;
  double error = 0.0, asymmetry = 0.0;
};

FrozenResult check_frozen(const FrozenCase& c) {
  const SingleThread single_thread;
  const ShellMesh mesh = tyre_patch_mesh();
  FrictionOnly f = friction_only(mesh, c.support, c.direction, c.deflection, c.rolling_radius, c.law);
  std::mt19937 rng(c.seed);
  // The push is against the flow: the support moves in direction · y.
  const Eigen::VectorXd u = random_state(mesh, rng, c.amplitude, c.lift, -c.direction * c.push);
  const FrictionPlan plan = f.form->plan(u);
  f.form->freeze_plan(plan);
  FrozenResult r;
  r.counts = count(plan);
  const Eigen::MatrixXd k = f.tangent(u);
  r.error = max_relative_error(fd_tangent(f, u), k);
  r.asymmetry = asymmetry(k);
  EXPECT_LT(r.error, kFdTolerance) << c.label << ": frozen plan, tangent vs central differences";
  std::printf("  %s: %d stick (%d anchored at the entry, %d on a slip point), slip %d (+) %d (−), %d out; "
              "tangent error %.2e, asymmetry %.2e\n",
              c.label, r.counts.stick, r.counts.stick_entry, r.counts.stick_on_slip, r.counts.slip_positive,
              r.counts.slip_negative, r.counts.out, r.error, r.asymmetry);
  return r;
}

void expect_mixed_plan(const FrozenResult& r, const char* label) {
  EXPECT_GT(r.counts.stick_entry, 0) << label << ": no stick point anchored at the entry";
  EXPECT_GT(r.counts.stick_on_slip, 0) << label << ": no stick point anchored on a slip point";
  EXPECT_GT(r.counts.slip_positive, 0) << label << ": no slip point with σ = +1";
  EXPECT_GT(r.counts.slip_negative, 0) << label << ": no slip point with σ = −1";
  EXPECT_GT(r.asymmetry, 1e-3) << label << ": the tangent must be unsymmetric";
}

constexpr double kBraking = 0.95 * kTreadRadius;  // Rk: 5 % slip

TEST(TreadFrictionTangent, CoulombFrozenPlanOnPlane) {
  RoadPlane plane;
  for (int direction : {1, -1}) {
    FrozenCase c{direction > 0 ? "plane, support in +y" : "plane, support in −y", plane, direction, 4.0, kBraking,
                 coulomb()};
    c.push = 5.0;
    expect_mixed_plan(check_frozen(c), c.label);
  }
}

TEST(TreadFrictionTangent, CoulombFrozenPlanOnDrum) {
  TestDrum drum(kDrumRadius);
  for (int direction : {-1, 1}) {
    FrozenCase c{direction > 0 ? "drum R 915, support in +y" : "drum R 915, support in −y", drum, direction, 4.0,
                 kBraking, coulomb()};
    c.push = 5.0;
    expect_mixed_plan(check_frozen(c), c.label);
  }
}

TEST(TreadFrictionTangent, FullStickAndFullSlipFrozenPlans) {
  RoadPlane plane;
  TestDrum drum(kDrumRadius);
  FrictionLaw stick;
  stick.mode = FrictionLaw::Mode::full_stick;
  const std::vector<const SupportSurface*> supports{&plane, &drum};
  for (const SupportSurface* s : supports) {
    const bool is_drum = s == &drum;
    const char* stick_label = is_drum ? "drum, full stick" : "plane, full stick";
    const FrozenResult r = check_frozen({stick_label, *s, -1, 4.0, kBraking, stick});
    EXPECT_EQ(r.counts.slip_positive + r.counts.slip_negative, 0);
    EXPECT_GT(r.counts.stick_entry, 0);
    EXPECT_GT(r.asymmetry, 1e-3) << "full stick: the anchor coupling makes the tangent unsymmetric";
    for (double sign : {1.0, -1.0}) {
      FrictionLaw slip;
      slip.mode = FrictionLaw::Mode::full_slip;
      slip.friction = 0.7;
      slip.slip_sign = sign;
      const char* label = is_drum ? (sign > 0 ? "drum, full slip σ = +1" : "drum, full slip σ = −1")
                                  : (sign > 0 ? "plane, full slip σ = +1" : "plane, full slip σ = −1");
      const FrozenResult q = check_frozen({label, *s, 1, 4.0, kBraking, slip});
      EXPECT_EQ(q.counts.stick, 0);
      EXPECT_GT(sign > 0 ? q.counts.slip_positive : q.counts.slip_negative, 0);
      EXPECT_GT(q.asymmetry, 1e-3) << "full slip: [Ksl] = μ kp t nᵀ is unsymmetric";
    }
  }
}

// ---- 5. released plan ----------------------------------------------------------------------------------

TEST(TreadFrictionTangent, CoulombReleasedPlan) {
  const SingleThread single_thread;
  const ShellMesh mesh = tyre_patch_mesh();
  TestDrum drum(kDrumRadius);
  FrictionOnly f = friction_only(mesh, drum, -1, 4.0, kBraking, coulomb());
  std::mt19937 rng(2024);
  const int n = mesh.dof_count();
  for (int attempt = 0; attempt < 20; ++attempt) {
    const Eigen::VectorXd u = random_state(mesh, rng, 0.2, 3.5, 5.0);
    const FrictionPlan plan = f.form->plan(u);
    // No tread point near g = 0.
    double closest = 1e300;
    for (const TreadPoint& p : f.form->points())
      closest = std::min(closest, std::abs(drum.penetration(position(p, u), 4.0).value));
    if (closest <= kMargin) continue;
    // No step of h changes the plan's decisions.
    bool stable = true;
    Eigen::VectorXd v = u;
    for (int j = 0; j < n && stable; ++j) {
      for (double step : {kFdStep, -kFdStep}) {
        v[j] = u[j] + step;
        stable = stable && same_decisions(plan, f.form->plan(v));
      }
      v[j] = u[j];
    }
    if (!stable) continue;
    const PlanCounts c = count(plan);
    ASSERT_GT(c.stick_entry, 0);
    ASSERT_GT(c.stick_on_slip, 0);
    ASSERT_GT(c.slip_positive + c.slip_negative, 0);
    f.form->release_plan();
    const Eigen::MatrixXd k = f.tangent(u);
    const double error = max_relative_error(fd_tangent(f, u), k);
    EXPECT_LT(error, kFdTolerance) << "released plan: tangent vs central differences";
    std::printf("  drum R 915, released plan (attempt %d): %d stick (%d at the entry, %d on slip), %d slip, closest "
                "|g| %.2e mm; tangent error %.2e\n",
                attempt + 1, c.stick, c.stick_entry, c.stick_on_slip, c.slip_positive + c.slip_negative, closest,
                error);
    return;
  }
  FAIL() << "no random state found where a step of h leaves the plan unchanged";
}

// ---- 6. evaluate() -------------------------------------------------------------------------------------

TEST(TreadFrictionTangent, EvaluateMatchesResidual) {
  const SingleThread single_thread;
  const ShellMesh mesh = tyre_patch_mesh();
  TestDrum drum(kDrumRadius);
  const int direction = -1;
  const double deflection = 4.0;
  FrictionOnly f = friction_only(mesh, drum, direction, deflection, kBraking, coulomb());
  std::mt19937 rng(4711);
  const Eigen::VectorXd u = random_state(mesh, rng, 0.2, 3.5, 5.0);
  const FrictionPlan plan = f.form->plan(u);
  f.form->freeze_plan(plan);
  const PlanCounts counts = count(plan);
  ASSERT_GT(counts.stick_entry, 0);
  ASSERT_GT(counts.stick_on_slip, 0);
  ASSERT_GT(counts.slip_positive + counts.slip_negative, 0);

  const std::vector<TreadTraction> tractions = f.form->evaluate(u);
  const Eigen::VectorXd r = f.residual(u);
  const std::vector<TreadPoint>& points = f.form->points();
  Eigen::Vector3d total = Eigen::Vector3d::Zero(), total_abs = Eigen::Vector3d::Zero(), residual_sum;
  for (const TreadTraction& t : tractions) total += t.force, total_abs += t.force.cwiseAbs();
  for (int c = 0; c < 3; ++c) {
    residual_sum[c] = 0.0;
    for (int p = 0; p < mesh.pair_count(); ++p) residual_sum[c] += r[outer_dof(p, c)] + r[inner_dof(p, c)];
  }
  double force_error = 0.0;
  for (int c = 0; c < 3; ++c) {
    const double e = std::abs(total[c] + residual_sum[c]) / total_abs.maxCoeff();
    force_error = std::max(force_error, e);
    EXPECT_LT(e, 1e-10) << "component " << c << ": Σ force " << total[c] << " vs −Σ residual " << -residual_sum[c];
  }

  // Tractions point by point, s recomputed from eq. (16) and the plan.
  auto travel = [&](int q) { return direction * drum.travel(position(points[q], u), deflection).value; };
  auto angle = [&](int q) { return direction * points[q].v; };
  double slip_error = 0.0, stick_error = 0.0;
  for (std::size_t q = 0; q < points.size(); ++q) {
    const FrictionPlanPoint& pp = plan[q];
    const TreadTraction& t = tractions[q];
    EXPECT_EQ(t.status, pp.status);
    if (pp.status == TreadContact::out) continue;
    const double g = drum.penetration(position(points[q], u), deflection).value;
    if (pp.status == TreadContact::slip) {
      const double expected = kMu * kKp * g;
      slip_error = std::max(slip_error, std::abs(std::abs(t.traction) - expected) / expected);
      EXPECT_GT(t.traction * pp.sign, 0.0) << "slip point " << q << ": the traction must act along σ t";
      continue;
    }
    const int a = pp.anchor_a, b = pp.anchor_b;
    const double w = pp.anchor_weight;
    double s_anchor = 0.0;
    if (pp.anchored_on_slip)
      s_anchor = pp.sign * kMu * kKp * drum.penetration(position(points[a], u), deflection).value *
                 points[a].height / kShear;
    const double s = s_anchor + kBraking * (angle(q) - (1 - w) * angle(a) - w * angle(b)) -
                     (travel(q) - (1 - w) * travel(a) - w * travel(b));
    const double expected = kShear * s / points[q].height;
    // s is a difference of O(100 mm) terms: its round-off is O(1e-14 mm), so it is compared to 1e-12 of
    // max(|s|, 1 mm); qt = G s/hp exactly as the form reports s.
    stick_error = std::max(stick_error, std::abs(t.shear - s) / std::max(std::abs(s), 1.0));
    stick_error = std::max(stick_error, std::abs(t.traction - kShear * t.shear / points[q].height) /
                                            std::max(std::abs(expected), 1e-300));
  }
  EXPECT_LT(slip_error, 1e-12) << "slip points: |qt| = μ kp g";
  EXPECT_LT(stick_error, 1e-12) << "stick points: qt = G s/hp, s from eq. (16)";
  std::printf("  drum R 915, frozen plan: Σ force + Σ residual %.2e of Σ|force|; slip |qt| vs μ kp g %.2e; "
              "stick qt vs G s/hp %.2e\n",
              force_error, slip_error, stick_error);
}

}  // namespace
}  // namespace tirefem::verification
