// Cornering (MODEL.md §7, issue 11): steady rolling at a slip angle on the full model (bead to bead) of a
// coarse mesh of the example tyre (40 × 12 per half, mirrored: 24 elements bead to bead; 4 × 4 tread points per element,
// μ = 0.7, footprint of 3000 N on the plane), with the planar tread shear.
// References and tolerances:
// - Signs (ISO 8855 / TYDEX W axes, README): α > 0 (the wheel moving to the left of its heading) gives a
//   lateral force to the right, Fy < 0, an aligning moment Mz > 0 that turns the wheel towards its
//   direction of travel, and a positive pneumatic trail −Mz/Fy.
// - Symmetry: the mesh and the tyre are symmetric about the equatorial plane, so α → −α (and γ → −γ)
//   mirrors the solution: Fy, Mz and the overturning moment change sign, Fx and Fz do not; 1e-6 of Fz (the two runs differ by round-off and
//   their iteration paths, the Newton tolerance is 1e-10).
// - Friction bound (eq. 15 in two dimensions): at every tread point |q_t| ≤ μ qn to round-off (1e-9
//   relative), so |(Fx, Fy)| ≤ μ Fz.
// - Equilibrium, all six components: the rim (the clamped beads) balances the contact forces, taken at
//   the breaker (the Winkler tread passes them on without the couple of a sheared block): the shell's
//   internal forces are self-equilibrated and the follower pressure on the closed full tyre has no
//   resultant and no moment about the axle centre (its boundary, the two bead circles, are circles about
//   the axis). 1e-6 of Fz (and of Fz × Rd for the moments).
// - At α = 0 the full model reproduces the half model (both with the planar shear): free-rolling radius
//   to 1e-6 relative, Qy at κ = 0.02 to 1e-4 of Qz (the half model's symmetry conditions against the full
//   model's symmetric solution: the same equations, solved along different paths).
#include <cmath>
#include <cstdio>
#include <map>

#include <gtest/gtest.h>

#include "contact_support.hpp"
#include "rolling_support.hpp"
#include "tirefem/analysis/rolling.hpp"

namespace tirefem::verification {
namespace {

RollingStateSpec state(RollingStateSpec::Kind kind, double slip, double alpha_deg, const char* name,
                       double camber_deg = 0.0) {
  RollingStateSpec s;
  s.kind = kind;
  s.slip = slip;
  s.slip_angle_deg = alpha_deg;
  s.camber_deg = camber_deg;
  s.name = name;
  return s;
}

const TyreMesh& tyre(bool half) {
  static std::map<bool, TyreMesh> meshes;
  auto it = meshes.find(half);
  // The full model mirrors the half model's 12 meridional elements (build_tyre_mesh doubles them).
  if (it == meshes.end()) it = meshes.emplace(half, build_tyre_mesh(example_case().tyre, coarse_mesh(40, 12, half))).first;
  return it->second;
}

ContactSettings settings() {
  ContactSettings s = test_contact_settings(ContactSettings::Iteration::single_loop);
  s.residual_tolerance = 1e-10;
  return s;
}

enum class Run { full, half };

const RollingResult& run(Run which) {
  static std::map<Run, RollingResult> cache;
  auto it = cache.find(which);
  if (it == cache.end()) {
    const Stopwatch clock;
    RollingStudy s;
    s.name = which == Run::full ? "full" : "half";
    s.target_load = 3000.0;
    s.friction = 0.7;
    s.tread_shear = RollingStudy::TreadShear::planar;
    using K = RollingStateSpec::Kind;
    s.states = {state(K::free, 0.0, 0.0, "free"), state(K::given_slip, 0.02, 0.0, "traction")};
    if (which == Run::full)
      s.states.insert(s.states.end(), {state(K::given_slip, 0.0, 2.0, "alpha+2"), state(K::given_slip, 0.0, -2.0, "alpha-2"),
                                       state(K::given_slip, 0.0, 0.0, "camber+2", 2.0),
                                       state(K::given_slip, 0.0, 0.0, "camber-2", -2.0),
                                       state(K::free, 0.0, 0.0, "free camber+2 held", 2.0)});
    if (which == Run::full) s.states.back().hold_load = true;
    const Case& c = example_case();
    it = cache.emplace(which, run_rolling(tyre(which == Run::half), c.tyre, c.inflation, settings(), s)).first;
    std::printf("  rolling study '%s': %.1f s, %d factorisations, %d Newton iterations\n", it->second.name.c_str(),
                clock.seconds(), it->second.counters.factorizations, it->second.counters.newton_iterations);
  }
  return it->second;
}

const RollingStateResult& named(const RollingResult& r, const std::string& name) {
  for (const RollingStateResult& s : r.states)
    if (s.name == name) {
      EXPECT_TRUE(s.converged) << name << ": " << s.failure;
      return s;
    }
  throw std::runtime_error("no state " + name);
}

// b is the mirror image of a in the equatorial plane: Fy, Mz and the overturning moment change sign, Fx
// and Fz do not (1e-6 of Fz, and of Fz × Rd for the moments).
void expect_mirrored(const RollingFigures& a, const RollingFigures& b, double loaded_radius) {
  const double tol = 1e-6 * a.Fz_N;
  EXPECT_NEAR(a.Fy_N, -b.Fy_N, tol);
  EXPECT_NEAR(a.Fx_N, b.Fx_N, tol);
  EXPECT_NEAR(a.Fz_N, b.Fz_N, tol);
  EXPECT_NEAR(a.aligning_moment_Nmm, -b.aligning_moment_Nmm, tol * loaded_radius);
  EXPECT_NEAR(a.overturning_moment_Nmm, -b.overturning_moment_Nmm, tol * loaded_radius);
}

TEST(Cornering, SlipAngleGivesLateralForceAndAligningMomentOfTheIsoSigns) {
  const RollingResult& r = run(Run::full);
  ASSERT_TRUE(r.completed) << r.failure;
  const RollingFigures& f = named(r, "alpha+2").figures;
  std::printf("  α +2°: Fx %.1f N, Fy %.1f N, Fz %.1f N, Mz %.0f N·mm, Mx %.0f N·mm, trail %.2f mm, Fy/Fz per degree "
              "%.3f\n", f.Fx_N, f.Fy_N, f.Fz_N, f.aligning_moment_Nmm, f.overturning_moment_Nmm,
              f.pneumatic_trail_mm.value_or(NAN), -f.Fy_N / f.Fz_N / 2.0);
  EXPECT_LT(f.Fy_N, -0.1 * f.Fz_N);
  EXPECT_GT(f.aligning_moment_Nmm, 0.0);
  ASSERT_TRUE(f.pneumatic_trail_mm.has_value());
  EXPECT_GT(*f.pneumatic_trail_mm, 0.0);
}

TEST(Cornering, OppositeSlipAnglesMirrorTheForces) {
  const RollingResult& r = run(Run::full);
  const RollingFigures& a = named(r, "alpha+2").figures;
  const RollingFigures& b = named(r, "alpha-2").figures;
  expect_mirrored(a, b, r.loaded_radius_mm);
  // Straight ahead the full model has no lateral force (its symmetric solution).
  const double tol = 1e-6 * a.Fz_N;
  const RollingFigures& free = named(r, "free").figures;
  EXPECT_NEAR(free.Fy_N, 0.0, tol);
  EXPECT_NEAR(free.aligning_moment_Nmm, 0.0, tol * r.loaded_radius_mm);
}

// Camber: the road tilted under the +x shoulder (γ > 0, the top of the wheel leaning right) pushes the
// tyre to the right, Fy < 0 (camber thrust towards the lean); γ → −γ mirrors the solution.
TEST(Cornering, OppositeCambersMirrorTheForces) {
  const RollingResult& r = run(Run::full);
  const RollingFigures& a = named(r, "camber+2").figures;
  const RollingFigures& b = named(r, "camber-2").figures;
  std::printf("  γ +2°: Fx %.2f N, Fy %.2f N, Fz %.2f N, Mz %.0f N·mm, overturning %.0f N·mm\n", a.Fx_N, a.Fy_N, a.Fz_N,
              a.aligning_moment_Nmm, a.overturning_moment_Nmm);
  EXPECT_LT(a.Fy_N, 0.0);
  expect_mirrored(a, b, r.loaded_radius_mm);
}

// hold = "load" on a free-rolling cambered state (as the tyre test's cambered states): Qz at the study's
// target within its tolerance, Qy = 0 at the held δz, and the state's tread points (what its traction maps
// show) evaluated at that δz: their forces add up to the state's figures.
TEST(Cornering, AHeldStateIsAtTheLoadWithItsTreadPointsAtItsDeflection) {
  const RollingResult& r = run(Run::full);
  const RollingStateResult& s = named(r, "free camber+2 held");
  const RollingFigures& f = s.figures;
  std::printf("  held γ +2°: Qz %.2f N (target 3000), δz %.4f mm (footprint %.4f mm), Qy %.3f N\n", f.Qz_N,
              s.deflection_mm.value_or(0.0), r.deflection_mm, f.Qy_N);
  EXPECT_NEAR(f.Qz_N, 3000.0, 1e-3 * 3000.0);
  EXPECT_LE(std::abs(f.Qy_N), 1e-4 * f.Qz_N);
  ASSERT_TRUE(s.deflection_mm.has_value());
  EXPECT_GT(std::abs(*s.deflection_mm - r.deflection_mm), 1e-3);  // it moved (camber changes Qz at fixed δz)
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (std::size_t q = 0; q < r.tread_points.size(); ++q) sum += s.normal[q].force + s.tangential[q].force;
  EXPECT_NEAR(sum.z(), f.Qz_N, 1e-9 * f.Qz_N);
  // The states solved after a held one start from the footprint's δz again: the unheld camber states
  // before it have no deflection of their own.
  EXPECT_FALSE(named(r, "camber+2").deflection_mm.has_value());
}

TEST(Cornering, NoPointCarriesMoreThanMuTimesItsPressure) {
  const RollingResult& r = run(Run::full);
  for (const char* name : {"alpha+2", "alpha-2", "traction"}) {
    const RollingStateResult& s = named(r, name);
    int slipping = 0;
    for (std::size_t q = 0; q < r.tread_points.size(); ++q) {
      const double w = r.tread_points[q].weight;
      const double qt = s.tangential[q].force.norm() / w, qn = s.normal[q].force.norm() / w;
      EXPECT_LE(qt, r.friction * qn * (1 + 1e-9) + 1e-12) << name << " point " << q;
      slipping += s.tangential[q].status == TreadContact::slip;
    }
    EXPECT_GT(slipping, 0) << name;  // the bound is met with equality somewhere, not vacuously
    const RollingFigures& f = s.figures;
    EXPECT_LE(std::hypot(f.Fx_N, f.Fy_N), r.friction * f.Fz_N);
  }
}

TEST(Cornering, RimBalancesAllSixComponentsOfTheContact) {
  const RollingResult& r = run(Run::full);
  const TyreMesh& tm = tyre(false);
  const Eigen::Vector3d centre(0.0, 0.0, tm.axis_z);
  for (const char* name : {"alpha+2", "camber+2", "traction"}) {
    const RollingStateResult& s = named(r, name);
    const RimReaction rim = rim_reaction(tm, example_case().inflation.pressure, s.displacement);
    RimReaction contact;  // the contact forces and their moment about the axle centre, at the breaker
    for (std::size_t q = 0; q < r.tread_points.size(); ++q) {
      const TreadPoint& p = r.tread_points[q];
      const Eigen::Vector3d x = s.normal[q].position - p.height * p.normal;  // at the breaker
      const Eigen::Vector3d f = s.normal[q].force + s.tangential[q].force;
      contact.force += f;
      contact.moment += (x - centre).cross(f);
    }
    const double fz = s.figures.Fz_N;
    std::printf("  %s: contact force (%.4f, %.4f, %.4f) N, rim (%.4f, %.4f, %.4f) N; moments (%.2f, %.2f, %.2f) / "
                "(%.2f, %.2f, %.2f) N·mm\n", name, contact.force.x(), contact.force.y(), contact.force.z(),
                -rim.force.x(), -rim.force.y(), -rim.force.z(), contact.moment.x(), contact.moment.y(),
                contact.moment.z(), -rim.moment.x(), -rim.moment.y(), -rim.moment.z());
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(contact.force[i], -rim.force[i], 1e-6 * fz) << name << " force " << i;
      EXPECT_NEAR(contact.moment[i], -rim.moment[i], 1e-6 * fz * r.loaded_radius_mm) << name << " moment " << i;
    }
  }
}

TEST(Cornering, StraightAheadTheFullModelReproducesTheHalfModel) {
  const RollingResult& full = run(Run::full);
  const RollingResult& half = run(Run::half);
  ASSERT_TRUE(full.effective_rolling_radius_mm && half.effective_rolling_radius_mm);
  std::printf("  Re full %.6f / half %.6f mm; traction Qy %.3f / %.3f N\n", *full.effective_rolling_radius_mm,
              *half.effective_rolling_radius_mm, named(full, "traction").figures.Qy_N,
              named(half, "traction").figures.Qy_N);
  EXPECT_NEAR(*full.effective_rolling_radius_mm / *half.effective_rolling_radius_mm, 1.0, 1e-6);
  EXPECT_NEAR(named(full, "traction").figures.Qy_N, named(half, "traction").figures.Qy_N,
              1e-4 * named(half, "traction").figures.Qz_N);
}

// The virtual rig's α sweep solves α ≥ 0 only and mirrors the rest (SlipAngleSweep::mirror_negative_angles)
// where the tyre is its own mirror image: the example's (balanced belt pair, radial carcass) on the full
// model, not a tyre whose belts are both laid at +22° nor a half model. The mirrored point at −2° equals
// the state solved there in the same study (1e-6 of Fz, as for two solved mirror states), and is marked
// as not solved; the cornering stiffness's probe at −0.2° is mirrored too, so it is −dFy/dα from one side.
TEST(Cornering, MirroredSweepPointsEqualTheSolvedStates) {
  EXPECT_TRUE(mirror_symmetric(tyre(false)));
  EXPECT_FALSE(mirror_symmetric(tyre(true)));
  TyreDescription one_handed = example_case().tyre;
  int angled = 0;
  for (Zone& z : one_handed.zones)
    for (Ply& p : z.outer.plies)
      if (p.angle_deg < 0) p.angle_deg = -p.angle_deg, ++angled;
  ASSERT_GT(angled, 0);
  EXPECT_FALSE(mirror_symmetric(build_tyre_mesh(one_handed, coarse_mesh(8, 12, false))));

  RollingStudy s;
  s.name = "mirrored";
  s.target_load = 3000.0;
  s.friction = 0.7;
  s.tread_shear = RollingStudy::TreadShear::planar;
  s.states = {state(RollingStateSpec::Kind::free, 0.0, 0.0, "free"),
              state(RollingStateSpec::Kind::given_slip, 0.0, -2.0, "alpha-2")};
  SlipAngleSweep sweep;
  sweep.from = -2.0;
  sweep.to = 2.0;
  sweep.points = 3;
  sweep.mirror_negative_angles = true;
  s.angle_sweep = sweep;
  const Case& c = example_case();
  const RollingResult r = run_rolling(tyre(false), c.tyre, c.inflation, settings(), s);
  ASSERT_EQ(r.angle_sweep.size(), 3u) << r.failure;
  const SweepPoint& minus = r.angle_sweep[0];
  EXPECT_EQ(minus.slip_angle_deg, -2.0);
  EXPECT_TRUE(minus.mirrored);
  EXPECT_EQ(minus.counts.newton_iterations, 0);
  EXPECT_FALSE(r.angle_sweep[2].mirrored);
  const RollingFigures& solved = named(r, "alpha-2").figures;
  std::printf("  α −2°: mirrored Fy %.3f N, Mz %.1f N·mm; solved Fy %.3f N, Mz %.1f N·mm\n", minus.figures.Fy_N,
              minus.figures.aligning_moment_Nmm, solved.Fy_N, solved.aligning_moment_Nmm);
  const double tol = 1e-6 * solved.Fz_N;
  EXPECT_NEAR(minus.figures.Fz_N, solved.Fz_N, tol);
  EXPECT_NEAR(minus.figures.Fy_N, solved.Fy_N, tol);
  EXPECT_NEAR(minus.figures.aligning_moment_Nmm, solved.aligning_moment_Nmm, tol * r.loaded_radius_mm);
  EXPECT_NEAR(minus.figures.overturning_moment_Nmm, solved.overturning_moment_Nmm, tol * r.loaded_radius_mm);
  EXPECT_NEAR(minus.figures.Fx_N, solved.Fx_N, tol);
  ASSERT_TRUE(r.cornering_stiffness_N_per_deg.has_value());
  EXPECT_LT(*r.cornering_stiffness_N_per_deg, 0.0) << "dFy/dα < 0 in W axes";
}

// A rolling state's effort is bounded (ContactSettings::max_state_iterations): the bound is checked before
// each stage, so one that cannot be reached within it is reported as not converged, with the reason (and
// the usual cause's README section), once the stage under way ends. Here α = 10° with a bound of 5 Newton
// iterations, fewer than its first stage alone needs; that stage is expected to end within one Newton
// solve's limit (max_newton_iterations, + 5 when converging fast).
TEST(Cornering, AStateGivesUpWithinItsIterationBound) {
  RollingStudy s;
  s.name = "bounded";
  s.target_load = 3000.0;
  s.friction = 0.7;
  s.tread_shear = RollingStudy::TreadShear::planar;
  using K = RollingStateSpec::Kind;
  s.states = {state(K::free, 0.0, 0.0, "free"), state(K::given_slip, 0.0, 10.0, "alpha+10")};
  ContactSettings cs = settings();
  cs.max_state_iterations = 5;
  const Case& c = example_case();
  const RollingResult r = run_rolling(tyre(false), c.tyre, c.inflation, cs, s);
  ASSERT_EQ(r.states.size(), 2u);
  ASSERT_TRUE(r.states[0].converged) << r.states[0].failure;
  const RollingStateResult& bounded = r.states[1];
  std::printf("  α = 10° with at most 5 Newton iterations: %d, '%s'\n", bounded.counts.newton_iterations,
              bounded.failure.c_str());
  EXPECT_FALSE(bounded.converged);
  EXPECT_NE(bounded.failure.find("gave up after"), std::string::npos) << bounded.failure;
  // and points to the usual cause, a mode of the mesh, and what to read about it
  EXPECT_NE(bounded.failure.find("README, \"How fine a mesh\""), std::string::npos) << bounded.failure;
  EXPECT_LE(bounded.counts.newton_iterations, 5 + cs.max_newton_iterations + 5);
}

}  // namespace
}  // namespace tirefem::verification
