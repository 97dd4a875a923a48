#pragma once
// The loaded standing tyre's tangential stiffness (a flat-plate test): at the static footprint the tread
// is glued to the road where it stands (forms/stuck_tread_form.hpp) and the road is moved in its plane by
// a small amount relative to the rim: along the travel (the longitudinal stiffness Cx), along the wheel
// axis (the lateral stiffness Cy) and turned about its normal through the centre of pressure (the yaw, or
// torsional, stiffness Cψ). Each is the force (moment) of the road on the tyre per unit of that motion,
// from one linear solve with the footprint's tangent: the shell, the inflation pressure and the Winkler
// tread as at the footprint, plus the tread's shear springs (one factorisation for all three).
//
// With the slip stiffness Kxκ and the cornering stiffness Kyα of the rolling tyre they give the
// relaxation lengths σκ = Kxκ/Cx and σα = Kyα/Cy (Pacejka, Tyre and Vehicle Dynamics, the single contact
// point transient model): the distance the tyre rolls before a change of slip builds its force up, which
// transient tyre models (the Magic Formula's PTX*, PTY*) need. For a rigid carcass Cy is the tread's own
// Σ (G/hp) w over the patch, and σα the mean distance of the contact area from the patch's leading edge
// (a for a rectangular patch of length 2a).
#include <cmath>
#include <numbers>
#include <optional>

#include "tirefem/analysis/footprint.hpp"
#include "tirefem/road/support_surface.hpp"
#include "tirefem/tyre/tyre_mesh.hpp"

namespace tirefem {

struct StandingStiffness {
  double longitudinal_N_per_mm = 0.0;       // Cx (a half model's doubled)
  std::optional<double> lateral_N_per_mm;   // Cy: full model only (the half model's symmetry plane holds it)
  std::optional<double> yaw_Nmm_per_rad;    // Cψ: full model only
  double tread_shear_N_per_mm = 0.0;        // Σ (G/hp) w over the points in contact: Cx and Cy of a rigid carcass
  Eigen::Vector3d centre_mm = Eigen::Vector3d::Zero();  // the centre of pressure the road turns about
  int contact_points = 0;
  bool stable = true;  // the glued tyre's tangent positive definite (else the footprint was an unstable state)
  int factorizations = 0;
  double assembly_s = 0.0, analysis_s = 0.0, factorization_s = 0.0;  // of the tangent, its ordering, its factor
  double time_s = 0.0;
};

// σ = K/C, mm: a slip stiffness K (N per unit κ, or a cornering stiffness per radian) over a standing
// stiffness C (N/mm); nothing without either or with C ≤ 0.
inline std::optional<double> relaxation_length_mm(std::optional<double> slip_stiffness_N,
                                                  std::optional<double> stiffness_N_per_mm) {
  if (!slip_stiffness_N || !stiffness_N_per_mm || !(*stiffness_N_per_mm > 0)) return std::nullopt;
  return std::abs(*slip_stiffness_N) / *stiffness_N_per_mm;
}
// A cornering stiffness per degree as per radian, and the yaw stiffness in N·m per degree, as reported.
inline std::optional<double> per_radian(std::optional<double> per_degree) {
  return per_degree ? std::optional(*per_degree * 180.0 / std::numbers::pi) : std::nullopt;
}
inline double Nm_per_deg(double Nmm_per_rad) { return Nmm_per_rad * 1e-3 * std::numbers::pi / 180.0; }

// At the converged static state u (support moved up by `deflection`) of the inflated tyre; `points` the
// tread points of that state (StaticContactResult::tread_points). Nothing when no point is in contact.
// `responses`, when given, receives the tyre's displacement per unit of each road motion (full length: along
// the travel, and on the full model across it and the turn, in that order).
std::optional<StandingStiffness> standing_stiffness(const TyreMesh& tm, const TyreDescription& tyre,
                                                    double pressure, const SupportSurface& support,
                                                    double deflection, const std::vector<TreadPoint>& points,
                                                    const Eigen::VectorXd& u,
                                                    std::vector<Eigen::VectorXd>* responses = nullptr);

}  // namespace tirefem
