#include "tirefem/magic_formula/coefficients.hpp"

#include <algorithm>
#include <array>

namespace tirefem {
namespace {

// The key is spelt once: the member and the `.tir` key are the same word.
#define TIR_KEY(key, section, neutral, description) \
  CoefficientInfo { #key, section, &MagicFormulaCoefficients::key, neutral, description }
#define TIR_OPTIONAL_KEY(key, section, neutral, description) \
  CoefficientInfo { #key, section, &MagicFormulaCoefficients::key, neutral, description, true }

constexpr std::string_view header = "MDI_HEADER";
constexpr std::string_view model = "MODEL";
constexpr std::string_view dimension = "DIMENSION";
constexpr std::string_view vertical = "VERTICAL";
constexpr std::string_view long_slip = "LONG_SLIP_RANGE";
constexpr std::string_view slip_angle = "SLIP_ANGLE_RANGE";
constexpr std::string_view inclination = "INCLINATION_ANGLE_RANGE";
constexpr std::string_view vertical_force = "VERTICAL_FORCE_RANGE";
constexpr std::string_view scaling = "SCALING_COEFFICIENTS";
constexpr std::string_view longitudinal = "LONGITUDINAL_COEFFICIENTS";
constexpr std::string_view overturning = "OVERTURNING_COEFFICIENTS";
constexpr std::string_view lateral = "LATERAL_COEFFICIENTS";
constexpr std::string_view rolling = "ROLLING_COEFFICIENTS";
constexpr std::string_view aligning = "ALIGNING_COEFFICIENTS";

const std::array table{
    TIR_KEY(FILE_VERSION, header, 3.0, "File version"),
    TIR_KEY(FITTYP, model, 6, "Magic Formula version: 6 = MF 5.2 / PAC2002"),
    TIR_KEY(USE_MODE, model, 4, "Tyre use switch: 4 = combined forces and moments"),
    TIR_KEY(VXLOW, model, 1, "Lower speed boundary (m/s)"),
    TIR_KEY(LONGVL, model, 16.7, "Measurement speed (m/s)"),
    TIR_KEY(UNLOADED_RADIUS, dimension, 0, "Free tyre radius (m)"),
    TIR_KEY(WIDTH, dimension, 0, "Nominal section width of the tyre (m)"),
    TIR_KEY(ASPECT_RATIO, dimension, 0, "Nominal aspect ratio"),
    TIR_KEY(RIM_RADIUS, dimension, 0, "Nominal rim radius (m)"),
    TIR_KEY(RIM_WIDTH, dimension, 0, "Rim width (m)"),
    TIR_KEY(FNOMIN, vertical, 0, "Nominal wheel load (N)"),
    TIR_KEY(VERTICAL_STIFFNESS, vertical, 0, "Tyre vertical stiffness (N/m)"),
    TIR_KEY(VERTICAL_DAMPING, vertical, 0, "Tyre vertical damping (N s/m)"),
    TIR_KEY(BREFF, vertical, 0, "Low load stiffness of effective rolling radius"),
    TIR_KEY(DREFF, vertical, 0, "Peak value of effective rolling radius"),
    TIR_KEY(FREFF, vertical, 0, "High load stiffness of effective rolling radius"),
    TIR_KEY(Q_RE0, vertical, 1, "Ratio of free tyre radius with nominal tyre radius"),
    TIR_KEY(Q_V1, vertical, 0, "Tyre radius increase with speed"),
    TIR_KEY(Q_V2, vertical, 0, "Vertical stiffness increase with speed"),
    TIR_OPTIONAL_KEY(Q_FZ1, vertical, 0, "Linear load-deflection coefficient"),
    TIR_KEY(Q_FZ2, vertical, 0, "Quadratic load-deflection coefficient"),
    TIR_KEY(Q_FCX, vertical, 0, "Longitudinal force influence on vertical stiffness"),
    TIR_KEY(Q_FCY, vertical, 0, "Lateral force influence on vertical stiffness"),
    TIR_KEY(KPUMIN, long_slip, -1.5, "Minimum valid wheel slip"),
    TIR_KEY(KPUMAX, long_slip, 1.5, "Maximum valid wheel slip"),
    TIR_KEY(ALPMIN, slip_angle, -1.5708, "Minimum valid slip angle (rad)"),
    TIR_KEY(ALPMAX, slip_angle, 1.5708, "Maximum valid slip angle (rad)"),
    TIR_KEY(CAMMIN, inclination, -0.26181, "Minimum valid camber angle (rad)"),
    TIR_KEY(CAMMAX, inclination, 0.26181, "Maximum valid camber angle (rad)"),
    TIR_KEY(FZMIN, vertical_force, 0, "Minimum allowed wheel load (N)"),
    TIR_KEY(FZMAX, vertical_force, 0, "Maximum allowed wheel load (N)"),
    TIR_KEY(LFZO, scaling, 1, "Scale factor of nominal (rated) load"),
    TIR_KEY(LCX, scaling, 1, "Scale factor of Fx shape factor"),
    TIR_KEY(LMUX, scaling, 1, "Scale factor of Fx peak friction coefficient"),
    TIR_KEY(LEX, scaling, 1, "Scale factor of Fx curvature factor"),
    TIR_KEY(LKX, scaling, 1, "Scale factor of Fx slip stiffness"),
    TIR_KEY(LHX, scaling, 1, "Scale factor of Fx horizontal shift"),
    TIR_KEY(LVX, scaling, 1, "Scale factor of Fx vertical shift"),
    TIR_KEY(LGAX, scaling, 1, "Scale factor of camber for Fx"),
    TIR_KEY(LCY, scaling, 1, "Scale factor of Fy shape factor"),
    TIR_KEY(LMUY, scaling, 1, "Scale factor of Fy peak friction coefficient"),
    TIR_KEY(LEY, scaling, 1, "Scale factor of Fy curvature factor"),
    TIR_KEY(LKY, scaling, 1, "Scale factor of Fy cornering stiffness"),
    TIR_KEY(LHY, scaling, 1, "Scale factor of Fy horizontal shift"),
    TIR_KEY(LVY, scaling, 1, "Scale factor of Fy vertical shift"),
    TIR_KEY(LGAY, scaling, 1, "Scale factor of camber for Fy"),
    TIR_KEY(LTR, scaling, 1, "Scale factor of peak of pneumatic trail"),
    TIR_KEY(LRES, scaling, 1, "Scale factor for offset of residual torque"),
    TIR_KEY(LGAZ, scaling, 1, "Scale factor of camber for Mz"),
    TIR_KEY(LXAL, scaling, 1, "Scale factor of alpha influence on Fx"),
    TIR_KEY(LYKA, scaling, 1, "Scale factor of kappa influence on Fy"),
    TIR_KEY(LVYKA, scaling, 1, "Scale factor of kappa induced Fy"),
    TIR_KEY(LS, scaling, 1, "Scale factor of moment arm of Fx"),
    TIR_KEY(LSGKP, scaling, 1, "Scale factor of relaxation length of Fx"),
    TIR_KEY(LSGAL, scaling, 1, "Scale factor of relaxation length of Fy"),
    TIR_KEY(LGYR, scaling, 1, "Scale factor of gyroscopic torque"),
    TIR_KEY(LMX, scaling, 1, "Scale factor of overturning couple"),
    TIR_KEY(LVMX, scaling, 1, "Scale factor of Mx vertical shift"),
    TIR_KEY(LMY, scaling, 1, "Scale factor of rolling resistance torque"),
    TIR_KEY(PCX1, longitudinal, 0, "Shape factor Cfx for longitudinal force"),
    TIR_KEY(PDX1, longitudinal, 0, "Longitudinal friction Mux at Fznom"),
    TIR_KEY(PDX2, longitudinal, 0, "Variation of friction Mux with load"),
    TIR_KEY(PDX3, longitudinal, 0, "Variation of friction Mux with camber squared"),
    TIR_KEY(PEX1, longitudinal, 0, "Longitudinal curvature Efx at Fznom"),
    TIR_KEY(PEX2, longitudinal, 0, "Variation of curvature Efx with load"),
    TIR_KEY(PEX3, longitudinal, 0, "Variation of curvature Efx with load squared"),
    TIR_KEY(PEX4, longitudinal, 0, "Factor in curvature Efx while driving"),
    TIR_KEY(PKX1, longitudinal, 0, "Longitudinal slip stiffness Kfx/Fz at Fznom"),
    TIR_KEY(PKX2, longitudinal, 0, "Variation of slip stiffness Kfx/Fz with load"),
    TIR_KEY(PKX3, longitudinal, 0, "Exponent in slip stiffness Kfx/Fz with load"),
    TIR_KEY(PHX1, longitudinal, 0, "Horizontal shift Shx at Fznom"),
    TIR_KEY(PHX2, longitudinal, 0, "Variation of shift Shx with load"),
    TIR_KEY(PVX1, longitudinal, 0, "Vertical shift Svx/Fz at Fznom"),
    TIR_KEY(PVX2, longitudinal, 0, "Variation of shift Svx/Fz with load"),
    TIR_KEY(RBX1, longitudinal, 0, "Slope factor for combined slip Fx reduction"),
    TIR_KEY(RBX2, longitudinal, 0, "Variation of slope Fx reduction with kappa"),
    TIR_OPTIONAL_KEY(RBX3, longitudinal, 0, "Influence of camber on stiffness for Fx combined (MF 6.1)"),
    TIR_KEY(RCX1, longitudinal, 0, "Shape factor for combined slip Fx reduction"),
    TIR_KEY(REX1, longitudinal, 0, "Curvature factor of combined Fx"),
    TIR_KEY(REX2, longitudinal, 0, "Curvature factor of combined Fx with load"),
    TIR_KEY(RHX1, longitudinal, 0, "Shift factor for combined slip Fx reduction"),
    TIR_KEY(PTX1, longitudinal, 0, "Relaxation length SigKap0/Fz at Fznom"),
    TIR_KEY(PTX2, longitudinal, 0, "Variation of SigKap0/Fz with load"),
    TIR_KEY(PTX3, longitudinal, 0, "Variation of SigKap0/Fz with exponent of load"),
    TIR_KEY(QSX1, overturning, 0, "Lateral force induced overturning moment"),
    TIR_KEY(QSX2, overturning, 0, "Camber induced overturning couple"),
    TIR_KEY(QSX3, overturning, 0, "Fy induced overturning couple"),
    TIR_KEY(PCY1, lateral, 0, "Shape factor Cfy for lateral forces"),
    TIR_KEY(PDY1, lateral, 0, "Lateral friction Muy"),
    TIR_KEY(PDY2, lateral, 0, "Variation of friction Muy with load"),
    TIR_KEY(PDY3, lateral, 0, "Variation of friction Muy with squared camber"),
    TIR_KEY(PEY1, lateral, 0, "Lateral curvature Efy at Fznom"),
    TIR_KEY(PEY2, lateral, 0, "Variation of curvature Efy with load"),
    TIR_KEY(PEY3, lateral, 0, "Zero order camber dependency of curvature Efy"),
    TIR_KEY(PEY4, lateral, 0, "Variation of curvature Efy with camber"),
    TIR_KEY(PKY1, lateral, 0, "Maximum value of stiffness Kfy/Fznom"),
    TIR_KEY(PKY2, lateral, 0, "Load at which Kfy reaches maximum value"),
    TIR_KEY(PKY3, lateral, 0, "Variation of Kfy/Fznom with camber"),
    TIR_KEY(PHY1, lateral, 0, "Horizontal shift Shy at Fznom"),
    TIR_KEY(PHY2, lateral, 0, "Variation of shift Shy with load"),
    TIR_KEY(PHY3, lateral, 0, "Variation of shift Shy with camber"),
    TIR_KEY(PVY1, lateral, 0, "Vertical shift in Svy/Fz at Fznom"),
    TIR_KEY(PVY2, lateral, 0, "Variation of shift Svy/Fz with load"),
    TIR_KEY(PVY3, lateral, 0, "Variation of shift Svy/Fz with camber"),
    TIR_KEY(PVY4, lateral, 0, "Variation of shift Svy/Fz with camber and load"),
    TIR_KEY(RBY1, lateral, 0, "Slope factor for combined Fy reduction"),
    TIR_KEY(RBY2, lateral, 0, "Variation of slope Fy reduction with alpha"),
    TIR_KEY(RBY3, lateral, 0, "Shift term for alpha in slope Fy reduction"),
    TIR_KEY(RCY1, lateral, 0, "Shape factor for combined Fy reduction"),
    TIR_KEY(REY1, lateral, 0, "Curvature factor of combined Fy"),
    TIR_KEY(REY2, lateral, 0, "Curvature factor of combined Fy with load"),
    TIR_KEY(RHY1, lateral, 0, "Shift factor for combined Fy reduction"),
    TIR_KEY(RHY2, lateral, 0, "Shift factor for combined Fy reduction with load"),
    TIR_KEY(RVY1, lateral, 0, "Kappa induced side force Svyk/Muy*Fz at Fznom"),
    TIR_KEY(RVY2, lateral, 0, "Variation of Svyk/Muy*Fz with load"),
    TIR_KEY(RVY3, lateral, 0, "Variation of Svyk/Muy*Fz with camber"),
    TIR_KEY(RVY4, lateral, 0, "Variation of Svyk/Muy*Fz with alpha"),
    TIR_KEY(RVY5, lateral, 0, "Variation of Svyk/Muy*Fz with kappa"),
    TIR_KEY(RVY6, lateral, 0, "Variation of Svyk/Muy*Fz with atan(kappa)"),
    TIR_KEY(PTY1, lateral, 0, "Peak value of relaxation length SigAlp0/R0"),
    TIR_KEY(PTY2, lateral, 0, "Value of Fz/Fznom where SigAlp0 is extreme"),
    TIR_KEY(QSY1, rolling, 0, "Rolling resistance torque coefficient"),
    TIR_KEY(QSY2, rolling, 0, "Rolling resistance torque depending on Fx"),
    TIR_KEY(QSY3, rolling, 0, "Rolling resistance torque depending on speed"),
    TIR_KEY(QSY4, rolling, 0, "Rolling resistance torque depending on speed^4"),
    TIR_KEY(QBZ1, aligning, 0, "Trail slope factor for trail Bpt at Fznom"),
    TIR_KEY(QBZ2, aligning, 0, "Variation of slope Bpt with load"),
    TIR_KEY(QBZ3, aligning, 0, "Variation of slope Bpt with load squared"),
    TIR_KEY(QBZ4, aligning, 0, "Variation of slope Bpt with camber"),
    TIR_KEY(QBZ5, aligning, 0, "Variation of slope Bpt with absolute camber"),
    TIR_KEY(QBZ9, aligning, 0, "Slope factor Br of residual torque Mzr"),
    TIR_KEY(QBZ10, aligning, 0, "Slope factor Br of residual torque Mzr with By*Cy"),
    TIR_KEY(QCZ1, aligning, 0, "Shape factor Cpt for pneumatic trail"),
    TIR_KEY(QDZ1, aligning, 0, "Peak trail Dpt = Dpt*(Fz/Fznom*R0)"),
    TIR_KEY(QDZ2, aligning, 0, "Variation of peak Dpt with load"),
    TIR_KEY(QDZ3, aligning, 0, "Variation of peak Dpt with camber"),
    TIR_KEY(QDZ4, aligning, 0, "Variation of peak Dpt with camber squared"),
    TIR_KEY(QDZ6, aligning, 0, "Peak residual torque Dmr = Dmr/(Fz*R0)"),
    TIR_KEY(QDZ7, aligning, 0, "Variation of peak factor Dmr with load"),
    TIR_KEY(QDZ8, aligning, 0, "Variation of peak factor Dmr with camber"),
    TIR_KEY(QDZ9, aligning, 0, "Variation of peak factor Dmr with camber and load"),
    TIR_KEY(QEZ1, aligning, 0, "Trail curvature Ept at Fznom"),
    TIR_KEY(QEZ2, aligning, 0, "Variation of curvature Ept with load"),
    TIR_KEY(QEZ3, aligning, 0, "Variation of curvature Ept with load squared"),
    TIR_KEY(QEZ4, aligning, 0, "Variation of curvature Ept with sign of Alpha-t"),
    TIR_KEY(QEZ5, aligning, 0, "Variation of Ept with camber and sign Alpha-t"),
    TIR_KEY(QHZ1, aligning, 0, "Trail horizontal shift Sht at Fznom"),
    TIR_KEY(QHZ2, aligning, 0, "Variation of shift Sht with load"),
    TIR_KEY(QHZ3, aligning, 0, "Variation of shift Sht with camber"),
    TIR_KEY(QHZ4, aligning, 0, "Variation of shift Sht with camber and load"),
    TIR_KEY(SSZ1, aligning, 0, "Nominal value of s/R0: effect of Fx on Mz"),
    TIR_KEY(SSZ2, aligning, 0, "Variation of distance s/R0 with Fy/Fznom"),
    TIR_KEY(SSZ3, aligning, 0, "Variation of distance s/R0 with camber"),
    TIR_KEY(SSZ4, aligning, 0, "Variation of distance s/R0 with load and camber"),
    TIR_KEY(QTZ1, aligning, 0, "Gyration torque constant"),
    TIR_KEY(MBELT, aligning, 0, "Belt mass of the wheel (kg)"),
};

#undef TIR_KEY
#undef TIR_OPTIONAL_KEY

}  // namespace

std::span<const CoefficientInfo> coefficient_table() { return table; }

const CoefficientInfo* find_coefficient(std::string_view key) {
  const auto it = std::find_if(table.begin(), table.end(), [&](const CoefficientInfo& info) { return info.key == key; });
  return it == table.end() ? nullptr : &*it;
}

}  // namespace tirefem
