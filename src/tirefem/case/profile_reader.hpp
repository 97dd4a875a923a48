#pragma once
// [tyre.profile] points = [[x, r], ...]: the carcass line from the crown on the equator (x = 0) to the
// bead, and its checks.
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "tirefem/case/toml_fields.hpp"
#include "tirefem/tyre/meridian_profile.hpp"

namespace tirefem::case_reading {

std::vector<Eigen::Vector2d> read_profile(TomlFields& f, const toml::table& tyre, const std::string& tyre_path);

// Checks the points (path: "tyre.profile.points") and returns the profile's arc length. Beyond finite,
// ordered points starting on the equator, the carcass line must be a simple curve the mesh can be built
// on: no two of its segments may cross or touch (nor may it touch the equator again, where the full
// model's mirror image would meet it), and it must not be inside out (see profile_is_inside_out).
double check_profile(const FieldChecker& c, const std::vector<Eigen::Vector2d>& pts, const std::string& path);

// The spline the mesh is built on, sampled kProfileSamplesPerSegment times between input points: it must
// stay off the equator (x > 0 after the start) and not cross itself, even where the points do not (an
// overshoot between badly spaced points). Part of check_profile.
inline constexpr int kProfileSamplesPerSegment = 4;
void check_interpolated_profile(const FieldChecker& c, const MeridianProfile& profile, const std::string& path);

// Signed area (mm²) enclosed by the profile, closed by the rim line from the bead back to the equator at
// the bead's radius and the equator itself. Negative (clockwise in (x, r)) for a tyre: the normal
// (−r', x') that the pressure follows points out of this cavity, away from the axis at the crown. A
// positive area is an inside-out profile: inflation would pull it inwards.
double profile_cavity_area(const std::vector<Eigen::Vector2d>& pts);

// Whether the closed segments [a, b] and [c, d] share a point.
bool segments_meet(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                   const Eigen::Vector2d& d);

}  // namespace tirefem::case_reading
