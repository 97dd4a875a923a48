#pragma once
// Runs the analyses a case lists and writes every result into one folder (written to a temporary folder
// and moved into place only when the run succeeds).
#include <exception>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "tirefem/case/case.hpp"
#include "tirefem/solver/newton.hpp"

namespace tirefem {

struct RunOptions {
  std::filesystem::path out_dir = "results";
  bool force = false;  // accept a non-empty out_dir that tirefem did not write (see ResultsFolder)
  ProgressSink progress;
  // Polled between solver steps; true stops the run (RunInterrupted) without writing anything.
  std::function<bool()> stop_requested;
};

struct RunOutcome {
  std::filesystem::path results_dir;  // where the results went (see completed)
  std::filesystem::path summary;      // summary.json in it
  bool completed = true;  // false when a study stopped short or failed: its converged points and every
                          // other study's results are then in `<out_dir>-incomplete`, out_dir is left
                          // as it was, and summary.json says why
  std::vector<std::string> skipped_reports;  // reports that could not be drawn (noted, not fatal)
};

// The run was stopped by RunOptions::stop_requested (e.g. on SIGINT); nothing was written.
class RunInterrupted : public std::exception {
 public:
  const char* what() const noexcept override { return "interrupted"; }
};

// Throws ResultsFolderError (before solving) when out_dir cannot be used, RunInterrupted, and
// std::runtime_error when the inflation fails or the results cannot be written (nothing is left then).
RunOutcome run_case(const Case& c, const RunOptions& options);

}  // namespace tirefem
