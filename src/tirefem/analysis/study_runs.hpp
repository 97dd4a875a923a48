#pragma once
// The studies' solves of one run (run_case), kept until their results are written, and their writing in
// the case's order, whatever order the studies ran in.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "tirefem/analysis/footprint.hpp"
#include "tirefem/analysis/rolling.hpp"
#include "tirefem/analysis/shared_states.hpp"
#include "tirefem/analysis/study_reports.hpp"
#include "tirefem/analysis/tyre_test.hpp"

namespace tirefem {

// One study's solve.
struct StudyRun {
  std::string phase;  // "load curve 'plane'", ...
  double seconds = 0.0;
  std::string error;  // the study threw: why
  std::optional<StaticContactResult> contact;
  std::optional<RollingResult> rolling;
};

// A tyre test's series at each load, in this order.
inline constexpr std::array kRigSeries{TyreTestSeries::longitudinal, TyreTestSeries::lateral};

// The studies' runs in the case's order: the load curves, the footprints, the rolling studies, then for
// each tyre test its loads' series (kRigSeries at each load) and its vertical curve.
inline int tyre_test_run_count(const Case& c) {
  int n = 0;
  for (const TyreTestStudy& s : c.tyre_tests) n += static_cast<int>(kRigSeries.size() * s.load_factors.size()) + 1;
  return n;
}

// Writes each study's tables, plots and VTU files into the folder and its entry into the summary
// ("load_curves", "footprints", "rolling", "tyre_tests"). A study that stopped short keeps what converged:
// it is reported as a warning and its message added to `incomplete`. The load curves' states are dropped
// once written.
void write_study_results(const Case& c, InflatedTyres& tyres, std::vector<StudyRun>& runs,
                         const ResultsFolder& folder, ReportWriter& plots, const ProgressSink& progress,
                         toml::table& summary, toml::array& incomplete);

}  // namespace tirefem
