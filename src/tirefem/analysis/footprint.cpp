#include "tirefem/analysis/footprint.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include <fmt/format.h>

#include "tirefem/analysis/static_contact_run.hpp"

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

InflationResult inflate_for_contact(const TyreMesh& tm, const InflationSettings& inflation,
                                    const ProgressSink& progress) {
  // The geometrically linear solution is linearised about the nonlinear inflated state (the tyre's
  // stiffness under load comes from its inflation: a linear theory about the unstressed state has no
  // pressure stiffening at all), so the inflation is nonlinear in both theories.
  InflationSettings inflate = inflation;
  inflate.linear = false;
  return run_inflation(tm, inflate, progress);
}

StaticContactResult run_load_curve(const TyreMesh& tm, const TyreDescription& tyre,
                                   const InflationSettings& inflation, const ContactSettings& contact,
                                   const LoadCurveStudy& study, const ProgressSink& progress,
                                   const InflationResult* inflated, bool keep_path) {
  const auto t0 = StaticContactClock::now();
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

}  // namespace tirefem
