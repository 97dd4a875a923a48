#include "tirefem/analysis/tyre_test_fit.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "tirefem/magic_formula/vertical_fit.hpp"

namespace tirefem {
namespace {
// mm → m by a division: 285 mm is then the double nearest 0.285 m, which the .tir prints as "0.285"
// (285 × 1e-3 prints as 0.28500000000000003, since 1e-3 itself is not exact).
double metres(double mm) { return mm / 1000.0; }
}  // namespace

RigData tyre_test_rig_data(const TyreTestResult& t) {
  RigData d;
  d.FNOMIN = t.nominal_load_N;
  d.UNLOADED_RADIUS = metres(t.unloaded_radius_mm);
  for (const TyreTestRow& r : t.rows)
    d.points.push_back({r.Fz_N, r.kappa, r.alpha_rad, r.gamma_rad, r.Fx_N, r.Fy_N, r.Mz_Nm, r.Mx_Nm});
  for (const TyreTestLoad& l : t.loads)
    if (l.effective_rolling_radius_mm && l.Fz_N > 0)
      d.radii.push_back({l.Fz_N, metres(*l.effective_rolling_radius_mm), metres(l.loaded_radius_mm)});
  for (const TyreTestLoad& l : t.loads) {
    RelaxationPoint p{l.Fz_N, {}, {}};
    if (l.longitudinal_relaxation_length_mm) p.sigma_kappa = metres(*l.longitudinal_relaxation_length_mm);
    if (l.lateral_relaxation_length_mm) p.sigma_alpha = metres(*l.lateral_relaxation_length_mm);
    if (l.Fz_N > 0 && (p.sigma_kappa || p.sigma_alpha)) d.relaxation.push_back(p);
  }
  if (t.vertical)
    for (const LoadPoint& p : t.vertical->points)
      if (p.patch.Qz_N > 0 && p.deflection_mm > 0) d.load_deflection.push_back({metres(p.deflection_mm), p.patch.Qz_N});
  return d;
}

TyreTestFit fit_tyre_test(const TyreTestResult& t, const TyreDescription& tyre, const std::string& source) {
  const RigData data = tyre_test_rig_data(t);
  const RigFit fit = fit_rig_data(data);
  TyreTestFit out;
  out.errors = fit.errors;
  out.not_determined = fit.not_determined;
  out.seconds = fit.seconds;
  TirFile& f = out.tir;
  f.coefficients = fit.coefficients;
  MagicFormulaCoefficients& c = f.coefficients;
  // Dimensions from the carcass line (the faces and the tread add a few mm outside it).
  double width = 0;
  for (const Eigen::Vector2d& p : tyre.profile) width = std::max(width, 2 * p.x());
  c.UNLOADED_RADIUS = data.UNLOADED_RADIUS;
  c.WIDTH = metres(width);
  c.RIM_RADIUS = metres(tyre.profile.back().y());
  c.RIM_WIDTH = metres(2 * tyre.profile.back().x());
  c.ASPECT_RATIO = width > 0 ? (t.unloaded_radius_mm - tyre.profile.back().y()) / width : 0.0;
  c.FNOMIN = t.nominal_load_N;
  // The ranges the rig covered.
  double fz_min = 1e300, fz_max = 0, k_min = 0, k_max = 0, a_min = 0, a_max = 0, g_min = 0, g_max = 0;
  for (const RigPoint& p : data.points) {
    fz_min = std::min(fz_min, p.FZ), fz_max = std::max(fz_max, p.FZ);
    k_min = std::min(k_min, p.KAPPA), k_max = std::max(k_max, p.KAPPA);
    a_min = std::min(a_min, p.ALPHA), a_max = std::max(a_max, p.ALPHA);
    g_min = std::min(g_min, p.GAMMA), g_max = std::max(g_max, p.GAMMA);
  }
  if (!data.points.empty()) {
    c.FZMIN = fz_min, c.FZMAX = fz_max;
    c.KPUMIN = k_min, c.KPUMAX = k_max;
    c.ALPMIN = a_min, c.ALPMAX = a_max;
    c.CAMMIN = g_min, c.CAMMAX = g_max;
  }
  f.header_comments = {
      fmt::format("tirefem virtual flat-track test '{}' of {} ({})", t.name, tyre.name, source),
      "steady-state PAC2002 coefficients fitted to finite-element rolling states (no dynamics, no speed effects)",
      "relaxation lengths PTX*, PTY*: slip (cornering) stiffness over the standing tyre's longitudinal (lateral) "
      "stiffness, tread glued to the plane",
      "coefficients marked 'not determined' hold their neutral values (or, where 0 is singular, an assumed one): "
      "the test did not excite them"};
  if (!fit.combined_slip_points)
    f.header_comments.push_back(
        "no combined-slip points: the combined-slip coefficients (RBX*, RBY*, RCX1, RCY1, REX*, REY*, RHX1, RHY*, "
        "RVY*, SSZ*) are 0, with which the file's Fx and Fy do not reduce each other: not for combined slip "
        "(a tyre test's `combined` grid fits RBX1-2, RCX1, RBY1-2, RCY1)");
  // The standing tyre's stiffness at the load nearest FNOMIN: MF 6.1 keeps it in [STRUCTURAL], which PAC2002
  // has not; a comment, for the user of a transient or MF 6.1 model.
  const TyreTestLoad* nominal = nullptr;
  for (const TyreTestLoad& l : t.loads)
    if (l.lateral_stiffness_N_per_mm &&
        (!nominal || std::abs(l.Fz_N - t.nominal_load_N) < std::abs(nominal->Fz_N - t.nominal_load_N)))
      nominal = &l;
  if (nominal)
    f.header_comments.push_back(fmt::format(
        "standing tyre at Fz = {:.0f} N, tread glued to the plane: LONGITUDINAL_STIFFNESS {:.0f} N/m, "
        "LATERAL_STIFFNESS {:.0f} N/m, YAW_STIFFNESS {:.0f} N m/rad (MF 6.1 [STRUCTURAL] keys)",
        nominal->Fz_N, nominal->longitudinal_stiffness_N_per_mm.value_or(0.0) * 1e3, *nominal->lateral_stiffness_N_per_mm * 1e3,
        nominal->yaw_stiffness_Nmm_per_rad.value_or(0.0) * 1e-3));
  // PKY2 and PTY2 divide Fz: their neutral value 0 would be singular, so they hold an assumed one.
  for (const std::string& key : fit.not_determined) {
    const CoefficientInfo* info = find_coefficient(key);
    f.notes[key] = !info || c.*(info->member) == info->neutral
                       ? "not determined by the test: neutral value"
                       : "not determined by the test: an assumed value, its neutral value 0 being singular";
  }
  for (const NeverDetermined& k : never_determined_by_the_rig())
    switch (k.reason) {
      case UndeterminedReason::rolling_resistance:
        f.notes[k.key] = "not determined: the model is elastic (no hysteresis), no rolling resistance; neutral value";
        break;
      case UndeterminedReason::steady_state:
        f.notes[k.key] = "not determined by a steady-state test: neutral value";
        break;
    }
  for (const char* key : combined_slip_keys())
    if (std::find(fit.not_determined.begin(), fit.not_determined.end(), key) != fit.not_determined.end())
      f.notes[key] = fit.combined_slip_points
                         ? "not determined by the test's combined-slip points: neutral value"
                         : "not determined: no combined-slip points; neutral value, with which kappa and alpha do "
                           "not reduce each other's force";
  // A BREFF fit that ran into a bound ends on it (vertical_fit.cpp): the file says so, and why.
  if (c.BREFF == kMaxBreff)
    f.notes["BREFF"] = fmt::format("at the fit's bound {}: the test's loads cannot tell atan(BREFF Fz/FNOMIN) from "
                                   "pi/2, DREFF and FREFF fitted with it", kMaxBreff);
  else if (c.BREFF == kMinBreff)
    f.notes["BREFF"] = fmt::format("at the fit's bound {}: atan(BREFF Fz/FNOMIN) is then nearly a line in Fz, which "
                                   "the test's loads cannot tell from FREFF's; DREFF and FREFF fitted with it", kMinBreff);
  f.notes["WIDTH"] = "twice the carcass line's largest x";
  f.notes["RIM_RADIUS"] = "bead point of the carcass line";
  f.notes["RIM_WIDTH"] = "twice the bead point's x";
  return out;
}

}  // namespace tirefem
