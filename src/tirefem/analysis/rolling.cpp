#include "tirefem/analysis/rolling.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "tirefem/forms/pressure_form.hpp"
#include "tirefem/forms/shell_internal_force.hpp"

namespace tirefem {

namespace {

using Clock = std::chrono::steady_clock;
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

// The inflated, statically loaded tyre with the tread's friction: forms, the Newton solver (LU) and the
// converged rolling states for predictions.
class RollingModel {
 public:
  RollingModel(const TyreMesh& tm, const TyreDescription& tyre, const InflationSettings& inflation,
               const ContactSettings& settings, const RollingStudy& study, RollingResult& result)
      : tm_(tm), settings_(settings), result_(result), support_(make_support(study.support)) {
    const StaticContactResult& fp = result.footprint;
    DofMap dofs(tm.mesh.dof_count());
    dofs.fix(tm.fixed_dofs);
    std::vector<std::unique_ptr<Form>> forms;
    forms.push_back(std::make_unique<ShellInternalForce>(tm.mesh, tm.sections, Kinematics::nonlinear));
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
    forms.push_back(std::move(friction));
    problem_ = std::make_unique<NonlinearProblem>(std::move(dofs), std::move(forms));
    problem_->load_scale();  // inflation load, before the support is raised (as in the static run)
    NewtonSettings ns;
    ns.max_iterations = settings.max_newton_iterations;
    ns.residual_tolerance = settings.residual_tolerance;
    // An unsymmetric LU costs about twice a Cholesky: reuse it as GMRES preconditioner while that
    // converges fast (the tangent changes little between iterations and neighbouring states).
    ns.reuse_factorization = true;
    // GMRES gives up after 25 iterations (then a fresh LU); measured on the 15-point sweep before the
    // refresh after 8 (NewtonSettings): 12 → 28 LUs, 41 s; 25 → 4 LUs, 31 s; 40 → 65 s.
    ns.max_krylov_iterations = 25;
    newton_ = std::make_unique<NewtonSolver>(*problem_, ns);
    set_deflection(fp.final_state.deflection_mm);
    base_ = fp.final_state.displacement;
    result.tread_points = contact_->points();
  }

  struct Solved {
    bool converged = false;
    std::string failure;
    RollingFigures figures;
    RollingSolveCounts counts;
    Eigen::VectorXd u;
  };

  // Solves with the given law at Rk. Coulomb and full stick: from the nearest converged Coulomb state
  // (predicted), with halving continuation in 1/Rk from it when a solve fails. Full slip: from the static
  // footprint (μ = 0 of this law), continued in μ with a secant predictor; the whole friction force at
  // once is tried first.
  Solved solve(const FrictionLaw& law, double rolling_radius) {
    const auto t0 = Clock::now();
    const int factorizations0 = newton_->linear_stats().factorizations;
    const int newton0 = newton_->total_iterations();
    Solved s;
    const bool full_slip = law.mode == FrictionLaw::Mode::full_slip;
    const double target = 1.0 / rolling_radius;
    const Known* from = full_slip ? nullptr : nearest(target);
    double done = 0.0, step = 1.0;  // continuation parameter from the start state (0) to the target (1)
    Eigen::VectorXd u = from ? from->u : base_;
    Eigen::VectorXd previous_u = u;  // full slip: the converged stage before u, at previous_t
    double previous_t = 0.0;
    const double p0 = from ? from->inverse_radius : target;
    int cutbacks = 0;
    ContactSolveOutcome last;
    while (done < 1.0) {
      const double t = std::min(1.0, done + step);
      FrictionLaw stage = law;
      double p = target;
      if (full_slip) stage.friction = law.friction * t;
      else p = p0 + t * (target - p0);
      friction_->set_law(stage);
      friction_->set_rolling_radius(1.0 / p);
      Eigen::VectorXd trial = u;
      if (law.mode == FrictionLaw::Mode::coulomb) trial = predict(p, u);
      else if (full_slip && done > previous_t) trial += (t - done) / (done - previous_t) * (u - previous_u);
      last = solve_rolling_state(*newton_, *contact_, *friction_, trial, settings_);
      ++s.counts.solves;
      if (last.converged && friction_->contact_outside_window(trial) > 0) {
        last.converged = false;
        last.failure = "the contact patch grew beyond the friction window";
        cutbacks = 6;  // not a convergence problem: do not cut back
      }
      if (!last.converged) {
        if (++cutbacks > 5) {
          s.failure = last.failure;
          break;
        }
        step *= 0.5;
        continue;
      }
      previous_u = std::move(u);
      previous_t = done;
      u = std::move(trial);
      done = t;
      if (law.mode == FrictionLaw::Mode::coulomb) known_.push_back({p, u});
    }
    s.converged = done >= 1.0;
    s.counts.contact_iterations = last.contact_iterations;
    s.counts.newton_iterations = newton_->total_iterations() - newton0;
    s.counts.factorizations = newton_->linear_stats().factorizations - factorizations0;
    s.counts.time_s = seconds_since(t0);
    if (s.converged) {
      s.figures = figures(u);
      s.u = std::move(u);
    }
    return s;
  }

  // Holds Qz at `target` by moving the support (δz): secant steps from the static vertical stiffness,
  // each a rolling solve from the last state, until |Qz − target| ≤ tolerance · target. Leaves the model
  // at the new deflection.
  void hold_load(Solved& s, double target, double tolerance, double stiffness) {
    const auto t0 = Clock::now();
    const int factorizations0 = newton_->linear_stats().factorizations;
    const int newton0 = newton_->total_iterations();
    double d0 = deflection_, q0 = s.figures.Qz_N, slope = stiffness;
    for (int it = 0; it < 8 && s.converged && std::abs(q0 - target) > tolerance * target; ++it) {
      const double d1 = d0 + (target - q0) / slope;
      set_deflection(d1);
      Eigen::VectorXd u = s.u;
      const ContactSolveOutcome o = solve_rolling_state(*newton_, *contact_, *friction_, u, settings_);
      ++s.counts.solves;
      if (!o.converged) {
        s.converged = false;
        s.failure = "holding Qz: " + o.failure;
        break;
      }
      s.u = std::move(u);
      s.figures = figures(s.u);
      if (s.figures.Qz_N != q0) slope = (s.figures.Qz_N - q0) / (d1 - d0);
      d0 = d1, q0 = s.figures.Qz_N;
    }
    if (s.converged && std::abs(q0 - target) > tolerance * target) {
      s.converged = false;
      s.failure = fmt::format("Qz = {} N not held within 8 deflection steps (Qz {:.1f} N)", target, q0);
    }
    s.counts.newton_iterations += newton_->total_iterations() - newton0;
    s.counts.factorizations += newton_->linear_stats().factorizations - factorizations0;
    s.counts.time_s += seconds_since(t0);
  }
  void set_deflection(double deflection) {
    deflection_ = deflection;
    contact_->set_deflection(deflection);
    friction_->set_deflection(deflection);
  }
  double deflection() const { return deflection_; }

  RollingFigures figures(const Eigen::VectorXd& u) const {
    return rolling_figures(contact_->points(), contact_->evaluate(u), friction_->evaluate(u), tm_.axis_z,
                           tm_.half_model, result_.reverse, wheel_frame(*support_, deflection_, result_.reverse));
  }
  // Qy of a full-stick plan at the static state for Rk (no solve): affine in Rk, it estimates Re.
  double static_full_stick_Qy(double rolling_radius) {
    FrictionLaw law;
    law.mode = FrictionLaw::Mode::full_stick;
    friction_->set_law(law);
    friction_->set_rolling_radius(rolling_radius);
    return figures(base_).Qy_N;
  }
  void fill(RollingStateResult& state, const Solved& s) {
    state.converged = s.converged;
    state.failure = s.failure;
    state.figures = s.figures;
    state.counts = s.counts;
    if (!s.converged) return;
    state.displacement = s.u;
    state.normal = contact_->evaluate(s.u);
    state.tangential = friction_->evaluate(s.u);
  }
  void finish(SolveCounters& c) const { add_counters(c, *newton_, *problem_); }

 private:
  struct Known {
    double inverse_radius;
    Eigen::VectorXd u;
  };
  const Known* nearest(double p, const Known* other = nullptr) const {
    const Known* best = nullptr;
    for (const Known& k : known_)
      if (&k != other && (!other || std::abs(k.inverse_radius - other->inverse_radius) > 1e-15) &&
          (!best || std::abs(k.inverse_radius - p) < std::abs(best->inverse_radius - p)))
        best = &k;
    return best;
  }
  // Secant in 1/Rk (linear in κ) through the two nearest converged states, when the target is within
  // twice their spacing (extrapolating further from two close states, e.g. the free-rolling iterates,
  // amplifies their difference); else the start.
  Eigen::VectorXd predict(double p, const Eigen::VectorXd& start) const {
    const Known* a = nearest(p);
    const Known* b = a ? nearest(p, a) : nullptr;
    if (!a || !b) return start;
    const double t = (p - a->inverse_radius) / (b->inverse_radius - a->inverse_radius);
    if (std::abs(t) > 2.0) return start;
    return a->u + t * (b->u - a->u);
  }

  const TyreMesh& tm_;
  ContactSettings settings_;
  RollingResult& result_;
  std::unique_ptr<SupportSurface> support_;
  WinklerContactForm* contact_ = nullptr;
  TreadFrictionForm* friction_ = nullptr;
  std::unique_ptr<NonlinearProblem> problem_;
  std::unique_ptr<NewtonSolver> newton_;
  Eigen::VectorXd base_;  // the static footprint
  double deflection_ = 0.0;
  std::vector<Known> known_;
};

const char* kind_name(RollingStateSpec::Kind k) {
  switch (k) {
    case RollingStateSpec::Kind::free: return "free";
    case RollingStateSpec::Kind::given_slip: return "given_slip";
    case RollingStateSpec::Kind::given_radius: return "given_radius";
    case RollingStateSpec::Kind::full_stick: return "full_stick";
    case RollingStateSpec::Kind::full_slip: return "full_slip";
  }
  return "?";
}

// Free rolling: secant iteration on Rk for Qy = 0 (|Qy| ≤ 1e-4 Qz), started from the rigid-tread estimate
// of the static state. Returns the state; sets Re and the slip stiffness dQy/dκ (least squares over the
// iterates within |κ| ≤ 0.003, else the last secant) in the result.
RollingStateResult free_rolling(RollingModel& model, const RollingStudy& study, RollingResult& result,
                                const ProgressSink& progress) {
  RollingStateResult state;
  state.spec.kind = RollingStateSpec::Kind::free;
  state.name = "free";
  FrictionLaw law;
  law.friction = study.friction;
  const double a = result.loaded_radius_mm, b = result.axle_z;
  const double qa = model.static_full_stick_Qy(a), qb = model.static_full_stick_Qy(b);
  double rk = qa != qb ? a - qa * (b - a) / (qb - qa) : 0.5 * (a + b);
  std::vector<std::pair<double, double>> tried;  // (Rk, Qy)
  RollingModel::Solved s;
  RollingSolveCounts total;
  double slope = (qb - qa) / (b - a);
  for (int it = 0; it < 15; ++it) {
    s = model.solve(law, rk);
    total.newton_iterations += s.counts.newton_iterations;
    total.factorizations += s.counts.factorizations;
    total.solves += s.counts.solves;
    total.time_s += s.counts.time_s;
    total.contact_iterations = s.counts.contact_iterations;
    if (!s.converged) break;
    tried.emplace_back(rk, s.figures.Qy_N);
    if (progress)
      progress(fmt::format("  free rolling: Rk {:.4f} mm → Qy {:+.2f} N", rk, s.figures.Qy_N));
    if (std::abs(s.figures.Qy_N) <= 1e-4 * std::abs(s.figures.Qz_N)) break;
    if (tried.size() >= 2) {
      const auto& [r0, q0] = tried[tried.size() - 2];
      if (q0 != s.figures.Qy_N) slope = (s.figures.Qy_N - q0) / (rk - r0);
    }
    rk -= s.figures.Qy_N / slope;
  }
  s.counts = total;
  model.fill(state, s);
  if (!state.converged || std::abs(s.figures.Qy_N) > 1e-4 * std::abs(s.figures.Qz_N)) {
    state.converged = false;
    if (state.failure.empty()) state.failure = "the free-rolling radius was not found in 15 secant steps";
    return state;
  }
  const double re = rk;
  result.effective_rolling_radius_mm = re;
  state.rolling_radius_mm = re;
  state.slip = 0.0;
  // dQy/dκ = dQy/dRk · dRk/dκ, dRk/dκ = −Re at κ = 0.
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for (const auto& [r, q] : tried)
    if (std::abs(re / r - 1.0) <= 0.003) sx += r, sy += q, sxx += r * r, sxy += r * q, ++n;
  if (n >= 2 && n * sxx - sx * sx > 0) slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  result.slip_stiffness_N = -re * slope;
  return state;
}

}  // namespace

RollingResult run_rolling(const TyreMesh& tm, const TyreDescription& tyre, const InflationSettings& inflation,
                          const ContactSettings& contact, const RollingStudy& study, const ProgressSink& progress,
                          const InflationResult* inflated, const StaticContactResult* footprint) {
  RollingResult r;
  r.name = study.name;
  r.support = study.support;
  r.friction = study.friction;
  r.reverse = study.reverse;
  r.half_model = tm.half_model;
  if (progress)
    progress(fmt::format("rolling '{}': {}, μ = {}, travel {}, at the footprint of Qz = {} N", study.name,
                         support_label(study.support), study.friction, study.reverse ? "-y" : "+y",
                         study.target_load));
  if (footprint && footprint->completed) {
    r.footprint = *footprint;
    r.footprint.name = study.name;
    if (progress)
      progress(fmt::format("  the static footprint solved before: Qz {:.1f} N at δz {:.3f} mm",
                           r.footprint.points.back().patch.Qz_N, r.footprint.final_state.deflection_mm));
  } else {
    FootprintStudy fs;
    fs.name = study.name;
    fs.support = study.support;
    fs.target_load = study.target_load;
    fs.load_tolerance = study.load_tolerance;
    r.footprint = run_footprint(tm, tyre, inflation, contact, fs, progress, inflated);
  }
  if (!r.footprint.completed) {
    r.failure = "static footprint: " + r.footprint.failure;
    return r;
  }
  const auto t_rolling = Clock::now();
  r.deflection_mm = r.footprint.final_state.deflection_mm;
  r.axle_z = tm.axis_z;
  r.loaded_radius_mm = tm.axis_z - r.deflection_mm;
  RollingModel model(tm, tyre, inflation, contact, study, r);

  const RollingStateResult free = free_rolling(model, study, r, progress);
  if (!free.converged) {
    r.failure = "free rolling: " + free.failure;
    r.states.push_back(free);
    model.finish(r.counters);
    r.counters.wall_s = seconds_since(t_rolling);
    return r;
  }
  const double re = *r.effective_rolling_radius_mm;
  if (progress)
    progress(fmt::format("  free rolling: Re = {:.3f} mm (Rd = {:.3f} mm), slip stiffness {:.0f} N, {} Newton "
                         "iterations, {:.2f} s", re, r.loaded_radius_mm, r.slip_stiffness_N.value_or(0.0),
                         free.counts.newton_iterations, free.counts.time_s));
  bool ok = true;
  for (const RollingStateSpec& spec : study.states) {
    RollingStateResult state;
    state.spec = spec;
    state.name = spec.name.empty() ? kind_name(spec.kind) : spec.name;
    if (spec.kind == RollingStateSpec::Kind::free) {
      const std::string name = state.name;
      state = free;
      state.spec = spec;
      state.name = name;
      r.states.push_back(std::move(state));
      continue;
    }
    FrictionLaw law;
    law.friction = study.friction;
    double rk = re / (1.0 + spec.slip);
    switch (spec.kind) {
      case RollingStateSpec::Kind::given_radius: rk = spec.rolling_radius; break;
      case RollingStateSpec::Kind::full_stick: law.mode = FrictionLaw::Mode::full_stick; break;
      case RollingStateSpec::Kind::full_slip:
        // Spinning: the tread drags the tyre forward, against the support's motion (σ = −1); locked: σ = +1.
        law.mode = FrictionLaw::Mode::full_slip;
        law.slip_sign = spec.braking ? 1.0 : -1.0;
        rk = re;
        break;
      default: break;
    }
    const RollingModel::Solved s = model.solve(law, rk);
    model.fill(state, s);
    if (spec.kind == RollingStateSpec::Kind::full_slip) {
      if (spec.braking) state.slip = -1.0;
    } else {
      state.rolling_radius_mm = rk;
      state.slip = re / rk - 1.0;
    }
    if (progress) {
      if (s.converged)
        progress(fmt::format("  {}: Qy {:+.1f} N, Qz {:.1f} N, Mx {:+.0f} N·mm, stick {:.0f}% ({} Newton "
                             "iterations, {} factorisations, {:.2f} s)",
                             state.name, s.figures.Qy_N, s.figures.Qz_N, s.figures.Mx_Nmm,
                             100 * s.figures.stick_area_fraction, s.counts.newton_iterations,
                             s.counts.factorizations, s.counts.time_s));
      else
        progress(fmt::format("  {}: did not converge: {}", state.name, s.failure));
    }
    if (!s.converged) {
      ok = false;
      if (r.failure.empty()) r.failure = fmt::format("state '{}': {}", state.name, s.failure);
    }
    r.states.push_back(std::move(state));
  }
  if (study.sweep) {
    // From free rolling outwards on each side, each point continuing from its neighbour.
    const SlipSweep& sw = *study.sweep;
    std::vector<double> slips;
    for (int i = 0; i < sw.points; ++i) slips.push_back(sw.from + (sw.to - sw.from) * i / (sw.points - 1));
    std::vector<double> up, down;
    for (double k : slips) (k >= 0 ? up : down).push_back(k);
    std::reverse(down.begin(), down.end());
    FrictionLaw law;
    law.friction = study.friction;
    // Vertical stiffness dQz/dδz of the last two static load points: the first step when holding Qz.
    const auto& lp = r.footprint.points;
    const double stiffness = lp.size() >= 2 ? (lp.back().patch.Qz_N - lp[lp.size() - 2].patch.Qz_N) /
                                                  (lp.back().deflection_mm - lp[lp.size() - 2].deflection_mm)
                                            : r.footprint.points.back().patch.Qz_N / r.deflection_mm;
    for (const auto* side : {&up, &down}) {
      model.set_deflection(r.deflection_mm);  // each side starts from free rolling
      for (double k : *side) {
        const double rk = re / (1.0 + k);
        RollingModel::Solved s = model.solve(law, rk);
        if (sw.hold_load && s.converged)
          model.hold_load(s, study.target_load, study.load_tolerance, stiffness);
        if (!s.converged) {
          ok = false;
          if (r.failure.empty()) r.failure = fmt::format("slip sweep at κ = {:g}: {}", k, s.failure);
          if (progress) progress(fmt::format("  sweep κ {:+.4f}: did not converge: {}", k, s.failure));
          break;  // the rest of this side would start from further away
        }
        r.sweep.push_back({k, rk, model.deflection(), s.figures, s.counts});
        if (progress)
          progress(fmt::format("  sweep κ {:+.4f}: Qy {:+8.1f} N, Qz {:.1f} N, stick {:3.0f}% ({} Newton "
                               "iterations, {:.2f} s)", k, s.figures.Qy_N, s.figures.Qz_N,
                               100 * s.figures.stick_area_fraction, s.counts.newton_iterations, s.counts.time_s));
      }
    }
    std::sort(r.sweep.begin(), r.sweep.end(), [](const SweepPoint& a, const SweepPoint& b) { return a.slip < b.slip; });
  }
  r.completed = ok;
  model.finish(r.counters);
  r.counters.wall_s = seconds_since(t_rolling);
  return r;
}

}  // namespace tirefem
