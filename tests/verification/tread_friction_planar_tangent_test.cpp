// Consistency of the planar (2D) tread shear of the tread friction form (slip angle, MODEL.md §7): the
// form's tangent is the exact derivative of its residual, including the derivative of the slip direction
// s/|s|, of the frame (t, b) and of the anchor's shear carried upstream along a chain of slip points to the
// patch entry; planar mode reduces to the 1D model when nothing moves across; the tractions obey the
// isotropic Coulomb bound and add up to the residual.
//
// Reference: central finite differences with h = 1e-5 mm (form_fd_support.hpp); tolerance: relative error
// 1e-6 of the largest entry (truncation and round-off are both below 1e-9 of it), for lateral drifts
// d = ±0.05 on the plane and on the drum R 915 with the support moving in −y and +y: frozen Coulomb plans,
// frozen full-stick and full-slip plans, and a released Coulomb plan at a state where no step of h changes
// the plan (no tread point within 1e-3 mm of g = 0, the plan's decisions identical at every perturbed
// state). The Coulomb plans are asserted to hold every kind of point (so the checks cannot pass
// vacuously): stick anchored at the entry with 0 < w < 1, slip points, stick re-anchored on a slip point,
// and a chain (a stick point re-anchored on a slip point that is itself anchored on a slip point: ≥ 2
// consecutive slip points then re-stick); the tangent must be unsymmetric (‖K − Kᵀ‖max > 1e-3 ‖K‖max).
// 1D limit: d = 0 and u_x = 0 on every DOF (η of every point stays that of its line, hence of its anchor):
// the same plan's decisions and the same residual as the 1D mode to 1e-12 of its largest entry (only the
// round-off of η_A = (1 − w) η_a + w η_b separates them). Coulomb bound: |q| ≤ μ kp g (1 + 1e-12) at every
// point, |q| = μ kp g to 1e-12 at slip points. Σ force = −Σ residual per component to 1e-10 of Σ|force|.
// The residual and tangent are bit-identical on 1 and 2 threads.
// A frozen plan's entry weights follow u: after a step that changes no decision its residual is the
// released plan's to 1e-12 of the largest entry (planar and 1D).
//
// State: as tread_friction_tangent_test.cpp (patch of form_fd_support.hpp, δz = 4 mm, kp = 1.3 N/mm³,
// G = 0.9 MPa, hp = 7 mm, μ = 0.2, Rk 5 % below the tread radius, random ±0.2 mm on every DOF, the node row
// at φ = 0 lifted by 3.5 mm and pushed 5 mm against the flow) plus a lateral push of that row by 1.5 mm in x
// against the drift, so that the lateral trial shear turns across the dip (slip chains, then re-stick).
#include <array>
#include <cstdio>
#include <random>

#include <gtest/gtest.h>

#include "form_fd_support.hpp"
#include "tirefem/forms/tread_friction_form.hpp"
#include "tirefem/road/support_surface.hpp"

namespace tirefem::verification {
namespace {

constexpr double kKp = 1.3, kShear = 0.9, kMu = 0.2, kDrumRadius = 915.0;
constexpr double kBraking = 0.95 * kAxisZ;  // Rk: 5 % slip
constexpr double kDeflection = 4.0;
constexpr double kMargin = 1e-3;  // released plan: no tread point this close to g = 0

using FrictionOnly = SingleFormProblem<TreadFrictionForm>;

FrictionLaw law_of(FrictionLaw::Mode mode, double sign = 1.0) {
  FrictionLaw law;
  law.mode = mode;
  law.friction = mode == FrictionLaw::Mode::full_slip ? 0.7 : kMu;
  law.slip_sign = sign;
  return law;
}

FrictionOnly friction_only(const ShellMesh& mesh, const SupportSurface& support, int direction,
                           const FrictionLaw& law, bool planar, double drift) {
  std::vector<TreadPoint> points = patch_points(mesh);
  std::vector<char> window(points.size(), 1);
  auto form = std::make_unique<TreadFrictionForm>(mesh, std::move(points), kKp, kShear, support, direction,
                                                  std::move(window));
  form->set_deflection(kDeflection);
  form->set_rolling_radius(kBraking);
  form->set_law(law);
  form->set_planar(planar);
  form->set_lateral_drift(drift);
  return FrictionOnly(mesh, std::move(form));
}

// Random ±amplitude on every DOF, plus the node row at φ = 0 lifted by `lift`, moved by `push` in y and by
// `lateral` in x.
Eigen::VectorXd random_state(const ShellMesh& mesh, std::mt19937& rng, double amplitude, double lift, double push,
                             double lateral) {
  std::uniform_real_distribution<double> uniform(-amplitude, amplitude);
  Eigen::VectorXd u(mesh.dof_count());
  for (int i = 0; i < u.size(); ++i) u[i] = uniform(rng);
  const int row = mesh.v_nodes() / 2;
  for (int i = 0; i < mesh.u_nodes(); ++i) {
    const int p = mesh.pair_index(i, row);
    u[outer_dof(p, 0)] += lateral;
    u[outer_dof(p, 1)] += push;
    u[outer_dof(p, 2)] += lift;
  }
  return u;
}

// The lateral push of the lifted row against the drift (1.5 mm for |d| = 0.05): the lateral trial shear
// then turns across the dip, so slip chains of ≥ 2 points with re-stick behind them appear for both signs.
double lateral_push(double drift) { return -30.0 * drift; }

Eigen::Vector3d position(const TreadPoint& p, const Eigen::VectorXd& u) {
  Eigen::Vector3d x = p.reference;
  for (int a = 0; a < 4; ++a) x += p.shape[a] * u.segment<3>(outer_dof(p.pairs[a], 0));
  return x;
}

struct PlanCounts {
  int out = 0, stick = 0, stick_entry = 0, stick_on_slip = 0, chained = 0, slip = 0;
};

PlanCounts count(const FrictionPlan& plan) {
  PlanCounts c;
  for (const FrictionPlanPoint& p : plan) {
    if (p.status == TreadContact::out) {
      ++c.out;
    } else if (p.status == TreadContact::slip) {
      ++c.slip;
    } else {
      ++c.stick;
      if (p.anchored_on_slip) {
        ++c.stick_on_slip;
        if (plan[p.anchor_a].anchored_on_slip) ++c.chained;  // its slip anchor is itself anchored on slip
      }
      if (!p.anchored_on_slip && p.anchor_a != p.anchor_b && p.anchor_weight > 0 && p.anchor_weight < 1)
        ++c.stick_entry;
    }
  }
  return c;
}

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

// The two supports with their names for the messages.
struct NamedSupport {
  const char* name;
  const SupportSurface* surface;
};
std::array<NamedSupport, 2> supports(const RoadPlane& plane, const TestDrum& drum) {
  return {NamedSupport{"plane", &plane}, NamedSupport{"drum R 915", &drum}};
}

std::string describe(const char* support, int direction, double drift) {
  char text[96];
  std::snprintf(text, sizeof text, "%s, support in %s, d = %+.2f", support, direction > 0 ? "+y" : "−y", drift);
  return text;
}

void expect_mixed_plan(const PlanCounts& c, const std::string& label) {
  EXPECT_GT(c.stick_entry, 0) << label << ": no stick point anchored at the entry with 0 < w < 1";
  EXPECT_GT(c.slip, 0) << label << ": no slip point";
  EXPECT_GT(c.stick_on_slip, 0) << label << ": no stick point re-anchored on a slip point";
  EXPECT_GT(c.chained, 0) << label << ": no chain of ≥ 2 slip points followed by re-stick";
}

struct FrozenResult {
  PlanCounts counts;
  double error = 0.0, asymmetry = 0.0;
};

FrozenResult check_frozen(const SupportSurface& s, int direction, double drift, const FrictionLaw& law,
                          const std::string& label) {
  const SingleThread single_thread;
  const ShellMesh mesh = tyre_patch_mesh();
  FrictionOnly f = friction_only(mesh, s, direction, law, true, drift);
  std::mt19937 rng(4711);
  const Eigen::VectorXd u = random_state(mesh, rng, 0.2, 3.5, -direction * 5.0, lateral_push(drift));
  const FrictionPlan plan = f.form->plan(u);
  f.form->freeze_plan(plan);
  FrozenResult r;
  r.counts = count(plan);
  const Eigen::MatrixXd k = f.tangent(u);
  r.error = max_relative_error(fd_tangent(f, u), k);
  r.asymmetry = asymmetry(k);
  EXPECT_LT(r.error, kFdTolerance) << label << ": frozen plan, tangent vs central differences";
  EXPECT_GT(r.asymmetry, 1e-3) << label << ": the tangent must be unsymmetric";
  std::printf("  %s: %d stick (%d at the entry, %d on slip, %d after a slip chain), %d slip, %d out; tangent "
              "error %.2e, asymmetry %.2e\n",
              label.c_str(), r.counts.stick, r.counts.stick_entry, r.counts.stick_on_slip, r.counts.chained,
              r.counts.slip, r.counts.out, r.error, r.asymmetry);
  return r;
}

// ---- 1. frozen plans -----------------------------------------------------------------------------------

TEST(TreadFrictionPlanar, CoulombFrozenPlans) {
  RoadPlane plane;
  TestDrum drum(kDrumRadius);
  for (const auto& [name, s] : supports(plane, drum))
    for (int direction : {-1, 1})
      for (double drift : {0.05, -0.05}) {
        const std::string label = describe(name, direction, drift);
        const FrozenResult r = check_frozen(*s, direction, drift, law_of(FrictionLaw::Mode::coulomb), label);
        expect_mixed_plan(r.counts, label);
      }
}

TEST(TreadFrictionPlanar, FullStickAndFullSlipFrozenPlans) {
  RoadPlane plane;
  TestDrum drum(kDrumRadius);
  for (const auto& [name, s] : supports(plane, drum))
    for (double drift : {0.05, -0.05}) {
      const std::string stick_label = describe(name, -1, drift) + ", full stick";
      const FrozenResult r = check_frozen(*s, -1, drift, law_of(FrictionLaw::Mode::full_stick), stick_label);
      EXPECT_EQ(r.counts.slip, 0);
      EXPECT_GT(r.counts.stick_entry, 0);
      const std::string slip_label = describe(name, 1, drift) + ", full slip σ = −1";
      const FrozenResult q = check_frozen(*s, 1, drift, law_of(FrictionLaw::Mode::full_slip, -1.0), slip_label);
      EXPECT_EQ(q.counts.stick, 0);
      EXPECT_GT(q.counts.slip, 0);
    }
}

// ---- 2. released plan ----------------------------------------------------------------------------------

void check_released(const char* name, const SupportSurface& s, int direction, double drift, unsigned seed) {
  const SingleThread single_thread;
  const ShellMesh mesh = tyre_patch_mesh();
  FrictionOnly f = friction_only(mesh, s, direction, law_of(FrictionLaw::Mode::coulomb), true, drift);
  const std::string label = describe(name, direction, drift) + ", released plan";
  std::mt19937 rng(seed);
  const int n = mesh.dof_count();
  for (int attempt = 0; attempt < 30; ++attempt) {
    const Eigen::VectorXd u = random_state(mesh, rng, 0.2, 3.5, -direction * 5.0, lateral_push(drift));
    const FrictionPlan plan = f.form->plan(u);
    double closest = 1e300;
    for (const TreadPoint& p : f.form->points())
      closest = std::min(closest, std::abs(s.penetration(position(p, u), kDeflection).value));
    if (closest <= kMargin) continue;
    const PlanCounts c = count(plan);
    if (c.stick_entry == 0 || c.slip == 0 || c.stick_on_slip == 0 || c.chained == 0) continue;
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
    f.form->release_plan();
    const Eigen::MatrixXd k = f.tangent(u);
    const double error = max_relative_error(fd_tangent(f, u), k);
    EXPECT_LT(error, kFdTolerance) << label << ": tangent vs central differences";
    EXPECT_GT(asymmetry(k), 1e-3) << label;
    std::printf("  %s (attempt %d): %d stick (%d at the entry, %d on slip, %d after a chain), %d slip, "
                "closest |g| %.2e mm; tangent error %.2e\n",
                label.c_str(), attempt + 1, c.stick, c.stick_entry, c.stick_on_slip, c.chained, c.slip, closest,
                error);
    return;
  }
  FAIL() << label << ": no random state with every kind of point where a step of h leaves the plan unchanged";
}

TEST(TreadFrictionPlanar, CoulombReleasedPlan) {
  RoadPlane plane;
  TestDrum drum(kDrumRadius);
  check_released("drum R 915", drum, -1, 0.05, 2024);
  check_released("plane", plane, 1, -0.05, 2025);
}

// A frozen plan holds the points' decisions, not where the patch's edge lies between two points: moved
// by a step that changes no decision, the frozen plan's residual is the released plan's (the entry weights
// follow u in both). Frozen weights lagged the iterate and left the two-level loop revising a plan whose
// decisions had settled (the 80 × 46 rig at 5550 N, α 2.2°: 1 560 "changes" at each revision, all weights).
void check_frozen_follows_edge(const char* name, const SupportSurface& s, int direction, double drift, bool planar,
                               unsigned seed) {
  const ShellMesh mesh = tyre_patch_mesh();
  FrictionOnly f = friction_only(mesh, s, direction, law_of(FrictionLaw::Mode::coulomb), planar, drift);
  const std::string label = describe(name, direction, drift) + (planar ? ", planar" : ", 1D");
  std::mt19937 rng(seed);
  for (int attempt = 0; attempt < 30; ++attempt) {
    const Eigen::VectorXd u = random_state(mesh, rng, 0.2, 3.5, -direction * 5.0, planar ? lateral_push(drift) : 0.0);
    const FrictionPlan plan = f.form->plan(u);
    const Eigen::VectorXd v = u + random_vector(mesh.dof_count(), seed + attempt, 1e-3);
    const FrictionPlan moved = f.form->plan(v);
    int weights_moved = 0;
    for (std::size_t q = 0; q < plan.size(); ++q)
      weights_moved += plan[q].status == TreadContact::stick && !plan[q].anchored_on_slip &&
                       std::abs(moved[q].anchor_weight - plan[q].anchor_weight) > 1e-6;
    if (!same_decisions(plan, moved) || weights_moved == 0) continue;
    f.form->release_plan();
    const Eigen::VectorXd released = f.residual(v);
    f.form->freeze_plan(plan);
    const double error = (f.residual(v) - released).cwiseAbs().maxCoeff() / released.cwiseAbs().maxCoeff();
    f.form->release_plan();
    EXPECT_LT(error, 1e-12) << label << ": frozen against released residual after a step";
    std::printf("  %s (attempt %d): %d entry weights moved; frozen vs released residual %.2e\n", label.c_str(),
                attempt + 1, weights_moved, error);
    return;
  }
  FAIL() << label << ": no step that moves entry weights and changes no decision";
}

TEST(TreadFrictionPlanar, AFrozenPlansEntryWeightsFollowTheIterate) {
  RoadPlane plane;
  TestDrum drum(kDrumRadius);
  for (bool planar : {true, false}) {
    check_frozen_follows_edge("drum R 915", drum, -1, 0.05, planar, 31);
    check_frozen_follows_edge("plane", plane, 1, -0.05, planar, 37);
  }
}

// ---- 3. 1D limit ---------------------------------------------------------------------------------------

TEST(TreadFrictionPlanar, ReducesTo1DWithoutLateralMotion) {
  const SingleThread single_thread;
  const ShellMesh mesh = tyre_patch_mesh();
  TestDrum drum(kDrumRadius);
  RoadPlane plane;
  for (const auto& [name, s] : supports(plane, drum))
    for (int direction : {-1, 1}) {
      FrictionOnly one = friction_only(mesh, *s, direction, law_of(FrictionLaw::Mode::coulomb), false, 0.0);
      FrictionOnly two = friction_only(mesh, *s, direction, law_of(FrictionLaw::Mode::coulomb), true, 0.0);
      std::mt19937 rng(99);
      Eigen::VectorXd u = random_state(mesh, rng, 0.2, 3.5, -direction * 5.0, 0.0);
      for (int p = 0; p < mesh.pair_count(); ++p) u[outer_dof(p, 0)] = u[inner_dof(p, 0)] = 0.0;
      const FrictionPlan plan1 = one.form->plan(u), plan2 = two.form->plan(u);
      const PlanCounts c = count(plan2);
      ASSERT_GT(c.slip, 0);
      ASSERT_GT(c.stick_on_slip, 0);
      for (std::size_t q = 0; q < plan1.size(); ++q) {
        EXPECT_EQ(plan1[q].status, plan2[q].status) << "point " << q;
        if (plan1[q].status == TreadContact::stick) {
          EXPECT_EQ(plan1[q].anchor_a, plan2[q].anchor_a);
          EXPECT_EQ(plan1[q].anchored_on_slip, plan2[q].anchored_on_slip);
        }
      }
      const Eigen::VectorXd r1 = one.residual(u), r2 = two.residual(u);
      const double error = (r1 - r2).cwiseAbs().maxCoeff() / r1.cwiseAbs().maxCoeff();
      EXPECT_LT(error, 1e-12) << describe(name, direction, 0.0);
      std::printf("  %s, u_x = 0: planar vs 1D residual %.2e (%d slip, %d re-stick)\n",
                  describe(name, direction, 0.0).c_str(), error, c.slip, c.stick_on_slip);
    }
}

// ---- 4. evaluate(): Coulomb bound and force balance ----------------------------------------------------

TEST(TreadFrictionPlanar, EvaluateBoundAndForces) {
  const SingleThread single_thread;
  const ShellMesh mesh = tyre_patch_mesh();
  TestDrum drum(kDrumRadius);
  RoadPlane plane;
  for (const auto& [name, s] : supports(plane, drum))
    for (double drift : {0.05, -0.05}) {
      const int direction = drift > 0 ? -1 : 1;
      const std::string label = describe(name, direction, drift);
      FrictionOnly f = friction_only(mesh, *s, direction, law_of(FrictionLaw::Mode::coulomb), true, drift);
      std::mt19937 rng(4711);
      const Eigen::VectorXd u = random_state(mesh, rng, 0.2, 3.5, -direction * 5.0, lateral_push(drift));
      const FrictionPlan plan = f.form->plan(u);
      const PlanCounts c = count(plan);
      ASSERT_GT(c.slip, 0);
      ASSERT_GT(c.chained, 0);
      const std::vector<TreadTraction> tractions = f.form->evaluate(u);  // released
      const Eigen::VectorXd r = f.residual(u);
      double bound = 0.0, slip_error = 0.0, lateral = 0.0;
      Eigen::Vector3d total = Eigen::Vector3d::Zero(), total_abs = Eigen::Vector3d::Zero(), residual_sum;
      for (std::size_t q = 0; q < tractions.size(); ++q) {
        const TreadTraction& t = tractions[q];
        EXPECT_EQ(t.status, plan[q].status);
        total += t.force, total_abs += t.force.cwiseAbs();
        if (t.status == TreadContact::out) continue;
        const double limit = kMu * kKp * s->penetration(position(f.form->points()[q], u), kDeflection).value;
        bound = std::max(bound, t.traction_vector.norm() / limit - 1.0);
        if (t.status == TreadContact::slip)
          slip_error = std::max(slip_error, std::abs(t.traction_vector.norm() - limit) / limit);
        EXPECT_EQ(t.traction, t.traction_vector.x());
        lateral = std::max(lateral, std::abs(t.traction_vector.y()));
      }
      for (int k = 0; k < 3; ++k) {
        residual_sum[k] = 0.0;
        for (int p = 0; p < mesh.pair_count(); ++p) residual_sum[k] += r[outer_dof(p, k)] + r[inner_dof(p, k)];
      }
      const double force_error = (total + residual_sum).cwiseAbs().maxCoeff() / total_abs.maxCoeff();
      EXPECT_LT(bound, 1e-12) << label << ": |q| ≤ μ kp g";
      EXPECT_LT(slip_error, 1e-12) << label << ": slip |q| = μ kp g";
      EXPECT_LT(force_error, 1e-10) << label << ": Σ force = −Σ residual";
      EXPECT_GT(lateral, 1e-3) << label << ": the tractions must have a lateral component";
      std::printf("  %s: max |q|/(μ kp g) − 1 %.2e, slip |q| vs μ kp g %.2e, Σ force + Σ residual %.2e of "
                  "Σ|force|, max |q_b| %.3f MPa\n",
                  label.c_str(), bound, slip_error, force_error, lateral);
    }
}

// ---- 5. determinism -------------------------------------------------------------------------------------

// The assembly is parallel over lines and sums per-point slots in point order: residual and tangent must be
// bit-identical on 1 and 2 threads.
// The smoothed Jacobian (TreadFrictionForm::set_jacobian_smoothing) changes Newton's direction only:
// the residual is bit for bit the same; with a band wider than any point's excess over the limit every
// sliding point takes (almost) its stick tangent instead, so the tangent changes. (With the default band
// 0 the tangent is the exact one: the finite-difference tests above.)
TEST(TreadFrictionPlanar, SmoothedJacobianKeepsTheResidual) {
  const ShellMesh mesh = tyre_patch_mesh();
  TestDrum drum(kDrumRadius);
  FrictionOnly f = friction_only(mesh, drum, -1, law_of(FrictionLaw::Mode::coulomb), true, 0.05);
  std::mt19937 rng(4711);
  const Eigen::VectorXd u = random_state(mesh, rng, 0.2, 3.5, 5.0, lateral_push(0.05));
  ASSERT_GT(count(f.form->plan(u)).slip, 0);
  const Eigen::MatrixXd exact = f.tangent(u);
  const Eigen::VectorXd r_exact = f.problem->system().residual();
  f.form->set_jacobian_smoothing(1e6);
  const Eigen::MatrixXd smoothed = f.tangent(u);
  EXPECT_EQ((f.problem->system().residual() - r_exact).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_GT((smoothed - exact).cwiseAbs().maxCoeff(), 1e-3 * exact.cwiseAbs().maxCoeff());
}

// The stick tangent's weight in the smoothed tangent is a blend weight: 1 at and below the limit (a frozen
// plan's sliding point may lie below it), linear to 0 at (1 + band) L, 0 beyond and for band 0.
TEST(TreadFrictionPlanar, StickTangentWeightIsABlend) {
  const double limit = 2.0, band = 0.1;
  EXPECT_EQ(stick_tangent_weight(0.0, limit, band), 1.0);
  EXPECT_EQ(stick_tangent_weight(0.5 * limit, limit, band), 1.0);
  EXPECT_EQ(stick_tangent_weight(limit, limit, band), 1.0);
  EXPECT_NEAR(stick_tangent_weight(1.05 * limit, limit, band), 0.5, 1e-12);
  EXPECT_NEAR(stick_tangent_weight(1.1 * limit, limit, band), 0.0, 1e-12);  // the band's end
  EXPECT_EQ(stick_tangent_weight(3.0 * limit, limit, band), 0.0);
  EXPECT_EQ(stick_tangent_weight(0.5 * limit, limit, 0.0), 0.0);
  EXPECT_EQ(stick_tangent_weight(1.05 * limit, limit, 0.0), 0.0);
}

// The tangent is summed per pair of elements of a strip (forms/strip_blocks.hpp), in strip, line and
// point order: bit for bit the same on one and two threads, in both modes (1D: drift 0, planar off).
TEST(TreadFrictionPlanar, SameResultOnAnyThreadCount) {
  const ShellMesh mesh = tyre_patch_mesh();
  TestDrum drum(kDrumRadius);
  for (const bool planar : {true, false}) {
    SCOPED_TRACE(planar ? "planar" : "1D");
    FrictionOnly f = friction_only(mesh, drum, -1, law_of(FrictionLaw::Mode::coulomb), planar, planar ? 0.05 : 0.0);
    std::mt19937 rng(4711);
    const Eigen::VectorXd u = random_state(mesh, rng, 0.2, 3.5, 5.0, lateral_push(planar ? 0.05 : 0.0));
    const int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    const Eigen::MatrixXd k1 = f.tangent(u);
    const Eigen::VectorXd r1 = f.problem->system().residual();
    omp_set_num_threads(2);
    const Eigen::MatrixXd k2 = f.tangent(u);
    const Eigen::VectorXd r2 = f.problem->system().residual();
    omp_set_num_threads(threads);
    EXPECT_GT(k1.cwiseAbs().maxCoeff(), 0.0);
    EXPECT_GT(r1.cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ((k1 - k2).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ((r1 - r2).cwiseAbs().maxCoeff(), 0.0);
  }
}

}  // namespace
}  // namespace tirefem::verification
