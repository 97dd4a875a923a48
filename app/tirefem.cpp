// tirefem command line: thin — parse arguments, read the case, run, report errors in one line.
#include <cstdio>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "tirefem/analysis/run_case.hpp"
#include "tirefem/case/case_reader.hpp"
#include "tirefem/solver/blas_kernel.hpp"

int main(int argc, char** argv) {
  tirefem::use_fast_blas_kernel(argv);
  CLI::App app{"tirefem: finite-element contact of a car tyre with a road or a test drum"};
  app.require_subcommand(1);
  std::string case_file, out_dir = "results";
  bool quiet = false;

  auto* run = app.add_subcommand("run", "run the analyses of a case and write the results into a folder");
  run->add_option("case", case_file, "case file (TOML)")->required()->check(CLI::ExistingFile);
  run->add_option("-o,--out", out_dir, "results folder (replaced when the run succeeds)")->capture_default_str();
  run->add_flag("-q,--quiet", quiet, "no progress output");

  auto* check = app.add_subcommand("check", "validate a case file without solving");
  check->add_option("case", case_file, "case file (TOML)")->required()->check(CLI::ExistingFile);

  CLI11_PARSE(app, argc, argv);
  try {
    const tirefem::Case c = tirefem::read_case(case_file);
    if (*check) {
      fmt::print("{}: ok ({})\n", case_file, c.title);
      return 0;
    }
    tirefem::RunOptions options;
    options.out_dir = out_dir;
    if (!quiet) options.progress = [](const std::string& m) { fmt::print("{}\n", m); std::fflush(stdout); };
    const tirefem::RunOutcome outcome = tirefem::run_case(c, options);
    if (!quiet) fmt::print("results in {} (summary: {})\n", out_dir, outcome.summary.string());
    if (!outcome.completed) {
      fmt::print(stderr, "tirefem: some studies stopped short; see 'incomplete' in {}\n", outcome.summary.string());
      return 2;
    }
    return 0;
  } catch (const std::exception& e) {
    fmt::print(stderr, "tirefem: error: {}\n", e.what());
    return 1;
  }
}
