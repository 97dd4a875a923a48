// The virtual rig end to end (issue 12): tests/smoke/tyre_test_case.toml runs a small [[tyre_test]] (2 loads,
// 7 slips, 7 slip angles, a cambered state, a 4 × 2 combined-slip grid, a vertical curve) on a coarse full mesh; the run must write the
// measurement table in SI units and W-axis signs, the plots, and a PAC2002 .tir that reads back, whose fit
// passes through the FE points (RMS below 3% of the peak for Fx and Fy, 10% for Mz: issue 12's criteria),
// with the signs of the W axes (braking Fx < 0, α > 0 gives Fy < 0 and PKY1 < 0). The tyre is its own mirror image, so its κ
// series runs on the half model: Fy, Mz and Mx of the straight-ahead rows are 0 to round-off.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tirefem/magic_formula/evaluator.hpp"
#include "tirefem/magic_formula/tir_reader.hpp"

namespace fs = std::filesystem;

namespace {

fs::path rig_scratch() {
  const fs::path p = fs::temp_directory_path() / ("tirefem_rig_smoke_" + std::to_string(::getpid()));
  fs::create_directories(p);
  return p / "out";
}

// The CSV's data rows by column name (comment lines skipped).
std::vector<std::map<std::string, double>> read_table(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::vector<std::string> columns;
  std::vector<std::map<std::string, double>> rows;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::stringstream ss(line);
    std::string cell;
    if (columns.empty()) {
      while (std::getline(ss, cell, ',')) columns.push_back(cell);
      continue;
    }
    std::map<std::string, double> row;
    for (std::size_t k = 0; std::getline(ss, cell, ','); ++k) row[columns.at(k)] = std::stod(cell);
    rows.push_back(row);
  }
  return rows;
}

// "relative_rms" of the channel in summary.json's fit errors (the JSON is written one key per line).
double fit_error(const std::string& summary, const std::string& channel) {
  const auto at = summary.find("\"channel\" : \"" + channel + "\"");
  if (at == std::string::npos) return -1;
  const auto start = summary.rfind('{', at), end = summary.find('}', at);
  const std::string entry = summary.substr(start, end - start);
  const auto key = entry.find("\"relative_rms\" : ");
  return key == std::string::npos ? -1 : std::stod(entry.substr(key + 17));
}

TEST(CliTyreTest, RigWritesTheTableAndAFittedTirFile) {
  const fs::path out = rig_scratch();
  const std::string command = std::string(TIREFEM_CLI) + " run " + TIREFEM_SOURCE_DIR +
                              "/tests/smoke/tyre_test_case.toml --quiet --out " + out.string() + " > " +
                              (out.parent_path() / "log").string() + " 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0);
  for (const char* f : {"rig/tyre_test.csv", "rig/vertical.csv", "rig/rig.tir", "plots/rig_fx_kappa.gp",
                        "plots/rig_fy_alpha.gp", "plots/rig_mz_alpha.gp", "plots/rig_vertical.gp", "rig/loads.csv",
                        "plots/rig_relaxation.gp", "plots/rig_combined.gp"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  const auto rows = read_table(out / "rig/tyre_test.csv");
  ASSERT_EQ(rows.size(), 2u * (1 + 1 + 7 + 7 + 8));
  int braking = 0, positive_alpha = 0, cambered = 0, combined = 0;
  for (const auto& r : rows) {
    // SI: N; held at the load (the sweeps and the cambered state within the load tolerance, 1e-3; the
    // straight-ahead free rolling, at the footprint's δz, within 2e-3)
    const bool held = r.at("GAMMA") != 0 || r.at("KAPPA") != 0 || r.at("ALPHA") != 0;
    EXPECT_NEAR(r.at("FZ"), r.at("TARGET_FZ"), (held ? 1e-3 : 2e-3) * r.at("TARGET_FZ") + 1e-9);
    if (r.at("KAPPA") < -1e-9 && r.at("ALPHA") == 0) {
      ++braking;
      EXPECT_LT(r.at("FX"), 0) << "braking gives Fx < 0";
    }
    if (r.at("GAMMA") != 0) {
      // The cambered free-rolling state (solved in the lateral series, on the full model): γ = +2° in
      // radians, and its camber thrust Fy < 0 in the W axes (test Cornering.OppositeCambersMirrorTheForces).
      ++cambered;
      EXPECT_NEAR(r.at("GAMMA"), 2.0 * 3.14159265358979 / 180.0, 1e-12);
      EXPECT_EQ(r.at("SERIES"), 3.0);
      EXPECT_EQ(r.at("ALPHA"), 0.0);
      EXPECT_LT(r.at("FY"), 0.0);
    }
    if (r.at("ALPHA") == 0 && r.at("GAMMA") == 0) {
      // The longitudinal series on the half model (the tyre is its own mirror image): no lateral force
      // or moment about z or x beyond round-off (on the full model the example's rig gave |Fy| up to
      // 3.6 N, |Mz| 0.35 N·m, |Mx| 0.27 N·m; on the half model 4e-13 N, 2e-14 N·m).
      EXPECT_LE(std::abs(r.at("FY")), 1e-9 * r.at("FZ"));
      EXPECT_LE(std::abs(r.at("MZ")), 1e-9 * r.at("FZ"));
      EXPECT_LE(std::abs(r.at("MX")), 1e-9 * r.at("FZ"));
    }
    if (r.at("SERIES") == 4.0) {
      // The combined-slip grid (κ ±0.015, ±0.03 × α 1.5°, 3°), Fz held: both forces, each with its own sign.
      ++combined;
      EXPECT_NE(r.at("KAPPA"), 0.0);
      EXPECT_GT(r.at("ALPHA"), 0.0);
      EXPECT_EQ(r.at("FX") > 0, r.at("KAPPA") > 0);
      EXPECT_LT(r.at("FY"), 0.0);
      continue;
    }
    if (r.at("ALPHA") > 1e-9) {
      ++positive_alpha;
      EXPECT_LT(r.at("FY"), 0) << "α > 0 gives Fy < 0 in the W axes";
      EXPECT_GT(r.at("MZ"), 0) << "and an aligning moment Mz > 0";
      EXPECT_LT(r.at("ALPHA"), 0.2) << "in radians";
      EXPECT_LT(std::abs(r.at("MZ")), 100.0) << "in N·m";
    }
    EXPECT_GT(r.at("RL"), 0.25);  // m
    EXPECT_LT(r.at("RL"), 0.29);
  }
  EXPECT_EQ(braking, 2 * 3);
  EXPECT_EQ(cambered, 2);
  EXPECT_EQ(positive_alpha, 2 * 3);
  EXPECT_EQ(combined, 2 * 8);
  const tirefem::TirFile tir = tirefem::read_tir_file(out / "rig/rig.tir");
  const tirefem::MagicFormulaCoefficients& c = tir.coefficients;
  EXPECT_EQ(c.FNOMIN, 2000.0);
  EXPECT_NEAR(c.UNLOADED_RADIUS, 0.285, 1e-9);
  EXPECT_LT(c.PKY1, 0);
  EXPECT_GT(c.PKX1, 0);
  EXPECT_GT(c.VERTICAL_STIFFNESS, 1e5);  // N/m
  EXPECT_LT(c.VERTICAL_STIFFNESS, 3e5);
  // The relaxation lengths from the standing tyre's stiffness (two loads: PTX3 not determined): positive,
  // and at each load the file gives back the lengths the rig measured (σ = K/C, in the summary).
  EXPECT_GT(c.PTX1, 0);
  EXPECT_GT(c.PTY1, 0);
  EXPECT_GT(c.PTY2, 0);
  {
    std::ifstream tir_text(out / "rig/rig.tir");
    std::string line;
    bool ptx3_flagged = false, combined_flagged = false, rolling_resistance_flagged = false;
    bool radius_as_entered = false;
    const auto flagged = [&](const char* key, const char* why) {
      return line.rfind(key, 0) == 0 && line.find(why) != std::string::npos;
    };
    while (std::getline(tir_text, line)) {
      ptx3_flagged = ptx3_flagged || flagged("PTX3", "not determined");
      // The combined-slip grid gives the weighting functions' slope and shape; their shifts stay neutral.
      combined_flagged = combined_flagged || flagged("RHX1 ", "not determined by the test's combined-slip points");
      EXPECT_FALSE(flagged("RBX1 ", "not determined") || flagged("RBY1 ", "not determined")) << line;
      rolling_resistance_flagged = rolling_resistance_flagged || flagged("QSY1 ", "no rolling resistance");
      // The case's 285 mm, printed as the user would write it (not 0.28500000000000003).
      radius_as_entered = radius_as_entered || (line.rfind("UNLOADED_RADIUS ", 0) == 0 &&
                                                line.find("= 0.285 ") != std::string::npos);
    }
    EXPECT_TRUE(radius_as_entered);
    EXPECT_TRUE(ptx3_flagged);
    EXPECT_TRUE(combined_flagged);
    EXPECT_TRUE(rolling_resistance_flagged);
  }
  std::ifstream in(out / "summary.json");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string summary = ss.str();
  EXPECT_NE(summary.find("\"tir_file\" : \"rig/rig.tir\""), std::string::npos);
  const double fx = fit_error(summary, "Fx"), fy = fit_error(summary, "Fy"), mz = fit_error(summary, "Mz");
  std::printf("  fit RMS of peak: Fx %.4f, Fy %.4f, Mz %.4f; PKX1 %.2f, PKY1 %.2f\n", fx, fy, mz, c.PKX1, c.PKY1);
  EXPECT_GE(fx, 0);
  EXPECT_LT(fx, 0.03);
  EXPECT_GE(fy, 0);
  EXPECT_LT(fy, 0.03);
  EXPECT_GE(mz, 0);
  EXPECT_LT(mz, 0.10);
  // The combined-slip surfaces through the grid's points within 5% of their peak (observed 2.4% and 2.1%),
  // and the file's Fx at κ 0.03 falls with α and keeps its sign (0 ≤ Gxα ≤ 1) up to 12°, as Fy at α 3°
  // with κ up to 0.15.
  const double fxc = fit_error(summary, "Fx combined"), fyc = fit_error(summary, "Fy combined");
  std::printf("  combined slip fit RMS of peak: Fx %.4f, Fy %.4f; RBX1 %.2f RCX1 %.2f RBY1 %.2f RCY1 %.2f\n", fxc, fyc,
              c.RBX1, c.RCX1, c.RBY1, c.RCY1);
  EXPECT_GE(fxc, 0);
  EXPECT_LT(fxc, 0.05);
  EXPECT_GE(fyc, 0);
  EXPECT_LT(fyc, 0.05);
  {
    using tirefem::SlipCombination;
    const auto at = [&](double kappa, double alpha_deg) {
      return tirefem::evaluate_magic_formula(c, {2000.0, kappa, alpha_deg * M_PI / 180, 0.0}, SlipCombination::combined);
    };
    double previous = at(0.03, 0.0).Fx;
    for (double a = 1.0; a <= 12.0; a += 1.0) {
      const double fx_at = at(0.03, a).Fx;
      EXPECT_GE(fx_at, 0.0) << a;
      EXPECT_LE(fx_at, previous) << a;
      previous = fx_at;
    }
    const double pure = at(0.0, 3.0).Fy;
    for (double k = 0.01; k <= 0.15; k += 0.01) {
      EXPECT_LE(at(k, 3.0).Fy, 0.0) << k;
      EXPECT_LE(std::abs(at(k, 3.0).Fy), std::abs(pure) * (1 + 1e-12)) << k;
    }
  }
  const double sk = fit_error(summary, "sigma_kappa"), sa = fit_error(summary, "sigma_alpha");
  EXPECT_GE(sk, 0);
  EXPECT_LT(sk, 1e-9);  // two loads, two coefficients each
  // σα here grows faster than Fz (118 mm at 1000 N, 257 mm at 2000 N on this coarse mesh: ×2.17), which
  // PAC2002's PTY1 sin(2 atan(Fz/(PTY2 Fz0))) cannot (at most ×2 for twice the load, as PTY2 → ∞): PTY2
  // then sits at its bound, 20, and the fit's error is reported (observed 2.6% of the peak); a σα that
  // grew at most in proportion would be fitted exactly.
  const auto loads = read_table(out / "rig/loads.csv");
  ASSERT_EQ(loads.size(), 2u);
  const double growth = loads[1].at("lateral_relaxation_length_mm") / loads[0].at("lateral_relaxation_length_mm");
  const double load_ratio = loads[1].at("Fz_N") / loads[0].at("Fz_N");
  std::printf("  sigma_alpha x%.3f for Fz x%.3f; PTY2 %.4g, fit error %.4f of peak\n", growth, load_ratio, c.PTY2, sa);
  EXPECT_GE(sa, 0);
  if (growth > load_ratio) {
    EXPECT_NEAR(c.PTY2, 20.0, 1e-6);
    EXPECT_LT(sa, 0.05);
  } else {
    EXPECT_LT(sa, 1e-6);
  }
  for (const char* key : {"\"lateral_stiffness_N_per_mm\"", "\"longitudinal_relaxation_length_mm\"",
                          "\"lateral_relaxation_length_mm\"", "\"PTY1\""})
    EXPECT_NE(summary.find(key), std::string::npos) << key;
  fs::remove_all(out.parent_path());
}

}  // namespace
