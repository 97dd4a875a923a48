#pragma once
// The whole PAC2002 fit of a (virtual) flat-track rig's table: pure longitudinal, pure lateral, aligning,
// overturning moment, load-deflection, effective rolling radius and the relaxation lengths, in that order.
//
// Point selection: the longitudinal group from points with alpha = 0 and gamma = 0; the lateral and aligning
// groups from points with kappa = 0 (gamma = 0 for the pure-slip passes, the cambered sweeps for the camber
// terms, see fitter.hpp); the overturning moment Mx = R0 Fz (QSX1 - QSX2 gamma + QSX3 Fy/Fz0) (4.E69, LVMX
// = LMX = 1) by linear least squares from the points with kappa = 0, with the fitted model's Fy (QSX2
// needs cambered points, QSX3 slip angles). Combined-slip points (kappa and alpha both non-zero) give the
// combined-slip weighting functions (combined_slip_fit.hpp); without them those keys stay neutral.
#include <span>
#include <string>
#include <vector>

#include "tirefem/magic_formula/combined_slip_fit.hpp"
#include "tirefem/magic_formula/fitter.hpp"
#include "tirefem/magic_formula/relaxation_fit.hpp"
#include "tirefem/magic_formula/vertical_fit.hpp"

namespace tirefem {

// One row of the rig's table: TYDEX/ISO W-axis signs, SI units.
struct RigPoint {
  double FZ = 0;     // N
  double KAPPA = 0;  // -
  double ALPHA = 0;  // rad
  double GAMMA = 0;  // rad
  double FX = 0, FY = 0;  // N
  double MZ = 0, MX = 0;  // N m
};

// Per load, free rolling: effective rolling radius (forward speed / spin) and loaded radius (wheel centre
// height), m.
struct RigLoadRadii {
  double FZ = 0;
  double effective_radius = 0;
  double loaded_radius = 0;
};

struct RigData {
  std::vector<RigPoint> points;
  std::vector<RigLoadRadii> radii;
  std::vector<LoadDeflectionPoint> load_deflection;  // (deflection, Fz); empty: R0 - loaded radius of `radii`
  std::vector<RelaxationPoint> relaxation;           // per load, where measured (relaxation_fit.hpp)
  double FNOMIN = 0;           // N
  double UNLOADED_RADIUS = 0;  // m
};

struct RigFit {
  MagicFormulaCoefficients coefficients;      // undetermined coefficients hold their neutral values
  std::vector<ChannelFitError> errors;        // Fx, Fy, Mz, Mx, Fz (load-deflection), Re, sigma_kappa, sigma_alpha
  std::vector<std::string> not_determined;    // keys of the fitted groups that the data do not determine
  std::vector<GroupFitResult> groups;         // the three slip groups' details (evaluations, time)
  bool combined_slip_points = false;          // the combined-slip weighting functions were fitted
  double seconds = 0;
};

// The keys a steady-state rig never determines, by why (fit_rig_data lists them in not_determined; the
// .tir writer's notes say why): rolling resistance (QSY*: the model is elastic), and speed, damping and
// transient terms. (The combined-slip keys: combined_slip_fit.hpp.)
enum class UndeterminedReason { rolling_resistance, steady_state };
struct NeverDetermined {
  const char* key;
  UndeterminedReason reason;
};
std::span<const NeverDetermined> never_determined_by_the_rig();

// Throws std::invalid_argument when FNOMIN or UNLOADED_RADIUS is not positive or a group has too few points.
RigFit fit_rig_data(const RigData& data);

}  // namespace tirefem
