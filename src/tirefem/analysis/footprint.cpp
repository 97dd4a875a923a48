#include "tirefem/analysis/footprint.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <numbers>
#include <tuple>

#include <fmt/format.h>

#include "tirefem/analysis/contact_iteration.hpp"
#include "tirefem/analysis/first_touch.hpp"
#include "tirefem/forms/linearized_form.hpp"
#include "tirefem/forms/pressure_form.hpp"
#include "tirefem/analysis/tyre_shell_forms.hpp"

namespace tirefem {

std::vector<TreadPoint> tyre_tread_points(const TyreMesh& tm, const TyreDescription& tyre, int quadrature) {
  const ShellMesh& m = tm.mesh;
  std::vector<int> elements;
  // Graded by zones, an element belongs to the tread by its centre (the tread edge is an element edge
  // unless that would make a sliver); graded uniformly, an element across the tread edge keeps the points
  // on its tread side.
  const bool by_inner_edge = tm.meridional_grading != MeshSettings::MeridionalGrading::zones;
  for (int e = 0; e < m.element_count(); ++e) {
    const int iu = e % m.u_elements(), jv = e / m.u_elements();
    const double phi = 0.5 * (m.v_values[jv] + m.v_values[jv + 1]);
    const double s = by_inner_edge ? std::min(std::abs(m.u_values[iu]), std::abs(m.u_values[iu + 1]))
                                   : std::abs(tm.element_s[e]);
    if (s < tyre.tread_end_s && std::abs(phi) <= 0.5 * std::numbers::pi)
      elements.push_back(e);
  }
  return make_tread_points(m, elements, quadrature, [&tyre](double s) {
    return std::abs(s) <= tyre.tread_end_s ? tread_height_at(tyre, s) : -1.0;
  });
}

namespace {

// Extent of the contact along lines of tread points (sorted by the other parameter), each end
// interpolated linearly in the penetration to g = 0 between the last point in contact and the next one.
// Returns the largest (max − min) of `coordinate` over the lines.
template <class LineKey, class Order>
std::pair<double, double> contact_extent(const std::vector<TreadPoint>& points,
                                         const std::vector<TreadPointState>& states, LineKey key, Order order,
                                         int coordinate) {
  std::map<double, std::vector<int>> lines;
  for (int q = 0; q < static_cast<int>(points.size()); ++q) lines[key(points[q])].push_back(q);
  double lo = 1e300, hi = -1e300;
  for (auto& [k, line] : lines) {
    std::sort(line.begin(), line.end(), [&](int a, int b) { return order(points[a]) < order(points[b]); });
    for (std::size_t i = 0; i < line.size(); ++i) {
      const TreadPointState& s = states[line[i]];
      if (s.penetration <= 0) continue;
      double c = s.position[coordinate];
      lo = std::min(lo, c), hi = std::max(hi, c);
      for (int dir : {-1, 1}) {  // edge towards a neighbour out of contact
        const long j = static_cast<long>(i) + dir;
        if (j < 0 || j >= static_cast<long>(line.size())) continue;
        const TreadPointState& n = states[line[j]];
        if (n.penetration > 0) continue;
        const double t = s.penetration / (s.penetration - n.penetration);
        const double edge = c + t * (n.position[coordinate] - c);
        lo = std::min(lo, edge), hi = std::max(hi, edge);
      }
    }
  }
  return {lo, hi};
}

}  // namespace

PatchFigures patch_figures(const std::vector<TreadPoint>& points, const std::vector<TreadPointState>& states,
                           bool half_model) {
  PatchFigures f;
  double pressure_integral = 0.0;
  for (std::size_t q = 0; q < points.size(); ++q) {
    if (states[q].pressure <= 0) continue;
    f.force_N += states[q].force;
    f.contact_area_mm2 += points[q].weight;
    pressure_integral += states[q].pressure * points[q].weight;
    f.max_pressure_MPa = std::max(f.max_pressure_MPa, states[q].pressure);
  }
  if (f.contact_area_mm2 == 0.0) return f;
  f.mean_pressure_MPa = pressure_integral / f.contact_area_mm2;
  // Lines of constant s give the length (along y), lines of constant φ the width (along x).
  const auto [y_lo, y_hi] = contact_extent(
      points, states, [](const TreadPoint& p) { return p.u; }, [](const TreadPoint& p) { return p.v; }, 1);
  const auto [x_lo, x_hi] = contact_extent(
      points, states, [](const TreadPoint& p) { return p.v; }, [](const TreadPoint& p) { return p.u; }, 0);
  f.patch_length_mm = y_hi - y_lo;
  f.patch_width_mm = half_model ? 2.0 * std::max(x_hi, 0.0) : x_hi - x_lo;
  if (half_model) {
    // Mirror image in x = 0: the lateral force cancels, the others double.
    f.force_N *= 2.0;
    f.force_N.x() = 0.0;
    f.contact_area_mm2 *= 2.0;
  }
  f.Qz_N = f.force_N.z();
  return f;
}

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Shell and inflation pressure linearised about the inflated state u0.
std::unique_ptr<Form> linearized_tyre(const TyreMesh& tm, double pressure, const Eigen::VectorXd& u0) {
  DofMap dofs(tm.mesh.dof_count());
  dofs.fix(tm.fixed_dofs);
  std::vector<std::unique_ptr<Form>> forms;
  add_tyre_shell_forms(forms, tm, Kinematics::nonlinear);
  forms.push_back(std::make_unique<PressureForm>(tm.mesh, tm.pressure_elements, pressure, Kinematics::nonlinear,
                                                 /*symmetrize=*/true));
  NonlinearProblem tyre(dofs, std::move(forms));
  tyre.evaluate(u0, 1.0, true);
  return std::make_unique<LinearizedForm>(dofs, tyre.system().tangent(), tyre.system().residual(), u0);
}

}  // namespace

InflationResult inflate_for_contact(const TyreMesh& tm, const InflationSettings& inflation,
                                    const ProgressSink& progress) {
  // The geometrically linear solution is linearised about the nonlinear inflated state (the tyre's
  // stiffness under load comes from its inflation: a linear theory about the unstressed state has no
  // pressure stiffening at all), so the inflation is nonlinear in both theories.
  InflationSettings inflate = inflation;
  inflate.linear = false;
  return run_inflation(tm, inflate, progress);
}

namespace {

// Inflated tyre + contact: the forms, the Newton solver and the deflection path over them.
class StaticContactRun {
 public:
  StaticContactRun(const TyreMesh& tm, const TyreDescription& tyre, const InflationSettings& inflation,
                   const ContactSettings& settings, const SupportDescription& support_description,
                   Kinematics kinematics, DeflectionOrigin origin, StaticContactResult& result,
                   const ProgressSink& progress, const InflationResult* inflated)
      : tm_(tm), settings_(settings), result_(result), progress_(progress),
        support_(make_support(support_description)) {
    result_.deflection_from = origin;
    result_.inflation = inflated ? *inflated : inflate_for_contact(tm, inflation, progress);
    if (!result_.inflation.converged) throw std::runtime_error("inflation did not converge");
    if (result_.inflation.kinematics != Kinematics::nonlinear || result_.inflation.pressure != inflation.pressure)
      throw std::invalid_argument("a contact study needs the nonlinear inflated state at its pressure");
    result_.tread_points = tyre_tread_points(tm, tyre, settings.quadrature);

    DofMap dofs(tm.mesh.dof_count());
    dofs.fix(tm.fixed_dofs);
    std::vector<std::unique_ptr<Form>> forms;
    if (kinematics == Kinematics::nonlinear) {
      add_tyre_shell_forms(forms, tm, kinematics);
      forms.push_back(std::make_unique<PressureForm>(tm.mesh, tm.pressure_elements, inflation.pressure,
                                                     kinematics, /*symmetrize=*/true));
    } else {
      forms.push_back(linearized_tyre(tm, inflation.pressure, result_.inflation.displacement));
    }
    auto contact = std::make_unique<WinklerContactForm>(tm.mesh, result_.tread_points,
                                                        tyre.tread_stiffness, *support_);
    contact_ = contact.get();
    forms.push_back(std::move(contact));
    problem_ = std::make_unique<NonlinearProblem>(std::move(dofs), std::move(forms));
    problem_->load_scale();  // the inflation load (no contact at δz = 0, u = 0) sets the residual scale
    NewtonSettings ns;
    ns.max_iterations = settings.max_newton_iterations;
    ns.residual_tolerance = settings.residual_tolerance;
    ns.reuse_factorization = settings.reuse_factorizations;
    ns.adaptive_krylov_tolerance = true;
    // The linearised tyre's tangent is the inflated state's (positive definite: its factorisations in
    // the inflation needed no shift, and the first one here would show a shift) plus the contact springs.
    ns.known_stable = kinematics == Kinematics::linear;
    ns.stable_equilibrium = settings.equilibrium == ContactSettings::Equilibrium::stable;
    newton_ = std::make_unique<NewtonSolver>(*problem_, ns);
    for (const TreadPointState& p : contact_->evaluate(result_.inflation.displacement))
      inflated_tread_.push_back(p.position);
    result_.first_touch_deflection_mm = first_touch_deflection(inflated_tread_, *support_);
    if (progress_)
      progress_(fmt::format("  the inflated tyre first touches the support at δz = {:.3f} mm (from the undeformed "
                            "tyre)",
                            result_.first_touch_deflection_mm));
    // δz is measured from the undeformed tyre (MODEL.md §2), so the inflated tyre, grown by about
    // 0.5 mm, already presses on the support at δz = 0: the first load point is solved like the others.
    // From the first touch, the first point is the inflated state itself, touching the support.
    start_ = origin == DeflectionOrigin::first_touch ? result_.first_touch_deflection_mm : 0.0;
    path_ = std::make_unique<DeflectionPath>(*newton_, *contact_, settings, result_.inflation.displacement, start_);
    if (!solve_at(start_))
      throw std::runtime_error(fmt::format(
          "the first contact state (δz = {:.3g}) did not converge: {}; check tyre.tread.stiffness (kp) and the "
          "contact settings (max_newton_iterations, residual_tolerance)",
          start_, result_.failure));
  }

  // δz (from the undeformed tyre) of the first load point: 0, or the first touch.
  double start() const { return start_; }
  // States of another study of this problem (a load curve's) for the predictor.
  void add_known_states(const std::vector<PathState>& states) {
    for (const PathState& p : states) path_->add_known_state(p.deflection_mm, p.displacement);
  }
  // The current converged state, to keep as a PathState.
  PathState current_state() const {
    return {path_->deflection(), result_.points.back().patch.Qz_N, path_->displacement()};
  }
  const std::vector<Eigen::Vector3d>& inflated_tread() const { return inflated_tread_; }
  const SupportSurface& support() const { return *support_; }

  // Solves at δz and records the load point; false (and result_.failure) when it does not converge.
  bool solve_at(double deflection) {
    const auto t0 = Clock::now();
    const int factorizations_before = newton_->linear_stats().factorizations;
    const DeflectionPath::Step step = path_->advance_to(deflection);
    if (!step.converged) {
      result_.failure = step.failure;
      return false;
    }
    record(deflection, step, seconds_since(t0), newton_->linear_stats().factorizations - factorizations_before);
    const LoadPoint& p = result_.points.back();
    const std::string where =
        result_.deflection_from == DeflectionOrigin::first_touch
            ? fmt::format("δ {:6.2f} mm from first touch (δz {:6.2f} mm)", deflection_from_origin(result_, deflection),
                          deflection)
            : fmt::format("δz {:6.2f} mm", deflection);
    if (progress_)
      progress_(fmt::format("  {}: Qz {:8.1f} N, patch {:5.1f} × {:5.1f} mm, pmax {:.3f} MPa "
                            "({} contact, {} Newton iterations{}, {:.2f} s){}{}",
                            where, p.patch.Qz_N, p.patch.patch_length_mm, p.patch.patch_width_mm,
                            p.patch.max_pressure_MPa, p.contact_iterations, p.newton_iterations,
                            step.cutbacks ? fmt::format(", {} cut-backs", step.cutbacks) : "", p.time_s,
                            stable(p.tangent_shift)
                                ? ""
                                : std::string(" UNSTABLE: its tangent is indefinite"),
                            p.escapes ? fmt::format(" PASSED AN INSTABILITY: left an unstable equilibrium "
                                                    "(tangent shift {:.0e}) for this stable state",
                                                    p.escaped_shift)
                                      : ""));
    return true;
  }

  void finish() {
    result_.final_state.deflection_mm = path_->deflection();
    result_.final_state.displacement = path_->displacement();
    contact_->set_deflection(path_->deflection());
    result_.final_state.tread = contact_->evaluate(path_->displacement());
    SolveCounters& c = result_.counters;
    c.load_steps = static_cast<int>(result_.points.size()) - 1;
    add_counters(c, *newton_, *problem_);
  }

  double last_Qz() const { return result_.points.back().patch.Qz_N; }

 private:
  void record(double deflection, const DeflectionPath::Step& step, double time, int factorizations) {
    LoadPoint p;
    p.deflection_mm = deflection;
    contact_->set_deflection(deflection);
    p.patch = patch_figures(result_.tread_points, contact_->evaluate(path_->displacement()), tm_.half_model);
    p.contact_iterations = step.last.contact_iterations;
    p.newton_iterations = step.newton_iterations;
    p.factorizations = factorizations;
    p.increments = step.increments;
    p.tangent_shift = step.last.tangent_shift;
    p.escapes = step.last.escapes;
    p.escaped_shift = step.last.escaped_shift;
    p.time_s = time;
    result_.points.push_back(p);
    result_.counters.cutbacks += step.cutbacks;
  }

  const TyreMesh& tm_;
  ContactSettings settings_;
  StaticContactResult& result_;
  ProgressSink progress_;
  std::unique_ptr<SupportSurface> support_;
  WinklerContactForm* contact_ = nullptr;
  std::unique_ptr<NonlinearProblem> problem_;
  std::unique_ptr<NewtonSolver> newton_;
  std::unique_ptr<DeflectionPath> path_;
  double start_ = 0.0;
  std::vector<Eigen::Vector3d> inflated_tread_;  // tread point positions in the inflated state
};

template <class Study>
StaticContactResult empty_result(const TyreMesh& tm, const ContactSettings& contact, const Study& study) {
  StaticContactResult result;
  result.name = study.name;
  result.support = study.support;
  result.kinematics = study.linear ? Kinematics::linear : Kinematics::nonlinear;
  result.iteration = contact.iteration;
  result.half_model = tm.half_model;
  result.deflection_from = study.deflection_from;
  return result;
}

const char* origin_label(DeflectionOrigin origin) {
  return origin == DeflectionOrigin::first_touch ? " from the inflated tyre's first touch" : "";
}

}  // namespace

StaticContactResult run_load_curve(const TyreMesh& tm, const TyreDescription& tyre,
                                   const InflationSettings& inflation, const ContactSettings& contact,
                                   const LoadCurveStudy& study, const ProgressSink& progress,
                                   const InflationResult* inflated, bool keep_path) {
  const auto t0 = Clock::now();
  StaticContactResult result = empty_result(tm, contact, study);
  if (progress)
    progress(fmt::format("load curve '{}': {}, {} theory, δz to {} mm{} in {} steps", study.name,
                         support_label(study.support), study.linear ? "linear" : "nonlinear",
                         study.max_deflection, origin_label(study.deflection_from), study.points));
  StaticContactRun run(tm, tyre, inflation, contact, study.support, result.kinematics, study.deflection_from, result,
                       progress, inflated);
  bool ok = true;
  if (keep_path) result.path.push_back(run.current_state());
  for (int k = 1; k <= study.points && ok; ++k) {
    ok = run.solve_at(run.start() + study.max_deflection * k / study.points);
    if (ok && keep_path) result.path.push_back(run.current_state());
  }
  run.finish();
  result.completed = ok;
  result.counters.wall_s = seconds_since(t0);
  return result;
}

std::pair<const PathState*, const PathState*> states_around_load(const std::vector<PathState>& path, double load) {
  const PathState* below = nullptr;
  const PathState* above = nullptr;
  for (const PathState& p : path) {
    if (p.Qz_N < load && (!below || p.deflection_mm > below->deflection_mm)) below = &p;
    if (p.Qz_N >= load && (!above || p.deflection_mm < above->deflection_mm)) above = &p;
  }
  if (!below || !above || above->deflection_mm <= below->deflection_mm) return {nullptr, nullptr};
  return {below, above};
}

namespace {

// The footprint at the study's given deflection: steps of at most max_step from the first point.
bool solve_at_given_deflection(StaticContactRun& run, double deflection, double max_step) {
  const double span = deflection - run.start();
  if (span == 0.0) return true;  // the first point is the footprint
  const int steps = std::max(1, static_cast<int>(std::ceil(std::abs(span) / max_step - 1e-9)));
  for (int k = 1; k <= steps; ++k)
    if (!run.solve_at(run.start() + span * k / steps)) return false;
  return true;
}

// Steps in δz towards the target load (at most max_step each while below it), then the Illinois variant
// of regula falsi inside the bracket. Every state tried is a converged load point. The first step goes to
// a membrane estimate of the deflection (first_touch.hpp), within [0.5, max_step] mm of the first point.
bool search_target_load(StaticContactRun& run, StaticContactResult& result, const FootprintStudy& study,
                        double pressure, double section_height, double max_step, const ProgressSink& progress,
                        const StaticContactResult* along, const std::vector<PathState>* nearby) {
  const double target = study.target_load, tolerance = study.load_tolerance * study.target_load;
  const double q0 = run.last_Qz();
  if (std::abs(q0 - target) <= tolerance) return true;
  double lo = run.start(), q_lo = q0;  // below the target
  double hi = 0.0, q_hi = 0.0;         // above it, once bracketed
  bool bracketed = false;
  int lo_side_repeats = 0, hi_side_repeats = 0;
  double next = 0.0;
  // The states of a load curve of the same problem: the bracket of the target from their Qz, the
  // prediction from them; the first point solved is then next to the target.
  const PathState* below = nullptr;
  const PathState* above = nullptr;
  if (along && q0 < target) {
    run.add_known_states(along->path);
    std::tie(below, above) = states_around_load(along->path, target);
  }
  if (below && above) {
    lo = below->deflection_mm, q_lo = below->Qz_N, hi = above->deflection_mm, q_hi = above->Qz_N, bracketed = true;
    next = lo + (target - q_lo) * (hi - lo) / (q_hi - q_lo);
    if (progress)
      progress(fmt::format("  from load curve '{}': Qz {:.1f} N at δz {:.2f} mm, {:.1f} N at {:.2f} mm; first "
                           "step to δz = {:.2f} mm",
                           along->name, q_lo, lo, q_hi, hi, next));
  } else if (nearby && nearby->size() >= 2 && q0 < target) {
    // States of another mesh carried onto this one (their Qz that mesh's): the prediction from them, and
    // the first step to where their Qz meets the target; the bracket from this mesh's own solves.
    run.add_known_states(*nearby);
    const PathState& a = nearby->front();
    const PathState& b = nearby->back();
    next = b.Qz_N != a.Qz_N ? a.deflection_mm + (target - a.Qz_N) * (b.deflection_mm - a.deflection_mm) / (b.Qz_N - a.Qz_N)
                            : b.deflection_mm;
    next = std::max(next, run.start() + 0.5);
    if (progress)
      progress(fmt::format("  from another mesh's load curve: Qz {:.1f} N at δz {:.2f} mm, {:.1f} N at {:.2f} mm "
                           "there; first step to δz = {:.2f} mm",
                           a.Qz_N, a.deflection_mm, b.Qz_N, b.deflection_mm, next));
  } else if (q0 > target) {
    // Passed already at δz = 0 (from the undeformed tyre): between the first touch (Qz = 0) and here.
    lo = result.first_touch_deflection_mm, q_lo = 0.0, hi = run.start(), q_hi = q0, bracketed = true;
    next = lo + (target - q_lo) * (hi - lo) / (q_hi - q_lo);
  } else {
    const double estimate =
        estimated_deflection_for_load(result.tread_points, run.inflated_tread(), run.support(), pressure,
                                      result.half_model, target, run.start(), section_height);
    next = run.start() + std::clamp(estimate - run.start(), 0.5, max_step);
    if (progress)
      progress(fmt::format("  membrane estimate of δz at {} N: {:.2f} mm; first step to δz = {:.2f} mm", target,
                           estimate, next));
  }
  for (int evaluation = 0; evaluation < 40; ++evaluation) {
    if (next > section_height) {
      if (result.points.back().deflection_mm >= section_height) {
        result.failure = fmt::format(
            "Qz = {} N not reached: Qz is {:.0f} N at δz = {:.1f} mm, the section height (crown to bead); "
            "lower target_load",
            target, result.points.back().patch.Qz_N, section_height);
        return false;
      }
      next = section_height;
    }
    if (!run.solve_at(next)) return false;
    const double q = run.last_Qz();
    if (std::abs(q - target) <= tolerance) return true;
    if (q < target) {
      lo = next, q_lo = q, ++lo_side_repeats, hi_side_repeats = 0;
    } else {
      hi = next, q_hi = q, bracketed = true, ++hi_side_repeats, lo_side_repeats = 0;
    }
    if (!bracketed) {
      // Not bracketed yet. Qz grows faster than δz at first (the patch grows), so a secant through the last
      // two points below the target overshoots, and a solve coming back down from above may find another
      // equilibrium: through them, a power law Qz = k (δz − δ0)^n from the first touch δ0 instead (n in
      // [1, 3]), else the secant.
      const auto& pts = result.points;
      const LoadPoint& a = pts[pts.size() - 2];
      const double touch = result.first_touch_deflection_mm, q_a = a.patch.Qz_N;
      double guess = next + max_step;
      if (q_a > 0 && q > q_a && a.deflection_mm > touch && next > a.deflection_mm) {
        const double n = std::clamp(std::log(q / q_a) / std::log((next - touch) / (a.deflection_mm - touch)), 1.0, 3.0);
        guess = touch + (next - touch) * std::pow(target / q, 1.0 / n);
      } else if (q > q_a) {
        guess = next + (target - q) * (next - a.deflection_mm) / (q - q_a);
      }
      next = std::min(std::max(guess, next + 0.5), next + max_step);
    } else {
      // Illinois: halve the stale end's residual when the same end moves twice in a row.
      const double f_lo = (q_lo - target) * (hi_side_repeats >= 2 ? 0.5 : 1.0);
      const double f_hi = (q_hi - target) * (lo_side_repeats >= 2 ? 0.5 : 1.0);
      next = lo - f_lo * (hi - lo) / (f_hi - f_lo);
    }
  }
  result.failure = fmt::format("Qz = {} N not reached within 40 load points", target);
  return false;
}

}  // namespace

StaticContactResult run_footprint(const TyreMesh& tm, const TyreDescription& tyre,
                                  const InflationSettings& inflation, const ContactSettings& contact,
                                  const FootprintStudy& study, const ProgressSink& progress,
                                  const InflationResult* inflated, const StaticContactResult* along,
                                  const std::vector<PathState>* nearby) {
  const auto t0 = Clock::now();
  StaticContactResult result = empty_result(tm, contact, study);
  if (study.deflection)
    result.given_deflection_mm = *study.deflection;
  else
    result.target_Qz_N = study.target_load;
  if (progress)
    progress(fmt::format("footprint '{}': {}, {} theory, {}", study.name, support_label(study.support),
                         study.linear ? "linear" : "nonlinear",
                         study.deflection ? fmt::format("δz = {} mm{}", *study.deflection,
                                                        origin_label(study.deflection_from))
                                          : fmt::format("Qz = {} N", study.target_load)));
  StaticContactRun run(tm, tyre, inflation, contact, study.support, result.kinematics, study.deflection_from, result,
                       progress, inflated);
  // Deflection steps of at most 5 mm on the way to the target load or deflection. From 7 mm up, the first
  // Newton iterate presses the tread that far into the support, the crown buckles inwards in it (indefinite
  // tangents needing shifts up to 10, LU steps) and the step costs 8–14 iterations. Measured on the 80 × 46
  // half model to 3700 N (the rolling benchmark's footprint, one run each): 10 mm 36 Newton iterations, 28
  // factorisations, 14.5 s; 7 mm 35, 26, 12.2 s; 6 mm 39, 16, 10.4 s; 5 mm 44, 17, 10.5 s; 4 mm 45, 16,
  // 12.4 s. In the whole example (one run each) the rolling studies' footprints 14.0 → 10.7 s (plane)
  // and 15.6 → 12.8 s (drum), 28 → 17 and 31 → 16 factorisations.
  constexpr double kMaxStep = 5.0;
  // A physical bound on the search: the section height (tread surface at the crown to the bead). Beyond
  // it the rim would be on the road.
  const double section_height = tm.axis_z - tm.profile.point(tm.profile.s_end())[1];
  bool ok = false;
  if (study.deflection) {
    // From the undeformed tyre the first point is at 0, from the first touch at the first touch.
    ok = solve_at_given_deflection(run, run.start() + *study.deflection, kMaxStep);
  } else {
    ok = search_target_load(run, result, study, inflation.pressure, section_height, kMaxStep, progress, along, nearby);
  }
  run.finish();
  result.completed = ok;
  result.counters.wall_s = seconds_since(t0);
  if (!ok && nearby) {
    // Another mesh's states may be too far from this mesh's solution to start Newton (a much coarser or
    // finer mesh round the patch): the search from the unloaded tyre, its work counted with this attempt's.
    if (progress)
      progress(fmt::format("  from another mesh's load curve: {}; searching again from the unloaded tyre",
                           result.failure));
    StaticContactResult again = run_footprint(tm, tyre, inflation, contact, study, progress, inflated, along);
    add_counters(again.counters, result.counters);
    return again;
  }
  return result;
}

}  // namespace tirefem
