#include "tirefem/report/rim_flange_report.hpp"

#include <limits>

namespace tirefem {

toml::table rim_flange_table(const std::string& side, const RimFlangeLoad& load) {
  return toml::table{{"side", side},
                     {"axial_force_N", load.axial_force_N},
                     {"radial_force_N", load.radial_force_N},
                     {"peak_pressure_MPa", load.peak_pressure_MPa},
                     {"contact_fraction", load.contact_fraction}};
}

void insert_rim_flanges(toml::table& t, const RollingFigures& f) {
  if (f.rim_flanges.empty()) return;
  toml::array flanges;
  for (const RollingFigures::Flange& flange : f.rim_flanges) flanges.push_back(rim_flange_table(flange.side, flange.load));
  t.insert("rim_flanges", std::move(flanges));
}

double largest_flange_axial_force_N(const RollingFigures& f) {
  double most = std::numeric_limits<double>::quiet_NaN();
  for (const RollingFigures::Flange& flange : f.rim_flanges)
    if (!(flange.load.axial_force_N <= most)) most = flange.load.axial_force_N;
  return most;
}

double smallest_flange_contact_fraction(const RollingFigures& f) {
  double least = std::numeric_limits<double>::quiet_NaN();
  for (const RollingFigures::Flange& flange : f.rim_flanges)
    if (!(flange.load.contact_fraction >= least)) least = flange.load.contact_fraction;
  return least;
}

}  // namespace tirefem
