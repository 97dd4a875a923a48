#include "tirefem/analysis/run_case.hpp"

#include <chrono>
#include <stdexcept>

#include <fmt/format.h>
#include <omp.h>
#include <toml++/toml.h>

#include "tirefem/analysis/inflation.hpp"
#include "tirefem/io/json_summary.hpp"
#include "tirefem/io/results_folder.hpp"
#include "tirefem/results/inflation_report.hpp"

namespace tirefem {
namespace {

toml::table counters_table(const SolveCounters& c) {
  return toml::table{{"load_steps", c.load_steps},
                     {"cutbacks", c.cutbacks},
                     {"newton_iterations", c.newton_iterations},
                     {"factorizations", c.factorizations},
                     {"assembly_time_s", c.assembly_s},
                     {"factorization_time_s", c.factorization_s},
                     {"time_s", c.wall_s}};
}

void report(const ProgressSink& progress, const std::string& message) {
  if (progress) progress(message);
}

}  // namespace

std::filesystem::path run_case(const Case& c, const RunOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  ResultsFolder folder(options.out_dir);
  const TyreMesh tm = build_tyre_mesh(c.tyre, c.mesh);
  const int equations = tm.mesh.dof_count() - static_cast<int>(tm.fixed_dofs.size());
  report(options.progress, fmt::format("{}: {} x {} {} model, {} elements, {} DOF ({} free)", c.title,
                                       c.mesh.circumferential_elements, c.mesh.meridional_elements,
                                       c.mesh.half_model ? "half" : "full", tm.mesh.element_count(),
                                       tm.mesh.dof_count(), equations));
  toml::table summary{{"tirefem_version", "0.1.0"},
                      {"title", c.title},
                      {"case_file", c.source.string()},
                      {"units", "mm, N, MPa"},
                      {"dof", tm.mesh.dof_count()},
                      {"free_dof", equations},
                      {"elements", tm.mesh.element_count()},
                      {"threads", omp_get_max_threads()},
                      {"mesh", toml::table{{"circumferential_elements", c.mesh.circumferential_elements},
                                           {"meridional_elements", c.mesh.meridional_elements},
                                           {"model", c.mesh.half_model ? "half" : "full"}}}};

  if (c.inflation.enabled) {
    const InflationResult r = run_inflation(tm, c.inflation, options.progress);
    if (!r.converged)
      throw std::runtime_error(fmt::format("inflation to {} MPa did not converge (after {} cut-backs)",
                                           c.inflation.pressure, r.counters.cutbacks));
    const auto elements = evaluate_element_results(tm, c.tyre, r.displacement, r.kinematics);
    const InflationSummary s = summarize_inflation(tm, r.displacement, elements);
    const CsvTable table = meridian_table(tm, c.tyre, r.displacement, elements);
    write_csv(folder.path("inflation_meridian.csv"), table);
    write_vtu(folder.path("inflation.vtu"), shell_vtu(tm, c.tyre, r.displacement, elements));
    bool rendered = true;
    for (const auto& [name, plot] : meridian_plots(table, tm, r.displacement))
      rendered = write_plot(folder.path("plots/inflation_" + name), plot) && rendered;
    if (!rendered) report(options.progress, "warning: gnuplot not found, plots written as scripts only");
    toml::table inflation{{"pressure_MPa", c.inflation.pressure},
                          {"theory", c.inflation.linear ? "linear" : "nonlinear"},
                          {"converged", r.converged},
                          {"crown_radius_growth_mm", s.crown_radius_growth_mm},
                          {"section_width_growth_mm", s.section_width_growth_mm},
                          {"max_carcass_cord_force_N", s.max_carcass_cord_force_N},
                          {"max_belt_cord_force_N", s.max_belt_cord_force_N},
                          {"max_carcass_cord_strain", s.max_carcass_cord_strain},
                          {"max_belt_cord_strain", s.max_belt_cord_strain},
                          {"newton_iterations", r.counters.newton_iterations}};
    inflation.insert("solver", counters_table(r.counters));
    summary.insert("inflation", std::move(inflation));
    report(options.progress,
           fmt::format("inflation: crown radius +{:.3f} mm, section width {:+.3f} mm, max cord force "
                       "carcass {:.2f} N, belt {:.2f} N ({} Newton iterations, {:.2f} s)",
                       s.crown_radius_growth_mm, s.section_width_growth_mm, s.max_carcass_cord_force_N,
                       s.max_belt_cord_force_N, r.counters.newton_iterations, r.counters.wall_s));
  }

  summary.insert("wall_time_s", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  write_json(folder.path("summary.json"), summary);
  folder.commit();
  return options.out_dir / "summary.json";
}

}  // namespace tirefem
