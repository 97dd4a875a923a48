#include "tirefem/analysis/rolling.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>
#include <stdexcept>

#include <fmt/format.h>

#include "tirefem/analysis/rolling_model.hpp"

namespace tirefem {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

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

constexpr double kDegree = 3.14159265358979323846 / 180.0;

std::string angles_label(double alpha_deg, double gamma_deg) {
  std::string s;
  if (alpha_deg != 0.0) s += fmt::format(", α {:+g}°", alpha_deg);
  if (gamma_deg != 0.0) s += fmt::format(", γ {:+g}°", gamma_deg);
  return s;
}

// Vertical stiffness dQz/dδz of the last two static load points: the first step when holding Qz.
double static_vertical_stiffness(const RollingResult& r) {
  const auto& lp = r.footprint.points;
  return lp.size() >= 2 ? (lp.back().patch.Qz_N - lp[lp.size() - 2].patch.Qz_N) /
                              (lp.back().deflection_mm - lp[lp.size() - 2].deflection_mm)
                        : lp.back().patch.Qz_N / r.deflection_mm;
}

// Holds Qz of the converged state `s` at the study's target load (RollingModel::hold_load). Free rolling
// (`free`) then finds Rk again at the held δz (Fx = 0 there moves Qz a little in turn), at most three
// rounds; `slip.rolling_radius` ends as the last Rk.
void hold_state_load(RollingModel& model, const RollingStudy& study, const RollingResult& r, const FrictionLaw& law,
                     WheelSlip& slip, bool free, RollingModel::Solved& s, const ProgressSink& progress) {
  const double stiffness = static_vertical_stiffness(r), target = study.target_load;
  const auto held = [&] { return std::abs(s.figures.Qz_N - target) <= study.load_tolerance * target; };
  for (int round = 0; round < 3 && s.converged; ++round) {
    model.hold_load(s, target, study.load_tolerance, stiffness);  // its work added to s.counts
    if (!s.converged || !free) break;
    std::vector<std::pair<double, double>> tried;
    RollingSolveCounts total = s.counts;
    s = secant_free_rolling(model, law, slip, -r.slip_stiffness_N.value_or(1e5) / *r.effective_rolling_radius_mm,
                            tried, total, progress);
    s.counts = total;
    if (!tried.empty()) slip.rolling_radius = tried.back().first;
    if (held()) break;
  }
  if (s.converged && !held()) {
    s.converged = false;
    s.failure = fmt::format("Qz = {} N not held with free rolling in three rounds (Qz {:.1f} N)", target,
                            s.figures.Qz_N);
  }
}

// Solves the points of a sweep in the given order (each continuing from the nearest converged state),
// from the footprint's deflection at the start of each branch; a branch stops at its first failure (the
// rest would start from further away).
struct SweepTarget {
  double slip = 0.0, alpha_deg = 0.0, gamma_deg = 0.0;
  bool new_branch = false;
};
bool run_sweep(RollingModel& model, const RollingStudy& study, RollingResult& r, const std::vector<SweepTarget>& targets,
               bool hold, std::vector<SweepPoint>& out, const std::string& what, const ProgressSink& progress,
               const std::function<void()>& point_done) {
  FrictionLaw law;
  law.friction = study.friction;
  const double re = *r.effective_rolling_radius_mm, stiffness = static_vertical_stiffness(r);
  bool ok = true, skip = false;
  for (const SweepTarget& t : targets) {
    if (t.new_branch) model.set_deflection(r.deflection_mm), skip = false;
    if (skip) {
      if (point_done) point_done();
      continue;
    }
    const double rk = re / (1.0 + t.slip);
    // Within a branch each point continues from its neighbour (the nearest state in (κ, tan α, γ) may
    // lie on another branch, e.g. the α sweep's point for a combined-slip one, and measured, diverge).
    RollingModel::Solved s = model.solve(law, {rk, t.alpha_deg * kDegree, t.gamma_deg * kDegree}, !t.new_branch);
    if (hold && s.converged) model.hold_load(s, study.target_load, study.load_tolerance, stiffness);
    const std::string label = fmt::format("{} κ {:+.4f}{}", what, t.slip, angles_label(t.alpha_deg, t.gamma_deg));
    if (!s.converged) {
      ok = false, skip = true;
      if (r.failure.empty()) r.failure = fmt::format("{}: {}", label, s.failure);
      if (progress) progress(fmt::format("  {}: did not converge: {}", label, s.failure));
      if (point_done) point_done();
      continue;
    }
    out.push_back({t.slip, t.alpha_deg, t.gamma_deg, rk, model.deflection(), s.figures, s.counts});
    if (progress)
      progress(fmt::format("  {}: Fx {:+8.1f} N, Fy {:+8.1f} N, Mz {:+9.0f} N·mm, Qz {:.1f} N, stick {:3.0f}% ({} "
                           "Newton iterations, {:.2f} s)",
                           label, s.figures.Fx_N, s.figures.Fy_N, s.figures.aligning_moment_Nmm, s.figures.Qz_N,
                           100 * s.figures.stick_area_fraction, s.counts.newton_iterations, s.counts.time_s));
    if (point_done) point_done();
  }
  return ok;
}

// From 0 outwards on each side (`values` in any order), each side a branch.
template <class Make>
std::vector<SweepTarget> outward(std::vector<double> values, Make make) {
  std::vector<double> up, down;
  for (double v : values) (v >= 0 ? up : down).push_back(v);
  std::sort(up.begin(), up.end());
  std::sort(down.rbegin(), down.rend());
  std::vector<SweepTarget> targets;
  for (const auto* side : {&up, &down})
    for (std::size_t i = 0; i < side->size(); ++i) {
      SweepTarget t = make((*side)[i]);
      t.new_branch = i == 0;
      targets.push_back(t);
    }
  return targets;
}

// The sweep points at the angles `mirrored` (each < 0) as the mirror images of the solved points at −α
// (SlipAngleSweep::mirror_negative_angles); none where that point failed (the sweep reports the failure).
void add_mirrored_points(const std::vector<double>& mirrored, std::vector<SweepPoint>& points,
                         const ProgressSink& progress, const std::function<void()>& point_done) {
  for (double a : mirrored) {
    const auto it = std::find_if(points.begin(), points.end(), [a](const SweepPoint& p) {
      return !p.mirrored && std::abs(p.slip_angle_deg + a) <= 1e-12 * std::abs(a);
    });
    if (it != points.end()) {
      SweepPoint m = *it;
      m.slip_angle_deg = a;
      m.figures = mirrored_figures(it->figures);
      m.counts = {};
      m.mirrored = true;
      if (progress)
        progress(fmt::format("  α sweep κ {:+.4f}, α {:g}°: the mirror image of α {:g}° (Fy {:+8.1f} N, Mz {:+9.0f} N·mm)",
                             m.slip, a, -a, m.figures.Fy_N, m.figures.aligning_moment_Nmm));
      points.push_back(std::move(m));
    }
    if (point_done) point_done();
  }
}

// The standing tyre's stiffness at the footprint, on a plane (a flat-plate test; analysis/standing_stiffness.hpp).
void measure_standing_stiffness(const TyreMesh& tm, const TyreDescription& tyre, const InflationSettings& inflation,
                                const RollingStudy& study, RollingResult& r, const ProgressSink& progress) {
  if (r.support.kind != SupportDescription::Kind::plane || !study.standing_stiffness) return;
  const RoadPlane plane;
  try {
    r.standing_stiffness = standing_stiffness(tm, tyre, inflation.pressure, plane, r.deflection_mm,
                                              r.footprint.tread_points, r.footprint.final_state.displacement);
  } catch (const std::exception& e) {  // a side measurement: the rolling states go on without it
    if (progress) progress(fmt::format("  standing stiffness not measured: {}", e.what()));
    return;
  }
  if (!progress || !r.standing_stiffness) return;
  const StandingStiffness& c = *r.standing_stiffness;
  progress(fmt::format("  standing tyre, tread glued to the plane: longitudinal stiffness {:.1f} N/mm{}{} ({:.2f} s)",
                       c.longitudinal_N_per_mm,
                       c.lateral_N_per_mm ? fmt::format(", lateral {:.1f} N/mm", *c.lateral_N_per_mm) : "",
                       c.yaw_Nmm_per_rad ? fmt::format(", yaw {:.1f} N·m/deg", Nm_per_deg(*c.yaw_Nmm_per_rad)) : "",
                       c.time_s));
  if (!c.stable)
    progress("  warning: the footprint's tangent is indefinite (an unstable state): its standing stiffness describes "
             "no state the tyre would stay in");
}

// σκ = Kxκ/Cx and σα = Kyα/Cy, where the study has both.
void relaxation_lengths(RollingResult& r, const ProgressSink& progress) {
  if (!r.standing_stiffness) return;
  const StandingStiffness& c = *r.standing_stiffness;
  r.longitudinal_relaxation_length_mm = relaxation_length_mm(r.slip_stiffness_N, c.longitudinal_N_per_mm);
  r.lateral_relaxation_length_mm = relaxation_length_mm(per_radian(r.cornering_stiffness_N_per_deg), c.lateral_N_per_mm);
  if (progress && r.longitudinal_relaxation_length_mm)
    progress(fmt::format("  relaxation lengths: longitudinal {:.0f} mm (slip stiffness / Cx){}",
                         *r.longitudinal_relaxation_length_mm,
                         r.lateral_relaxation_length_mm
                             ? fmt::format(", lateral {:.0f} mm (cornering stiffness / Cy)", *r.lateral_relaxation_length_mm)
                             : ""));
}

// dFy/dα and the pneumatic trail at α = 0 (κ and γ of the sweep): central differences over ±kProbeAngle,
// two extra solves near the straight-ahead state, where the patch still sticks almost everywhere (the
// sweep's own points lie in the nonlinear range). Not sweep points: not reported as such.
constexpr double kProbeAngle = 0.2;  // degrees
// `mirror`: the tyre is its own mirror image (SlipAngleSweep::mirror_negative_angles), so the probe at
// −kProbeAngle is the mirror image of the one at +kProbeAngle, not solved.
void cornering_stiffness(RollingModel& model, const RollingStudy& study, RollingResult& r, bool mirror,
                         const ProgressSink& progress) {
  const SlipAngleSweep& sw = *study.angle_sweep;
  FrictionLaw law;
  law.friction = study.friction;
  const double rk = *r.effective_rolling_radius_mm / (1.0 + sw.slip);
  model.set_deflection(r.deflection_mm);
  RollingModel::Solved plus = model.solve(law, {rk, kProbeAngle * kDegree, sw.camber_deg * kDegree});
  if (!plus.converged) return;
  RollingModel::Solved minus;
  if (mirror) {
    minus.converged = true;
    minus.figures = mirrored_figures(plus.figures);
  } else {
    minus = model.solve(law, {rk, -kProbeAngle * kDegree, sw.camber_deg * kDegree});
    if (!minus.converged) return;
  }
  r.cornering_stiffness_N_per_deg = (plus.figures.Fy_N - minus.figures.Fy_N) / (2.0 * kProbeAngle);
  const double dfy = plus.figures.Fy_N - minus.figures.Fy_N;
  if (dfy != 0.0)
    r.pneumatic_trail_at_zero_mm = -(plus.figures.aligning_moment_Nmm - minus.figures.aligning_moment_Nmm) / dfy;
  if (r.footprint.points.empty()) return;
  const PatchFigures& patch = r.footprint.points.back().patch;
  if (patch.Qz_N > 0) r.cornering_stiffness_over_Fz_per_deg = -*r.cornering_stiffness_N_per_deg / patch.Qz_N;
  if (r.pneumatic_trail_at_zero_mm && patch.patch_length_mm > 0)
    r.pneumatic_trail_over_patch_length = *r.pneumatic_trail_at_zero_mm / patch.patch_length_mm;
  if (progress && r.cornering_stiffness_over_Fz_per_deg && r.pneumatic_trail_over_patch_length)
    progress(fmt::format("  cornering stiffness at α = 0: {:.0f} N/deg = {:.3f} Fz per degree (radial passenger "
                         "tyres: about 0.11–0.19); pneumatic trail {:.1f} mm = {:.2f} of the patch length {:.0f} "
                         "mm (typically about 1/6)",
                         -*r.cornering_stiffness_N_per_deg, *r.cornering_stiffness_over_Fz_per_deg,
                         *r.pneumatic_trail_at_zero_mm, *r.pneumatic_trail_over_patch_length,
                         patch.patch_length_mm));
}

}  // namespace

std::vector<double> mirrored_angles(const std::vector<double>& angles) {
  std::vector<double> mirrored;
  std::copy_if(angles.begin(), angles.end(), std::back_inserter(mirrored), [&](double a) {
    return a < 0 && std::any_of(angles.begin(), angles.end(), [a](double b) { return std::abs(a + b) <= 1e-12 * std::abs(a); });
  });
  return mirrored;
}

std::vector<double> sweep_values(double from, double to, int points, SweepSpacing spacing) {
  std::vector<double> v;
  for (int i = 0; i < points; ++i) {
    const double t = points > 1 ? from + (to - from) * i / (points - 1) : from;
    if (spacing == SweepSpacing::even || from * to > 0) v.push_back(t);
    else v.push_back(t < 0 ? from * (t / from) * (t / from) : (to != 0 ? to * (t / to) * (t / to) : 0.0));
  }
  return v;
}

RollingResult run_rolling(const TyreMesh& tm, const TyreDescription& tyre, const InflationSettings& inflation,
                          const ContactSettings& contact, const RollingStudy& study, const ProgressSink& progress,
                          const InflationResult* inflated, const StaticContactResult* footprint,
                          const std::function<void()>& point_done, const std::vector<PathState>* nearby,
                          const RollingStart* start) {
  RollingResult r = rolling_result_of(study, tm);
  if (progress)
    progress(fmt::format("rolling '{}': {}, μ = {}, travel {}, at the footprint of Qz = {} N", study.name,
                         support_label(study.support), study.friction, study.reverse ? "-y" : "+y",
                         study.target_load));
  if (start && (start->friction != study.friction || start->reverse != study.reverse))
    throw std::invalid_argument("run_rolling: a rolling start solved with another friction or travel");
  // (A start whose footprint failed: the study fails with it, rather than solving it again.)
  r.footprint = start && !start->footprint.completed
                    ? start->footprint
                    : rolling_footprint(tm, tyre, inflation, contact, study, progress, inflated,
                                        start ? &start->footprint : footprint, start ? nullptr : nearby);
  if (!r.footprint.completed) {
    r.failure = "static footprint: " + r.footprint.failure;
    return r;
  }
  const auto t_rolling = Clock::now();
  place_axle_at_footprint(r, tm);
  measure_standing_stiffness(tm, tyre, inflation, study, r, progress);
  RollingModel model(tm, tyre, inflation, contact, study, r);
  model.set_progress(progress);

  RollingStateResult free;
  if (start) {
    free = start->free;
    r.effective_rolling_radius_mm = start->effective_rolling_radius_mm;
    r.slip_stiffness_N = start->slip_stiffness_N;
    model.adopt(start->states);
  } else {
    free = free_rolling(model, study, r, progress);
  }
  if (point_done) point_done();
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
    const bool cornering = spec.slip_angle_deg != 0.0 || spec.camber_deg != 0.0;
    if (spec.kind == RollingStateSpec::Kind::free && !cornering) {  // solved (and counted) above
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
    WheelSlip slip{rk, spec.slip_angle_deg * kDegree, spec.camber_deg * kDegree};
    RollingModel::Solved s;
    if (spec.kind == RollingStateSpec::Kind::free) {
      // Free rolling at a slip angle or camber: Fx = 0 there, from Re with the straight-ahead slope.
      std::vector<std::pair<double, double>> tried;
      RollingSolveCounts total;
      s = secant_free_rolling(model, law, slip, -r.slip_stiffness_N.value_or(1e5) / re, tried, total, progress);
      s.counts = total;
      if (!tried.empty()) rk = tried.back().first;
    } else {
      // Combined slip: the longitudinal slip first, straight ahead, then the angles (measured on 40 × 12:
      // κ = 0.02 from the state at α = 2° diverged at every cut-back; from κ = 0.02 at α = 0 it converges).
      if (spec.slip != 0.0 && cornering && law.mode == FrictionLaw::Mode::coulomb) {
        const RollingModel::Solved straight = model.solve(law, {rk, 0.0, 0.0});
        s.counts = straight.counts;
      }
      const RollingSolveCounts first = s.counts;
      s = model.solve(law, slip, first.solves > 0);
      s.counts.newton_iterations += first.newton_iterations;
      s.counts.factorizations += first.factorizations;
      s.counts.solves += first.solves;
      s.counts.time_s += first.time_s;
    }
    if (spec.hold_load && s.converged) {
      slip.rolling_radius = rk;
      hold_state_load(model, study, r, law, slip, spec.kind == RollingStateSpec::Kind::free, s, progress);
      if (s.converged) state.deflection_mm = model.deflection();
      rk = slip.rolling_radius;
    }
    model.fill(state, s);  // (its tread points' states at the state's own δz)
    if (spec.hold_load) model.set_deflection(r.deflection_mm);  // the next state at the footprint's δz again
    if (spec.kind == RollingStateSpec::Kind::full_slip) {
      if (spec.braking) state.slip = -1.0;
    } else {
      state.rolling_radius_mm = rk;
      state.slip = re / rk - 1.0;
    }
    if (progress) {
      if (s.converged)
        progress(fmt::format("  {}: Qy {:+.1f} N, Qz {:.1f} N, Mx {:+.0f} N·mm{}, stick {:.0f}% ({} Newton "
                             "iterations, {} factorisations, {:.2f} s)",
                             state.name, s.figures.Qy_N, s.figures.Qz_N, s.figures.Mx_Nmm,
                             cornering ? fmt::format(", Fy {:+.1f} N, Mz {:+.0f} N·mm", s.figures.Fy_N,
                                                     s.figures.aligning_moment_Nmm)
                                       : "",
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
    if (point_done) point_done();
  }
  if (study.sweep) {
    const SlipSweep& sw = *study.sweep;
    const std::vector<double> slips = sweep_values(sw.from, sw.to, sw.points, sw.spacing);
    const auto targets = outward(slips, [](double k) { return SweepTarget{k, 0.0, 0.0}; });
    ok = run_sweep(model, study, r, targets, sw.hold_load, r.sweep, "sweep", progress, point_done) && ok;
    std::sort(r.sweep.begin(), r.sweep.end(), [](const SweepPoint& a, const SweepPoint& b) { return a.slip < b.slip; });
  }
  if (study.angle_sweep) {
    const SlipAngleSweep& sw = *study.angle_sweep;
    std::vector<double> angles = sweep_values(sw.from, sw.to, sw.points, sw.spacing), mirrored;
    // A tyre that is its own mirror image, at camber 0: the state at −α is the mirror image of the one at
    // +α, so only α ≥ 0 is solved (measured on the rig's 80 × 46 full model at 3700 N: Fy(−α) = −Fy(α)
    // to the printed digits when both were solved).
    const bool mirror = sw.mirror_negative_angles && sw.camber_deg == 0.0 && mirror_symmetric(tm);
    if (mirror) {
      mirrored = mirrored_angles(angles);
      std::erase_if(angles, [&](double a) { return std::find(mirrored.begin(), mirrored.end(), a) != mirrored.end(); });
      std::sort(mirrored.rbegin(), mirrored.rend());  // from α = 0 outwards, as solved
    }
    const auto targets = outward(angles, [&](double a) { return SweepTarget{sw.slip, a, sw.camber_deg}; });
    ok = run_sweep(model, study, r, targets, sw.hold_load, r.angle_sweep, "α sweep", progress, point_done) && ok;
    add_mirrored_points(mirrored, r.angle_sweep, progress, point_done);
    std::sort(r.angle_sweep.begin(), r.angle_sweep.end(),
              [](const SweepPoint& a, const SweepPoint& b) { return a.slip_angle_deg < b.slip_angle_deg; });
    cornering_stiffness(model, study, r, mirror, progress);
  }
  if (study.combined) {
    // Each slip κ a branch outwards in α from the point nearest α = 0.
    std::vector<SweepTarget> targets;
    for (double k : study.combined->slips) {
      const auto line = outward(study.combined->slip_angles_deg, [k](double a) { return SweepTarget{k, a, 0.0}; });
      targets.insert(targets.end(), line.begin(), line.end());
    }
    ok = run_sweep(model, study, r, targets, study.combined->hold_load, r.combined, "combined", progress, point_done) && ok;
    std::sort(r.combined.begin(), r.combined.end(), [](const SweepPoint& a, const SweepPoint& b) {
      return a.slip != b.slip ? a.slip < b.slip : a.slip_angle_deg < b.slip_angle_deg;
    });
  }
  relaxation_lengths(r, progress);
  r.completed = ok;
  model.finish(r.counters);
  r.counters.wall_s = seconds_since(t_rolling);
  return r;
}

}  // namespace tirefem
