// The command line end to end: the example case runs and writes every promised file; `check` accepts
// the example; bad input stops with a one-line error naming the field and writes nothing.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

namespace fs = std::filesystem;

namespace {

struct CliRun {
  int exit_code;
  std::string output;
};

CliRun run_cli(const std::string& args) {
  const fs::path log = fs::temp_directory_path() / ("tirefem_cli_" + std::to_string(::getpid()) + ".log");
  const std::string cmd = std::string(TIREFEM_CLI) + " " + args + " > " + log.string() + " 2>&1";
  const int status = std::system(cmd.c_str());
  std::ifstream in(log);
  std::stringstream ss;
  ss << in.rdbuf();
  fs::remove(log);
  return {WEXITSTATUS(status), ss.str()};
}

fs::path scratch(const std::string& name) {
  const fs::path p = fs::temp_directory_path() / ("tirefem_smoke_" + std::to_string(::getpid())) / name;
  fs::create_directories(p.parent_path());
  return p;
}

const std::string kExample = std::string(TIREFEM_SOURCE_DIR) + "/examples/175-70R13.toml";

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(Cli, CheckAcceptsTheExample) {
  const CliRun r = run_cli("check " + kExample);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("ok"), std::string::npos) << r.output;
}

TEST(Cli, RunWritesAllResultsOfTheExample) {
  const fs::path out = scratch("example");
  const CliRun r = run_cli("run " + kExample + " --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* f : {"summary.json", "inflation_meridian.csv", "inflation.vtu",
                        "plots/inflation_cord_tension.gp", "plots/inflation_cross_section.gp"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  const std::string summary = read_text(out / "summary.json");
  for (const char* key : {"\"dof\"", "\"elements\"", "\"wall_time_s\"", "\"crown_radius_growth_mm\"",
                          "\"section_width_growth_mm\"", "\"max_carcass_cord_force_N\"",
                          "\"max_belt_cord_force_N\"", "\"newton_iterations\""})
    EXPECT_NE(summary.find(key), std::string::npos) << key;
  EXPECT_NE(summary.find("\"converged\" : true"), std::string::npos);
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

}  // namespace
