#pragma once
// The files of one study in the results folder: tables, VTU files and plots of a loaded state and of a
// rolling study, each report guarded so that one that cannot be drawn is skipped with a note.
#include <string>

#include <toml++/toml.h>
#include <vector>

#include "tirefem/analysis/footprint.hpp"
#include "tirefem/analysis/inflation.hpp"
#include "tirefem/analysis/rolling.hpp"
#include "tirefem/analysis/tyre_test.hpp"
#include "tirefem/analysis/tyre_test_fit.hpp"
#include "tirefem/analysis/run_case.hpp"
#include "tirefem/io/plot_writer.hpp"
#include "tirefem/io/results_folder.hpp"

namespace tirefem {

// Writes the plots (gnuplot may be missing: warn once; it renders in the background while the other files
// are written) and guards every report: a report that cannot be made (e.g. no ply, hence no cord tension
// to plot) is skipped with a note, never a failure that would discard the solve.
class ReportWriter {
 public:
  ReportWriter(const ResultsFolder& folder, const ProgressSink& progress) : folder_(folder), progress_(progress) {}
  void plot(const std::string& stem, const Plot& p);
  void heatmap(const std::string& stem, const HeatMap& m);
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
  // The reports skipped, once every plot started has been rendered (a failed render is a plot skipped).
  const std::vector<std::string>& skipped();

 private:
  void skip(const std::string& name, const std::string& why);
  void note(bool rendered);
  const ResultsFolder& folder_;
  ProgressSink progress_;
  bool warned_ = false;
  std::vector<std::string> skipped_;
  PlotRenderer renderer_;
};

// Everything about one loaded state: VTU of the shell and the support, the tread points, the pressure
// maps, the cord strains under the patch centre (Fig. 5) and the belt tension round the equator (Fig. 8).
void write_loaded_state(const ResultsFolder& folder, ReportWriter& plots, const TyreMesh& tm, const Case& c,
                        const StaticContactResult& r);

// A rolling study: the states and the sweep as tables, per state the tread points (CSV and point cloud),
// the loaded shell and the traction map (Fig. 7), and the belt tension of all states together with the
// inflated and the static one (Fig. 8).
void write_rolling(const ResultsFolder& folder, ReportWriter& plots, const TyreMesh& tm, const Case& c,
                   const RollingResult& r);

// A footprint study: NAME/load_points.csv, and when it completed its loaded state (write_loaded_state) and
// a progress line with its figures. Returns its summary.json entry.
toml::table report_footprint(const ResultsFolder& folder, ReportWriter& plots, const ProgressSink& progress,
                             const TyreMesh& tm, const Case& c, const StaticContactResult& r);

// A rolling study's files (write_rolling, on its own mesh `tm`); returns its summary.json entry.
toml::table report_rolling(const ResultsFolder& folder, ReportWriter& plots, const TyreMesh& tm, const Case& c,
                           const RollingResult& r);

// A tyre test: fits its Magic Formula (progress: the fit's errors and normalised figures), writes
// NAME/tyre_test.csv (the measurement table), NAME/vertical.csv, with a fit NAME/NAME.tir, and the plots of
// FX(κ), FY(α), MZ(α) at every load and of the vertical characteristic; returns its summary.json entry. A
// fit or a report that cannot be made is skipped with a note.
toml::table report_tyre_test(const ResultsFolder& folder, ReportWriter& plots, const ProgressSink& progress,
                             const Case& c, const TyreTestResult& t);

// The inflated state: inflation_meridian.csv, inflation.vtu and the meridian plots; progress: its figures
// and the rim flanges' loads. Returns its summary.json entry.
toml::table write_inflation(const ResultsFolder& folder, ReportWriter& plots, const ProgressSink& progress,
                            const TyreMesh& tm, const Case& c, const InflationResult& r);

// A solve's counters as summary.json keeps them ("solver" of each study); add_krylov adds the GMRES ones.
toml::table counters_table(const SolveCounters& c);
void add_krylov(toml::table& t, const SolveCounters& c);

}  // namespace tirefem
