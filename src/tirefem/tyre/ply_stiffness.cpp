#include "tirefem/tyre/ply_stiffness.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace tirefem {
namespace {

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

// Halpin–Tsai, VERIFICATION.md §7: E1 by the rule of mixtures; E2 by Halpin–Tsai with ξ = 2 (circular
// fibres); G12 = Gr (1 + Vc)/(1 − Vc) (the usual approximation); ν12 by the rule of mixtures of the cord's
// and the rubber's Poisson's ratios (cord ν from the ply, default 0.3).
PlyProperties halpin_tsai(const Ply& ply, double vc) {
  const double ec = ply.cord_modulus, er = ply.rubber_modulus;
  const double gr = er / (2.0 * (1.0 + ply.rubber_poisson));
  const double ratio = ec / er;
  const double eta = (ratio - 1.0) / (ratio + 2.0);
  PlyProperties p;
  p.volume_fraction = vc;
  p.E1 = ec * vc + er * (1.0 - vc);
  p.E2 = er * (1.0 + 2.0 * eta * vc) / (1.0 - eta * vc);
  p.G12 = gr * (1.0 + vc) / (1.0 - vc);
  p.nu12 = ply.cord_poisson * vc + ply.rubber_poisson * (1.0 - vc);
  return p;
}

// The tyre-mechanics rule named after Gough (Rubber Chem. Technol. 41, 988 (1968)) and Tangorra (1965),
// as used in S. K. Clark (ed.), "Mechanics of Pneumatic Tires" (NHTSA, 1981), ch. 1. Its assumptions:
// the skim rubber is incompressible (ν = ½) and the cords are far stiffer than the rubber. What follows
// from them, and what is implemented:
//   E1  = Ec Vc + Er (1 − Vc)   cords and rubber stretch together along the cords;
//   E2  = (4/3) Er / (1 − Vc)   across the cords the rubber works in series with rigid cords, and the cords
//                               stop it contracting along them: plane strain, Er / (1 − ν²) = 4 Er / 3;
//   G12 = Gr / (1 − Vc)         in-plane shear of rubber in series with rigid cords, Gr = Er / 3;
//   ν12 = ½                     incompressible rubber, cords inextensible compared with it.
// The ply's rubber_poisson and cord_poisson are not used by this rule. We could not check these forms
// against the original papers. They hold for real plies only (Vc → 0 leaves E2 = 4Er/3, not Er: the
// cord constraint does not fade). For Vc ≈ 0.1–0.35 they give E2 within about ±20 % of Halpin–Tsai (above
// it at low Vc, below at high Vc) and G12 10–25 % below it; E1 is the same.
PlyProperties gough_tangorra(const Ply& ply, double vc) {
  const double ec = ply.cord_modulus, er = ply.rubber_modulus;
  PlyProperties p;
  p.volume_fraction = vc;
  p.E1 = ec * vc + er * (1.0 - vc);
  p.E2 = 4.0 * er / (3.0 * (1.0 - vc));
  p.G12 = er / (3.0 * (1.0 - vc));
  p.nu12 = 0.5;
  return p;
}

}  // namespace

double cord_volume_fraction(const Ply& ply) { return ply.cord_area * ply.ends_per_mm / ply.thickness; }

PlyProperties ply_properties(const Ply& ply, CordRubberRule rule) {
  const double vc = cord_volume_fraction(ply);
  if (!(vc > 0.0 && vc < 1.0))
    throw std::invalid_argument("ply '" + ply.name + "': cord volume fraction must be in (0, 1)");
  switch (rule) {
    case CordRubberRule::halpin_tsai:
      return halpin_tsai(ply, vc);
    case CordRubberRule::gough_tangorra:
      return gough_tangorra(ply, vc);
  }
  throw std::invalid_argument("unknown cord-rubber rule");
}

Eigen::Matrix3d reduced_stiffness(const PlyProperties& p) {
  const double nu21 = p.nu12 * p.E2 / p.E1;
  const double d = 1.0 - p.nu12 * nu21;
  Eigen::Matrix3d q;
  // clang-format off
  q << p.E1 / d,             p.nu12 * p.E2 / d, 0.0,
       p.nu12 * p.E2 / d,    p.E2 / d,          0.0,
       0.0,                  0.0,               p.G12;
  // clang-format on
  return q;
}

Eigen::Vector2d cord_direction(double angle_deg) {
  // Exact for radial and circumferential cords, so such plies give exactly A16 = A26 = 0.
  if (angle_deg == 0.0) return {0.0, 1.0};
  if (std::abs(angle_deg) == 90.0) return {angle_deg > 0 ? 1.0 : -1.0, 0.0};
  const double t = radians(angle_deg);
  return {std::sin(t), std::cos(t)};
}

Eigen::Matrix3d rotate_to_tyre_frame(const Eigen::Matrix3d& q, double angle_deg) {
  const Eigen::Vector2d d = cord_direction(angle_deg);
  const double c = d[0], s = d[1];  // cos and sin of the angle from the meridian to the cords
  // Ply-frame engineering strains from tyre-frame ones: ε_cc = dᵀεd, ε_tt = bᵀεb, γ_ct = 2dᵀεb,
  // with b = (−s, c) across the cords.
  Eigen::Matrix3d t;
  // clang-format off
  t << c * c,         s * s,        c * s,
       s * s,         c * c,       -c * s,
      -2.0 * c * s,   2.0 * c * s,  c * c - s * s;
  // clang-format on
  return t.transpose() * q * t;
}

MembraneStiffness ply_membrane_stiffness(const Ply& ply, CordRubberRule rule) {
  return rotate_to_tyre_frame(reduced_stiffness(ply_properties(ply, rule)), ply.angle_deg) * ply.thickness;
}

MembraneStiffness face_stiffness(const FaceLayup& face) {
  MembraneStiffness a = face.direct_stiffness.value_or(MembraneStiffness::Zero());
  for (const Ply& ply : face.plies) a += ply_membrane_stiffness(ply, face.rule);
  return a;
}

std::vector<CordSoftening> face_cord_softening(const FaceLayup& face) {
  std::vector<CordSoftening> out;
  for (const Ply& ply : face.plies) {
    const double k = (ply.cord_modulus - ply.compression_modulus()) * ply.cord_area * ply.ends_per_mm;
    if (!(k > 0.0)) continue;
    const Eigen::Vector2d d = cord_direction(ply.angle_deg);
    const Eigen::Vector3d m(d[0] * d[0], d[1] * d[1], d[0] * d[1]);
    auto same = std::find_if(out.begin(), out.end(), [&](const CordSoftening& c) { return (c.direction - m).norm() < 1e-12; });
    if (same != out.end()) same->stiffness += k;
    else out.push_back({m, k});
  }
  return out;
}

double cord_strain(const Eigen::Vector3d& e, double angle_deg) {
  const Eigen::Vector2d d = cord_direction(angle_deg);
  return d[0] * d[0] * e[0] + d[1] * d[1] * e[1] + d[0] * d[1] * e[2];
}

}  // namespace tirefem
