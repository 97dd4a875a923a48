// Steady slow rolling with stick and slip (MODEL.md §5, eqs. 15–17) on a coarse mesh of the example tyre
// (40 × 12 half model, 4 × 4 tread points per element, μ = 0.7, footprint of 3000 N on the plane).
// References and tolerances:
// - Full slip: every contact point carries μ qn along the support's motion, so Qy = ±μ Qz exactly up to
//   the tilt of the support force (zero on the plane) and the Newton remainder: 1e-3 relative (the issue's
//   0.1%); the sign follows the wheel (spinning: traction, Qy > 0; locked: braking, Qy < 0).
// - Full stick: no slip point by construction; free rolling: |Qy| < 1e-3 Qz (the secant search stops at
//   1e-4 Qz).
// - Equilibrium (statics): the rim reaction balances the contact forces. The shell's internal forces sum
//   to zero and have no moment (invariance of the strains under rigid motion); the follower pressure has no
//   resultant in y, z and no moment about x (its boundary, the bead circle and the equator line, lies in
//   planes x = const, see contact_equilibrium_test.cpp; ∫ r × n dA = −½∮|r|² dl has no x component
//   there). So Qy and Qz of the contact equal minus the rim's: 1e-6 relative (Newton remainder ~1e-10).
//   The moment: the Winkler tread passes the road's force to the breaker without the couple hp·qt of a
//   real sheared tread block, so the rim balances the moment of the contact forces taken at the breaker;
//   the reported Mx takes them at the tread surface, as the paper does (the real tread carries the
//   couple): the two differ by ≈ hp·Qy, checked too.
// - Reversing the direction of travel mirrors the solution: Qy and Mx (reported in the mirrored frame)
//   and every tread point's traction at φ equal the forward run's at −φ; the mesh is symmetric in φ, so
//   the two runs differ only by round-off and the iteration path: 1e-6 relative.
// - Monotone physics: Qy grows with the slip and the stick zone shrinks; traction under braking is the
//   reverse of traction.
#include <cmath>
#include <cstdio>
#include <map>

#include <gtest/gtest.h>

#include "contact_support.hpp"
#include "rolling_support.hpp"
#include "tirefem/analysis/rolling.hpp"

namespace tirefem::verification {
namespace {

RollingStateSpec state(RollingStateSpec::Kind kind, double slip = 0.0, bool braking = false) {
  RollingStateSpec s;
  s.kind = kind;
  s.slip = slip;
  s.braking = braking;
  return s;
}

RollingStudy study(bool reverse) {
  RollingStudy s;
  s.name = reverse ? "reverse" : "forward";
  if (reverse) s.reverse = true;
  s.target_load = 3000.0;
  s.friction = 0.7;
  s.reverse = reverse;
  using K = RollingStateSpec::Kind;
  s.states = {state(K::free), state(K::given_slip, 0.02), state(K::given_slip, -0.02), state(K::full_stick, 0.01),
              state(K::full_slip, 0.0, false), state(K::full_slip, 0.0, true), state(K::given_slip, 0.05)};
  return s;
}

const TyreMesh& coarse_tyre() {
  static const TyreMesh tm = build_tyre_mesh(example_case().tyre, coarse_mesh(40, 12));
  return tm;
}

ContactSettings settings() {
  ContactSettings s = test_contact_settings(ContactSettings::Iteration::single_loop);
  s.residual_tolerance = 1e-10;
  return s;
}

// The drum (1830 mm) with fewer states: free rolling, traction, full slip.
RollingStudy drum_study() {
  RollingStudy s;
  s.name = "drum";
  s.support = drum_support(1830.0);
  s.target_load = 3000.0;
  using K = RollingStateSpec::Kind;
  s.states = {state(K::free), state(K::given_slip, 0.02), state(K::full_slip)};
  return s;
}

enum class Run { forward, reverse, drum };

const RollingResult& run(Run which) {
  static std::map<Run, RollingResult> cache;
  auto it = cache.find(which);
  if (it == cache.end()) {
    const Stopwatch clock;
    const Case& c = example_case();
    const RollingStudy s = which == Run::drum ? drum_study() : study(which == Run::reverse);
    it = cache.emplace(which, run_rolling(coarse_tyre(), c.tyre, c.inflation, settings(), s)).first;
    std::printf("  rolling study '%s' on 40 x 12: %.1f s, %d factorisations, %d Newton iterations\n",
                it->second.name.c_str(), clock.seconds(), it->second.counters.factorizations,
                it->second.counters.newton_iterations);
  }
  return it->second;
}

const RollingStateResult& nth(const RollingResult& r, int i) {
  EXPECT_TRUE(r.states.at(i).converged) << r.states.at(i).name << ": " << r.states.at(i).failure;
  return r.states.at(i);
}

TEST(Rolling, StudyCompletes) {
  const RollingResult& r = run(Run::forward);
  ASSERT_TRUE(r.completed) << r.failure;
  ASSERT_TRUE(r.effective_rolling_radius_mm.has_value());
  std::printf("  Re %.3f mm, Rd %.3f mm, free radius %.3f mm, slip stiffness %.0f N\n", *r.effective_rolling_radius_mm,
              r.loaded_radius_mm, r.axle_z, r.slip_stiffness_N.value_or(0));
  // A radial tyre's belt barely stretches: Re lies between the loaded and the free radius.
  EXPECT_GT(*r.effective_rolling_radius_mm, r.loaded_radius_mm);
  EXPECT_LT(*r.effective_rolling_radius_mm, r.axle_z);
  EXPECT_GT(r.slip_stiffness_N.value_or(0), 0.0);
}

TEST(Rolling, FreeRollingHasNoLongitudinalForce) {
  const RollingStateResult& s = nth(run(Run::forward), 0);
  std::printf("  free rolling: Qy %.4f N, Qz %.1f N, stick %.3f\n", s.figures.Qy_N, s.figures.Qz_N,
              s.figures.stick_area_fraction);
  EXPECT_LT(std::abs(s.figures.Qy_N), 1e-3 * s.figures.Qz_N);
  EXPECT_NEAR(s.figures.Qz_N, 3000.0, 3.0);  // the footprint's load, held by the axle height
}

TEST(Rolling, FullSlipGivesMuTimesQz) {
  const RollingResult& r = run(Run::forward);
  for (int i : {4, 5}) {
    const RollingStateResult& s = nth(r, i);
    const double ratio = s.figures.Qy_N / (r.friction * s.figures.Qz_N);
    std::printf("  %s (%s): Qy %.3f N, μ Qz %.3f N, ratio %.6f, stick %.3f\n", s.name.c_str(),
                s.spec.braking ? "locked" : "spinning", s.figures.Qy_N, r.friction * s.figures.Qz_N, ratio,
                s.figures.stick_area_fraction);
    EXPECT_NEAR(ratio, s.spec.braking ? -1.0 : 1.0, 1e-3);
    EXPECT_EQ(s.figures.stick_area_fraction, 0.0);
  }
}

TEST(Rolling, FullStickHasNoSlipPoint) {
  const RollingStateResult& s = nth(run(Run::forward), 3);
  int slip = 0, stick = 0;
  for (const TreadTraction& t : s.tangential) slip += t.status == TreadContact::slip, stick += t.status == TreadContact::stick;
  std::printf("  full stick at κ = 0.01: %d stick points, %d slip points, Qy %.1f N\n", stick, slip, s.figures.Qy_N);
  EXPECT_EQ(slip, 0);
  EXPECT_GT(stick, 100);
  EXPECT_DOUBLE_EQ(s.figures.stick_area_fraction, 1.0);
  // Without a friction limit Qy is linear in κ up to the geometric nonlinearity, so at κ = 0.01 it is the
  // slip stiffness (measured at κ ≈ 0, where 1% of the patch slides) times κ: 1%.
  const RollingResult& r = run(Run::forward);
  std::printf("  full stick Qy %.2f N, slip stiffness × κ %.2f N\n", s.figures.Qy_N, *r.slip_stiffness_N * 0.01);
  EXPECT_NEAR(s.figures.Qy_N, *r.slip_stiffness_N * 0.01, 0.01 * *r.slip_stiffness_N * 0.01);
}

TEST(Rolling, TractionAndBrakingAreOppositeAndGrowWithSlip) {
  const RollingResult& r = run(Run::forward);
  const RollingStateResult &drive = nth(r, 1), &brake = nth(r, 2), &more = nth(r, 6);
  std::printf("  κ = +0.02: Qy %.1f N, stick %.2f; κ = −0.02: Qy %.1f N, stick %.2f; κ = 0.05: Qy %.1f N, stick %.2f\n",
              drive.figures.Qy_N, drive.figures.stick_area_fraction, brake.figures.Qy_N,
              brake.figures.stick_area_fraction, more.figures.Qy_N, more.figures.stick_area_fraction);
  EXPECT_GT(drive.figures.Qy_N, 0.0);
  EXPECT_LT(brake.figures.Qy_N, 0.0);
  EXPECT_GT(more.figures.Qy_N, drive.figures.Qy_N);
  EXPECT_LT(more.figures.Qy_N, r.friction * more.figures.Qz_N);
  EXPECT_LT(more.figures.stick_area_fraction, drive.figures.stick_area_fraction);
  EXPECT_GT(drive.figures.stick_area_fraction, 0.0);
  EXPECT_LT(drive.figures.stick_area_fraction, 1.0);
  // Traction pulls the tyre forward at the road, below the axle: Mx ≈ Qy Rd.
  EXPECT_NEAR(drive.figures.Mx_Nmm / (drive.figures.Qy_N * r.loaded_radius_mm), 1.0, 0.1);
}

void check_axle_loads(const RollingResult& r, std::initializer_list<int> states) {
  for (int i : states) {
    const RollingStateResult& s = nth(r, i);
    const RimReaction rim = rim_reaction(coarse_tyre(), example_case().inflation.pressure, s.displacement);
    // Half model: the rim reaction of half the tyre, doubled; contact + rim = 0.
    const double qy = -2.0 * rim.force.y(), qz = -2.0 * rim.force.z(), mx = -2.0 * rim.moment.x();
    double at_breaker = 0.0, mean_height = 0.0;
    for (std::size_t q = 0; q < r.tread_points.size(); ++q) {
      const TreadPoint& p = r.tread_points[q];
      const Eigen::Vector3d x = s.normal[q].position - p.height * p.normal;
      const Eigen::Vector3d f = s.normal[q].force + s.tangential[q].force;
      at_breaker += 2.0 * (x.y() * f.z() - (x.z() - r.axle_z) * f.y());
      mean_height += 2.0 * p.height * f.y();
    }
    mean_height /= s.figures.Qy_N;
    std::printf("  %s: Qy contact %.6f / rim %.6f N, Qz %.6f / %.6f N, Mx at the breaker %.3f / rim %.3f N·mm, "
                "reported Mx %.3f N·mm (tread couple %.1f N·mm = Qy × %.2f mm)\n", s.name.c_str(), s.figures.Qy_N, qy,
                s.figures.Qz_N, qz, at_breaker, mx, s.figures.Mx_Nmm, s.figures.Mx_Nmm - at_breaker, mean_height);
    EXPECT_NEAR(qy, s.figures.Qy_N, 1e-6 * s.figures.Qz_N);
    EXPECT_NEAR(qz, s.figures.Qz_N, 1e-6 * s.figures.Qz_N);
    EXPECT_NEAR(mx, at_breaker, 1e-6 * s.figures.Qz_N * r.loaded_radius_mm);
    // The couple of the tread is the tread height times the tangential force (up to the small tilt of
    // the tread normal under the patch): within 5%.
    EXPECT_NEAR(s.figures.Mx_Nmm - at_breaker, mean_height * s.figures.Qy_N,
                0.05 * std::abs(mean_height * s.figures.Qy_N));
  }
}

TEST(Rolling, AxleLoadsBalanceTheContactStresses) { check_axle_loads(run(Run::forward), {1, 4, 6}); }

// The drum: the same statics; free rolling; traction; full slip. The friction force follows the drum
// surface, so on the drum μ relates the tangential to the normal force point by point (Σ|Ft| = μ Σ|Fn|
// to round-off), not Qy to Qz: the normals over the patch tilt by ±θ about the drum axis, and under full
// slip the pressure centroid moves off the top, which tilts the resultant by ε(1 + μ²)/μ (ε = Σ Fn,y /
// Σ Fn,z): printed, not checked against μ.
TEST(Rolling, DrumRollingBalancesAndSlides) {
  const RollingResult& r = run(Run::drum);
  ASSERT_TRUE(r.completed) << r.failure;
  check_axle_loads(r, {1, 2});
  const RollingStateResult &free = nth(r, 0), &drive = nth(r, 1), &slide = nth(r, 2);
  std::printf("  drum: Re %.3f mm, free Qy %.4f N, κ = 0.02: Qy %.1f N (stick %.2f), full slip Qy/(μQz) %.5f\n",
              *r.effective_rolling_radius_mm, free.figures.Qy_N, drive.figures.Qy_N,
              drive.figures.stick_area_fraction, slide.figures.Qy_N / (r.friction * slide.figures.Qz_N));
  EXPECT_LT(std::abs(free.figures.Qy_N), 1e-3 * free.figures.Qz_N);
  EXPECT_GT(drive.figures.Qy_N, 0.0);
  double tangential = 0.0, normal = 0.0;
  Eigen::Vector3d normal_force = Eigen::Vector3d::Zero();
  for (std::size_t q = 0; q < r.tread_points.size(); ++q) {
    tangential += slide.tangential[q].force.norm();
    normal += slide.normal[q].force.norm();
    normal_force += slide.normal[q].force;
  }
  const double tilt = normal_force.y() / normal_force.z();
  std::printf("  drum full slip: Σ|Ft| / (μ Σ|Fn|) = %.12f; pressure-centroid tilt ε = %.4f, "
              "ε(1 + μ²)/μ = %.4f\n", tangential / (r.friction * normal), tilt,
              tilt * (1 + r.friction * r.friction) / r.friction);
  EXPECT_NEAR(tangential / (r.friction * normal), 1.0, 1e-9);
  EXPECT_EQ(slide.figures.stick_area_fraction, 0.0);
}

TEST(Rolling, ReversedTravelMirrorsTheSolution) {
  const RollingResult &fwd = run(Run::forward), &rev = run(Run::reverse);
  ASSERT_TRUE(rev.completed) << rev.failure;
  EXPECT_NEAR(*rev.effective_rolling_radius_mm, *fwd.effective_rolling_radius_mm, 1e-6);
  // Tread points of φ and −φ: same (s, |φ|) key.
  const auto& pts = fwd.tread_points;
  std::map<std::pair<long, long>, int> index;
  for (int q = 0; q < static_cast<int>(pts.size()); ++q)
    index[{std::lround(pts[q].u * 1e6), std::lround(pts[q].v * 1e9)}] = q;
  for (int i : {1, 2, 5}) {
    const RollingStateResult &a = nth(fwd, i), &b = nth(rev, i);
    std::printf("  %s: Qy %.6f / %.6f N, Mx %.3f / %.3f N·mm\n", a.name.c_str(), a.figures.Qy_N, b.figures.Qy_N,
                a.figures.Mx_Nmm, b.figures.Mx_Nmm);
    EXPECT_NEAR(a.figures.Qy_N, b.figures.Qy_N, 1e-6 * a.figures.Qz_N);
    EXPECT_NEAR(a.figures.Qz_N, b.figures.Qz_N, 1e-6 * a.figures.Qz_N);
    EXPECT_NEAR(a.figures.Mx_Nmm, b.figures.Mx_Nmm, 1e-6 * a.figures.Qz_N * fwd.loaded_radius_mm);
    double worst = 0.0;
    int matched = 0;
    for (int q = 0; q < static_cast<int>(pts.size()); ++q) {
      const auto m = index.find({std::lround(pts[q].u * 1e6), std::lround(-pts[q].v * 1e9)});
      ASSERT_NE(m, index.end()) << "the mesh is symmetric in φ";
      // y components of the tangential force are opposite in the mirror image.
      worst = std::max(worst, std::abs(a.tangential[q].force.y() + b.tangential[m->second].force.y()));
      matched += a.tangential[q].status != TreadContact::out;
      EXPECT_EQ(a.tangential[q].status, b.tangential[m->second].status);
    }
    std::printf("    %d points in contact, largest mismatch of the mirrored tangential force %.2e N\n", matched, worst);
    EXPECT_LT(worst, 1e-6 * a.figures.Qz_N / 100);
  }
}

}  // namespace
}  // namespace tirefem::verification

namespace tirefem::verification {
namespace {

// A rolling study started from the static footprint of an earlier study at the same load (run_case shares
// it between studies) gives the same states as one that solves its own footprint.
TEST(Rolling, SharedFootprintGivesTheSameStates) {
  const RollingResult& own = run(Run::drum);
  ASSERT_TRUE(own.footprint.completed);
  const Case& c = example_case();
  RollingStudy s = drum_study();
  s.name = "drum_shared";
  std::string progress;
  const RollingResult shared = run_rolling(coarse_tyre(), c.tyre, c.inflation, settings(), s,
                                           [&](const std::string& m) { progress += m + "\n"; }, nullptr,
                                           &own.footprint);
  EXPECT_EQ(shared.footprint.name, "drum_shared");
  EXPECT_NE(progress.find("static footprint solved before"), std::string::npos) << progress;
  EXPECT_EQ(progress.find("footprint 'drum_shared'"), std::string::npos) << "the footprint was solved again";
  EXPECT_EQ(shared.footprint.counters.newton_iterations, own.footprint.counters.newton_iterations);
  ASSERT_EQ(shared.states.size(), own.states.size());
  for (std::size_t i = 0; i < own.states.size(); ++i) {
    EXPECT_EQ(shared.states[i].converged, own.states[i].converged);
    EXPECT_NEAR(shared.states[i].figures.Qy_N, own.states[i].figures.Qy_N, 1e-9 * own.footprint.target_Qz_N.value_or(3000.0))
        << own.states[i].name;
    EXPECT_NEAR(shared.states[i].figures.Qz_N, own.states[i].figures.Qz_N, 1e-9 * own.footprint.target_Qz_N.value_or(3000.0));
  }
}

}  // namespace
}  // namespace tirefem::verification
