#pragma once
// Runs the analyses a case lists and writes every result into one folder (written to a temporary folder
// and moved into place only when the run succeeds).
#include <filesystem>

#include "tirefem/case/case.hpp"
#include "tirefem/solver/newton.hpp"

namespace tirefem {

struct RunOptions {
  std::filesystem::path out_dir = "results";
  ProgressSink progress;
};

struct RunOutcome {
  std::filesystem::path summary;  // summary.json
  bool completed = true;          // false when a load curve or footprint stopped short (its converged
                                  // points are written; summary.json says why)
};

// Throws on failure of the inflation or of the writers (nothing is left in out_dir then).
RunOutcome run_case(const Case& c, const RunOptions& options);

}  // namespace tirefem
