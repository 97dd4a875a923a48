// tirefem command line: thin — parse arguments, read the case, run, report errors in one line.
// Exit codes: 0 done, 1 bad case file or command line (nothing solved, nothing written), 2 a study stopped
// short (its converged results are in <out>-incomplete), 3 interrupted (nothing written), 4 the run failed
// (the inflation did not converge, or the results could not be written; nothing written).
#include <atomic>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <string>

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "tirefem/analysis/run_case.hpp"
#include "tirefem/case/case_reader.hpp"
#include "tirefem/io/results_folder.hpp"
#include "tirefem/solver/blas_kernel.hpp"
#include "tirefem/solver/heap_settings.hpp"

namespace {

enum ExitCode { kDone = 0, kBadInput = 1, kStoppedShort = 2, kInterrupted = 3, kRunFailed = 4 };

// Set by SIGINT/SIGTERM/SIGHUP; the run polls it between solver steps. A second signal ends the process
// at once (the next run removes its temporary folder). The user is told so at once: a step of a large
// model can take minutes (write(2) is safe in a signal handler, stdio is not).
std::atomic<bool> stop_signal{false};
constexpr char kStopMessage[] =
    "tirefem: stopping after the current solver step, without writing results (signal again to stop at once)\n";
extern "C" void on_stop_signal(int sig) {
  stop_signal = true;
  std::signal(sig, SIG_DFL);
  [[maybe_unused]] const ssize_t written = ::write(STDERR_FILENO, kStopMessage, sizeof kStopMessage - 1);
}

int error(int code, const std::string& message) {
  fmt::print(stderr, "tirefem: error: {}\n", message);
  return code;
}

// A case file that does not exist or is not a file: tirefem's own one-line message, not CLI11's.
std::string case_file_problem(const std::string& file) {
  std::error_code ec;
  const auto status = std::filesystem::status(file, ec);
  if (!std::filesystem::exists(status)) return fmt::format("case file '{}' does not exist", file);
  if (std::filesystem::is_directory(status)) return fmt::format("case file '{}' is a folder, not a file", file);
  return {};
}

}  // namespace

int main(int argc, char** argv) {
  tirefem::use_fast_blas_kernel(argv);
  tirefem::keep_freed_memory();
  CLI::App app{"tirefem: finite-element contact of a car tyre with a road or a test drum"};
  app.require_subcommand(1);
  std::string case_file, out_dir = "results";
  bool quiet = false, force = false;

  auto* run = app.add_subcommand("run", "run the analyses of a case and write the results into a folder");
  run->add_option("case", case_file, "case file (TOML)")->required();
  run->add_option("-o,--out", out_dir,
                  "results folder: a new or empty folder, or one tirefem wrote before (its results are "
                  "replaced when the run succeeds; nothing else in it is touched)")
      ->capture_default_str();
  run->add_flag("-f,--force", force,
                "also accept a non-empty folder tirefem did not write: the results are put beside its files");
  run->add_flag("-q,--quiet", quiet, "no progress output");

  auto* check = app.add_subcommand("check", "validate a case file without solving");
  check->add_option("case", case_file, "case file (TOML)")->required();

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    return error(kBadInput, fmt::format("{} (see tirefem --help)", e.what()));
  }
  if (const std::string problem = case_file_problem(case_file); !problem.empty()) return error(kBadInput, problem);

  tirefem::Case c;
  try {
    c = tirefem::read_case(case_file);
  } catch (const std::exception& e) {
    return error(kBadInput, e.what());
  }
  if (*check) {
    fmt::print("{}: ok ({})\n", case_file, c.title);
    return kDone;
  }

  for (int sig : {SIGINT, SIGTERM, SIGHUP}) std::signal(sig, on_stop_signal);
  tirefem::RunOptions options;
  options.out_dir = out_dir;
  options.force = force;
  options.stop_requested = [] { return stop_signal.load(); };
  if (!quiet) options.progress = [](const std::string& m) { fmt::print("{}\n", m); std::fflush(stdout); };
  try {
    const tirefem::RunOutcome outcome = tirefem::run_case(c, options);
    if (!outcome.completed) {
      fmt::print(stderr,
                 "tirefem: some studies stopped short; their converged results are in {} ('incomplete' in "
                 "summary.json says why); {} was left as it was\n",
                 outcome.results_dir.string(), out_dir);
      return kStoppedShort;
    }
    const bool elsewhere = outcome.results_dir != std::filesystem::absolute(out_dir).lexically_normal();
    if (elsewhere)
      fmt::print(stderr, "tirefem: a result's name is taken by a file in {}: the results went to {}\n", out_dir,
                 outcome.results_dir.string());
    else if (!quiet)
      fmt::print("results in {} (summary: {})\n", outcome.results_dir.string(), outcome.summary.string());
    return kDone;
  } catch (const tirefem::ResultsFolderError& e) {
    return error(kBadInput, fmt::format("--out: {}", e.what()));
  } catch (const tirefem::RunInterrupted&) {
    return error(kInterrupted, fmt::format("interrupted: nothing written ({} was left as it was)", out_dir));
  } catch (const std::exception& e) {
    return error(kRunFailed, e.what());
  }
}
