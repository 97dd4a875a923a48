#pragma once
// Fits of the [VERTICAL] section: the load-deflection curve and the effective rolling radius.
//
// Load-deflection, as the MF-Tyre 5.2/6.1 readers have it (MFeval; MBSim's MF code:
// Q_FZ1 = sqrt((Cz R0/Fz0)^2 - 4 Q_FZ2)): Fz = FNOMIN (Q_FZ1 rho/R0 + Q_FZ2 (rho/R0)^2), rho the deflection,
// R0 = UNLOADED_RADIUS; VERTICAL_STIFFNESS is the slope at Fz = FNOMIN, (FNOMIN/R0) sqrt(Q_FZ1^2 + 4 Q_FZ2).
// Chrono's ChPac02Tire (no vertical table) uses the linear Fz = VERTICAL_STIFFNESS rho (its
// Q_FZ1 = Cz R0/FNOMIN, Q_FZ2 = 0): with a quadratic Q_FZ2 it sees the stiffness at the nominal load.
// Fitted by linear least squares; Q_FZ2 needs 3 distinct deflections, else Q_FZ2 = 0 (linear).
//
// Effective rolling radius, the MF-Tyre manual's form (evaluator.hpp, effective_rolling_radius; Pacejka's
// book writes Cz rho/Fz0 for Fz/Fz0, the same for a linear spring):
// Re = R0 Q_RE0 - (FNOMIN/Cz)(DREFF atan(BREFF Fz/FNOMIN) + FREFF Fz/FNOMIN), Q_RE0 = 1, Cz the
// VERTICAL_STIFFNESS already in the coefficients. DREFF and FREFF enter linearly: BREFF is first chosen on
// a logarithmic grid (0.1..100) with DREFF, FREFF solved linearly, then all three by Levenberg-Marquardt,
// BREFF kept within the grid's range (beyond 100 the rig's loads cannot tell atan(BREFF rho) from π/2).
// Needs 3 distinct loads (2: FREFF only, BREFF = DREFF = 0).
#include <span>
#include <vector>

#include "tirefem/magic_formula/fitter.hpp"

namespace tirefem {

// BREFF's range in the fit (vertical_fit.cpp says why it is bounded).
inline constexpr double kMinBreff = 0.1, kMaxBreff = 100.0;

struct LoadDeflectionPoint {
  double deflection = 0;  // m
  double Fz = 0;          // N
};

struct RollingRadiusPoint {
  double Fz = 0;                // N
  double effective_radius = 0;  // m, free rolling: forward speed / wheel spin
};

// Sets Q_FZ1, Q_FZ2 and VERTICAL_STIFFNESS; the error is of Fz. `not_determined` gains Q_FZ2 when too few
// deflections.
ChannelFitError fit_load_deflection(std::span<const LoadDeflectionPoint> points, MagicFormulaCoefficients& c,
                                    std::vector<std::string>& not_determined);

// Sets BREFF, DREFF, FREFF (Q_RE0 = 1); the error is of Re (m), its peak the largest fall R0 - Re.
ChannelFitError fit_effective_rolling_radius(std::span<const RollingRadiusPoint> points, MagicFormulaCoefficients& c,
                                             std::vector<std::string>& not_determined);

}  // namespace tirefem
