#include "tirefem/analysis/tyre_test.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "tirefem/tyre/tyre_mesh.hpp"

namespace tirefem {
namespace {
constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;

TyreTestRow row(TyreTestRow::Kind kind, double target, const RollingFigures& f, double kappa, double alpha_deg,
                double gamma_deg, double loaded_radius_mm, double re_mm, const RollingSolveCounts& counts) {
  TyreTestRow r;
  r.kind = kind;
  r.target_load_N = target;
  r.Fz_N = f.Fz_N;
  r.kappa = kappa;
  r.alpha_rad = alpha_deg * kRadiansPerDegree;
  r.gamma_rad = gamma_deg * kRadiansPerDegree;
  r.Fx_N = f.Fx_N;
  r.Fy_N = f.Fy_N;
  r.Mz_Nm = f.aligning_moment_Nmm * 1e-3;
  r.Mx_Nm = f.overturning_moment_Nmm * 1e-3;
  r.loaded_radius_m = loaded_radius_mm * 1e-3;
  r.effective_radius_m = re_mm * 1e-3;
  r.newton_iterations = counts.newton_iterations;
  r.factorizations = counts.factorizations;
  r.time_s = counts.time_s;
  return r;
}
}  // namespace

int tyre_test_points(const TyreTestStudy& s) {
  const int combined = s.combined ? static_cast<int>(s.combined->slips.size() * s.combined->slip_angles_deg.size()) : 0;
  const int per_load =
      2 + static_cast<int>(s.cambers_deg.size()) + s.slip_sweep.points + s.angle_sweep.points + combined;
  return per_load * static_cast<int>(s.load_factors.size());
}

namespace {
constexpr double kLoadExponent = 1.5;    // a point's work grows as (Fz / FNOMIN)^1.5 (TyreTestProgress)
constexpr double kHalfModelShare = 0.25;  // a half-model point's work against a full-model one's
constexpr double kFirstPointShare = 3.0;  // a series' first point: its footprint and free rolling too
}  // namespace

TyreTestProgress::TyreTestProgress(const TyreTestStudy& study, TyreTestLongitudinalModel longitudinal)
    : name_(study.name), total_(tyre_test_points(study)), start_(std::chrono::steady_clock::now()) {
  const bool half = longitudinal == TyreTestLongitudinalModel::half;
  const int cambers = static_cast<int>(study.cambers_deg.size());
  for (double factor : study.load_factors) {
    const double load_work = std::pow(factor, kLoadExponent);
    Series kappa, alpha;
    kappa.points = kappa.solved = 1 + (half ? 0 : cambers) + study.slip_sweep.points;
    kappa.weight = half ? kHalfModelShare * load_work : load_work;
    alpha.points = 1 + (half ? cambers : 0) + study.angle_sweep.points +
                   (study.combined ? static_cast<int>(study.combined->slips.size() * study.combined->slip_angles_deg.size()) : 0);
    // The rig mirrors its α sweep (camber 0) where the tyre is its own mirror image: where the κ series
    // runs on the half model.
    const SlipAngleSweep& sweep = study.angle_sweep;
    const auto mirrored = mirrored_angles(sweep_values(sweep.from, sweep.to, sweep.points, sweep.spacing));
    alpha.solved = alpha.points - (half ? static_cast<int>(mirrored.size()) : 0);
    alpha.weight = load_work;
    for (const Series& s : {kappa, alpha}) {
      for (int k = 0; k < s.points; ++k) total_work_ += point_work(s, k);
      series_.push_back(s);
    }
  }
}

double TyreTestProgress::point_work(const Series& s, int index) {
  if (index >= s.solved) return 0.0;
  return index == 0 ? kFirstPointShare * s.weight : s.weight;
}

std::string TyreTestProgress::point_done(std::size_t load_index, TyreTestSeries series) {
  const std::lock_guard lock(mutex_);
  const std::size_t j = 2 * load_index + (series == TyreTestSeries::lateral ? 1 : 0);
  if (j < series_.size()) done_work_ += point_work(series_[j], series_[j].done++);
  const int before = 10 * done_ / total_;
  ++done_;
  if (10 * done_ / total_ == before || done_ > total_) return {};
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double share = std::min(done_work_ / total_work_, 1.0);
  const std::string left = done_ < total_ && share > 0 ? fmt::format(", about {:.0f} s left", elapsed * (1 - share) / share) : "";
  return fmt::format("tyre test '{}': {} of {} points after {:.0f} s{}", name_, done_, total_, elapsed, left);
}

double TyreTestProgress::work_done() const {
  const std::lock_guard lock(mutex_);
  return total_work_ > 0 ? done_work_ / total_work_ : 0.0;
}

TyreTestLongitudinalModel tyre_test_longitudinal_model(const TyreMesh& rig_full_mesh) {
  return mirror_symmetric(rig_full_mesh) ? TyreTestLongitudinalModel::half : TyreTestLongitudinalModel::full;
}

RollingStudy tyre_test_rolling_study(const TyreTestStudy& study, std::size_t load_index, TyreTestSeries series,
                                     const MeshSettings& rig_mesh, TyreTestLongitudinalModel longitudinal) {
  const double load = study.load_factors.at(load_index) * study.nominal_load;
  RollingStudy r;
  const bool lateral = series == TyreTestSeries::lateral;
  const bool half = longitudinal == TyreTestLongitudinalModel::half;
  r.name = fmt::format("{}_Fz{:.0f}{}", study.name, load, lateral ? "_alpha" : "");
  r.target_load = load;
  r.load_tolerance = study.load_tolerance;
  r.friction = study.friction;
  r.tread_shear = RollingStudy::TreadShear::planar;
  r.mesh = lateral || !half ? rig_mesh : tyre_test_half_mesh(rig_mesh);
  r.standing_stiffness = lateral;  // Cx, Cy and Cψ at once, on the full model
  // Cambered free rolling needs the full model: in the longitudinal series when that has it, else in the
  // lateral one (solved before its α sweep, which starts from free rolling all the same).
  const auto add_cambered_states = [&] {
    for (double gamma : study.cambers_deg) {
      RollingStateSpec s;
      s.camber_deg = gamma;
      s.name = fmt::format("free_camber_{:g}", gamma);
      s.hold_load = true;  // at the load, as every point of the rig but the straight-ahead free rolling
      r.states.push_back(s);
    }
  };
  if (lateral) {
    if (half) add_cambered_states();
    r.angle_sweep = study.angle_sweep;
    r.angle_sweep->slip = 0.0;
    r.angle_sweep->camber_deg = 0.0;
    r.angle_sweep->hold_load = true;
    r.angle_sweep->mirror_negative_angles = true;  // where the tyre is its own mirror image (camber 0 here)
    r.combined = study.combined;                    // after the α sweep (RollingStudy), Fz held
    return r;  // free rolling is solved all the same (the sweep starts from it), not reported twice
  }
  r.states.push_back({});  // free rolling: Re at this load
  if (!half) add_cambered_states();
  r.sweep = study.slip_sweep;
  r.sweep->hold_load = true;
  return r;
}

LoadCurveStudy tyre_test_vertical_study(const TyreTestStudy& study) {
  LoadCurveStudy s;
  s.name = study.name + "_vertical";
  s.max_deflection = study.vertical_max_deflection;
  s.points = study.vertical_points;
  return s;
}

MeshSettings tyre_test_half_mesh(const MeshSettings& rig_mesh) {
  MeshSettings m = rig_mesh;
  m.half_model = true;
  return m;
}

TyreTestResult assemble_tyre_test(const TyreTestStudy& study, double unloaded_radius_mm,
                                  const std::vector<TyreTestLoadRuns>& loads,
                                  std::optional<StaticContactResult> vertical, const std::string& vertical_error) {
  using Kind = TyreTestRow::Kind;
  TyreTestResult t;
  t.name = study.name;
  t.nominal_load_N = study.nominal_load;
  t.unloaded_radius_mm = unloaded_radius_mm;
  for (std::size_t i = 0; i < study.load_factors.size(); ++i) {
    TyreTestLoad l;
    l.target_load_N = study.load_factors[i] * study.nominal_load;
    // Each series that ran, and a failure for each that did not complete (a load without any: "not run").
    const TyreTestLoadRuns none;
    const TyreTestLoadRuns& runs = i < loads.size() ? loads[i] : none;
    std::vector<const RollingResult*> series;
    l.completed = true;
    for (std::size_t j = 0; j < std::max<std::size_t>(runs.series.size(), 1); ++j) {
      const RollingResult* r = j < runs.series.size() ? runs.series[j] : nullptr;
      if (r) series.push_back(r);
      if (r && r->completed) continue;
      const std::string failure = r                                                 ? r->failure
                                  : j < runs.errors.size() && !runs.errors[j].empty() ? runs.errors[j]
                                                                                      : "not run";
      l.completed = false;
      if (l.failure.empty()) l.failure = failure;
      t.failures.push_back(fmt::format("load {:.0f} N: {}", l.target_load_N, failure));
    }
    // The footprint, the radii and the slip stiffness: the same in both series (the same footprint and free
    // rolling, or the half model's, equal to 1e-6), taken from the first that has them; the cornering
    // stiffness from the lateral one.
    bool footprint = false;
    for (const RollingResult* r : series) {
      if (!footprint && !r->footprint.points.empty()) {
        footprint = true;
        const PatchFigures& p = r->footprint.points.back().patch;
        l.Fz_N = p.Qz_N;
        l.patch_length_mm = p.patch_length_mm;
        l.patch_width_mm = p.patch_width_mm;
        l.deflection_mm = r->deflection_mm;
        l.loaded_radius_mm = r->loaded_radius_mm;
      }
      if (!l.effective_rolling_radius_mm) l.effective_rolling_radius_mm = r->effective_rolling_radius_mm;
      if (!l.slip_stiffness_N) l.slip_stiffness_N = r->slip_stiffness_N;
      if (!l.cornering_stiffness_N_per_deg) {
        l.cornering_stiffness_N_per_deg = r->cornering_stiffness_N_per_deg;
        l.pneumatic_trail_mm = r->pneumatic_trail_at_zero_mm;
      }
      if (const auto& c = r->standing_stiffness) {
        if (!l.longitudinal_stiffness_N_per_mm) l.longitudinal_stiffness_N_per_mm = c->longitudinal_N_per_mm;
        if (!l.lateral_stiffness_N_per_mm) l.lateral_stiffness_N_per_mm = c->lateral_N_per_mm;
        if (!l.yaw_stiffness_Nmm_per_rad) l.yaw_stiffness_Nmm_per_rad = c->yaw_Nmm_per_rad;
      }
    }
    l.longitudinal_relaxation_length_mm = relaxation_length_mm(l.slip_stiffness_N, l.longitudinal_stiffness_N_per_mm);
    l.lateral_relaxation_length_mm =
        relaxation_length_mm(per_radian(l.cornering_stiffness_N_per_deg), l.lateral_stiffness_N_per_mm);
    t.loads.push_back(l);
    const double re = l.effective_rolling_radius_mm.value_or(std::nan(""));
    for (const RollingResult* r : series) {
      const auto radius = [&](double deflection) { return loaded_radius_at(*r, deflection); };
      for (const RollingStateResult& s : r->states) {
        if (!s.converged) continue;
        const Kind kind = s.spec.camber_deg != 0.0 ? Kind::camber : Kind::free;
        t.rows.push_back(row(kind, l.target_load_N, s.figures, s.slip.value_or(0.0), s.spec.slip_angle_deg,
                             s.spec.camber_deg, radius(s.deflection_mm.value_or(r->deflection_mm)), re, s.counts));
      }
      for (const SweepPoint& p : r->sweep)
        t.rows.push_back(row(Kind::slip_sweep, l.target_load_N, p.figures, p.slip, p.slip_angle_deg, p.camber_deg,
                             radius(p.deflection_mm), re, p.counts));
      for (const SweepPoint& p : r->angle_sweep) {
        t.rows.push_back(row(Kind::angle_sweep, l.target_load_N, p.figures, p.slip, p.slip_angle_deg, p.camber_deg,
                             radius(p.deflection_mm), re, p.counts));
        t.rows.back().mirrored = p.mirrored;
      }
      for (const SweepPoint& p : r->combined)
        t.rows.push_back(row(Kind::combined, l.target_load_N, p.figures, p.slip, p.slip_angle_deg, p.camber_deg,
                             radius(p.deflection_mm), re, p.counts));
    }
  }
  t.vertical = std::move(vertical);
  if (!vertical_error.empty()) t.failures.push_back("load–deflection curve: " + vertical_error);
  else if (t.vertical && !t.vertical->completed)
    t.failures.push_back("load–deflection curve: " + t.vertical->failure);
  t.completed = t.failures.empty();
  return t;
}

}  // namespace tirefem
