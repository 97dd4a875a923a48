// The footprint study (analysis/footprint.hpp): the static contact at a given deflection, or at a target
// load found by stepping δz and regula falsi (MODEL.md §4).
#include <algorithm>
#include <cmath>
#include <tuple>

#include <fmt/format.h>

#include "tirefem/analysis/first_touch.hpp"
#include "tirefem/analysis/footprint.hpp"
#include "tirefem/analysis/static_contact_run.hpp"

namespace tirefem {

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
  const auto t0 = StaticContactClock::now();
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
