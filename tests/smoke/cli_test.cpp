// The command line end to end: a case runs and writes every promised file; `check` accepts the example;
// bad input stops with a one-line error naming the field and writes nothing.
//
// The run uses tests/smoke/coarse_case.toml, the example on a 36 × 10 mesh with 4 points per load curve
// and all its studies (three load curves, one footprint): a few seconds instead of the minutes the
// example's 120 × 46 mesh takes. A separate test keeps the two cases in step (same studies and settings).
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tirefem/case/case_reader.hpp"

namespace fs = std::filesystem;

namespace {

struct CliRun {
  int exit_code;
  std::string output;
};

// Runs a shell command, its stdout and stderr captured together.
CliRun run_cli_command(const std::string& command) {
  const fs::path log = fs::temp_directory_path() / ("tirefem_cli_" + std::to_string(::getpid()) + ".log");
  const std::string cmd = "(" + command + ") > " + log.string() + " 2>&1";
  const int status = std::system(cmd.c_str());
  std::ifstream in(log);
  std::stringstream ss;
  ss << in.rdbuf();
  fs::remove(log);
  return {WEXITSTATUS(status), ss.str()};
}

CliRun run_cli(const std::string& args) { return run_cli_command(std::string(TIREFEM_CLI) + " " + args); }

fs::path scratch(const std::string& name) {
  const fs::path p = fs::temp_directory_path() / ("tirefem_smoke_" + std::to_string(::getpid())) / name;
  fs::create_directories(p.parent_path());
  return p;
}

const std::string kExample = std::string(TIREFEM_SOURCE_DIR) + "/examples/175-70R13.toml";
const std::string kCoarseCase = std::string(TIREFEM_SOURCE_DIR) + "/tests/smoke/coarse_case.toml";

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

bool gnuplot_on_path() { return std::system("command -v gnuplot > /dev/null 2>&1") == 0; }

// The raw value of a key of the outermost JSON object ("" when absent): the text after its colon up to the
// next ',' or '}' at that level, or the opening bracket of an array / object value.
std::string top_level_value(const std::string& json, const std::string& key) {
  int depth = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < json.size(); ++i) {
    const char c = json[i];
    if (in_string) {
      if (c == '\\') ++i;
      else if (c == '"') in_string = false;
      continue;
    }
    if (c == '{' || c == '[') ++depth;
    else if (c == '}' || c == ']') --depth;
    else if (c == '"') {
      const std::size_t end = json.find('"', i + 1);
      if (depth == 1 && json.compare(i + 1, end - i - 1, key) == 0) {
        std::size_t v = json.find(':', end) + 1;
        while (v < json.size() && std::isspace(static_cast<unsigned char>(json[v]))) ++v;
        if (json[v] == '[' || json[v] == '{') return std::string(1, json[v]);
        std::size_t e = v;
        while (e < json.size() && json[e] != ',' && json[e] != '}' && json[e] != '\n') ++e;
        std::string value = json.substr(v, e - v);
        while (!value.empty() && std::isspace(static_cast<unsigned char>(value.back()))) value.pop_back();
        return value;
      }
      in_string = true;
    }
  }
  return "";
}

TEST(Cli, CheckAcceptsTheExample) {
  const CliRun r = run_cli("check " + kExample);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("ok"), std::string::npos) << r.output;
}

TEST(Cli, CheckAcceptsTheCorneringExample) {
  const CliRun r = run_cli("check " + std::string(TIREFEM_SOURCE_DIR) + "/examples/175-70R13-cornering.toml");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("ok"), std::string::npos) << r.output;
}

// A cornering study writes its tables, plots and the W-axis figures of every state to the summary.
TEST(Cli, RunWritesTheCorneringResults) {
  const fs::path out = scratch("cornering");
  const CliRun r = run_cli("run " + std::string(TIREFEM_SOURCE_DIR) + "/tests/smoke/cornering_case.toml --out " +
                           out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* f : {"cornering/states.csv", "cornering/angle_sweep.csv", "cornering/combined_slip.csv",
                        "cornering/alpha_+2/tread_points.vtu", "plots/cornering_lateral_force.gp",
                        "plots/cornering_aligning_moment.gp", "plots/cornering_friction_ellipse.gp"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  const std::string summary = read_text(out / "summary.json");
  for (const char* key : {"\"slip_angle_deg\"", "\"camber_deg\"", "\"Fx_N\"", "\"Fy_N\"", "\"Fz_N\"",
                          "\"Mz_Nmm\"", "\"overturning_moment_Nmm\"", "\"pneumatic_trail_mm\"", "\"mu\"",
                          "\"angle_sweep\"", "\"combined\"", "\"cornering_stiffness_N_per_deg\"",
                          "\"tread_shear\" : \"planar\"",
                          // α = −2° of the sweep: the mirror image of +2° (the tyre is its own, camber 0)
                          "\"mirrored\" : true"})
    EXPECT_NE(summary.find(key), std::string::npos) << key;
  const std::string vtu = read_text(out / "cornering/alpha_+2/tread_points.vtu");
  EXPECT_NE(vtu.find("tangential_stress_MPa"), std::string::npos);
  EXPECT_EQ(top_level_value(summary, "completed"), "true") << r.output;
  fs::remove_all(out.parent_path());
}

TEST(Cli, CheckAcceptsTheCoarseCase) {
  const CliRun r = run_cli("check " + kCoarseCase);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("ok"), std::string::npos) << r.output;
}

// The coarse case is the example with a coarser mesh and fewer load points, nothing else that the run
// depends on: same tyre, inflation, contact settings and studies.
TEST(Cli, CoarseCaseKeepsInStepWithTheExample) {
  const tirefem::Case example = tirefem::read_case(kExample);
  const tirefem::Case coarse = tirefem::read_case(kCoarseCase);
  EXPECT_EQ(coarse.mesh.circumferential_elements, 36);
  EXPECT_EQ(coarse.mesh.meridional_elements, 10);
  EXPECT_EQ(coarse.mesh.half_model, example.mesh.half_model);
  EXPECT_EQ(coarse.mesh.circumferential_refinement, example.mesh.circumferential_refinement);
  EXPECT_EQ(coarse.title, example.title);
  EXPECT_EQ(coarse.tyre.name, example.tyre.name);
  EXPECT_EQ(coarse.tyre.zones.size(), example.tyre.zones.size());
  EXPECT_EQ(coarse.tyre.profile.size(), example.tyre.profile.size());
  EXPECT_EQ(coarse.tyre.tread_stiffness, example.tyre.tread_stiffness);
  EXPECT_EQ(coarse.tyre.tread_end_s, example.tyre.tread_end_s);
  EXPECT_EQ(coarse.inflation.pressure, example.inflation.pressure);
  EXPECT_EQ(coarse.inflation.linear, example.inflation.linear);
  EXPECT_EQ(coarse.contact.iteration, example.contact.iteration);
  EXPECT_EQ(coarse.contact.quadrature, example.contact.quadrature);
  EXPECT_EQ(coarse.contact.reuse_factorizations, example.contact.reuse_factorizations);
  EXPECT_EQ(coarse.contact.residual_tolerance, example.contact.residual_tolerance);
  // equilibrium differs on purpose: see coarse_case.toml.
  ASSERT_EQ(coarse.load_curves.size(), example.load_curves.size()) << "the coarse case must keep all load curves";
  for (std::size_t i = 0; i < example.load_curves.size(); ++i) {
    const auto &a = coarse.load_curves[i], &b = example.load_curves[i];
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.support.kind, b.support.kind) << a.name;
    EXPECT_EQ(a.support.drum_diameter, b.support.drum_diameter) << a.name;
    EXPECT_EQ(a.linear, b.linear) << a.name;
    EXPECT_EQ(a.max_deflection, b.max_deflection) << a.name;
    EXPECT_EQ(a.points, 4) << a.name;
  }
  ASSERT_EQ(coarse.footprints.size(), example.footprints.size()) << "the coarse case must keep all footprints";
  for (std::size_t i = 0; i < example.footprints.size(); ++i) {
    const auto &a = coarse.footprints[i], &b = example.footprints[i];
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.support.kind, b.support.kind) << a.name;
    EXPECT_EQ(a.linear, b.linear) << a.name;
    EXPECT_EQ(a.target_load, b.target_load) << a.name;
    EXPECT_EQ(a.load_tolerance, b.load_tolerance) << a.name;
  }
  ASSERT_EQ(coarse.rolling.size(), example.rolling.size()) << "the coarse case must keep all rolling studies";
  for (std::size_t i = 0; i < example.rolling.size(); ++i) {
    const auto &a = coarse.rolling[i], &b = example.rolling[i];
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.support.kind, b.support.kind) << a.name;
    EXPECT_EQ(a.friction, b.friction) << a.name;
    EXPECT_EQ(a.target_load, b.target_load) << a.name;
    ASSERT_EQ(a.states.size(), b.states.size()) << a.name;
    for (std::size_t k = 0; k < a.states.size(); ++k) {
      EXPECT_EQ(a.states[k].kind, b.states[k].kind) << a.name;
      EXPECT_EQ(a.states[k].name, b.states[k].name) << a.name;
      EXPECT_EQ(a.states[k].slip, b.states[k].slip) << a.name;
    }
    EXPECT_EQ(a.sweep.has_value(), b.sweep.has_value()) << a.name;
  }
}

TEST(Cli, RunWritesAllResultsOfTheCoarseCase) {
  const fs::path out = scratch("coarse");
  const CliRun r = run_cli("run " + kCoarseCase + " --out " + out.string());
  // Exit code 2: a load curve or the footprint stopped short (its converged points are written).
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* f : {"summary.json", "inflation_meridian.csv", "inflation.vtu", "plots/inflation_cord_tension.gp",
                        "plots/inflation_cross_section.gp", "load_curve_plane.csv", "load_curve_drum.csv",
                        "load_curve_plane_linear.csv", "plots/load_characteristic.gp",
                        "footprint_3700N/shell.vtu", "footprint_3700N/support.vtu",
                        "footprint_3700N/tread_points.csv", "footprint_3700N/meridian_under_patch.csv",
                        "footprint_3700N/belt_tension_equator.csv", "plots/footprint_3700N_footprint.gp",
                        "plots/footprint_3700N_pressure_s_phi.gp", "plots/footprint_3700N_cord_strain.gp",
                        "plots/footprint_3700N_belt_tension.gp", "rolling_plane/states.csv",
                        "rolling_plane/slip_sweep.csv", "rolling_plane/belt_tension_equator.csv",
                        "rolling_plane/footprint_load_points.csv", "rolling_plane/traction/tread_points.csv",
                        "rolling_plane/traction/tread_points.vtu", "rolling_plane/traction/shell.vtu",
                        "rolling_plane/full_slip_spinning/tread_points.csv", "plots/rolling_plane_slip_curve.gp",
                        "plots/rolling_plane_traction_traction.gp", "plots/rolling_plane_belt_tension.gp",
                        "rolling_drum/states.csv", "rolling_drum/traction/tread_points.csv"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  // Plots are rendered only when gnuplot is on PATH (otherwise the scripts above are all there is).
  if (gnuplot_on_path()) {
    for (const char* f : {"plots/load_characteristic.png", "plots/load_characteristic.svg",
                          "plots/footprint_3700N_footprint.png", "plots/footprint_3700N_pressure_s_phi.png",
                          "plots/footprint_3700N_cord_strain.png", "plots/footprint_3700N_belt_tension.png",
                          "plots/rolling_plane_slip_curve.png", "plots/rolling_plane_traction_traction.png",
                          "plots/rolling_plane_belt_tension.png"})
      EXPECT_TRUE(fs::exists(out / f)) << f;
  } else {
    std::printf("  gnuplot is not on PATH: rendered plots not checked\n");
  }
  const std::string summary = read_text(out / "summary.json");
  for (const char* key : {"\"dof\"", "\"elements\"", "\"wall_time_s\"", "\"crown_radius_growth_mm\"",
                          "\"section_width_growth_mm\"", "\"max_carcass_cord_force_N\"",
                          "\"max_belt_cord_force_N\"", "\"newton_iterations\""})
    EXPECT_NE(summary.find(key), std::string::npos) << key;
  EXPECT_NE(summary.find("\"converged\" : true"), std::string::npos);
  EXPECT_NE(summary.find("\"faces\" : \"compatible\""), std::string::npos) << "summary.json: mesh.faces";
  EXPECT_EQ(top_level_value(summary, "load_curves"), "[") << "summary.json: load_curves must be an array";
  EXPECT_EQ(top_level_value(summary, "footprints"), "[") << "summary.json: footprints must be an array";
  EXPECT_EQ(top_level_value(summary, "rolling"), "[") << "summary.json: rolling must be an array";
  for (const char* key : {"\"effective_rolling_radius_mm\"", "\"slip_stiffness_N\"", "\"Qy_N\"", "\"Mx_Nmm\"",
                          "\"stick_area_fraction\"", "\"loaded_radius_mm\"", "\"full_slip\""})
    EXPECT_NE(summary.find(key), std::string::npos) << key;
  EXPECT_EQ(top_level_value(summary, "completed"), "true") << "summary.json: every study must have completed";
  fs::remove_all(out.parent_path());
}

TEST(Cli, BadCaseNamesTheFieldAndWritesNothing) {
  std::string text = read_text(kExample);
  const std::string key = "circumferential_elements = 120";
  const auto pos = text.find(key);
  ASSERT_NE(pos, std::string::npos) << "the example no longer sets " << key;
  text.replace(pos, key.size(), "circumferential_elements = 0");
  const fs::path bad = scratch("bad.toml");
  std::ofstream(bad) << text;
  const fs::path out = scratch("bad_out");
  const CliRun r = run_cli("run " + bad.string() + " --out " + out.string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("circumferential_elements"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out));
  const CliRun c = run_cli("check " + bad.string());
  EXPECT_NE(c.exit_code, 0);
  EXPECT_NE(c.output.find("circumferential_elements"), std::string::npos) << c.output;
  fs::remove_all(out.parent_path());
}

TEST(Cli, MissingFileIsAnError) {
  const CliRun r = run_cli("run /nonexistent/case.toml");
  EXPECT_NE(r.exit_code, 0);
}


CliRun run_cli_in(const fs::path& cwd, const std::string& args, bool prefix_cli = true);

// ------------------------------------------------------------------------------------- determinism
// A results file without what legitimately differs between runs: CSV columns of times, summary.json
// lines of times and of thread counts.
std::string without_timings(const fs::path& file) {
  std::istringstream in(read_text(file));
  std::ostringstream out;
  std::string line;
  std::vector<bool> keep;  // per CSV column
  const bool csv = file.extension() == ".csv", json = file.extension() == ".json";
  while (std::getline(in, line)) {
    if (json && (line.find("time") != std::string::npos || line.find("threads\"") != std::string::npos)) continue;
    if (!csv || line.starts_with("#")) {
      out << line << '\n';
      continue;
    }
    std::vector<std::string> cells;
    std::stringstream cs(line);
    for (std::string cell; std::getline(cs, cell, ',');) cells.push_back(cell);
    if (keep.empty())
      for (const std::string& h : cells) keep.push_back(h.find("time") == std::string::npos);
    for (std::size_t i = 0; i < cells.size(); ++i)
      if (i >= keep.size() || keep[i]) out << cells[i] << ',';
    out << '\n';
  }
  return out.str();
}

// Two runs of the coarse case, one with one thread and one with two, write the same numbers: every CSV,
// VTU, plot data file and summary.json, times apart. With two threads the inflation assembles on two and
// the studies then run side by side, one thread each. The BLAS is kept on one thread in both runs: its
// own round-off depends on its thread count, and the studies side by side run it on one.
TEST(Cli, RunsAreBitIdenticalWhateverTheAssemblyThreads) {
  const fs::path work = scratch("determinism");
  fs::create_directories(work);
  fs::copy_file(kCoarseCase, work / "case.toml", fs::copy_options::overwrite_existing);
  for (const std::string threads : std::vector<std::string>{"1", "2"}) {
    const CliRun r = run_cli_in(work, "OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=" + threads + " " + TIREFEM_CLI +
                                          " run case.toml -q --out run" + threads, /*prefix_cli=*/false);
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  int compared = 0;
  for (const auto& e : fs::recursive_directory_iterator(work / "run1")) {
    const std::string ext = e.path().extension().string();
    if (!e.is_regular_file() || ext == ".png" || ext == ".svg") continue;
    const fs::path other = work / "run2" / fs::relative(e.path(), work / "run1");
    ASSERT_TRUE(fs::exists(other)) << other;
    EXPECT_EQ(without_timings(e.path()), without_timings(other)) << fs::relative(e.path(), work / "run1");
    ++compared;
  }
  EXPECT_GT(compared, 40);
  fs::remove_all(work);
}

// ---------------------------------------------------------------------------------- the output folder
// Cases cut from the coarse case: up to its first study (the inflation alone, about a second), plus one
// load curve whose contact Newton may stop at once (a study that stops short).
std::string coarse_up_to_first_study() {
  const std::string text = read_text(kCoarseCase);
  return text.substr(0, text.find("[[load_curve]]"));
}

fs::path write_case(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << text;
  return file;
}

// `tirefem ARGS` run in folder `cwd`.
CliRun run_cli_in(const fs::path& cwd, const std::string& args, bool prefix_cli) {
  return run_cli_command("cd '" + cwd.string() + "' && " + (prefix_cli ? std::string(TIREFEM_CLI) + " " : "") + args);
}

bool has_hidden_leftovers(const fs::path& dir) {
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().find(".tmp-") != std::string::npos ||
        e.path().filename().string().find(".old-") != std::string::npos)
      return true;
  return false;
}

TEST(CliOutputFolder, NeverDeletesTheUsersFiles) {
  const fs::path work = scratch("folder_policy");
  const fs::path case_file = write_case(work / "case.toml", coarse_up_to_first_study());
  std::ofstream(work / "notes.txt") << "mine\n";

  // A new folder, then the same folder again with a file of the user's added: the file stays.
  ASSERT_EQ(run_cli_in(work, "run case.toml --out res -q").exit_code, 0);
  EXPECT_TRUE(fs::exists(work / "res" / ".tirefem-results"));
  std::ofstream(work / "res" / "my_notes.txt") << "mine\n";
  const CliRun again = run_cli_in(work, "run case.toml --out res -q");
  EXPECT_EQ(again.exit_code, 0) << again.output;
  EXPECT_EQ(read_text(work / "res" / "my_notes.txt"), "mine\n");
  EXPECT_TRUE(fs::exists(work / "res" / "summary.json"));

  // The current folder, its parent, the case file's folder and a file are refused before solving.
  for (const std::string out : std::vector<std::string>{".", "..", "./", work.string(), "case.toml", "notes.txt"}) {
    const CliRun r = run_cli_in(work, "run case.toml -q --force --out " + out);
    EXPECT_EQ(r.exit_code, 1) << out << ": " << r.output;
    EXPECT_NE(r.output.find("--out"), std::string::npos) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << "one line: " << r.output;
  }
  EXPECT_EQ(read_text(work / "notes.txt"), "mine\n");
  EXPECT_TRUE(fs::exists(work / "case.toml"));

  // A folder tirefem did not write: refused; with --force the results go beside the user's files.
  fs::create_directories(work / "user" / "sub");
  std::ofstream(work / "user" / "data.txt") << "mine\n";
  EXPECT_EQ(run_cli_in(work, "run case.toml -q --out user").exit_code, 1);
  EXPECT_EQ(run_cli_in(work, "run case.toml -q --out user --force").exit_code, 0);
  EXPECT_EQ(read_text(work / "user" / "data.txt"), "mine\n");
  EXPECT_TRUE(fs::exists(work / "user" / "sub"));
  EXPECT_TRUE(fs::exists(work / "user" / "summary.json"));
  EXPECT_FALSE(has_hidden_leftovers(work));
  fs::remove_all(work);
}

TEST(CliOutputFolder, StoppedShortRunLeavesTheLastResultsAndSaysWhere) {
  const fs::path work = scratch("stopped_short");
  std::string text = coarse_up_to_first_study();
  write_case(work / "case.toml", text);
  ASSERT_EQ(run_cli_in(work, "run case.toml --out res -q").exit_code, 0);
  const std::string complete_summary = read_text(work / "res" / "summary.json");
  // One Newton iteration per contact solve cannot converge: the load curve stops short at its first point.
  const std::string key = "max_newton_iterations = 25";
  const auto contact = text.find("[contact]");
  ASSERT_NE(contact, std::string::npos);
  const auto pos = text.find(key, contact);
  ASSERT_NE(pos, std::string::npos) << "the coarse case no longer sets contact." << key;
  text.replace(pos, key.size(), "max_newton_iterations = 1");
  text += "\n[[load_curve]]\nname = \"plane\"\nsupport = { kind = \"plane\" }\nmax_deflection = 10.0\npoints = 2\n";
  write_case(work / "short.toml", text);
  const CliRun r = run_cli_in(work, "run short.toml --out res -q");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("res-incomplete"), std::string::npos) << r.output;
  EXPECT_EQ(read_text(work / "res" / "summary.json"), complete_summary) << "the complete results were replaced";
  const std::string partial = read_text(work / "res-incomplete" / "summary.json");
  EXPECT_EQ(top_level_value(partial, "completed"), "false");
  EXPECT_NE(partial.find("plane"), std::string::npos);
  EXPECT_TRUE(fs::exists(work / "res-incomplete" / "inflation_meridian.csv")) << "the converged inflation is kept";
  EXPECT_FALSE(has_hidden_leftovers(work));
  fs::remove_all(work);
}

TEST(CliOutputFolder, InterruptCleansUpAndExitsWith3) {
  const fs::path work = scratch("interrupt");
  fs::create_directories(work);
  fs::copy_file(kCoarseCase, work / "case.toml", fs::copy_options::overwrite_existing);
  // Interrupt once the contact studies are under way (after the inflation), as a user's Ctrl-C would.
  const std::string script =
      "cd '" + work.string() + "' && (" + TIREFEM_CLI + " run case.toml --out res > log.txt 2>&1 & pid=$!; "
      "for i in $(seq 600); do grep -q \"load curve\" log.txt 2>/dev/null && break; sleep 0.1; done; "
      "kill -INT $pid; wait $pid; echo \"exit=$?\")";
  const CliRun r = run_cli_command(script);
  EXPECT_NE(r.output.find("exit=3"), std::string::npos) << r.output << read_text(work / "log.txt");
  EXPECT_NE(read_text(work / "log.txt").find("interrupted"), std::string::npos);
  EXPECT_NE(read_text(work / "log.txt").find("stopping after the current solver step"), std::string::npos)
      << "the signal is acknowledged at once";
  EXPECT_FALSE(fs::exists(work / "res"));
  EXPECT_FALSE(has_hidden_leftovers(work)) << "the temporary folder was left behind";
  fs::remove_all(work);
}

TEST(Cli, MissingOrFolderCaseFileIsAOneLineError) {
  for (const std::string args : std::vector<std::string>{"check /nonexistent/case.toml", "run /nonexistent/case.toml", "check /tmp"}) {
    const CliRun r = run_cli(args);
    EXPECT_EQ(r.exit_code, 1) << args;
    EXPECT_EQ(r.output.rfind("tirefem: error: case file", 0), 0u) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  }
}

// A tyre without plies has no cord tension to plot: the report is skipped with a note, the solve is kept.
TEST(Cli, ATyreWithoutPliesWritesItsResults) {
  const fs::path work = scratch("no_plies");
  std::string text = coarse_up_to_first_study();
  auto replace_all = [&](const std::string& from, const std::string& to) {
    for (auto p = text.find(from); p != std::string::npos; p = text.find(from, p + to.size()))
      text.replace(p, from.size(), to);
  };
  replace_all(R"(inner = { plies = ["carcass", "carcass"] })", "inner = { rubber = { E = 40.0, nu = 0.49, thickness = 2.0 } }");
  replace_all(R"(outer = { plies = ["belt1", "belt2"], bending_stiffness = [100.0, 300.0] })",
              "outer = { rubber = { E = 60.0, nu = 0.49, thickness = 2.4 }, bending_stiffness = [100.0, 300.0] }");
  ASSERT_EQ(text.find("{ plies = ["), std::string::npos) << "the coarse case's zones changed";
  write_case(work / "case.toml", text);
  const CliRun r = run_cli_in(work, "run case.toml --out res");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("skipped"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::exists(work / "res" / "inflation_meridian.csv"));
  EXPECT_NE(read_text(work / "res" / "summary.json").find("skipped_reports"), std::string::npos);
  fs::remove_all(work);
}

}  // namespace
