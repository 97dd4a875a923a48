// magic_formula_fit::LogBounded: a coefficient kept within its bounds for Levenberg–Marquardt, and the
// value a fit reports on a bound it ran into.
#include <gtest/gtest.h>

#include "tirefem/magic_formula/fit_points.hpp"

namespace tirefem {
namespace {

using magic_formula_fit::LogBounded;

TEST(LogBounded, AFitThatRanIntoABoundReportsTheBoundItself) {
  const LogBounded b{0.1, 100.0};
  // Saturated parameters: value() ends within round-off of the bound, on either side of it.
  for (const double v : {18.0, 25.0, 40.0}) {
    EXPECT_NEAR(b.value(v), 100.0, 1e-9 * 100.0);
    EXPECT_EQ(b.result(v), 100.0);
    EXPECT_NEAR(b.value(-v), 0.1, 1e-9 * 0.1);
    EXPECT_EQ(b.result(-v), 0.1);
  }
}

TEST(LogBounded, InsideTheBoundsResultIsTheValue) {
  const LogBounded b{1.0, 50.0};
  for (const double x : {1.5, 7.0, 20.0, 49.0}) {
    const double v = b.parameter(x);
    EXPECT_NEAR(b.value(v), x, 1e-12 * x);
    EXPECT_EQ(b.result(v), b.value(v));
  }
}

}  // namespace
}  // namespace tirefem
