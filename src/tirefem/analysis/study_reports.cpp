#include "tirefem/analysis/study_reports.hpp"

#include <optional>

#include <fmt/format.h>

#include "tirefem/io/csv_writer.hpp"
#include "tirefem/io/vtu_writer.hpp"
#include "tirefem/report/footprint_report.hpp"
#include "tirefem/report/inflation_report.hpp"
#include "tirefem/report/cornering_report.hpp"
#include "tirefem/report/rim_flange_report.hpp"
#include "tirefem/report/rolling_report.hpp"
#include "tirefem/report/shell_results.hpp"
#include "tirefem/magic_formula/tir_writer.hpp"
#include "tirefem/report/tyre_test_report.hpp"

namespace tirefem {

void ReportWriter::plot(const std::string& stem, const Plot& p) {
  if (p.series.empty()) return skip(stem, "nothing to plot");
  note(write_plot(folder_.path("plots/" + stem), p, &renderer_));
}

void ReportWriter::heatmap(const std::string& stem, const HeatMap& m) {
  note(write_heatmap(folder_.path("plots/" + stem), m, &renderer_));
}

const std::vector<std::string>& ReportWriter::skipped() {
  for (const PlotRenderer::Failure& f : renderer_.finish()) skip(f.script.stem().string(), f.message);
  return skipped_;
}

void ReportWriter::skip(const std::string& name, const std::string& why) {
  skipped_.push_back(fmt::format("{}: {}", name, why));
  if (progress_) progress_(fmt::format("note: report '{}' skipped: {}", name, why));
}

void ReportWriter::note(bool rendered) {
  if (!rendered && !warned_ && progress_) progress_("warning: gnuplot not found, plots written as scripts only");
  warned_ = warned_ || !rendered;
}

// Everything about one loaded state: VTU of the shell and the support, the tread points, the pressure
// maps, the cord strains under the patch centre (Fig. 5) and the belt tension round the equator (Fig. 8).
void write_loaded_state(const ResultsFolder& folder, ReportWriter& plots, const TyreMesh& tm, const Case& c,
                        const StaticContactResult& r) {
  const std::string& n = r.name;
  const auto loaded = evaluate_element_results(tm, c.tyre, r.final_state.displacement, r.kinematics);
  const auto inflated =
      evaluate_element_results(tm, c.tyre, r.inflation.displacement, r.inflation.kinematics);
  write_vtu(folder.path(n + "/shell.vtu"), loaded_shell_vtu(tm, c.tyre, r, loaded));
  write_vtu(folder.path(n + "/support.vtu"), support_vtu(r));
  write_csv(folder.path(n + "/tread_points.csv"), tread_points_table(r));
  plots.heatmap(n + "_pressure_s_phi", pressure_map_s_phi(r));
  plots.heatmap(n + "_footprint", footprint_map_xy(r));
  const CsvTable meridian_loaded = meridian_table(tm, c.tyre, r.final_state.displacement, loaded);
  const CsvTable meridian_inflated = meridian_table(tm, c.tyre, r.inflation.displacement, inflated);
  write_csv(folder.path(n + "/meridian_under_patch.csv"), meridian_loaded);
  plots.plot(n + "_cord_strain", meridian_cord_strain_plot({{"inflated", &meridian_inflated},
                                                            {"loaded", &meridian_loaded}}));
  const CsvTable belt = circumferential_belt_table(tm, c.tyre, {{"inflated", &inflated}, {"loaded", &loaded}});
  write_csv(folder.path(n + "/belt_tension_equator.csv"), belt);
  plots.plot(n + "_belt_tension", circumferential_belt_plot(belt));
}

// A rolling study: the states and the sweep as tables, per state the tread points (CSV and point cloud),
// the loaded shell and the traction map (Fig. 7), and the belt tension of all states together with the
// inflated and the static one (Fig. 8).
void write_rolling(const ResultsFolder& folder, ReportWriter& plots, const TyreMesh& tm, const Case& c,
                   const RollingResult& r) {
  const std::string& n = r.name;
  write_csv(folder.path(n + "/states.csv"), rolling_states_table(r));
  write_csv(folder.path(n + "/footprint_load_points.csv"), load_curve_table(r.footprint));
  if (!r.sweep.empty()) {
    write_csv(folder.path(n + "/slip_sweep.csv"), slip_sweep_table(r));
    plots.plot(n + "_slip_curve", slip_sweep_plot(r));
  }
  if (!r.angle_sweep.empty()) {
    write_csv(folder.path(n + "/angle_sweep.csv"), angle_sweep_table(r));
    plots.plot(n + "_lateral_force", lateral_force_plot(r));
    plots.plot(n + "_aligning_moment", aligning_moment_plot(r));
  }
  if (!r.combined.empty()) {
    write_csv(folder.path(n + "/combined_slip.csv"), combined_slip_table(r));
    plots.plot(n + "_friction_ellipse", friction_ellipse_plot(r));
  }
  if (!r.footprint.completed) return;
  const auto inflated = evaluate_element_results(tm, c.tyre, r.footprint.inflation.displacement, Kinematics::nonlinear);
  const auto loaded = evaluate_element_results(tm, c.tyre, r.footprint.final_state.displacement, Kinematics::nonlinear);
  std::vector<std::vector<ElementResult>> rolling;
  std::vector<std::string> labels;
  for (const RollingStateResult& s : r.states) {
    if (!s.converged) continue;
    const std::string dir = n + "/" + s.name + "/";
    write_csv(folder.path(dir + "tread_points.csv"), rolling_tread_table(r, s));
    write_vtu(folder.path(dir + "tread_points.vtu"), tread_points_vtu(r, s));
    StaticContactResult as_static = r.footprint;  // the loaded shell with this state's displacement
    as_static.final_state.displacement = s.displacement;
    as_static.final_state.tread = s.normal;
    rolling.push_back(evaluate_element_results(tm, c.tyre, s.displacement, Kinematics::nonlinear));
    labels.push_back(s.name);
    write_vtu(folder.path(dir + "shell.vtu"), loaded_shell_vtu(tm, c.tyre, as_static, rolling.back()));
    plots.heatmap(n + "_" + s.name + "_traction", traction_map_s_phi(r, s));
  }
  std::vector<std::pair<std::string, const std::vector<ElementResult>*>> belt{{"inflated", &inflated},
                                                                              {"static", &loaded}};
  for (std::size_t i = 0; i < rolling.size(); ++i) belt.emplace_back(labels[i], &rolling[i]);
  const CsvTable table = circumferential_belt_table(tm, c.tyre, belt);
  write_csv(folder.path(n + "/belt_tension_equator.csv"), table);
  plots.plot(n + "_belt_tension", circumferential_belt_plot(table));
}

toml::table report_footprint(const ResultsFolder& folder, ReportWriter& plots, const ProgressSink& progress,
                             const TyreMesh& tm, const Case& c, const StaticContactResult& r) {
  write_csv(folder.path(r.name + "/load_points.csv"), load_curve_table(r));
  if (r.completed) {
    plots.attempt("footprint '" + r.name + "'", [&] { write_loaded_state(folder, plots, tm, c, r); });
    const PatchFigures& p = r.points.back().patch;
    if (progress)
      progress(fmt::format("footprint '{}': Qz {:.1f} N at δz {:.2f} mm{}, patch {:.1f} × {:.1f} mm, area {:.0f} "
                           "mm², pmax {:.3f} MPa",
                           r.name, p.Qz_N, deflection_from_origin(r, r.final_state.deflection_mm),
                           r.deflection_from == DeflectionOrigin::first_touch ? " from first touch" : "",
                           p.patch_length_mm, p.patch_width_mm, p.contact_area_mm2, p.max_pressure_MPa));
  }
  toml::table t = footprint_summary(r);
  t.insert("solver", counters_table(r.counters));
  add_krylov(*t["solver"].as_table(), r.counters);
  return t;
}

toml::table report_rolling(const ResultsFolder& folder, ReportWriter& plots, const TyreMesh& tm, const Case& c,
                           const RollingResult& r) {
  plots.attempt("rolling '" + r.name + "'", [&] { write_rolling(folder, plots, tm, c, r); });
  toml::table t = rolling_summary(r);
  t.insert("footprint_solver", counters_table(r.footprint.counters));
  t.insert("solver", counters_table(r.counters));
  add_krylov(*t["solver"].as_table(), r.counters);
  return t;
}

toml::table report_tyre_test(const ResultsFolder& folder, ReportWriter& plots, const ProgressSink& progress,
                             const Case& c, const TyreTestResult& t) {
  // The Magic Formula of the converged points (a test that stopped short is fitted on what it has).
  std::optional<TyreTestFit> fit;
  plots.attempt("tyre test '" + t.name + "': Magic Formula fit", [&] {
    fit = fit_tyre_test(t, c.tyre, c.source.filename().string());
    if (progress) progress(tyre_test_fit_line(t, *fit));
  });
  const TyreTestFit* f = fit ? &*fit : nullptr;
  plots.attempt("tyre test '" + t.name + "'", [&] {
    write_csv(folder.path(t.name + "/tyre_test.csv"), tyre_test_table(t));
    if (t.vertical) write_csv(folder.path(t.name + "/vertical.csv"), tyre_test_vertical_table(t));
    write_csv(folder.path(t.name + "/loads.csv"), tyre_test_loads_table(t));
    if (f) write_tir_file(folder.path(t.name + "/" + t.name + ".tir"), f->tir);
    plots.plot(t.name + "_fx_kappa", tyre_test_fx_plot(t, f));
    plots.plot(t.name + "_fy_alpha", tyre_test_fy_plot(t, f));
    plots.plot(t.name + "_mz_alpha", tyre_test_mz_plot(t, f));
    plots.plot(t.name + "_vertical", tyre_test_vertical_plot(t, f));
    if (const Plot relaxation = tyre_test_relaxation_plot(t, f); !relaxation.series.empty())
      plots.plot(t.name + "_relaxation", relaxation);
    if (const Plot combined = tyre_test_combined_plot(t, f); !combined.series.empty())
      plots.plot(t.name + "_combined", combined);
  });
  return tyre_test_summary(t, f);
}

toml::table write_inflation(const ResultsFolder& folder, ReportWriter& plots, const ProgressSink& progress,
                            const TyreMesh& tm, const Case& c, const InflationResult& r) {
  const auto elements = evaluate_element_results(tm, c.tyre, r.displacement, r.kinematics);
  const InflationSummary s = summarize_inflation(tm, r.displacement, elements);
  const CsvTable table = meridian_table(tm, c.tyre, r.displacement, elements);
  write_csv(folder.path("inflation_meridian.csv"), table);
  write_vtu(folder.path("inflation.vtu"), shell_vtu(tm, c.tyre, r.displacement, elements));
  plots.attempt("inflation plots", [&] {
    for (const auto& [name, plot] : meridian_plots(table, tm, r.displacement))
      plots.plot("inflation_" + name, plot);
  });
  toml::table inflation{{"pressure_MPa", c.inflation.pressure},
                        {"theory", c.inflation.linear ? "linear" : "nonlinear"},
                        {"converged", r.converged},
                        {"stable", r.tangent_shift <= 0.0},
                        {"crown_radius_growth_mm", s.crown_radius_growth_mm},
                        {"section_width_growth_mm", s.section_width_growth_mm},
                        {"max_carcass_cord_force_N", s.max_carcass_cord_force_N},
                        {"max_belt_cord_force_N", s.max_belt_cord_force_N},
                        {"max_carcass_cord_strain", s.max_carcass_cord_strain},
                        {"max_belt_cord_strain", s.max_belt_cord_strain},
                        {"newton_iterations", r.counters.newton_iterations}};
  if (!s.rim_flanges.empty()) {
    toml::array flanges;
    for (const RimFlangeLoad& l : s.rim_flanges)
      flanges.push_back(rim_flange_table(rim_flange_side(l, tm.half_model, false), l));
    inflation.insert("rim_flanges", std::move(flanges));
  }
  inflation.insert("solver", counters_table(r.counters));
  if (!progress) return inflation;
  progress(fmt::format("inflation: crown radius +{:.3f} mm, section width {:+.3f} mm, max cord force carcass "
                       "{:.2f} N, belt {:.2f} N ({} Newton iterations, {:.2f} s)",
                       s.crown_radius_growth_mm, s.section_width_growth_mm, s.max_carcass_cord_force_N,
                       s.max_belt_cord_force_N, r.counters.newton_iterations, r.counters.wall_s));
  for (const RimFlangeLoad& l : s.rim_flanges)
    progress(fmt::format("  rim flange ({}): axial push {:.0f} N, peak pressure {:.3f} MPa, in contact over "
                         "{:.0f}% of the round",
                         rim_flange_side(l, tm.half_model, false), l.axial_force_N, l.peak_pressure_MPa,
                         100 * l.contact_fraction));
  return inflation;
}

toml::table counters_table(const SolveCounters& c) {
  return toml::table{{"load_steps", c.load_steps},
                     {"cutbacks", c.cutbacks},
                     {"newton_iterations", c.newton_iterations},
                     {"factorizations", c.factorizations},
                     {"assembly_time_s", c.assembly_s},
                     {"factorization_time_s", c.factorization_s},
                     {"time_s", c.wall_s}};
}

void add_krylov(toml::table& t, const SolveCounters& c) {
  t.insert("reused_factorizations", c.krylov_solves);
  t.insert("krylov_iterations", c.krylov_iterations);
}

}  // namespace tirefem
