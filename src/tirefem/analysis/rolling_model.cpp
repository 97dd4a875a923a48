#include "tirefem/analysis/rolling_model.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>

#include <fmt/format.h>

#include "tirefem/analysis/inflation.hpp"
#include "tirefem/forms/pressure_form.hpp"
#include "tirefem/analysis/tyre_shell_forms.hpp"

namespace tirefem {

namespace {

using Clock = std::chrono::steady_clock;
constexpr double kAngleStep = 0.04;  // largest first step in tan α (2.3°) and in γ (rad)
// hold_load's du/dδz: ∂R/∂δz by central differences over ±kRateStep (mm), solved to kRateTolerance. At a
// fixed u the residual is smooth in δz only on a scale far below the gaps of neighbouring tread points
// (the patch entry between two points moves with δz): measured on the 40 × 12 full model, a step of 1e-2
// gave dQz/dδz 12% low and 1e-1 2.7 times too high; 1e-4 and 1e-5 agree with converged states 0.01 mm
// apart (RollingDeflectionRate.*).
constexpr double kRateStep = 1e-5;
constexpr double kRateTolerance = 1e-6;
// parameter_rate's central differences: a step of 1e-7 in the largest of (axle height / Rk, tan α, γ).
constexpr double kParameterStep = 1e-7;
constexpr int kEasyIterations = 6;   // a step that converged within this many Newton iterations doubles
constexpr double kJacobianSmoothing = 0.1;  // TreadFrictionForm::set_jacobian_smoothing, see below
constexpr double kDegree = 3.14159265358979323846 / 180.0;
constexpr double kQuietSeconds = 10.0;      // a state taking longer reports its stages (set_progress)
// Why a state gives up, most often. Measured: the main example's quick rig at 0.16 MPa gave up its 2800 N
// α sweep past 3.1° on 64 × 12 full and reached 10° on 80 × 24 (8–13 Newton iterations per state).
constexpr const char* kMeshModeHint =
    "a state that needs ever smaller steps is often a mode of the mesh (the wall's or the carcass's, at the "
    "scale of its elements): a finer mesh may reach it (README, \"How fine a mesh\")";
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Points that may touch the support while rolling: the static patch's angular extent along the flow,
// widened by 30% of its length and two elements on each side (the patch moves and grows little).
std::vector<char> friction_window(const ShellMesh& mesh, const std::vector<TreadPoint>& points,
                                  const std::vector<TreadPointState>& states) {
  double lo = 1e300, hi = -1e300;
  for (std::size_t q = 0; q < points.size(); ++q)
    if (states[q].pressure > 0) lo = std::min(lo, points[q].v), hi = std::max(hi, points[q].v);
  double element_angle = 0.0;
  for (int j = 0; j + 1 < static_cast<int>(mesh.v_values.size()); ++j)
    if (mesh.v_values[j] <= 0.0 && mesh.v_values[j + 1] >= 0.0) element_angle = mesh.v_values[j + 1] - mesh.v_values[j];
  const double margin = 0.3 * (hi - lo) + 2.0 * element_angle;
  std::vector<char> window(points.size());
  for (std::size_t q = 0; q < points.size(); ++q) window[q] = points[q].v >= lo - margin && points[q].v <= hi + margin;
  return window;
}

}  // namespace

RollingModel::RollingModel(const TyreMesh& tm, const TyreDescription& tyre, const InflationSettings& inflation,
                           const ContactSettings& settings, const RollingStudy& study, RollingResult& result)
    : tm_(tm), settings_(settings), result_(result) {
  // On a plane the road may be cambered: the model keeps access to its tilt.
  if (study.support.kind == SupportDescription::Kind::plane) {
    auto plane = std::make_unique<CamberedPlane>();
    cambered_ = plane.get();
    support_ = std::move(plane);
  } else {
    support_ = make_support(study.support);
  }
  const StaticContactResult& fp = result.footprint;
  DofMap dofs(tm.mesh.dof_count());
  dofs.fix(tm.fixed_dofs);
  std::vector<std::unique_ptr<Form>> forms;
  flange_ = add_tyre_shell_forms(forms, tm, Kinematics::nonlinear);
  forms.push_back(std::make_unique<PressureForm>(tm.mesh, tm.pressure_elements, inflation.pressure,
                                                 Kinematics::nonlinear, /*symmetrize=*/false));
  auto contact = std::make_unique<WinklerContactForm>(tm.mesh, fp.tread_points, tyre.tread_stiffness, *support_);
  contact_ = contact.get();
  forms.push_back(std::move(contact));
  // The vehicle travels in +y: the support moves in −y under the tyre (reversed: +y).
  auto friction = std::make_unique<TreadFrictionForm>(
      tm.mesh, contact_->points(), tyre.tread_stiffness, tyre.tread_shear_modulus, *support_,
      study.reverse ? 1 : -1, friction_window(tm.mesh, contact_->points(), fp.final_state.tread));
  friction_ = friction.get();
  const RollingStudy::TreadShear shear = study.tread_shear.value_or(
      tm.half_model ? RollingStudy::TreadShear::longitudinal : RollingStudy::TreadShear::planar);
  friction_->set_planar(shear == RollingStudy::TreadShear::planar);
  // Planar friction: Newton's tangent of a point just past the friction limit blends in its stick tangent
  // (the residual, hence every converged state, is unchanged). Measured on the 80 × 46 full model at
  // 3700 N: α = 4° from free rolling failed after 436 Newton iterations (a few points along the lines
  // flipping between stick and slip at every iterate, the residual cycling about 1e-3), and converges
  // with it (63 iterations; α = 6° next, 236). On the 80 × 24 cornering bench it costs 171 instead of
  // 155 iterations, 47 instead of 43 LUs.
  friction_->set_jacobian_smoothing(kJacobianSmoothing);
  result.planar_shear = friction_->planar();
  forms.push_back(std::move(friction));
  problem_ = std::make_unique<NonlinearProblem>(std::move(dofs), std::move(forms));
  problem_->load_scale();  // inflation load, before the support is raised (as in the static run)
  NewtonSettings ns;
  ns.max_iterations = settings.max_newton_iterations;
  ns.residual_tolerance = settings.residual_tolerance;
  // An unsymmetric LU costs about twice a Cholesky: reuse it as GMRES preconditioner while that
  // converges fast (the tangent changes little between iterations and neighbouring states), unless the
  // case asks for a factorisation per iteration.
  ns.reuse_factorization = settings.reuse_factorizations;
  // GMRES gives up after 25 iterations (then a fresh LU); measured on the 15-point sweep before the
  // refresh after 8 (NewtonSettings): 12 → 28 LUs, 41 s; 25 → 4 LUs, 31 s; 40 → 65 s.
  ns.max_krylov_iterations = 25;
  // Below a residual of 1e-2 the LU held serves to the end of the state (NewtonSettings): one or two more
  // steps on it cost less than a new one (docs/studies/rolling-newton-cost.md, last sections). Not
  // refreshed after many GMRES iterations: on the rolling bench (80 × 46 half, 3700 N), three alternating
  // runs, the κ = 0.02 state 2 → 1 LUs, 1.31 → 0.93 s (medians), the 15-point sweep 57 → 52 Newton
  // iterations, 8 → 7 LUs, 10.2 → 8.4 s. And GMRES goes on when its true residual is too large: the
  // cornering bench's α = 2° state 3 → 2 LUs (8 → 9 iterations), its sweep 5 → 4 LUs (22 → 24). The
  // tyre-test example's counts within a few per series either way, its time unchanged within the noise.
  ns.keep_lu_below_residual = 1e-2;
  newton_ = std::make_unique<NewtonSolver>(*problem_, ns);
  set_deflection(fp.final_state.deflection_mm);
  base_ = fp.final_state.displacement;
  result.tread_points = contact_->points();
}

RollingModel::Parameters RollingModel::parameters(const WheelSlip& slip) const {
  return {tm_.axis_z / slip.rolling_radius, std::tan(slip.slip_angle), slip.camber, deflection_ / tm_.axis_z};
}

void RollingModel::apply(const Parameters& p) {
  friction_->set_rolling_radius(tm_.axis_z / p[0]);
  // Per unit of the support's travel it moves sideways by tan α along +x (reversed travel: along −x).
  friction_->set_lateral_drift(result_.reverse ? -p[1] : p[1]);
  if (cambered_) cambered_->set_camber(p[2]);
  else if (p[2] != 0.0) throw std::invalid_argument("camber on a support other than a plane");
}

RollingModel::Solved RollingModel::solve(const FrictionLaw& law, const WheelSlip& slip, bool from_last,
                                         bool along_tangent) {
  const auto t0 = Clock::now();
  const int factorizations0 = newton_->linear_stats().factorizations;
  const int newton0 = newton_->total_iterations();
  Solved s;
  const bool full_slip = law.mode == FrictionLaw::Mode::full_slip;
  const Parameters target = parameters(slip);
  const Known* from = full_slip ? nullptr : from_last && !known_.empty() ? &known_.back() : nearest(target);
  const int from_index = from ? static_cast<int>(from - known_.data()) : -1;
  // Bounded by contact.max_state_iterations. (A second attempt from free rolling after a failed one from
  // the neighbour, tried on 80 × 46 full at α = 4° with Qz held, failed as well and doubled the time to
  // the failure: docs/studies/planar-friction-newton.md, fifth look.)
  Attempt a = continuation(law, target, from_index, along_tangent, s.counts.solves);
  s.converged = a.converged;
  s.failure = a.failure;
  s.parameters = target;
  s.continued = law.mode == FrictionLaw::Mode::coulomb;
  s.counts.contact_iterations = a.last.contact_iterations;
  s.counts.newton_iterations = newton_->total_iterations() - newton0;
  s.counts.factorizations = newton_->linear_stats().factorizations - factorizations0;
  s.counts.time_s = seconds_since(t0);
  if (s.converged) {
    s.figures = figures(a.u);
    s.u = std::move(a.u);
  }
  return s;
}

RollingModel::Attempt RollingModel::continuation(const FrictionLaw& law, const Parameters& target, int from_index,
                                                 bool along_tangent, int& solves) {
  Attempt a;
  const bool full_slip = law.mode == FrictionLaw::Mode::full_slip;
  const int newton0 = newton_->total_iterations();
  // ContactSettings::max_state_iterations: a stage that converges only in ever smaller steps could
  // otherwise run for hours (the default, 250, is above the 236 iterations of the hardest state measured
  // to converge: 80 × 46 full, α 4° → 6° at 3700 N).
  const int budget = settings_.max_state_iterations;
  double done = 0.0, step = 1.0;  // continuation parameter from the start state (0) to the target (1)
  Eigen::VectorXd u = from_index >= 0 ? known_[from_index].u : base_;
  Eigen::VectorXd previous_u = u;  // full slip: the converged stage before u, at previous_t
  double previous_t = 0.0;
  const Parameters p0 = from_index >= 0 ? known_[from_index].parameters : target;
  // A slip angle or camber far from the start state turns much of the patch from sticking to sliding
  // at once: steps of at most kAngleStep in tan α and γ, doubled after an easy one. Measured first on
  // the 40 × 12 full model with a step of 0.02 (Newton iterations, one step against these): α 0 → 2°
  // 32 → 15, 0 → −4° 131 → 44, 0 → 4° 24 → 53, a combined state 66 → 98; 258 → 215 in all. With
  // today's solver 0.04 (one stage up to 2.3°) against 0.02, the same converged states:
  //  - cornering bench (80 × 46 full, rim flange): α = 2° from free rolling 13 → 8, α sweep 37 → 22;
  //  - cornering example (80 × 24): α ±4° 13 → 7 each, camber 2° 19 → 14, combined 19 → 14, combined
  //    sweep 14 + 12 + 12 → 9 + 6 + 6; its rolling study 89.5 → 63.9 s;
  //  - the 80 × 46 rig's α series, 1.7–2.8° apart: at 1850 N and 3700 N 2–6 fewer per state (e.g. 3.92°
  //    13 → 8, 14 → 10); at 5550 N 31 / 59 / 47 → 30 / 34 / 10 at 2.2° / 3.92° / 6.12°; the rig 238 → 189–201 s;
  //  - the main example's quick rig (64 × 12): at 2800 N 2.5° from 0.625° 19 → 30 (its series 5.5 →
  //    7.3 s; the example's wall time unchanged).
  const double angle_change = std::max(std::abs(target[1] - p0[1]), std::abs(target[2] - p0[2]));
  if (angle_change > kAngleStep) step = kAngleStep / angle_change;
  int cutbacks = 0;
  const auto t0 = Clock::now();
  // A long state reports each stage: where it is on the way (in the parameters that change) and how the
  // stage went.
  const auto report = [&](double t, const Parameters& p, const std::string& how) {
    if (!progress_ || seconds_since(t0) < kQuietSeconds) return;
    std::string where;
    if (full_slip) where = fmt::format("μ {:.3f}", friction_->law().friction);
    if (std::abs(target[0] - p0[0]) > 0) where += fmt::format("Rk {:.3f} mm ", tm_.axis_z / p[0]);
    if (std::abs(target[1] - p0[1]) > 0) where += fmt::format("α {:.2f}° ", std::atan(p[1]) / kDegree);
    if (std::abs(target[2] - p0[2]) > 0) where += fmt::format("γ {:.2f}° ", p[2] / kDegree);
    progress_(fmt::format("    stage {:.0f}% of the way ({}): {} ({} Newton iterations, {:.0f} s so far)", 100 * t,
                          where.empty() ? "the start state" : where.substr(0, where.find_last_not_of(' ') + 1),
                          how, newton_->total_iterations() - newton0, seconds_since(t0)));
  };
  std::vector<int> path;  // indices in known_ of the start state and the converged stages
  if (from_index >= 0) path.push_back(from_index);
  int paced_from = -1;  // Newton iterations used when the attempt of the first stage that converged began
  Eigen::VectorXd rate;  // du/dt at the state u at t = rate_at (parameter_rate)
  double rate_at = -1.0, rate_force = 0.0, rate_reserve = 0.0;  // |d(Fx, Fy)/dt| there, μ Fz − |(Fx, Fy)|
  while (done < 1.0) {
    if (newton_->total_iterations() - newton0 > budget) {
      a.failure = fmt::format("gave up after {} Newton iterations (contact.max_state_iterations), {:.0f}% of the "
                              "way from its start state{}; {}",
                              newton_->total_iterations() - newton0, 100 * done,
                              a.last.converged ? "" : fmt::format(" (last stage: {})", a.last.failure),
                              kMeshModeHint);
      break;
    }
    const double t = std::min(1.0, done + step);
    FrictionLaw stage = law;
    Parameters p = target;
    if (full_slip) stage.friction = law.friction * t;
    else p.head<3>() = p0.head<3>() + t * (target.head<3>() - p0.head<3>());  // at the model's δz
    friction_->set_law(stage);
    apply(p);
    Eigen::VectorXd trial = u;
    if (law.mode == FrictionLaw::Mode::coulomb && !predict(p, path, trial)) {
      // No secant, and asked for (free rolling's secant on Rk): along the tangent at the stage's start state
      // (the tread sticking where it sticks there), where that linear response's change of the tread's
      // force (Fx, Fy) is within what friction still allows, μ Fz − |F|; beyond, from the start state.
      // Measured on every stage without a secant (docs/studies/rolling-newton-cost.md): one Newton
      // iteration fewer on most such states, but the rig's hardest states, reached on another path, took
      // more (5550 N, α 3.92°: 55–57 against 34–35 iterations on two BLAS kernels; the rig 202–219 s
      // against 170–180 s); in free rolling alone, 1–2 iterations fewer per study and the rest as before.
      // Without the friction bound, κ 0 → 0.15 on the coarse test case took 139 iterations from the whole
      // tangent step (its Fx 6.5 times what friction allows) against 7 from the start state.
      if (along_tangent && rate_at != done && (target - p0).head<3>().cwiseAbs().maxCoeff() > 0.0) {
        const Parameters from = p0 + done * (target - p0);
        Parameters direction = target - p0;
        direction[3] = 0.0;
        Eigen::Vector2d force_rate;
        if (!parameter_rate(u, from, direction, rate, force_rate)) rate.resize(0);
        else {
          const RollingFigures f = figures(u);
          rate_force = force_rate.norm();
          rate_reserve = friction_->law().friction * f.Fz_N - Eigen::Vector2d(f.Fx_N, f.Fy_N).norm();
        }
        rate_at = done;
        apply(p);
      }
      if (rate.size() == u.size() && (t - done) * rate_force <= rate_reserve) trial += (t - done) * rate;
    } else if (full_slip && done > previous_t) trial += (t - done) / (done - previous_t) * (u - previous_u);
    const int attempt_start = newton_->total_iterations() - newton0;
    a.last = solve_rolling_state(*newton_, *contact_, *friction_, trial, settings_);
    ++solves;
    if (a.last.converged && friction_->contact_outside_window(trial) > 0) {
      a.last.converged = false;
      a.last.failure = "the contact patch grew beyond the friction window";
      cutbacks = 6;  // not a convergence problem: do not cut back
    }
    if (!a.last.converged) {
      if (++cutbacks > 5) {
        a.failure = a.last.failure;
        break;
      }
      step *= 0.5;
      report(t, p, fmt::format("no convergence ({}), step halved", a.last.failure));
      continue;
    }
    if (t < 1.0) report(t, p, fmt::format("converged in {} Newton iterations", a.last.newton_iterations));
    // The pace since the first stage that converged (Newton iterations per share of the way, the failed
    // attempts after it included, those before it not: a continuation may need a few halvings to find
    // its step) must bring the state within its bound, else it gives up now rather than at the bound.
    // Measured on the tyre-test example's 5550 N lateral series (80 × 46 full), α 2.2° → 3.92°: stages
    // converged at 8% (6 iterations, after 71 in failed attempts), 12% and 15% of the way, with failures
    // between them, and it gave up at the pace test of the converged stages alone after 214 iterations
    // (455 s); counted this way it gives up at 12%, after 127 (about 392 more projected; the whole rig
    // 787 → 666 s). The states that converged on that rig project at most 161 in all (8.82° at 3700 N:
    // 96 iterations; its first stage converged after 22).
    if (paced_from < 0) paced_from = attempt_start;
    const int used = newton_->total_iterations() - newton0;
    const double more = (used - paced_from) / t * (1.0 - t);
    if (t < 1.0 && used + more > budget) {
      a.failure = fmt::format("gave up after {} Newton iterations, {:.0f}% of the way from its start state: at its "
                              "pace since its first converged stage it would need about {:.0f} more, beyond "
                              "contact.max_state_iterations ({}); {}",
                              used, 100 * t, more, budget, kMeshModeHint);
      break;
    }
    previous_u = std::move(u);
    previous_t = done;
    u = std::move(trial);
    done = t;
    cutbacks = 0;  // the limit is on halvings in a row: a stage that converged is progress
    if (a.last.newton_iterations <= kEasyIterations) step *= 2.0;
    if (law.mode == FrictionLaw::Mode::coulomb) {
      known_.push_back({p, u});
      path.push_back(static_cast<int>(known_.size()) - 1);
    }
  }
  a.converged = done >= 1.0;
  if (a.converged) a.u = std::move(u);
  return a;
}

bool RollingModel::solution_rate(const Eigen::VectorXd& u, const std::function<void(double)>& move, double h,
                                 Eigen::VectorXd& rate) {
  const DofMap& dofs = problem_->dofs();
  // The tangent at u, the friction's exact one (not Newton's smoothed blend): a derivative of the solution.
  const double smoothing = friction_->jacobian_smoothing();
  friction_->set_jacobian_smoothing(0.0);
  move(0.0);
  problem_->evaluate(u, 1.0, true);
  friction_->set_jacobian_smoothing(smoothing);
  const auto residual_at = [&](double t) {
    move(t);
    problem_->evaluate(u, 1.0, false);  // the tangent assembled at u stays
    return Eigen::VectorXd(dofs.gather(problem_->system().residual()));
  };
  const Eigen::VectorXd dr = (residual_at(h) - residual_at(-h)) / (2.0 * h);
  move(0.0);
  Eigen::VectorXd v;
  if (!newton_->solve_with_tangent(-dr, v, kRateTolerance)) return false;
  rate = Eigen::VectorXd::Zero(u.size());
  dofs.scatter_add(v, rate);
  return true;
}

bool RollingModel::deflection_rate(const Eigen::VectorXd& u, Eigen::VectorXd& rate, double& stiffness) {
  const double d = deflection_, h = kRateStep;
  if (!solution_rate(u, [&](double t) { set_deflection(d + t); }, h, rate)) return false;
  set_deflection(d + h);
  const double above = figures(u + h * rate).Qz_N;
  set_deflection(d - h);
  const double below = figures(u - h * rate).Qz_N;
  set_deflection(d);
  stiffness = (above - below) / (2.0 * h);
  return std::isfinite(stiffness) && stiffness > 0.0;
}

bool RollingModel::parameter_rate(const Eigen::VectorXd& u, const Parameters& at, const Parameters& direction,
                                  Eigen::VectorXd& rate, Eigen::Vector2d& force_rate) {
  const double h = kParameterStep / direction.head<3>().cwiseAbs().maxCoeff();
  if (!solution_rate(u, [&](double t) { apply(at + t * direction); }, h, rate)) return false;
  const auto force_at = [&](double t) {
    apply(at + t * direction);
    const RollingFigures f = figures(u + t * rate);
    return Eigen::Vector2d(f.Fx_N, f.Fy_N);
  };
  force_rate = (force_at(h) - force_at(-h)) / (2.0 * h);
  apply(at);
  return force_rate.allFinite();
}

bool RollingModel::slip_rate(const Eigen::VectorXd& u, const WheelSlip& from, const WheelSlip& to,
                             Eigen::VectorXd& rate, Eigen::Vector2d& force_rate) {
  const Parameters at = parameters(from);
  Parameters direction = parameters(to) - at;
  direction[3] = 0.0;
  return direction.cwiseAbs().maxCoeff() > 0.0 && parameter_rate(u, at, direction, rate, force_rate);
}

void RollingModel::hold_load(Solved& s, double target, double tolerance, double stiffness) {
  const auto t0 = Clock::now();
  const int factorizations0 = newton_->linear_stats().factorizations;
  const int newton0 = newton_->total_iterations();
  double d0 = deflection_, q0 = s.figures.Qz_N, slope = stiffness;
  int cutbacks = 0, steps = 0;
  // du/dδz at the state each δz step starts from, and dQz/dδz along it: the step to the target load and
  // the prediction of the state there (without it the patch's newly touching edge starts the solve far
  // off). Empty where that solve failed: then the static stiffness and the secant of the steps serve.
  Eigen::VectorXd rate;
  while (steps < 8 && s.converged && std::abs(q0 - target) > tolerance * target) {
    // (At each state a step starts from; a cut-back keeps the rate.)
    if (cutbacks == 0) {
      double k = 0.0;
      if (deflection_rate(s.u, rate, k)) slope = k;
      else rate.resize(0);
    }
    const double d1 = d0 + (target - q0) / slope * std::pow(0.5, cutbacks);
    set_deflection(d1);
    Eigen::VectorXd u = s.u;
    if (rate.size() == u.size()) u += (d1 - d0) * rate;
    const ContactSolveOutcome o = solve_rolling_state(*newton_, *contact_, *friction_, u, settings_);
    ++s.counts.solves;
    if (!o.converged) {
      // A smaller change of δz from the last converged state (measured: the first δz step of a
      // cornering state at α = 2° diverged where its halves converge).
      if (++cutbacks <= 3) {
        set_deflection(d0);
        continue;
      }
      s.converged = false;
      s.failure = "holding Qz: " + o.failure;
      break;
    }
    cutbacks = 0;
    ++steps;
    s.u = std::move(u);
    s.figures = figures(s.u);
    if (progress_ && s.counts.time_s + seconds_since(t0) >= kQuietSeconds)
      progress_(fmt::format("    holding Qz: δz {:.3f} mm → Qz {:.1f} N ({} Newton iterations, {:.0f} s so far)", d1,
                            s.figures.Qz_N, o.newton_iterations, s.counts.time_s + seconds_since(t0)));
    if (s.figures.Qz_N != q0) slope = (s.figures.Qz_N - q0) / (d1 - d0);
    d0 = d1, q0 = s.figures.Qz_N;
  }
  if (s.converged && std::abs(q0 - target) > tolerance * target) {
    s.converged = false;
    s.failure = fmt::format("Qz = {} N not held within 8 deflection steps (Qz {:.1f} N)", target, q0);
  }
  if (s.converged && steps > 0) {
    s.parameters[3] = deflection_ / tm_.axis_z;
    if (s.continued) known_.push_back({s.parameters, s.u});
  }
  s.counts.newton_iterations += newton_->total_iterations() - newton0;
  s.counts.factorizations += newton_->linear_stats().factorizations - factorizations0;
  s.counts.time_s += seconds_since(t0);
}

void RollingModel::set_deflection(double deflection) {
  deflection_ = deflection;
  contact_->set_deflection(deflection);
  friction_->set_deflection(deflection);
}

RollingFigures RollingModel::figures(const Eigen::VectorXd& u) const {
  RollingFigures f = rolling_figures(contact_->points(), contact_->evaluate(u), friction_->evaluate(u), tm_.axis_z,
                                     tm_.half_model, result_.reverse,
                                     wheel_frame(*support_, deflection_, result_.reverse));
  if (flange_)
    for (const RimFlangeLoad& load : flange_->loads(u))
      f.rim_flanges.push_back({rim_flange_side(load, tm_.half_model, result_.reverse), load});
  return f;
}

double RollingModel::static_full_stick_Qy(double rolling_radius) {
  FrictionLaw law;
  law.mode = FrictionLaw::Mode::full_stick;
  friction_->set_law(law);
  apply(parameters({rolling_radius, 0.0, 0.0}));
  return figures(base_).Qy_N;
}

void RollingModel::fill(RollingStateResult& state, const Solved& s) const {
  state.converged = s.converged;
  state.failure = s.failure;
  state.figures = s.figures;
  state.counts = s.counts;
  if (!s.converged) return;
  state.displacement = s.u;
  state.normal = contact_->evaluate(s.u);
  state.tangential = friction_->evaluate(s.u);
}

void RollingModel::finish(SolveCounters& c) const { add_counters(c, *newton_, *problem_); }

const RollingModel::Known* RollingModel::nearest(const Parameters& p, const Known* other) const {
  const Known* best = nullptr;
  for (const Known& k : known_)
    if (&k != other && (!other || (k.parameters - other->parameters).norm() > 1e-15) &&
        (!best || (k.parameters - p).norm() < (best->parameters - p).norm()))
      best = &k;
  return best;
}

// Secant through the two nearest converged states, when the target lies on (or close to) their line,
// between them or at most one spacing beyond the nearest (extrapolating further from two close states,
// e.g. the free-rolling iterates, amplifies their difference); else through the last two states of the
// continuation under way (`path`: the start state, then its converged stages), on the same condition;
// else the start. The two nearest may lie on different branches (a combined-slip stage at κ and the
// α sweep's state at κ = 0 beside it) with the target off their line; the start alone was then the
// prediction, and which states happened to be known decided whether a state converged. Measured on
// 64 × 12 at 2000 N, κ −0.02, α 0 → 2°: the secant along the path converges in 8 + 7 Newton iterations
// (Fx −581.0 N, Fy −898.9 N) with or without an α sweep solved before; from the start (tan α 0.02 →
// 0.0349) Newton diverges, the cut-backs' two-level fallback settles at tan α 0.0225 on a neighbouring
// equilibrium (Fx −701.4 N, stick 62.7%, against −703.5 N, 62.5% along the path) and from there steps
// of 0.0006 in tan α diverge.
bool RollingModel::predict(const Parameters& p, const std::vector<int>& path, Eigen::VectorXd& out) const {
  const auto secant = [&](const Known* a, const Known* b, Eigen::VectorXd& out) {
    const Parameters ab = b->parameters - a->parameters, ap = p - a->parameters;
    if (ab.norm() <= 1e-15) return false;
    const double t = ap.dot(ab) / ab.squaredNorm();
    // At most about one spacing beyond the nearest state (t ≈ −1 continues a sweep with equal steps, up
    // to round-off on either side of −1); two spacings (measured: α = −4° extrapolated from α = 0 and
    // +2°) are worse than the nearest state itself.
    if (t < -1.5 || t > 2.0 || (ap - t * ab).norm() > 0.25 * ap.norm()) return false;
    out = a->u + t * (b->u - a->u);
    return true;
  };
  const Known* a = nearest(p);
  const Known* b = a ? nearest(p, a) : nullptr;
  if (a && b && secant(a, b, out)) return true;
  return path.size() >= 2 && secant(&known_[path.back()], &known_[path[path.size() - 2]], out);
}

}  // namespace tirefem
