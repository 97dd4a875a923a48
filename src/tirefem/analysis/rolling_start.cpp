// Where a rolling study begins: its static footprint and free rolling straight ahead (the search for the
// effective rolling radius Re), solved by the study itself or once for all the studies at its load
// (RollingStart).
#include <cmath>

#include <fmt/format.h>

#include "tirefem/analysis/rolling_model.hpp"

namespace tirefem {

namespace {
constexpr double kDegree = 3.14159265358979323846 / 180.0;
}  // namespace

RollingModel::Solved secant_free_rolling(RollingModel& model, const FrictionLaw& law, WheelSlip slip, double slope,
                                         std::vector<std::pair<double, double>>& tried, RollingSolveCounts& total,
                                         const ProgressSink& progress) {
  RollingModel::Solved s;
  for (int it = 0; it < 15; ++it) {
    s = model.solve(law, slip, false, /*along_tangent=*/true);
    total.newton_iterations += s.counts.newton_iterations;
    total.factorizations += s.counts.factorizations;
    total.solves += s.counts.solves;
    total.time_s += s.counts.time_s;
    total.contact_iterations = s.counts.contact_iterations;
    if (!s.converged) break;
    tried.emplace_back(slip.rolling_radius, s.figures.Qy_N);
    if (progress)
      progress(fmt::format("  free rolling{}: Rk {:.4f} mm → Qy {:+.2f} N",
                           slip.slip_angle != 0.0 || slip.camber != 0.0
                               ? fmt::format(" at α {:g}°, γ {:g}°", slip.slip_angle / kDegree, slip.camber / kDegree)
                               : "",
                           slip.rolling_radius, s.figures.Qy_N));
    if (std::abs(s.figures.Qy_N) <= 1e-4 * std::abs(s.figures.Qz_N)) return s;
    if (tried.size() >= 2) {
      const auto& [r0, q0] = tried[tried.size() - 2];
      if (q0 != s.figures.Qy_N) slope = (s.figures.Qy_N - q0) / (slip.rolling_radius - r0);
    }
    slip.rolling_radius -= s.figures.Qy_N / slope;
  }
  if (s.converged) {
    s.converged = false;
    s.failure = "the free-rolling radius was not found in 15 secant steps";
  }
  return s;
}

RollingStateResult free_rolling(RollingModel& model, const RollingStudy& study, RollingResult& result,
                                const ProgressSink& progress) {
  RollingStateResult state;
  state.spec.kind = RollingStateSpec::Kind::free;
  state.name = "free";
  FrictionLaw law;
  law.friction = study.friction;
  const double a = result.loaded_radius_mm, b = result.axle_z;
  const double qa = model.static_full_stick_Qy(a), qb = model.static_full_stick_Qy(b);
  const double rk = qa != qb ? a - qa * (b - a) / (qb - qa) : 0.5 * (a + b);
  std::vector<std::pair<double, double>> tried;  // (Rk, Qy)
  RollingSolveCounts total;
  RollingModel::Solved s = secant_free_rolling(model, law, {rk, 0.0, 0.0}, (qb - qa) / (b - a), tried, total, progress);
  s.counts = total;
  model.fill(state, s);
  if (!state.converged) return state;
  const double re = tried.back().first;
  result.effective_rolling_radius_mm = re;
  state.rolling_radius_mm = re;
  state.slip = 0.0;
  // dQy/dκ = dQy/dRk · dRk/dκ, dRk/dκ = −Re at κ = 0.
  double sx = 0, sy = 0, sxx = 0, sxy = 0, slope = 0.0;
  int n = 0;
  for (const auto& [r, q] : tried)
    if (std::abs(re / r - 1.0) <= 0.003) sx += r, sy += q, sxx += r * r, sxy += r * q, ++n;
  if (n >= 2 && n * sxx - sx * sx > 0) slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  else if (tried.size() >= 2) slope = (tried.back().second - tried[tried.size() - 2].second) /
                                      (tried.back().first - tried[tried.size() - 2].first);
  else slope = (qb - qa) / (b - a);
  result.slip_stiffness_N = -re * slope;
  return state;
}

RollingResult rolling_result_of(const RollingStudy& study, const TyreMesh& tm) {
  RollingResult r;
  r.name = study.name;
  r.support = study.support;
  r.friction = study.friction;
  r.reverse = study.reverse;
  r.half_model = tm.half_model;
  return r;
}

void place_axle_at_footprint(RollingResult& r, const TyreMesh& tm) {
  r.deflection_mm = r.footprint.final_state.deflection_mm;
  r.axle_z = tm.axis_z;
  r.loaded_radius_mm = tm.axis_z - r.deflection_mm;
}

StaticContactResult rolling_footprint(const TyreMesh& tm, const TyreDescription& tyre, const InflationSettings& inflation,
                                      const ContactSettings& contact, const RollingStudy& study,
                                      const ProgressSink& progress, const InflationResult* inflated,
                                      const StaticContactResult* footprint, const std::vector<PathState>* nearby) {
  if (footprint && footprint->completed) {
    StaticContactResult r = *footprint;
    r.name = study.name;
    if (progress)
      progress(fmt::format("  the static footprint solved before: Qz {:.1f} N at δz {:.3f} mm",
                           r.points.back().patch.Qz_N, r.final_state.deflection_mm));
    return r;
  }
  FootprintStudy fs;
  fs.name = study.name;
  fs.support = study.support;
  fs.target_load = study.target_load;
  fs.load_tolerance = study.load_tolerance;
  return run_footprint(tm, tyre, inflation, contact, fs, progress, inflated, nullptr, nearby);
}

RollingStart solve_rolling_start(const TyreMesh& tm, const TyreDescription& tyre, const InflationSettings& inflation,
                                 const ContactSettings& contact, const RollingStudy& study,
                                 const ProgressSink& progress, const InflationResult* inflated,
                                 const StaticContactResult* footprint, const std::vector<PathState>* nearby) {
  RollingStart start;
  start.friction = study.friction;
  start.reverse = study.reverse;
  start.footprint = rolling_footprint(tm, tyre, inflation, contact, study, progress, inflated, footprint, nearby);
  if (!start.footprint.completed) return start;
  // The model as run_rolling builds it, at the footprint's deflection.
  RollingResult r = rolling_result_of(study, tm);
  r.footprint = start.footprint;
  place_axle_at_footprint(r, tm);
  RollingModel model(tm, tyre, inflation, contact, study, r);
  model.set_progress(progress);
  start.free = free_rolling(model, study, r, progress);
  start.effective_rolling_radius_mm = r.effective_rolling_radius_mm;
  start.slip_stiffness_N = r.slip_stiffness_N;
  start.states = model.converged_states();
  return start;
}

}  // namespace tirefem
