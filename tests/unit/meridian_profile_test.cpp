// The interpolated meridian against the exact geometry of the example tyre's carcass line: three tangent
// circular arcs (tyres/175-70R13.md), sampled at 35 points rounded to 0.01 mm.
#include "tirefem/tyre/meridian_profile.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace tirefem {
namespace {

std::vector<Eigen::Vector2d> example_points() {
  const double xr[][2] = {
      {0.00, 272.00},  {4.90, 271.96},  {9.80, 271.84},  {14.69, 271.64}, {19.58, 271.36}, {24.47, 271.00},
      {29.35, 270.56}, {34.22, 270.04}, {39.08, 269.44}, {43.94, 268.77}, {48.78, 268.01}, {53.60, 267.17},
      {58.42, 266.26}, {62.07, 265.24}, {65.53, 263.68}, {68.71, 261.61}, {71.54, 259.09}, {73.96, 256.17},
      {75.91, 252.92}, {77.78, 248.80}, {79.36, 244.56}, {80.62, 240.22}, {81.56, 235.80}, {82.18, 231.32},
      {82.47, 226.81}, {82.44, 222.29}, {82.08, 217.78}, {81.40, 213.31}, {80.39, 208.90}, {79.06, 204.58},
      {77.43, 200.36}, {75.50, 196.28}, {73.27, 192.34}, {70.77, 188.57}, {68.00, 185.00}};
  std::vector<Eigen::Vector2d> p;
  for (const auto& q : xr) p.emplace_back(q[0], q[1]);
  return p;
}

struct Arc {
  Eigen::Vector2d centre;
  double radius;
};
const Arc kCrown{{0.0, -28.0}, 300.0}, kShoulder{{53.55, 241.74}, 25.0}, kSidewall{{20.08, 225.0}, 62.42};

double distance_to(const Arc& a, const Eigen::Vector2d& p) {
  return std::abs((p - a.centre).norm() - a.radius);
}

// Exact arc lengths of the three arcs (junctions at (58.42, 266.26) and (75.91, 252.92)).
double arc_angle(const Arc& a, const Eigen::Vector2d& p, const Eigen::Vector2d& q) {
  const Eigen::Vector2d u = p - a.centre, v = q - a.centre;
  return std::abs(std::atan2(u.x() * v.y() - u.y() * v.x(), u.dot(v)));
}
const Eigen::Vector2d kJ1{58.42, 266.26}, kJ2{75.91, 252.92}, kBead{68.0, 185.0};
const double kS1 = kCrown.radius * arc_angle(kCrown, {0.0, 272.0}, kJ1);
const double kS2 = kS1 + kShoulder.radius * arc_angle(kShoulder, kJ1, kJ2);
const double kLength = kS2 + kSidewall.radius * arc_angle(kSidewall, kJ2, kBead);

TEST(MeridianProfile, LengthMatchesTheArcs) {
  const MeridianProfile p(example_points());
  EXPECT_NEAR(kLength, 153.9, 0.1);  // the sheet's value, rounded
  EXPECT_NEAR(p.length(), kLength, 0.02);
  EXPECT_EQ(p.s_begin(), 0.0);
  EXPECT_EQ(p.s_end(), p.length());
}

// Between the samples the spline stays on the arcs. The error budget: the samples are rounded to 0.01 mm,
// and where two arcs meet the curvature jumps (1/300 → 1/25 → 1/62.4), which a C² spline smooths over
// about one sample spacing (≈ 5 mm); 0.05 mm covers both.
TEST(MeridianProfile, InterpolatedPointsLieOnTheArcs) {
  const MeridianProfile p(example_points());
  double worst = 0.0;
  for (double s = 0.0; s <= p.length(); s += 0.1) {
    const Eigen::Vector2d x = p.point(s);
    double d;
    if (s < kS1 - 3.0)
      d = distance_to(kCrown, x);
    else if (s < kS1 + 3.0)
      d = std::min(distance_to(kCrown, x), distance_to(kShoulder, x));
    else if (s < kS2 - 3.0)
      d = distance_to(kShoulder, x);
    else if (s < kS2 + 3.0)
      d = std::min(distance_to(kShoulder, x), distance_to(kSidewall, x));
    else
      d = distance_to(kSidewall, x);
    worst = std::max(worst, d);
  }
  EXPECT_LT(worst, 0.05);
}

TEST(MeridianProfile, PassesThroughTheSamplesAtTheSheetsArcLengths) {
  const std::vector<Eigen::Vector2d> pts = example_points();
  const MeridianProfile p(pts);
  const double sheet_s[] = {0.0,   4.9,   9.8,   14.7,  19.6,  24.5,  29.4,  34.3,  39.2,  44.1,  49.0, 53.9,
                            58.8,  62.6,  66.4,  70.2,  74.0,  77.8,  81.5,  86.1,  90.6,  95.1,  99.6, 104.2,
                            108.7, 113.2, 117.7, 122.2, 126.8, 131.3, 135.8, 140.3, 144.8, 149.4, 153.9};
  ASSERT_EQ(p.point_arc_lengths().size(), pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const double s = p.point_arc_lengths()[i];
    EXPECT_NEAR(s, sheet_s[i], 0.1) << i;
    EXPECT_LT((p.point(s) - pts[i]).norm(), 1e-9) << i;
  }
}

TEST(MeridianProfile, IsParametrisedByArcLength) {
  const MeridianProfile p(example_points());
  const double h = 1e-4;
  for (double s = 0.5; s < p.length() - 0.5; s += 3.7) {
    const Eigen::Vector2d t = p.tangent(s);
    EXPECT_NEAR(t.norm(), 1.0, 1e-12);
    const Eigen::Vector2d fd = (p.point(s + h) - p.point(s - h)) / (2 * h);
    EXPECT_LT((fd - t).norm(), 1e-7) << s;
    // the curvature is the turning rate of the tangent, dt/ds = −κ n
    const Eigen::Vector2d dt = (p.tangent(s + h) - p.tangent(s - h)) / (2 * h);
    EXPECT_NEAR(dt.dot(-p.normal(s)), p.curvature(s), 1e-5) << s;
  }
}

TEST(MeridianProfile, CurvatureFollowsTheArcsAwayFromTheJunctions) {
  const MeridianProfile p(example_points());
  // The curvature is a second derivative, so it is far noisier than the points: rounding the samples to
  // 0.01 mm moves it by about 6 · 0.005 / 4.9² ≈ 1.3e-3 /mm, and the jumps in curvature where the arcs meet
  // make the spline ring for a couple of spacings either side. Hence 3e-3 /mm, at least 12 mm from a
  // junction (5 mm on the short shoulder arc). Only the points and tangents enter the mesh.
  for (double s = 0.0; s < kS1 - 12.0; s += 0.5) EXPECT_NEAR(p.curvature(s), 1.0 / 300, 3e-3) << s;
  for (double s = kS1 + 5.0; s < kS2 - 5.0; s += 0.5) EXPECT_NEAR(p.curvature(s), 1.0 / 25, 3e-3) << s;
  for (double s = kS2 + 12.0; s <= kLength; s += 0.5) EXPECT_NEAR(p.curvature(s), 1.0 / 62.42, 3e-3) << s;
}

TEST(MeridianProfile, EquatorIsSymmetric) {
  const MeridianProfile p(example_points());
  EXPECT_LT((p.point(0.0) - Eigen::Vector2d(0.0, 272.0)).norm(), 1e-12);
  EXPECT_LT((p.tangent(0.0) - Eigen::Vector2d(1.0, 0.0)).norm(), 1e-12);
  EXPECT_LT((p.normal(0.0) - Eigen::Vector2d(0.0, 1.0)).norm(), 1e-12);
}

TEST(MeridianProfile, MirroredProfileIsSmoothThroughTheEquator) {
  const MeridianProfile half(example_points());
  const MeridianProfile full = half.mirrored();
  EXPECT_TRUE(full.is_mirrored());
  EXPECT_DOUBLE_EQ(full.s_begin(), -half.length());
  EXPECT_DOUBLE_EQ(full.s_end(), half.length());
  EXPECT_DOUBLE_EQ(full.length(), 2 * half.length());
  for (double s : {0.3, 10.0, 70.0, 120.0, half.length()}) {
    const Eigen::Vector2d a = full.point(s), b = full.point(-s);
    EXPECT_DOUBLE_EQ(b.x(), -a.x());
    EXPECT_DOUBLE_EQ(b.y(), a.y());
    EXPECT_DOUBLE_EQ(full.curvature(-s), full.curvature(s));
    EXPECT_LT((full.point(s) - half.point(s)).norm(), 1e-14);
  }
  const double h = 1e-3;
  EXPECT_LT((full.tangent(h) - full.tangent(-h)).norm(), 1e-4);
  EXPECT_NEAR(full.curvature(h), full.curvature(-h), 1e-12);
  EXPECT_LT((full.point(h) - full.point(-h) - 2 * h * full.tangent(0.0)).norm(), 1e-8);
  // The far side's normal points away from the axis too (−x at the sidewall).
  EXPECT_LT(full.normal(-106.0).x(), -0.9);
  EXPECT_GT(full.normal(106.0).x(), 0.9);
}

TEST(MeridianProfile, MeridianFunctionsOutliveTheProfile) {
  Meridian m;
  {
    const MeridianProfile p(example_points());
    m = p.meridian();
  }
  EXPECT_LT((m.point(0.0) - Eigen::Vector2d(0.0, 272.0)).norm(), 1e-12);
  EXPECT_NEAR(m.tangent(50.0).norm(), 1.0, 1e-12);
}

TEST(MeridianProfile, RejectsBadInput) {
  EXPECT_THROW(MeridianProfile({{0.0, 1.0}}), std::invalid_argument);
  EXPECT_THROW(MeridianProfile({{1.0, 272.0}, {5.0, 271.0}}), std::invalid_argument);
  EXPECT_THROW(MeridianProfile({{0.0, 272.0}, {0.0, 272.0}, {5.0, 271.0}}), std::invalid_argument);
  const MeridianProfile p(example_points());
  EXPECT_THROW(p.point(-1.0), std::out_of_range);
  EXPECT_THROW(p.point(p.length() + 1.0), std::out_of_range);
  EXPECT_NO_THROW(p.point(p.length() * (1 + 1e-12)));
}

TEST(MeridianProfile, TwoAndThreePointProfilesWork) {
  const MeridianProfile line({{0.0, 100.0}, {50.0, 100.0}});  // a cylinder
  EXPECT_NEAR(line.length(), 50.0, 1e-12);
  EXPECT_NEAR(line.point(20.0).y(), 100.0, 1e-12);
  EXPECT_NEAR(line.curvature(20.0), 0.0, 1e-12);
  const MeridianProfile three({{0.0, 100.0}, {10.0, 99.5}, {20.0, 98.0}});
  EXPECT_GT(three.length(), 20.0);
  EXPECT_NEAR(three.tangent(0.0).y(), 0.0, 1e-12);
}

}  // namespace
}  // namespace tirefem
