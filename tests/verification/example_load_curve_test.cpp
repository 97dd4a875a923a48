// The example's plane load curve against the values the solver gave before the speed work of issue 9
// (tests/verification/data/load_curve_175-70R13_Qz.csv, commit a39d379), on the example tyre as it was then
// (tests/data/example_175-70R13_before_revision.toml): 120 × 46 half model, 0–40 mm in 20
// points, single loop, stable equilibrium, reused factorisations — the case file's own settings. Every
// solver change (GMRES, predictors, factorisation reuse, thread settings) must keep each Qz to 1e-6
// relative: the Newton tolerance (1e-8 of the inflation load) moves Qz by far less, so a larger change
// means another equilibrium (e.g. a different state past the instability at 26 mm). Runtime ≈ 40 s.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "contact_support.hpp"

namespace tirefem::verification {
namespace {

std::vector<std::pair<double, double>> recorded_values() {
  std::ifstream in(std::string(TIREFEM_SOURCE_DIR) + "/tests/verification/data/load_curve_175-70R13_Qz.csv");
  std::vector<std::pair<double, double>> v;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 'd') continue;
    std::istringstream s(line);
    double d = 0, q = 0;
    char comma = 0;
    if (s >> d >> comma >> q) v.emplace_back(d, q);
  }
  return v;
}

TEST(ExampleLoadCurve, QzEqualsTheRecordedSolverToOnePartPerMillion) {
  const auto recorded = recorded_values();
  ASSERT_EQ(recorded.size(), 21u);
  const Stopwatch clock;
  const Case c = read_case(std::string(TIREFEM_SOURCE_DIR) + "/tests/data/example_175-70R13_before_revision.toml");
  const TyreMesh tm = build_tyre_mesh(c.tyre, c.mesh);
  const StaticContactResult r = run_load_curve(tm, c.tyre, c.inflation, c.contact, c.load_curves.front());
  ASSERT_TRUE(r.completed) << r.failure;
  double worst = 0.0;
  for (const auto& [d, q] : recorded) {
    const double now = Qz_at(r, d);
    ASSERT_TRUE(std::isfinite(now)) << "no load point at " << d << " mm";
    worst = std::max(worst, std::abs(now / q - 1.0));
    EXPECT_NEAR(now, q, 1e-6 * q) << "δz " << d << " mm";
  }
  std::printf("  plane load curve, 120 x 46: 21 points, largest relative difference %.1e (%.1f s)\n", worst,
              clock.seconds());
}

}  // namespace
}  // namespace tirefem::verification
