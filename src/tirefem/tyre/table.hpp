#pragma once
// A quantity given along the meridian as a piecewise-linear table in the arc length s (mm from the
// equator), e.g. the interlayer thickness or the tread height. Tables, not steps: a step in a thickness
// would tear the face resting on it.
#include <algorithm>
#include <stdexcept>
#include <vector>

namespace tirefem {

struct Table {
  std::vector<double> s;      // strictly increasing
  std::vector<double> value;  // same size as s

  // Linear interpolation; constant beyond the first and last entries. A one-entry table is a constant.
  double at(double s_query) const {
    if (s.empty() || s.size() != value.size()) throw std::logic_error("Table::at: empty or malformed table");
    if (s_query <= s.front()) return value.front();
    if (s_query >= s.back()) return value.back();
    const auto hi = static_cast<std::size_t>(std::upper_bound(s.begin(), s.end(), s_query) - s.begin());
    const std::size_t lo = hi - 1;
    const double w = (s_query - s[lo]) / (s[hi] - s[lo]);
    return (1.0 - w) * value[lo] + w * value[hi];
  }

  static Table constant(double v) { return Table{{0.0}, {v}}; }
};

}  // namespace tirefem
