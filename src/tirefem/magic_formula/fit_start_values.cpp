#include "tirefem/magic_formula/fit_start_values.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tirefem::magic_formula_fit {
namespace {

struct LoadLevelFeatures {
  double Fz = 0, dfz = 0;
  double peak = 0;            // max |F| (Fx or Fy)
  double at_largest_slip = 0; // |F| at the largest |slip|
  double slope = 0;           // dF/dslip at zero slip
  double at_zero = 0;         // F at zero slip
  double trail = 0;           // -dMz/dFy near zero slip
  double residual_moment = 0; // Mz where Fy = 0
};

// Features of one load level's gamma = 0 points (data.loads[k]); the force channel is Fx for the
// longitudinal group, Fy else.
LoadLevelFeatures load_level_features(FitGroup group, const GroupPoints& data, std::size_t k, double Fz0) {
  const FitGroup force = group == FitGroup::aligning ? FitGroup::pure_lateral : group;
  const double load = data.loads[k];
  std::vector<const TyreTestPoint*> level;
  for (const TyreTestPoint& p : data.points)
    if (nearest_level(p.Fz, data.loads) == k && p.gamma == 0) level.push_back(&p);
  std::sort(level.begin(), level.end(),
            [&](auto* a, auto* b) { return std::abs(slip(group, *a)) < std::abs(slip(group, *b)); });
  LoadLevelFeatures f;
  f.Fz = load;
  f.dfz = (load - Fz0) / Fz0;
  for (auto* p : level) f.peak = std::max(f.peak, std::abs(measured(force, *p)));
  if (!level.empty()) f.at_largest_slip = std::abs(measured(force, *level.back()));
  // Least-squares lines through the (up to) 5 points nearest zero slip: F(slip) for the slope and F(0),
  // Mz(Fy) for the trail and the residual moment. More than two points keep a 1%
  // noise from spoiling the start.
  const std::size_t n = std::min<std::size_t>(level.size(), 5);
  std::vector<double> s, F, Mz;
  for (std::size_t i = 0; i < n; ++i) {
    s.push_back(slip(group, *level[i]));
    F.push_back(measured(force, *level[i]));
    Mz.push_back(level[i]->Mz);
  }
  if (distinct_values(s, 0.0).size() < 2) return f;
  const auto [F0, dF] = fit_line(s, F);
  f.slope = dF;
  f.at_zero = F0;
  if (group == FitGroup::aligning) {
    const auto [M0, dM] = fit_line(F, Mz);
    f.trail = -dM;
    f.residual_moment = M0;  // Mz = -t Fy + Mzr (4.E31): Mzr is Mz where Fy = 0
  }
  return f;
}

// Shape factor from the fall after the peak: y_max = D sin(C pi/2) is approached at large slip, so
// C = 2 - (2/pi) asin(y_end/D) once the data pass the peak; `typical` when they do not (C <= 1).
double shape_factor(const std::vector<LoadLevelFeatures>& levels, double typical) {
  double sum = 0;
  int count = 0;
  for (const auto& l : levels)
    if (l.peak > 0 && l.at_largest_slip < 0.99 * l.peak) {
      sum += 2 - (2 / std::numbers::pi) * std::asin(l.at_largest_slip / l.peak);
      ++count;
    }
  return count > 0 ? std::clamp(sum / count, 1.05, 1.9) : typical;
}

double sin_2_atan(double x) { return std::sin(2 * std::atan(x)); }

// PKY2 from the ratio of the cornering stiffnesses at the smallest and largest load:
// K2/K1 = sin(2 atan(F2/(p Fz0)))/sin(2 atan(F1/(p Fz0))) (4.E25), solved for p by bisection on
// [0.05, 50]: the ratio rises from about F1/F2 (p -> 0) to F2/F1 (p -> infinity).
double cornering_stiffness_peak_load(const LoadLevelFeatures& low, const LoadLevelFeatures& high, double Fz0) {
  if (low.slope == 0 || high.Fz <= low.Fz) return 1.5;
  const double target = high.slope / low.slope;
  auto ratio = [&](double p) { return sin_2_atan(high.Fz / (p * Fz0)) / sin_2_atan(low.Fz / (p * Fz0)); };
  double a = 0.05, b = 50;
  if (target <= ratio(a)) return a;
  if (target >= ratio(b)) return b;
  for (int i = 0; i < 200 && b - a > 1e-15 * b; ++i) {
    const double m = 0.5 * (a + b);
    (ratio(m) < target ? a : b) = m;
  }
  return 0.5 * (a + b);
}

}  // namespace

void set_start_values(FitGroup group, const GroupPoints& data, MagicFormulaCoefficients& c) {
  const double Fz0 = c.FNOMIN * c.LFZO;
  std::vector<LoadLevelFeatures> levels;
  for (std::size_t k = 0; k < data.loads.size(); ++k) levels.push_back(load_level_features(group, data, k, Fz0));
  std::vector<double> dfz, mu, stiffness, shift, trail, residual;
  for (const auto& l : levels) {
    dfz.push_back(l.dfz);
    mu.push_back(l.peak / l.Fz);
    stiffness.push_back(l.slope / l.Fz);
    // Shift at zero slip read as a horizontal shift: F(0) = K SH (the vertical shift starts at 0).
    shift.push_back(l.slope != 0 ? l.at_zero / l.slope : 0.0);
    trail.push_back(l.trail * Fz0 / (l.Fz * c.UNLOADED_RADIUS));          // (4.E42) QDZ1 + QDZ2 dfz
    residual.push_back(l.residual_moment / (l.Fz * c.UNLOADED_RADIUS));  // (4.E47) QDZ6 + QDZ7 dfz
  }
  const auto [mu0, mu1] = fit_line(dfz, mu);
  const auto [shift0, shift1] = fit_line(dfz, shift);
  if (group == FitGroup::pure_longitudinal) {
    const auto [k0, k1] = fit_line(dfz, stiffness);
    c.PCX1 = shape_factor(levels, 1.6);
    c.PDX1 = std::max(mu0, 0.1) / c.LMUX;   // (4.E13)
    c.PDX2 = mu1 / c.LMUX;
    c.PKX1 = k0 / c.LKX;                    // (4.E15) with PKX3 = 0
    c.PKX2 = k1 / c.LKX;
    c.PHX1 = shift0 / c.LHX;                // (4.E17)
    c.PHX2 = shift1 / c.LHX;
  } else if (group == FitGroup::pure_lateral) {
    c.PCY1 = shape_factor(levels, 1.3);
    c.PDY1 = std::max(mu0, 0.1) / c.LMUY;   // (4.E23)
    c.PDY2 = mu1 / c.LMUY;
    // Within the fit's bound for PKY2 (fitter.cpp: Bound::peak_load).
    c.PKY2 = levels.size() >= 2 ? std::clamp(cornering_stiffness_peak_load(levels.front(), levels.back(), Fz0), 0.5, 4.0) : 1.5;
    double sum = 0;  // PKY1 from each load's stiffness with that PKY2 (4.E25)
    for (const auto& l : levels) sum += l.slope / (Fz0 * sin_2_atan(l.Fz / (c.PKY2 * Fz0)) * c.LKY);
    c.PKY1 = levels.empty() ? -10.0 : sum / static_cast<double>(levels.size());
    c.PHY1 = shift0 / c.LHY;                // (4.E27)
    c.PHY2 = shift1 / c.LHY;
  } else {
    const auto [t0, t1] = fit_line(dfz, trail);
    const auto [r0, r1] = fit_line(dfz, residual);
    c.QBZ1 = 10;   // typical: the trail's fall with slip angle is not read off the data
    c.QCZ1 = 1.2;
    c.QDZ1 = t0 / c.LTR;
    c.QDZ2 = t1 / c.LTR;
    c.QBZ9 = 10;
    c.QDZ6 = r0 / (c.LRES * c.LMUY);
    c.QDZ7 = r1 / (c.LRES * c.LMUY);
  }
}

}  // namespace tirefem::magic_formula_fit
