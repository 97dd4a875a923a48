#pragma once
// Internal to the reports (footprint_report.cpp, rolling_report.cpp): the tread points of a result as a
// structured grid over (u, v) = (s, φ), the window of that grid around the contact patch, and the axes of
// a map over that window.
#include <vector>

#include "tirefem/forms/winkler_contact_form.hpp"
#include "tirefem/io/plot_writer.hpp"

namespace tirefem {

// Tread points as a structured grid over (u, v) = (s, φ); in a half model the columns with s > 0 also
// appear mirrored (s → −s, x → −x), first, so the grid spans the whole patch.
struct TreadGrid {
  std::vector<double> u, v;    // column and row parameters, increasing
  std::vector<char> mirrored;  // per column
  std::vector<int> point;      // [j * nu + i]: tread point index, −1 = none

  int nu() const { return static_cast<int>(u.size()); }
  int nv() const { return static_cast<int>(v.size()); }
  int at(int i, int j) const { return point[static_cast<std::size_t>(j) * u.size() + i]; }
};

// The grid of `points`. Parameters closer than a relative 1e-9 count as one (the tread points' parameters
// are bit-identical along a grid line, the tolerance only guards against other producers).
TreadGrid tread_grid(const std::vector<TreadPoint>& points, bool half_model);

// Points that define the patch, one flag per state: qn > 0, or (no contact at all) those of largest
// penetration.
std::vector<char> patch_points(const std::vector<TreadPointState>& states);

struct TreadWindow {
  int i0, i1, j0, j1;  // inclusive grid index ranges
};

// The grid index ranges of the patch_points(states) plus `margin` rows / columns, within the grid.
TreadWindow patch_window(const TreadGrid& g, const std::vector<TreadPointState>& states, int margin);

// The axes of a map over the window (s–φ maps): x = s [mm] of its columns, y = φ [deg] of its rows, and
// their labels.
void set_s_phi_axes(HeatMap& m, const TreadGrid& g, const TreadWindow& w);

}  // namespace tirefem
