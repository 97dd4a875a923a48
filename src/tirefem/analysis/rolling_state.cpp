// Axle loads of a rolling state and the solve of one state (the iteration over contact region and
// stick/slip plan); the study around them is in rolling.cpp.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "tirefem/analysis/rolling.hpp"

namespace tirefem {

WheelFrame wheel_frame(const SupportSurface& support, double deflection, bool reverse) {
  WheelFrame w;
  w.centre = Eigen::Vector3d(0.0, 0.0, support.height(0.0, 0.0, deflection));
  const Eigen::Vector3d normal = -support.penetration(w.centre, deflection).gradient.normalized();
  const Eigen::Vector3d travel(0.0, reverse ? -1.0 : 1.0, 0.0);
  w.z = normal;
  w.x = (travel - travel.dot(normal) * normal).normalized();
  w.y = w.z.cross(w.x);
  return w;
}

RollingFigures rolling_figures(const std::vector<TreadPoint>& points, const std::vector<TreadPointState>& normal,
                               const std::vector<TreadTraction>& tangential, double axle_z, bool half_model,
                               bool reverse, const WheelFrame& frame) {
  RollingFigures f;
  double stick_area = 0.0, moment = 0.0, normal_sum = 0.0;
  Eigen::Vector3d about_centre = Eigen::Vector3d::Zero(), pressure_moment = Eigen::Vector3d::Zero();
  for (std::size_t q = 0; q < points.size(); ++q) {
    const Eigen::Vector3d force = normal[q].force + tangential[q].force;
    const Eigen::Vector3d& x = normal[q].position;
    f.force_N += force;
    moment += x.y() * force.z() - (x.z() - axle_z) * force.y();  // (r − r_axle) × F, x component
    about_centre += (x - frame.centre).cross(force);
    const double fn = normal[q].force.dot(frame.z);
    normal_sum += fn;
    pressure_moment += fn * (x - frame.centre);
    if (normal[q].pressure > 0) {
      f.contact_area_mm2 += points[q].weight;
      if (tangential[q].status == TreadContact::stick) stick_area += points[q].weight;
    }
    if (tangential[q].status != TreadContact::out)
      f.max_traction_MPa = std::max(f.max_traction_MPa, std::abs(tangential[q].traction));
  }
  f.stick_area_fraction = f.contact_area_mm2 > 0 ? stick_area / f.contact_area_mm2 : 0.0;
  if (half_model) {
    // The mirror image in x = 0 (positions (−x, y, z), forces (−Fx, Fy, Fz)) doubles all but the lateral
    // force and the moments about y and z, which it cancels; C lies on x = 0.
    f.force_N *= 2.0;
    f.force_N.x() = 0.0;
    moment *= 2.0;
    about_centre = Eigen::Vector3d(2.0 * about_centre.x(), 0.0, 0.0);
    pressure_moment = Eigen::Vector3d(0.0, 2.0 * pressure_moment.y(), 2.0 * pressure_moment.z());
    normal_sum *= 2.0;
    f.contact_area_mm2 *= 2.0;
  }
  // A reversed study is the mirror image (y → −y) of a forward one: report its figures in that frame.
  const double sign = reverse ? -1.0 : 1.0;
  f.Qz_N = f.force_N.z();
  f.Qy_N = sign * f.force_N.y();
  f.Mx_Nmm = sign * moment;
  f.Fx_N = f.force_N.dot(frame.x);
  f.Fy_N = f.force_N.dot(frame.y);
  f.Fz_N = f.force_N.dot(frame.z);
  f.overturning_moment_Nmm = about_centre.dot(frame.x);
  f.rolling_moment_Nmm = about_centre.dot(frame.y);
  f.aligning_moment_Nmm = about_centre.dot(frame.z);
  if (std::abs(f.Fy_N) > 1e-3 * std::abs(f.Fz_N)) f.pneumatic_trail_mm = -f.aligning_moment_Nmm / f.Fy_N;
  if (normal_sum != 0.0) {
    const Eigen::Vector3d cp = pressure_moment / normal_sum;
    f.centre_of_pressure_mm = Eigen::Vector2d(cp.dot(frame.x), cp.dot(frame.y));
  }
  return f;
}

std::string rim_flange_side(const RimFlangeLoad& load, bool half_model, bool reverse) {
  if (half_model) return "each";
  return (load.side < 0) != reverse ? "left" : "right";
}

RollingFigures mirrored_figures(const RollingFigures& f) {
  RollingFigures m = f;
  m.force_N.x() = -f.force_N.x();
  m.Fy_N = -f.Fy_N;
  m.overturning_moment_Nmm = -f.overturning_moment_Nmm;
  m.aligning_moment_Nmm = -f.aligning_moment_Nmm;
  m.centre_of_pressure_mm.y() = -f.centre_of_pressure_mm.y();
  for (RollingFigures::Flange& flange : m.rim_flanges) {
    flange.load.side = -flange.load.side;
    if (flange.side != "each") flange.side = flange.side == "left" ? "right" : "left";
  }
  return m;
}

namespace {
constexpr int kSingleLoopIterations = 12;

int count_plan_changes(const FrictionPlan& a, const FrictionPlan& b) {
  int n = 0;
  // Not the entry anchors' weights between their two points: a frozen plan's follow u (TreadFrictionForm).
  for (std::size_t k = 0; k < a.size(); ++k)
    n += a[k].status != b[k].status || a[k].sign != b[k].sign || a[k].anchor_a != b[k].anchor_a ||
         a[k].anchor_b != b[k].anchor_b || a[k].anchored_on_slip != b[k].anchored_on_slip;
  return n;
}
int count_changes(const std::vector<char>& a, const std::vector<char>& b) {
  int n = 0;
  for (std::size_t k = 0; k < a.size(); ++k) n += (a[k] != 0) != (b[k] != 0);
  return n;
}

// The two-level loop with the contact region (eq. 5) and the stick/slip plan (eq. 15) frozen and revised
// together (MODEL.md §5).
//
// The friction's smoothed Jacobian (TreadFrictionForm::set_jacobian_smoothing) keeps Newton from cycling
// while the plan is still moving, but it is not the residual's derivative: a point sliding just past its
// limit then costs the convergence its quadratic rate. Once a revision found the plan and region settled,
// the polishing solve has the exact tangent. Measured on the 80 × 46 full model at 5550 N, α 5.6° → 6.1°
// (cords at 10% in compression, neo-Hookean rubber): with the smoothed tangent the polish fell by a
// factor 0.82 per iteration (1.9e-6 → 5.3e-8 in 25) and the stage failed; the friction form's tangent was
// 59% off its difference quotient along the step, every other form's within 1e-8.
ContactSolveOutcome two_level(NewtonSolver& newton, WinklerContactForm& contact, TreadFrictionForm& friction,
                              Eigen::VectorXd& u, const ContactSettings& settings) {
  std::vector<char> region;
  FrictionPlan plan;
  const double smoothing = friction.jacobian_smoothing();
  int last_changes = -1;
  bool exact_polish = smoothing > 0.0, polishing = false;
  Eigen::VectorXd before_polish;
  const auto freeze = [&](const Eigen::VectorXd& v) {
    if (region.empty()) region = contact.region(v), plan = friction.plan(v, region);
    contact.freeze_region(region);
    friction.freeze_plan(plan);
    polishing = exact_polish && last_changes == 0;
    if (polishing) before_polish = v;
    friction.set_jacobian_smoothing(polishing ? 0.0 : smoothing);
  };
  const auto revise = [&](const Eigen::VectorXd& v) {
    std::vector<char> revised_region = contact.region(v);
    FrictionPlan revised_plan = friction.plan(v, revised_region);
    const int changes = count_changes(region, revised_region) + count_plan_changes(plan, revised_plan);
    region = std::move(revised_region);
    plan = std::move(revised_plan);
    last_changes = changes;
    return changes;
  };
  ContactSolveOutcome out = two_level_iteration(newton, u, settings, freeze, revise);
  if (!out.converged && polishing) {
    // The exact tangent did not serve (a point crossing its limit at every iterate): polish again from
    // where it began, with the smoothed one.
    exact_polish = false;
    u = before_polish;
    const int newton_iterations = out.newton_iterations;
    out = two_level_iteration(newton, u, settings, freeze, revise);
    out.newton_iterations += newton_iterations;
  }
  contact.release_region();
  friction.release_plan();
  friction.set_jacobian_smoothing(smoothing);
  return out;
}
}  // namespace

ContactSolveOutcome solve_rolling_state(NewtonSolver& newton, WinklerContactForm& contact,
                                        TreadFrictionForm& friction, Eigen::VectorXd& u,
                                        const ContactSettings& settings) {
  if (settings.iteration == ContactSettings::Iteration::two_level)
    return two_level(newton, contact, friction, u, settings);
  const Eigen::VectorXd start = u;
  contact.release_region();
  friction.release_plan();
  // Near a stick/slip boundary the plan may cycle between iterates: after a few single-loop iterations
  // the two-level loop takes over from the last iterate (from the start if that one went astray).
  const int max_iterations = newton.max_iterations();
  newton.set_max_iterations(std::min(max_iterations, kSingleLoopIterations));
  const NewtonOutcome n = newton.solve(u, 1.0);
  newton.set_max_iterations(max_iterations);
  if (n.converged) {
    ContactSolveOutcome out;
    out.converged = true;
    out.contact_iterations = 1;
    out.newton_iterations = n.iterations;
    out.tangent_shift = n.final_shift;
    return out;
  }
  if (!u.allFinite() || !(n.relative_residual < 1.0)) u = start;
  ContactSolveOutcome out = two_level(newton, contact, friction, u, settings);
  out.newton_iterations += n.iterations;
  return out;
}

}  // namespace tirefem
