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

// Throws on failure (nothing is left in out_dir then). Returns the path of summary.json.
std::filesystem::path run_case(const Case& c, const RunOptions& options);

}  // namespace tirefem
