#include "tirefem/analysis/run_case.hpp"

#include <chrono>
#include <map>
#include <memory>
#include <tuple>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>
#include <omp.h>
#include <toml++/toml.h>

#include "tirefem/analysis/footprint.hpp"
#include "tirefem/analysis/inflation.hpp"
#include "tirefem/analysis/rolling.hpp"
#include "tirefem/io/json_summary.hpp"
#include "tirefem/io/results_folder.hpp"
#include "tirefem/results/footprint_report.hpp"
#include "tirefem/results/inflation_report.hpp"
#include "tirefem/results/rolling_report.hpp"
#include "tirefem/solver/blas_kernel.hpp"

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

toml::table blas_table() {
  const BlasKernel b = blas_kernel();
  return toml::table{{"library", b.library}, {"kernel", b.core}, {"kernel_forced", b.forced}};
}

void report(const ProgressSink& progress, const std::string& message) {
  if (progress) progress(message);
}

void add_krylov(toml::table& t, const SolveCounters& c) {
  t.insert("reused_factorizations", c.krylov_solves);
  t.insert("krylov_iterations", c.krylov_iterations);
}

// Writes the plots (gnuplot may be missing: warn once) and guards every report: a report that cannot be
// made (e.g. no ply, hence no cord tension to plot) is skipped with a note, never a failure that would
// discard the solve.
class ReportWriter {
 public:
  ReportWriter(const ResultsFolder& folder, const ProgressSink& progress) : folder_(folder), progress_(progress) {}
  void plot(const std::string& stem, const Plot& p) {
    if (p.series.empty()) return skip(stem, "nothing to plot");
    note(write_plot(folder_.path("plots/" + stem), p));
  }
  void heatmap(const std::string& stem, const HeatMap& m) { note(write_heatmap(folder_.path("plots/" + stem), m)); }
  // Runs `write`; an exception (other than an interrupt) skips the rest of that report with a note.
  template <class F>
  void attempt(const std::string& report_name, F&& write) {
    try {
      write();
    } catch (const RunInterrupted&) {
      throw;
    } catch (const std::exception& e) {
      skip(report_name, e.what());
    }
  }
  const std::vector<std::string>& skipped() const { return skipped_; }

 private:
  void skip(const std::string& name, const std::string& why) {
    skipped_.push_back(fmt::format("{}: {}", name, why));
    report(progress_, fmt::format("note: report '{}' skipped: {}", name, why));
  }
  void note(bool rendered) {
    if (!rendered && !warned_) report(progress_, "warning: gnuplot not found, plots written as scripts only");
    warned_ = warned_ || !rendered;
  }
  const ResultsFolder& folder_;
  ProgressSink progress_;
  bool warned_ = false;
  std::vector<std::string> skipped_;
};

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

// Wall time per phase of the run, printed at the end and kept in summary.json. A shared inflation is a
// phase of its own, taken out of the study during which it was solved.
class PhaseTimes {
 public:
  using Clock = std::chrono::steady_clock;
  void begin(std::string name) {
    name_ = std::move(name);
    start_ = Clock::now();
    nested_ = 0.0;
  }
  void end() { phases_.emplace_back(name_, seconds(start_) - nested_); }
  void nested(std::string name, double s) {
    phases_.emplace_back(std::move(name), s);
    nested_ += s;
  }
  void report(const ProgressSink& progress, double total) const {
    if (!progress) return;
    progress("time per phase:");
    for (const auto& [name, s] : phases_) progress(fmt::format("  {:<40} {:9.2f} s", name, s));
    progress(fmt::format("  {:<40} {:9.2f} s", "total", total));
  }
  toml::array table() const {
    toml::array a;
    for (const auto& [name, s] : phases_) a.push_back(toml::table{{"phase", name}, {"time_s", s}});
    return a;
  }

 private:
  static double seconds(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
  std::string name_;
  Clock::time_point start_;
  double nested_ = 0.0;
  std::vector<std::pair<std::string, double>> phases_;
};

// One tyre mesh and one nonlinear inflation per mesh setting, shared by all studies of a run: the
// inflation is solved once per tyre and mesh, not once per study.
class InflatedTyres {
 public:
  InflatedTyres(const Case& c, const ProgressSink& progress, PhaseTimes& times)
      : case_(c), progress_(progress), times_(times) {}
  const TyreMesh& mesh(const MeshSettings& m) {
    Entry& e = entry(m);
    if (!e.mesh) e.mesh = std::make_unique<TyreMesh>(build_tyre_mesh(case_.tyre, m));
    return *e.mesh;
  }
  // The nonlinear inflated state of that mesh at the case's pressure.
  const InflationResult& inflated(const MeshSettings& m) {
    Entry& e = entry(m);
    if (!e.inflated) {
      e.inflated = inflate_for_contact(mesh(m), case_.inflation, progress_);
      times_.nested(fmt::format("inflation ({} x {}, shared)", m.circumferential_elements, m.meridional_elements),
                    e.inflated->counters.wall_s);
      if (!e.inflated->converged) throw std::runtime_error(e.inflated->failure);
    }
    return *e.inflated;
  }
  void adopt(const MeshSettings& m, const InflationResult& r) { entry(m).inflated = r; }

 private:
  struct Entry {
    std::unique_ptr<TyreMesh> mesh;  // stable address: forms refer to it
    std::optional<InflationResult> inflated;
  };
  Entry& entry(const MeshSettings& m) {
    return entries_[{m.circumferential_elements, m.meridional_elements, m.half_model, m.circumferential_refinement,
                      static_cast<int>(m.meridional_grading)}];
  }
  const Case& case_;
  ProgressSink progress_;
  PhaseTimes& times_;
  std::map<std::tuple<int, int, bool, double, int>, Entry> entries_;
};

// Completed static footprints by mesh, support and target load: a rolling study at the load and on the
// support of an earlier footprint (a [[footprint]] study on the case's mesh, or another rolling study)
// starts from it instead of solving it again.
class SharedFootprints {
 public:
  const StaticContactResult* find(const MeshSettings& m, const SupportDescription& s, double load,
                                  double tolerance) const {
    const auto it = entries_.find(key(m, s, load, tolerance));
    return it == entries_.end() ? nullptr : &it->second;
  }
  void keep(const MeshSettings& m, const SupportDescription& s, double load, double tolerance,
            const StaticContactResult& r) {
    if (r.completed) entries_.try_emplace(key(m, s, load, tolerance), r);
  }

 private:
  static std::string key(const MeshSettings& m, const SupportDescription& s, double load, double tolerance) {
    std::string k = fmt::format("{} {} {} {:a} {} | {} {:a} | {:a} {:a}", m.circumferential_elements,
                                m.meridional_elements, m.half_model, m.circumferential_refinement,
                                static_cast<int>(m.meridional_grading), static_cast<int>(s.kind), s.drum_diameter,
                                load, tolerance);
    for (const auto& t : s.terms) k += fmt::format(" {:a} {} {}", t.coefficient, t.x_power, t.y_power);
    return k;
  }
  std::map<std::string, StaticContactResult> entries_;
};

std::string incomplete_message(const StaticContactResult& r) {
  return fmt::format("'{}' stopped at δz = {:.3g} mm: {}", r.name, r.final_state.deflection_mm, r.failure);
}

}  // namespace

RunOutcome run_case(const Case& c, const RunOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  ResultsFolder folder(options.out_dir, {.force = options.force, .case_file = c.source});
  // Every solver reports progress between steps: that is where a requested stop takes effect.
  const ProgressSink progress = [&](const std::string& message) {
    if (options.stop_requested && !folder.committed() && options.stop_requested()) throw RunInterrupted();
    if (options.progress) options.progress(message);
  };
  PhaseTimes times;
  times.begin("mesh");
  InflatedTyres tyres(c, progress, times);
  const TyreMesh& tm = tyres.mesh(c.mesh);
  const int equations = tm.mesh.dof_count() - static_cast<int>(tm.fixed_dofs.size());
  report(progress, fmt::format("{}: {} x {} {} model, {} elements, {} DOF ({} free)", c.title,
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
                      {"blas", blas_table()},
                      {"mesh", toml::table{{"circumferential_elements", c.mesh.circumferential_elements},
                                           {"meridional_elements", c.mesh.meridional_elements},
                                           {"model", c.mesh.half_model ? "half" : "full"}}}};

  times.end();
  ReportWriter plots(folder, progress);
  toml::array incomplete;
  // A study that throws (e.g. its first contact state does not converge) stops short like one whose load
  // path ends early; the other studies go on.
  auto study = [&](const std::string& name, auto&& run) {
    times.begin(name);
    try {
      run();
    } catch (const RunInterrupted&) {
      throw;
    } catch (const std::exception& e) {
      const std::string m = fmt::format("{} failed: {}", name, e.what());
      report(progress, "warning: " + m);
      incomplete.push_back(m);
    }
    times.end();
  };
  if (c.inflation.enabled) {
    times.begin("inflation");
    const InflationResult r = run_inflation(tm, c.inflation, progress);
    if (!r.converged) throw std::runtime_error(r.failure);
    if (r.kinematics == Kinematics::nonlinear) tyres.adopt(c.mesh, r);  // the contact studies start here
    const auto elements = evaluate_element_results(tm, c.tyre, r.displacement, r.kinematics);
    const InflationSummary s = summarize_inflation(tm, r.displacement, elements);
    const CsvTable table = meridian_table(tm, c.tyre, r.displacement, elements);
    write_csv(folder.path("inflation_meridian.csv"), table);
    write_vtu(folder.path("inflation.vtu"), shell_vtu(tm, c.tyre, r.displacement, elements));
    plots.attempt("inflation plots", [&] {
      for (const auto& [name, plot] : meridian_plots(table, tm, r.displacement)) plots.plot("inflation_" + name, plot);
    });
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
    report(progress,
           fmt::format("inflation: crown radius +{:.3f} mm, section width {:+.3f} mm, max cord force "
                       "carcass {:.2f} N, belt {:.2f} N ({} Newton iterations, {:.2f} s)",
                       s.crown_radius_growth_mm, s.section_width_growth_mm, s.max_carcass_cord_force_N,
                       s.max_belt_cord_force_N, r.counters.newton_iterations, r.counters.wall_s));
    times.end();
  }

  std::vector<StaticContactResult> curves;
  toml::array curve_summaries, footprint_summaries, rolling_summaries;
  for (const LoadCurveStudy& study_case : c.load_curves) {
    study("load curve '" + study_case.name + "'", [&] {
      StaticContactResult r =
          run_load_curve(tm, c.tyre, c.inflation, c.contact, study_case, progress, &tyres.inflated(c.mesh));
      if (!r.completed) {
        report(progress, "warning: load curve " + incomplete_message(r) + " (converged points kept)");
        incomplete.push_back(incomplete_message(r));
      }
      write_csv(folder.path("load_curve_" + r.name + ".csv"), load_curve_table(r));
      toml::table t = load_curve_summary(r);
      t.insert("solver", counters_table(r.counters));
      add_krylov(*t["solver"].as_table(), r.counters);
      curve_summaries.push_back(std::move(t));
      r.final_state.displacement.resize(0);  // keep the curve, not its last state
      r.inflation.displacement.resize(0);
      curves.push_back(std::move(r));
    });
  }
  if (!curves.empty()) {
    std::vector<const StaticContactResult*> list;
    for (const auto& r : curves) list.push_back(&r);
    plots.attempt("load characteristic", [&] { plots.plot("load_characteristic", load_characteristic_plot(list)); });
    summary.insert("load_curves", std::move(curve_summaries));
  }
  SharedFootprints footprints;
  for (const FootprintStudy& study_case : c.footprints) {
    study("footprint '" + study_case.name + "'", [&] {
      const StaticContactResult r =
          run_footprint(tm, c.tyre, c.inflation, c.contact, study_case, progress, &tyres.inflated(c.mesh));
      // Shared only as a rolling study would solve it: nonlinear, at a target load, δz from the undeformed tyre.
      if (!study_case.linear && !study_case.deflection && study_case.deflection_from == DeflectionOrigin::undeformed)
        footprints.keep(c.mesh, study_case.support, study_case.target_load, study_case.load_tolerance, r);
      write_csv(folder.path(r.name + "/load_points.csv"), load_curve_table(r));
      if (!r.completed) {
        report(progress, "warning: footprint " + incomplete_message(r));
        incomplete.push_back(incomplete_message(r));
      } else {
        plots.attempt("footprint '" + r.name + "'", [&] { write_loaded_state(folder, plots, tm, c, r); });
        report(progress,
               fmt::format("footprint '{}': Qz {:.1f} N at δz {:.2f} mm{}, patch {:.1f} × {:.1f} mm, area {:.0f} "
                           "mm², pmax {:.3f} MPa",
                           r.name, r.points.back().patch.Qz_N, deflection_from_origin(r, r.final_state.deflection_mm),
                           r.deflection_from == DeflectionOrigin::first_touch ? " from first touch" : "",
                           r.points.back().patch.patch_length_mm, r.points.back().patch.patch_width_mm,
                           r.points.back().patch.contact_area_mm2, r.points.back().patch.max_pressure_MPa));
      }
      toml::table t = footprint_summary(r);
      t.insert("solver", counters_table(r.counters));
      add_krylov(*t["solver"].as_table(), r.counters);
      footprint_summaries.push_back(std::move(t));
    });
  }
  if (!c.footprints.empty()) summary.insert("footprints", std::move(footprint_summaries));
  for (const RollingStudy& study_case : c.rolling) {
    study("rolling '" + study_case.name + "'", [&] {
      const MeshSettings& settings = study_case.mesh.value_or(c.mesh);
      const TyreMesh& mesh = tyres.mesh(settings);
      if (study_case.mesh)
        report(progress, fmt::format("rolling '{}' on its own mesh: {} x {}, {} elements", study_case.name,
                                     settings.circumferential_elements, settings.meridional_elements,
                                     mesh.mesh.element_count()));
      const RollingResult r = run_rolling(
          mesh, c.tyre, c.inflation, c.contact, study_case, progress, &tyres.inflated(settings),
          footprints.find(settings, study_case.support, study_case.target_load, study_case.load_tolerance));
      footprints.keep(settings, study_case.support, study_case.target_load, study_case.load_tolerance, r.footprint);
      if (!r.completed) {
        const std::string m = fmt::format("rolling '{}': {}", r.name, r.failure);
        report(progress, "warning: " + m + " (converged states kept)");
        incomplete.push_back(m);
      }
      plots.attempt("rolling '" + r.name + "'", [&] { write_rolling(folder, plots, mesh, c, r); });
      toml::table t = rolling_summary(r);
      t.insert("footprint_solver", counters_table(r.footprint.counters));
      t.insert("solver", counters_table(r.counters));
      add_krylov(*t["solver"].as_table(), r.counters);
      rolling_summaries.push_back(std::move(t));
    });
  }
  if (!c.rolling.empty()) summary.insert("rolling", std::move(rolling_summaries));
  const bool completed = incomplete.empty();
  summary.insert("completed", completed);
  if (!incomplete.empty()) summary.insert("incomplete", std::move(incomplete));
  toml::array skipped;
  for (const std::string& m : plots.skipped()) skipped.push_back(m);
  if (!skipped.empty()) summary.insert("skipped_reports", std::move(skipped));

  times.begin("summary and results folder");
  const double before_writing = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  summary.insert("phases", times.table());
  summary.insert("wall_time_s", before_writing);
  write_json(folder.path("summary.json"), summary);
  // A run that stopped short leaves the last complete results as they were.
  const std::filesystem::path where = folder.commit(completed ? "" : "-incomplete");
  times.end();
  times.report(progress, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  return {where, where / "summary.json", completed, plots.skipped()};
}

}  // namespace tirefem
