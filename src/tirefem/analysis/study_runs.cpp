#include "tirefem/analysis/study_runs.hpp"

#include <fmt/format.h>

#include "tirefem/case/tyre_reader.hpp"
#include "tirefem/io/csv_writer.hpp"
#include "tirefem/report/footprint_report.hpp"
#include "tirefem/report/rolling_report.hpp"

namespace tirefem {
namespace {

std::string incomplete_message(const StaticContactResult& r) {
  return fmt::format("'{}' stopped at δz = {:.3g} mm: {}", r.name, r.final_state.deflection_mm, r.failure);
}

}  // namespace

void write_study_results(const Case& c, InflatedTyres& tyres, std::vector<StudyRun>& runs,
                         const ResultsFolder& folder, ReportWriter& plots, const ProgressSink& progress,
                         toml::table& summary, toml::array& incomplete) {
  toml::array curve_summaries, footprint_summaries, rolling_summaries;
  std::vector<const StaticContactResult*> curves;
  int k = 0;
  for (std::size_t i = 0; i < c.load_curves.size(); ++i, ++k) {
    if (!runs[k].contact) continue;
    StaticContactResult& r = *runs[k].contact;
    if (!r.completed) {
      if (progress) progress("warning: load curve " + incomplete_message(r) + " (converged points kept)");
      incomplete.push_back(incomplete_message(r));
    }
    write_csv(folder.path("load_curve_" + r.name + ".csv"), load_curve_table(r));
    toml::table t = load_curve_summary(r);
    t.insert("solver", counters_table(r.counters));
    add_krylov(*t["solver"].as_table(), r.counters);
    curve_summaries.push_back(std::move(t));
    r.final_state.displacement.resize(0);  // keep the curve, not its states
    r.inflation.displacement.resize(0);
    r.path.clear();
    curves.push_back(&r);
  }
  if (!curves.empty()) {
    plots.attempt("load characteristic", [&] { plots.plot("load_characteristic", load_characteristic_plot(curves)); });
    summary.insert("load_curves", std::move(curve_summaries));
  }
  for (std::size_t i = 0; i < c.footprints.size(); ++i, ++k) {
    if (!runs[k].contact) continue;
    const StaticContactResult& r = *runs[k].contact;
    if (!r.completed) {
      if (progress) progress("warning: footprint " + incomplete_message(r));
      incomplete.push_back(incomplete_message(r));
    }
    footprint_summaries.push_back(report_footprint(folder, plots, progress, tyres.mesh(c.mesh), c, r));
  }
  if (!c.footprints.empty()) summary.insert("footprints", std::move(footprint_summaries));
  for (std::size_t i = 0; i < c.rolling.size(); ++i, ++k) {
    if (!runs[k].rolling) continue;
    const RollingResult& r = *runs[k].rolling;
    if (!r.completed) {
      const std::string m = fmt::format("rolling '{}': {}", r.name, r.failure);
      if (progress) progress("warning: " + m + " (converged states kept)");
      incomplete.push_back(m);
    }
    rolling_summaries.push_back(report_rolling(folder, plots, tyres.mesh(c.rolling[i].mesh.value_or(c.mesh)), c, r));
  }
  if (!c.rolling.empty()) summary.insert("rolling", std::move(rolling_summaries));
  toml::array rig_summaries;
  for (const TyreTestStudy& s : c.tyre_tests) {
    std::vector<TyreTestLoadRuns> loads(s.load_factors.size());
    for (TyreTestLoadRuns& load : loads)
      for (std::size_t j = 0; j < kRigSeries.size(); ++j, ++k) {
        load.series.push_back(runs[k].rolling ? &*runs[k].rolling : nullptr);
        load.errors.push_back(runs[k].error);
      }
    const StudyRun& vertical = runs[k++];
    const TyreTestResult t =
        assemble_tyre_test(s, case_reading::tyre_outer_radius(c.tyre), loads, vertical.contact, vertical.error);
    for (const std::string& m : t.failures) {
      if (progress) progress(fmt::format("warning: tyre test '{}': {} (converged points kept)", s.name, m));
      incomplete.push_back(fmt::format("tyre test '{}': {}", s.name, m));
    }
    rig_summaries.push_back(report_tyre_test(folder, plots, progress, c, t));
  }
  if (!c.tyre_tests.empty()) summary.insert("tyre_tests", std::move(rig_summaries));
}

}  // namespace tirefem
