#include "tirefem/report/tyre_test_report.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

#include <fmt/format.h>

#include "tirefem/magic_formula/evaluator.hpp"

namespace tirefem {
namespace {
constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;
const double kNaN = std::nan("");

const TyreTestLoad* load_of(const TyreTestResult& t, double target) {
  for (const TyreTestLoad& l : t.loads)
    if (l.target_load_N == target) return &l;
  return nullptr;
}

// One colour per load, shared by its FE points and its fitted curve.
std::string load_colour(std::size_t i) {
  static constexpr const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"};
  return fmt::format("lc rgb '{}'", colours[i % 6]);
}

// One curve per load of the rows of `kind`: x and y taken from the row.
template <class X, class Y>
std::vector<PlotSeries> per_load(const TyreTestResult& t, TyreTestRow::Kind kind, X x, Y y) {
  std::vector<PlotSeries> series;
  for (std::size_t i = 0; i < t.loads.size(); ++i) {
    const TyreTestLoad& l = t.loads[i];
    PlotSeries s{fmt::format("Fz {:.0f} N", l.target_load_N), {}, {}, "linespoints pt 7 " + load_colour(i)};
    for (const TyreTestRow& r : t.rows)
      if (r.kind == kind && r.target_load_N == l.target_load_N) s.x.push_back(x(r)), s.y.push_back(y(r));
    if (!s.x.empty()) series.push_back(std::move(s));
  }
  return series;
}
// The fit's pure-slip curve of one channel at each load's Fz over [from, to] of the swept variable.
enum class Channel { fx, fy, mz };
std::vector<PlotSeries> fitted_curves(const TyreTestResult& t, const TyreTestFit* fit, Channel channel, double from,
                                      double to) {
  std::vector<PlotSeries> series;
  if (!fit || !(to > from)) return series;
  for (std::size_t k = 0; k < t.loads.size(); ++k) {
    const TyreTestLoad& l = t.loads[k];
    if (!(l.Fz_N > 0)) continue;
    PlotSeries s{fmt::format("Magic Formula, Fz {:.0f} N", l.target_load_N), {}, {}, "lines " + load_colour(k)};
    for (int i = 0; i <= 80; ++i) {
      const double v = from + (to - from) * i / 80.0;
      WheelSlipState w;
      w.Fz = l.Fz_N;
      if (channel == Channel::fx) w.kappa = v;
      else w.alpha = v / kDegreesPerRadian;
      const TyreForcesAndMoments f = evaluate_magic_formula(fit->tir.coefficients, w, SlipCombination::pure);
      s.x.push_back(v);
      s.y.push_back(channel == Channel::fx ? f.Fx : channel == Channel::fy ? f.Fy : f.Mz);
    }
    series.push_back(std::move(s));
  }
  return series;
}

// The range of the swept variable over the plot's FE points.
std::pair<double, double> x_range(const std::vector<PlotSeries>& series) {
  double lo = 1e300, hi = -1e300;
  for (const PlotSeries& s : series)
    for (double x : s.x) lo = std::min(lo, x), hi = std::max(hi, x);
  return {lo, hi};
}

void add_fit(Plot& p, const TyreTestResult& t, const TyreTestFit* fit, Channel channel) {
  for (PlotSeries& s : p.series) s.style.replace(0, std::string("linespoints").size(), "points");
  const auto [lo, hi] = x_range(p.series);
  for (PlotSeries& s : fitted_curves(t, fit, channel, lo, hi)) p.series.push_back(std::move(s));
}
}  // namespace

CsvTable tyre_test_table(const TyreTestResult& t) {
  CsvTable table;
  table.comments = {
      fmt::format("tirefem: virtual flat-track test '{}', FNOMIN {:.0f} N, unloaded radius {:.4f} m", t.name,
                  t.nominal_load_N, t.unloaded_radius_mm * 1e-3),
      "TYDEX / ISO 8855 W axes at the contact centre: FX along the heading, FY to the left, FZ up, MX overturning, MZ "
      "aligning; ALPHA > 0 gives FY < 0; GAMMA > 0 leans the top of the wheel to the right",
      "units: FZ FX FY N; KAPPA -; ALPHA GAMMA rad; MX MZ N*m; RE RL PATCH_LENGTH PATCH_WIDTH m; TIME s",
      "RE: effective rolling radius of free rolling at the load; RL: loaded radius (axle above the road) at the "
      "point; PATCH_*: the static footprint at the load",
      "SERIES: 0 free rolling, 1 longitudinal slip sweep, 2 slip-angle sweep, 3 cambered free rolling, 4 combined slip; FZ held at "
      "TARGET_FZ in the sweeps"};
  if (std::any_of(t.rows.begin(), t.rows.end(), [](const TyreTestRow& r) { return r.mirrored; }))
    table.comments.push_back(
        "slip-angle sweep points at ALPHA < 0 with 0 Newton iterations are the mirror images of those at -ALPHA, "
        "not solved: the tyre is its own mirror image and GAMMA = 0 (FY, MZ, MX change sign)");
  table.columns = {"FZ", "KAPPA", "ALPHA", "GAMMA", "FX", "FY", "MZ", "MX", "RE", "RL", "PATCH_LENGTH",
                   "PATCH_WIDTH", "TARGET_FZ", "SERIES", "NEWTON_ITERATIONS", "FACTORIZATIONS", "TIME"};
  for (const TyreTestRow& r : t.rows) {
    const TyreTestLoad* l = load_of(t, r.target_load_N);
    table.rows.push_back({r.Fz_N, r.kappa, r.alpha_rad, r.gamma_rad, r.Fx_N, r.Fy_N, r.Mz_Nm, r.Mx_Nm,
                          r.effective_radius_m, r.loaded_radius_m, l ? l->patch_length_mm * 1e-3 : kNaN,
                          l ? l->patch_width_mm * 1e-3 : kNaN, r.target_load_N, static_cast<double>(r.kind),
                          static_cast<double>(r.newton_iterations), static_cast<double>(r.factorizations),
                          r.time_s});
  }
  return table;
}

CsvTable tyre_test_vertical_table(const TyreTestResult& t) {
  CsvTable table;
  table.comments = {fmt::format("tirefem: load-deflection curve of '{}' on a plane (half model, full-tyre "
                                "figures), deflection from the undeformed tyre",
                                t.name)};
  table.columns = {"deflection_mm", "Qz_N", "loaded_radius_mm", "patch_length_mm", "patch_width_mm"};
  if (!t.vertical) return table;
  for (const LoadPoint& p : t.vertical->points)
    table.rows.push_back({p.deflection_mm, p.patch.Qz_N, t.unloaded_radius_mm - p.deflection_mm,
                          p.patch.patch_length_mm, p.patch.patch_width_mm});
  return table;
}

CsvTable tyre_test_loads_table(const TyreTestResult& t) {
  CsvTable table;
  table.comments = {fmt::format("tirefem: per load of tyre test '{}': static footprint, free rolling, and the "
                                "standing tyre (tread glued to the plane); relaxation length = slip (cornering) "
                                "stiffness / longitudinal (lateral) stiffness; nan: not measured",
                                t.name)};
  table.columns = {"target_load_N", "Fz_N", "deflection_mm", "loaded_radius_mm", "effective_rolling_radius_mm",
                   "patch_length_mm", "patch_width_mm", "slip_stiffness_N", "cornering_stiffness_N_per_deg",
                   "pneumatic_trail_mm", "longitudinal_stiffness_N_per_mm", "lateral_stiffness_N_per_mm",
                   "yaw_stiffness_Nm_per_deg", "longitudinal_relaxation_length_mm", "lateral_relaxation_length_mm"};
  const auto v = [](const std::optional<double>& x) { return x ? *x : kNaN; };
  for (const TyreTestLoad& l : t.loads)
    table.rows.push_back({l.target_load_N, l.Fz_N, l.deflection_mm, l.loaded_radius_mm, v(l.effective_rolling_radius_mm),
                          l.patch_length_mm, l.patch_width_mm, v(l.slip_stiffness_N), v(l.cornering_stiffness_N_per_deg),
                          v(l.pneumatic_trail_mm), v(l.longitudinal_stiffness_N_per_mm), v(l.lateral_stiffness_N_per_mm),
                          l.yaw_stiffness_Nmm_per_rad ? Nm_per_deg(*l.yaw_stiffness_Nmm_per_rad) : kNaN, v(l.longitudinal_relaxation_length_mm),
                          v(l.lateral_relaxation_length_mm)});
  return table;
}

Plot tyre_test_relaxation_plot(const TyreTestResult& t, const TyreTestFit* fit) {
  Plot p{fmt::format("{}: relaxation lengths (stiffness of the rolling tyre over the standing tyre's)", t.name), "Fz [N]",
         "relaxation length [mm]", {}};
  p.key_top_left = true;  // the lengths grow with the load
  PlotSeries kappa{"longitudinal, slip stiffness / Cx", {}, {}, "points pt 7 ps 1.5"};
  PlotSeries alpha{"lateral, cornering stiffness / Cy", {}, {}, "points pt 5 ps 1.5"};
  double top = 0;
  for (const TyreTestLoad& l : t.loads) {
    if (l.longitudinal_relaxation_length_mm) kappa.x.push_back(l.Fz_N), kappa.y.push_back(*l.longitudinal_relaxation_length_mm);
    if (l.lateral_relaxation_length_mm) alpha.x.push_back(l.Fz_N), alpha.y.push_back(*l.lateral_relaxation_length_mm);
    top = std::max(top, l.Fz_N);
  }
  const bool measured = !kappa.x.empty() || !alpha.x.empty();
  if (fit && measured) {
    const MagicFormulaCoefficients& c = fit->tir.coefficients;
    PlotSeries mk{"Magic Formula (PTX1-PTX3)", {}, {}, "lines"}, ma{"Magic Formula (PTY1, PTY2)", {}, {}, "lines"};
    for (int i = 1; i <= 40; ++i) {
      const double Fz = 1.1 * top * i / 40.0;
      const RelaxationLengths r = relaxation_lengths(c, Fz);
      if (!kappa.x.empty()) mk.x.push_back(Fz), mk.y.push_back(r.sigma_kappa * 1e3);
      if (!alpha.x.empty()) ma.x.push_back(Fz), ma.y.push_back(r.sigma_alpha * 1e3);
    }
    for (PlotSeries* s : {&mk, &ma})
      if (!s->x.empty()) p.series.push_back(std::move(*s));
  }
  for (PlotSeries* s : {&kappa, &alpha})
    if (!s->x.empty()) p.series.push_back(std::move(*s));
  return p;
}

Plot tyre_test_combined_plot(const TyreTestResult& t, const TyreTestFit* fit) {
  Plot p{fmt::format("{}: combined slip (W axes, Fz held): FX against FY", t.name), "FY [N]", "FX [N]", {}};
  std::map<double, PlotSeries> points;                    // per target load
  std::map<std::pair<double, double>, double> kappa_lo, kappa_hi;  // per (load, α): the grid's κ range
  for (const TyreTestRow& r : t.rows) {
    if (r.kind != TyreTestRow::Kind::combined) continue;
    PlotSeries& s = points[r.target_load_N];
    if (s.title.empty()) s = {fmt::format("Fz {:.0f} N", r.target_load_N), {}, {}, "points pt 7 ps 1.2"};
    s.x.push_back(r.Fy_N), s.y.push_back(r.Fx_N);
    const std::pair key{r.target_load_N, r.alpha_rad};
    double& lo = kappa_lo.try_emplace(key, r.kappa).first->second;
    double& hi = kappa_hi.try_emplace(key, r.kappa).first->second;
    lo = std::min(lo, r.kappa);
    hi = std::max(hi, r.kappa);
  }
  if (fit)
    for (const auto& [key, lo] : kappa_lo) {
      const auto [load, alpha] = key;
      PlotSeries curve{fmt::format("Magic Formula, {:.0f} N, α {:g}°", load, alpha * kDegreesPerRadian), {}, {}, "lines"};
      for (int i = 0; i <= 40; ++i) {
        const double kappa = lo + (kappa_hi[key] - lo) * i / 40.0;
        const auto f = evaluate_magic_formula(fit->tir.coefficients, {load, kappa, alpha, 0.0}, SlipCombination::combined);
        curve.x.push_back(f.Fy), curve.y.push_back(f.Fx);
      }
      p.series.push_back(std::move(curve));
    }
  for (auto& [load, s] : points) p.series.push_back(std::move(s));
  return p;
}

namespace {
// FX(κ), FY(α) or MZ(α) of every load's sweep, with the fit's curves.
Plot sweep_plot(const TyreTestResult& t, const TyreTestFit* fit, Channel channel) {
  const bool longitudinal = channel == Channel::fx;
  static constexpr const char* titles[] = {"longitudinal force", "lateral force", "aligning moment"};
  static constexpr const char* labels[] = {"FX [N]", "FY [N]", "MZ [N·m]"};
  const int c = static_cast<int>(channel);
  Plot p{fmt::format("{}: {} (W axes, Fz held)", t.name, titles[c]),
         longitudinal ? "longitudinal slip κ [-]" : "slip angle α [deg]", labels[c], {}};
  p.series = per_load(
      t, longitudinal ? TyreTestRow::Kind::slip_sweep : TyreTestRow::Kind::angle_sweep,
      [longitudinal](const TyreTestRow& r) { return longitudinal ? r.kappa : r.alpha_rad * kDegreesPerRadian; },
      [channel](const TyreTestRow& r) { return channel == Channel::fx ? r.Fx_N : channel == Channel::fy ? r.Fy_N : r.Mz_Nm; });
  if (fit) add_fit(p, t, fit, channel);
  return p;
}
}  // namespace

Plot tyre_test_fx_plot(const TyreTestResult& t, const TyreTestFit* fit) { return sweep_plot(t, fit, Channel::fx); }
Plot tyre_test_fy_plot(const TyreTestResult& t, const TyreTestFit* fit) { return sweep_plot(t, fit, Channel::fy); }
Plot tyre_test_mz_plot(const TyreTestResult& t, const TyreTestFit* fit) { return sweep_plot(t, fit, Channel::mz); }

Plot tyre_test_vertical_plot(const TyreTestResult& t, const TyreTestFit* fit) {
  Plot p{fmt::format("{}: vertical characteristic on a plane", t.name), "deflection δz [mm]", "Fz [N]", {}};
  PlotSeries curve{"load-deflection curve", {}, {}, "linespoints pt 7"};
  if (t.vertical)
    for (const LoadPoint& q : t.vertical->points) curve.x.push_back(q.deflection_mm), curve.y.push_back(q.patch.Qz_N);
  PlotSeries rig{"footprints of the test loads", {}, {}, "points pt 6 ps 2"};
  for (const TyreTestLoad& l : t.loads)
    if (l.Fz_N > 0) rig.x.push_back(l.deflection_mm), rig.y.push_back(l.Fz_N);
  if (fit && !curve.x.empty()) {
    // Fz = FNOMIN (Q_FZ1 ρ/R0 + Q_FZ2 (ρ/R0)²), the fitted vertical characteristic.
    const MagicFormulaCoefficients& c = fit->tir.coefficients;
    PlotSeries mf{"Magic Formula (Q_FZ1, Q_FZ2)", {}, {}, "lines"};
    const double top = *std::max_element(curve.x.begin(), curve.x.end());
    for (int i = 0; i <= 40; ++i) {
      const double d = top * i / 40.0, rho = d * 1e-3 / c.UNLOADED_RADIUS;
      mf.x.push_back(d);
      mf.y.push_back(c.FNOMIN * (c.Q_FZ1 * rho + c.Q_FZ2 * rho * rho));
    }
    p.series = {std::move(curve), std::move(rig), std::move(mf)};
    return p;
  }
  p.series = {std::move(curve), std::move(rig)};
  return p;
}

toml::table tyre_test_summary(const TyreTestResult& t, const TyreTestFit* fit) {
  toml::array loads;
  for (const TyreTestLoad& l : t.loads) {
    toml::table e{{"target_load_N", l.target_load_N}, {"completed", l.completed}};
    if (!l.failure.empty()) e.insert("failure", l.failure);
    e.insert("Fz_N", l.Fz_N);
    e.insert("deflection_mm", l.deflection_mm);
    e.insert("loaded_radius_mm", l.loaded_radius_mm);
    if (l.effective_rolling_radius_mm) e.insert("effective_rolling_radius_mm", *l.effective_rolling_radius_mm);
    e.insert("patch_length_mm", l.patch_length_mm);
    e.insert("patch_width_mm", l.patch_width_mm);
    if (l.slip_stiffness_N) e.insert("slip_stiffness_N", *l.slip_stiffness_N);
    if (l.cornering_stiffness_N_per_deg) e.insert("cornering_stiffness_N_per_deg", *l.cornering_stiffness_N_per_deg);
    if (l.pneumatic_trail_mm) e.insert("pneumatic_trail_mm", *l.pneumatic_trail_mm);
    if (l.longitudinal_stiffness_N_per_mm) e.insert("longitudinal_stiffness_N_per_mm", *l.longitudinal_stiffness_N_per_mm);
    if (l.lateral_stiffness_N_per_mm) e.insert("lateral_stiffness_N_per_mm", *l.lateral_stiffness_N_per_mm);
    if (l.yaw_stiffness_Nmm_per_rad) e.insert("yaw_stiffness_Nm_per_deg", Nm_per_deg(*l.yaw_stiffness_Nmm_per_rad));
    if (l.longitudinal_relaxation_length_mm)
      e.insert("longitudinal_relaxation_length_mm", *l.longitudinal_relaxation_length_mm);
    if (l.lateral_relaxation_length_mm) e.insert("lateral_relaxation_length_mm", *l.lateral_relaxation_length_mm);
    loads.push_back(std::move(e));
  }
  toml::table s{{"name", t.name},
                {"nominal_load_N", t.nominal_load_N},
                {"unloaded_radius_mm", t.unloaded_radius_mm},
                {"completed", t.completed},
                {"points", static_cast<int64_t>(t.rows.size())},
                {"table", t.name + "/tyre_test.csv"},
                {"loads", std::move(loads)}};
  if (!t.failures.empty()) {
    toml::array f;
    for (const std::string& m : t.failures) f.push_back(m);
    s.insert("failures", std::move(f));
  }
  if (fit) {
    const MagicFormulaCoefficients& c = fit->tir.coefficients;
    toml::array errors, undetermined;
    for (const ChannelFitError& e : fit->errors)
      errors.push_back(toml::table{{"channel", e.channel}, {"points", e.points}, {"rms", e.rms}, {"peak", e.peak},
                                   {"relative_rms", e.relative_rms}});
    for (const std::string& k : fit->not_determined) undetermined.push_back(k);
    toml::table coefficients;
    for (const auto& [key, value] :
         {std::pair{"FNOMIN", c.FNOMIN}, {"UNLOADED_RADIUS", c.UNLOADED_RADIUS}, {"VERTICAL_STIFFNESS", c.VERTICAL_STIFFNESS},
          {"Q_FZ1", c.Q_FZ1}, {"Q_FZ2", c.Q_FZ2}, {"BREFF", c.BREFF}, {"DREFF", c.DREFF}, {"FREFF", c.FREFF},
          {"PCX1", c.PCX1}, {"PDX1", c.PDX1}, {"PDX2", c.PDX2}, {"PEX1", c.PEX1}, {"PKX1", c.PKX1}, {"PKX2", c.PKX2},
          {"PKX3", c.PKX3}, {"PCY1", c.PCY1}, {"PDY1", c.PDY1}, {"PDY2", c.PDY2}, {"PEY1", c.PEY1}, {"PKY1", c.PKY1},
          {"PKY2", c.PKY2}, {"QBZ1", c.QBZ1}, {"QCZ1", c.QCZ1}, {"QDZ1", c.QDZ1}, {"QSX1", c.QSX1}, {"PTX1", c.PTX1},
          {"PTX2", c.PTX2}, {"PTX3", c.PTX3}, {"PTY1", c.PTY1}, {"PTY2", c.PTY2}, {"PVY3", c.PVY3}, {"QDZ8", c.QDZ8},
          {"QSX2", c.QSX2}, {"RBX1", c.RBX1}, {"RBX2", c.RBX2}, {"RCX1", c.RCX1}, {"RBY1", c.RBY1}, {"RBY2", c.RBY2},
          {"RCY1", c.RCY1}})
      coefficients.insert(key, value);
    s.insert("magic_formula", toml::table{{"tir_file", t.name + "/" + t.name + ".tir"},
                                          {"fit_time_s", fit->seconds},
                                          {"fit_errors", std::move(errors)},
                                          {"not_determined", std::move(undetermined)},
                                          {"coefficients", std::move(coefficients)}});
  }
  return s;
}

std::string tyre_test_fit_line(const TyreTestResult& t, const TyreTestFit& fit) {
  std::string errors;
  for (const ChannelFitError& e : fit.errors)
    if (e.channel == "Fx" || e.channel == "Fy" || e.channel == "Mz")
      errors += fmt::format("{}{} {:.1f}%", errors.empty() ? "" : ", ", e.channel, 100 * e.relative_rms);
  const MagicFormulaCoefficients& c = fit.tir.coefficients;
  // Public PAC2002 files of passenger tyres, for plausibility (Chrono's example data): 185/80R14 at FNOMIN
  // 3800 N and a 245-section sedan tyre at 4850 N.
  // Their relaxation lengths at FNOMIN (evaluator.hpp): 185/80R14 sigma_kappa 715 mm, sigma_alpha 565 mm;
  // sedan 814 mm, 593 mm.
  const RelaxationLengths sigma = relaxation_lengths(c, c.FNOMIN);
  const bool relaxation = c.PTX1 != 0 || c.PTY1 != 0;
  return fmt::format(
      "tyre test '{}': Magic Formula fitted in {:.2f} s, RMS error of peak {}; VERTICAL_STIFFNESS {:.0f} N/mm, "
      "PKX1 {:.1f}, PKY1 {:.1f}, PDX1 {:.2f}, PDY1 {:.2f}, Re(FNOMIN) {:.1f} mm of R0 {:.1f} mm{} (public files: "
      "185/80R14 175 N/mm, PKX1 19.7, PKY1 -12.5, PDX1 1.09, PDY1 0.94{}; 245-section sedan 281 N/mm, PKX1 22.3, "
      "PKY1 -21.9, PDX1 1.17, PDY1 1.05{})",
      t.name, fit.seconds, errors, c.VERTICAL_STIFFNESS * 1e-3, c.PKX1, c.PKY1, c.PDX1, c.PDY1,
      effective_rolling_radius(c, c.FNOMIN) * 1e3, c.UNLOADED_RADIUS * 1e3,
      relaxation ? fmt::format(", relaxation lengths at FNOMIN {:.0f} mm (longitudinal), {:.0f} mm (lateral)",
                               sigma.sigma_kappa * 1e3, sigma.sigma_alpha * 1e3)
                 : "",
      relaxation ? ", 715 and 565 mm" : "", relaxation ? ", 814 and 593 mm" : "");
}

}  // namespace tirefem
