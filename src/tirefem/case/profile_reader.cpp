#include "tirefem/case/profile_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "tirefem/tyre/meridian_profile.hpp"

namespace tirefem::case_reading {

std::vector<Eigen::Vector2d> read_profile(TomlFields& f, const toml::table& tyre, const std::string& tyre_path) {
  const std::string pp = join(tyre_path, "profile");
  const toml::table& prof =
      f.table(f.need(tyre, tyre_path, "profile", "a table with points = [[x, r], ...]"), pp, {"points"});
  const std::string ptp = join(pp, "points");
  const toml::array& pts =
      f.array(f.need(prof, pp, "points", "an array of [x, r] pairs (mm)"), ptp, "[x, r] pairs (mm)");
  std::vector<Eigen::Vector2d> profile;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const std::vector<double> xy = f.numbers(pts[i], index(ptp, i), " (mm)");
    if (xy.size() != 2) f.fail(index(ptp, i), fmt::format("must be a pair [x, r] (got {} numbers)", xy.size()));
    profile.emplace_back(xy[0], xy[1]);
  }
  return profile;
}

namespace {

// Orientation of c relative to the line a→b: > 0 left, < 0 right, 0 on it.
double orientation(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

bool within_box(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p) {
  return p.x() >= std::min(a.x(), b.x()) && p.x() <= std::max(a.x(), b.x()) && p.y() >= std::min(a.y(), b.y()) &&
         p.y() <= std::max(a.y(), b.y());
}

int sign(double v) { return (v > 0) - (v < 0); }

}  // namespace

bool segments_meet(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                   const Eigen::Vector2d& d) {
  const int o1 = sign(orientation(a, b, c)), o2 = sign(orientation(a, b, d));
  const int o3 = sign(orientation(c, d, a)), o4 = sign(orientation(c, d, b));
  if (o1 != o2 && o3 != o4) return true;
  return (o1 == 0 && within_box(a, b, c)) || (o2 == 0 && within_box(a, b, d)) ||
         (o3 == 0 && within_box(c, d, a)) || (o4 == 0 && within_box(c, d, b));
}

double profile_cavity_area(const std::vector<Eigen::Vector2d>& pts) {
  std::vector<Eigen::Vector2d> closed = pts;
  closed.emplace_back(0.0, pts.back().y());  // the rim line back to the equator
  double twice = 0.0;
  for (std::size_t i = 0; i < closed.size(); ++i) {
    const Eigen::Vector2d& p = closed[i];
    const Eigen::Vector2d& q = closed[(i + 1) % closed.size()];
    twice += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * twice;
}

namespace {

// The index of the input segment (points[k]–points[k+1]) that contains arc length s.
std::size_t segment_at(const std::vector<double>& knot_s, double s) {
  const auto it = std::upper_bound(knot_s.begin(), knot_s.end(), s);
  const auto k = static_cast<std::size_t>(std::max<std::ptrdiff_t>(it - knot_s.begin() - 1, 0));
  return std::min(k, knot_s.size() - 2);
}

}  // namespace

void check_interpolated_profile(const FieldChecker& c, const MeridianProfile& profile, const std::string& path) {
  const std::vector<double>& knot_s = profile.point_arc_lengths();
  std::vector<double> s;
  for (std::size_t k = 0; k + 1 < knot_s.size(); ++k)
    for (int j = 0; j < kProfileSamplesPerSegment; ++j)
      s.push_back(knot_s[k] + (knot_s[k + 1] - knot_s[k]) * j / kProfileSamplesPerSegment);
  s.push_back(profile.length());
  std::vector<Eigen::Vector2d> x;
  for (double si : s) x.push_back(profile.point(si));
  for (std::size_t i = 1; i < x.size(); ++i)
    if (!(x[i].x() > 0)) {
      const std::size_t k = segment_at(knot_s, s[i]);
      c.fail(index(path, k), fmt::format("the smooth curve through the points reaches x = {:.3g} between points[{}] "
                                         "and points[{}]: it crosses the equator (add points or smooth the profile)",
                                         x[i].x(), k, k + 1));
    }
  // Sampled segments sorted by their smallest x; each compared with those whose x-ranges overlap it.
  struct Piece {
    double x_min, x_max;
    std::size_t i;
  };
  std::vector<Piece> pieces;
  for (std::size_t i = 0; i + 1 < x.size(); ++i)
    pieces.push_back({std::min(x[i].x(), x[i + 1].x()), std::max(x[i].x(), x[i + 1].x()), i});
  std::sort(pieces.begin(), pieces.end(), [](const Piece& a, const Piece& b) { return a.x_min < b.x_min; });
  for (std::size_t a = 0; a < pieces.size(); ++a)
    for (std::size_t b = a + 1; b < pieces.size() && pieces[b].x_min <= pieces[a].x_max; ++b) {
      const std::size_t i = std::min(pieces[a].i, pieces[b].i), j = std::max(pieces[a].i, pieces[b].i);
      if (j - i < 2 || !segments_meet(x[i], x[i + 1], x[j], x[j + 1])) continue;
      const std::size_t ki = segment_at(knot_s, s[i]), kj = segment_at(knot_s, s[j]);
      c.fail(index(path, kj), fmt::format("the smooth curve through the points crosses itself between points[{}]–"
                                          "points[{}] and points[{}]–points[{}] (add points or smooth the profile)",
                                          kj, kj + 1, ki, ki + 1));
    }
}

double check_profile(const FieldChecker& c, const std::vector<Eigen::Vector2d>& pts, const std::string& path) {
  if (pts.size() < 2) c.fail(path, fmt::format("needs at least 2 points [x, r] (got {})", pts.size()));
  if (pts.size() > static_cast<std::size_t>(kMaxProfilePoints))
    c.fail(path, fmt::format("at most {} points (got {})", kMaxProfilePoints, pts.size()));
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const std::string p = index(path, i);
    c.finite(pts[i].x(), p);
    c.finite(pts[i].y(), p);
    if (!(pts[i].x() >= 0)) c.fail(p, fmt::format("x must be ≥ 0 (got {})", pts[i].x()));
    if (!(pts[i].y() > 0)) c.fail(p, fmt::format("r must be > 0 (got {})", pts[i].y()));
  }
  if (pts[0].x() != 0.0)
    c.fail(index(path, 0), fmt::format("the profile must start on the equator, x = 0 (got x = {})", pts[0].x()));
  for (std::size_t i = 1; i < pts.size(); ++i) {
    const Eigen::Vector2d chord = pts[i] - pts[i - 1];
    if (!(chord.norm() > 1e-6))
      c.fail(index(path, i), fmt::format("same point as points[{}]: arc length must increase", i - 1));
    if (i >= 2 && chord.dot(pts[i - 1] - pts[i - 2]) <= 0)
      c.fail(index(path, i),
             fmt::format("the profile turns back at points[{}] (more than 90°): points out of order?", i - 1));
  }
  for (std::size_t i = 1; i < pts.size(); ++i)
    if (pts[i].x() == 0.0)
      c.fail(index(path, i),
             "only the first point may lie on the equator (x = 0): the full model's mirror image would touch "
             "the carcass there");
  // Non-adjacent segments i–i+1 and j–j+1 (adjacent ones share a point and cannot overlap: the turn
  // check above).
  for (std::size_t j = 2; j + 1 < pts.size(); ++j)
    for (std::size_t i = 0; i + 1 < j; ++i)
      if (segments_meet(pts[i], pts[i + 1], pts[j], pts[j + 1]))
        c.fail(index(path, j),
               fmt::format("the segment points[{}]–points[{}] crosses or touches points[{}]–points[{}]: the "
                           "carcass line must not cross itself",
                           j, j + 1, i, i + 1));
  if (const double area = profile_cavity_area(pts); !(area < 0))
    c.fail(path, fmt::format("the profile is inside out: from the crown (x = 0) to the bead it must run "
                             "clockwise around the cavity it closes with the rim line r = {:g} (the tyre "
                             "below the crown, towards the wheel axis), so that the pressure pushes the "
                             "crown away from the axis (enclosed signed area {:.4g} mm², must be < 0)",
                             pts.back().y(), area));
  MeridianProfile profile;
  try {
    profile = MeridianProfile(pts);
  } catch (const std::exception& e) {
    c.fail(path, e.what());
  }
  check_interpolated_profile(c, profile, path);
  return profile.length();
}

}  // namespace tirefem::case_reading
