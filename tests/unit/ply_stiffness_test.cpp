// Cord–rubber rules and lamination (VERIFICATION.md §7) against hand formulas and the known properties of
// laminates: a balanced ±θ pair has no shear–extension coupling, crossed steel belts have an in-plane
// Poisson's ratio near cot²θ, a single ply at 0° or 90° reproduces its own moduli.
#include "tirefem/tyre/ply_stiffness.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace tirefem {
namespace {

Ply steel_belt(double angle) {  // the example tyre's belts
  Ply p;
  p.name = "belt";
  p.cord_modulus = 160000.0;
  p.cord_area = 0.196;
  p.ends_per_mm = 0.8;
  p.angle_deg = angle;
  p.thickness = 1.2;
  p.rubber_modulus = 6.0;
  return p;
}

Ply polyester_carcass() {
  Ply p;
  p.name = "carcass";
  p.cord_modulus = 3500.0;
  p.cord_area = 0.33;
  p.ends_per_mm = 1.0;
  p.angle_deg = 90.0;
  p.thickness = 1.0;
  p.rubber_modulus = 4.0;
  return p;
}

double rel(double a, double b) { return std::abs(a - b) / std::max(std::abs(a), std::abs(b)); }

TEST(PlyStiffness, HalpinTsaiMatchesHandFormulas) {
  const Ply p = steel_belt(22.0);
  const double vc = 0.196 * 0.8 / 1.2;
  const double ratio = 160000.0 / 6.0, eta = (ratio - 1) / (ratio + 2), gr = 6.0 / (2 * 1.49);
  const PlyProperties q = ply_properties(p, CordRubberRule::halpin_tsai);
  EXPECT_NEAR(q.volume_fraction, vc, 1e-15);
  EXPECT_LT(rel(q.E1, 160000.0 * vc + 6.0 * (1 - vc)), 1e-14);
  EXPECT_LT(rel(q.E2, 6.0 * (1 + 2 * eta * vc) / (1 - eta * vc)), 1e-14);
  EXPECT_LT(rel(q.G12, gr * (1 + vc) / (1 - vc)), 1e-14);
  EXPECT_LT(rel(q.nu12, 0.3 * vc + 0.49 * (1 - vc)), 1e-14);
}

TEST(PlyStiffness, GoughTangorraMatchesItsFormulas) {
  const Ply p = polyester_carcass();
  const double vc = 0.33;
  const PlyProperties q = ply_properties(p, CordRubberRule::gough_tangorra);
  EXPECT_LT(rel(q.E1, 3500.0 * vc + 4.0 * (1 - vc)), 1e-14);
  EXPECT_LT(rel(q.E2, 4.0 * 4.0 / (3.0 * (1 - vc))), 1e-14);
  EXPECT_LT(rel(q.G12, 4.0 / (3.0 * (1 - vc))), 1e-14);
  EXPECT_EQ(q.nu12, 0.5);
  // Same cord-direction modulus as Halpin–Tsai; across and in shear the same order of magnitude.
  const PlyProperties h = ply_properties(p, CordRubberRule::halpin_tsai);
  EXPECT_EQ(q.E1, h.E1);
  EXPECT_GT(q.E2 / h.E2, 0.6);
  EXPECT_LT(q.E2 / h.E2, 1.0);
}

// A single ply with cords along an axis: uniaxial stress along the cords gives E1 t, across them E2 t,
// shear G12 t, and the contraction ratio is ν12 (exact up to rounding).
TEST(PlyStiffness, SinglePlyAlongTheAxesReproducesItsModuli) {
  for (CordRubberRule rule : {CordRubberRule::halpin_tsai, CordRubberRule::gough_tangorra}) {
    Ply radial = polyester_carcass();  // 90°: cords meridional (axis 1)
    const PlyProperties q = ply_properties(radial, rule);
    const Eigen::Matrix3d c90 = ply_membrane_stiffness(radial, rule).inverse();
    EXPECT_LT(rel(1.0 / c90(0, 0), q.E1 * radial.thickness), 1e-12);
    EXPECT_LT(rel(1.0 / c90(1, 1), q.E2 * radial.thickness), 1e-12);
    EXPECT_LT(rel(1.0 / c90(2, 2), q.G12 * radial.thickness), 1e-12);
    EXPECT_LT(rel(-c90(0, 1) / c90(0, 0), q.nu12), 1e-12);

    Ply hoop = radial;  // 0°: cords circumferential (axis 2)
    hoop.angle_deg = 0.0;
    const Eigen::Matrix3d c0 = ply_membrane_stiffness(hoop, rule).inverse();
    EXPECT_LT(rel(1.0 / c0(1, 1), q.E1 * hoop.thickness), 1e-12);
    EXPECT_LT(rel(1.0 / c0(0, 0), q.E2 * hoop.thickness), 1e-12);
    EXPECT_LT(rel(1.0 / c0(2, 2), q.G12 * hoop.thickness), 1e-12);
    EXPECT_NEAR(ply_membrane_stiffness(hoop, rule)(0, 2), 0.0, 1e-12);
  }
}

TEST(PlyStiffness, RadialCarcassIsStiffMeridionally) {
  FaceLayup carcass{{polyester_carcass(), polyester_carcass()}, CordRubberRule::halpin_tsai, std::nullopt};
  const MembraneStiffness a = face_stiffness(carcass);
  EXPECT_GT(a(0, 0), 50.0 * a(1, 1));
  EXPECT_NEAR(a(0, 2), 0.0, 1e-9 * a(0, 0));
  EXPECT_NEAR(a(1, 2), 0.0, 1e-9 * a(0, 0));
  EXPECT_LT(rel(a(0, 0), 2.0 * reduced_stiffness(
                                   ply_properties(polyester_carcass(), CordRubberRule::halpin_tsai))(0, 0)),
            1e-12);
}

TEST(PlyStiffness, BalancedSteelBeltPairHasNoCouplingAndLargePoissonRatio) {
  for (CordRubberRule rule : {CordRubberRule::halpin_tsai, CordRubberRule::gough_tangorra}) {
    FaceLayup belts{{steel_belt(22.0), steel_belt(-22.0)}, rule, std::nullopt};
    const MembraneStiffness a = face_stiffness(belts);
    const double scale = a.cwiseAbs().maxCoeff();
    EXPECT_LE(std::abs(a(0, 2)), 1e-9 * scale);
    EXPECT_LE(std::abs(a(1, 2)), 1e-9 * scale);
    EXPECT_LT((a - a.transpose()).norm(), 1e-12 * scale);
    // Pull circumferentially (N1 = 0): the meridional contraction ratio is A12/A11. A net of inextensible
    // cords at ±θ gives exactly cot²θ (the cords keep their length: sin²θ ε1 + cos²θ ε2 = 0). The rubber
    // adds terms of relative size E2/(E1 cos⁴α) and G12/(E1 cos⁴α) (α = 68° from the meridian, cos⁴α ≈ 0.02)
    // to A11, about 1–3 % here, so 5 % is the tolerance; A12/A22 ≈ tan²θ likewise.
    const double t = std::tan(22.0 * std::numbers::pi / 180.0);
    EXPECT_NEAR(a(0, 1) / a(0, 0), 1.0 / (t * t), 0.05 / (t * t));
    EXPECT_NEAR(a(0, 1) / a(1, 1), t * t, 0.05 * t * t);
    EXPECT_GT(a(0, 1) / a(0, 0), 5.0);   // "several units"
    EXPECT_GT(a(1, 1), 20.0 * a(0, 0));  // nearly circumferential cords
  }
}

TEST(PlyStiffness, OppositeAnglesGiveTheSameNormalStiffness) {
  for (double angle : {0.0, 10.0, 22.0, 45.0, 60.0, 89.0, 90.0}) {
    const Eigen::Matrix3d plus = ply_membrane_stiffness(steel_belt(angle), CordRubberRule::halpin_tsai);
    const Eigen::Matrix3d minus = ply_membrane_stiffness(steel_belt(-angle), CordRubberRule::halpin_tsai);
    const double scale = plus.cwiseAbs().maxCoeff();
    for (auto [i, j] : {std::pair{0, 0}, {1, 1}, {0, 1}, {2, 2}})
      EXPECT_NEAR(plus(i, j), minus(i, j), 1e-12 * scale);
    EXPECT_NEAR(plus(0, 2), -minus(0, 2), 1e-12 * scale);
    EXPECT_NEAR(plus(1, 2), -minus(1, 2), 1e-12 * scale);
  }
}

// Q̄11 + Q̄22 + 2Q̄12 and Q̄66 − Q̄12 do not depend on the angle (rotation invariants of a plane
// orthotropic stiffness); the energy of a strain along the cords is Q11 ε² at any angle.
TEST(PlyStiffness, RotationKeepsInvariantsAndCordEnergy) {
  const Eigen::Matrix3d q = reduced_stiffness(ply_properties(steel_belt(0.0), CordRubberRule::halpin_tsai));
  for (double angle = -90.0; angle <= 90.0; angle += 7.5) {
    const Eigen::Matrix3d b = rotate_to_tyre_frame(q, angle);
    EXPECT_NEAR(b(0, 0) + b(1, 1) + 2 * b(0, 1), q(0, 0) + q(1, 1) + 2 * q(0, 1), 1e-10 * q(0, 0));
    EXPECT_NEAR(b(2, 2) - b(0, 1), q(2, 2) - q(0, 1), 1e-10 * q(0, 0));
    const Eigen::Vector2d d = cord_direction(angle);
    const Eigen::Vector3d along(d[0] * d[0], d[1] * d[1], 2 * d[0] * d[1]);  // ε = d ⊗ d
    EXPECT_NEAR(along.dot(b * along), q(0, 0), 1e-10 * q(0, 0));
    EXPECT_NEAR(cord_strain(along, angle), 1.0, 1e-14);
    const Eigen::Vector3d across(d[1] * d[1], d[0] * d[0], -2 * d[0] * d[1]);  // ε = b ⊗ b, b ⟂ d
    EXPECT_NEAR(cord_strain(across, angle), 0.0, 1e-14);
    EXPECT_NEAR(across.dot(b * across), q(1, 1), 1e-10 * q(0, 0));
  }
}

TEST(PlyStiffness, FaceSumsPliesAndDirectStiffness) {
  const Eigen::Matrix3d rubber = isotropic_membrane(4.0, 0.49, 4.0);
  FaceLayup face{{polyester_carcass()}, CordRubberRule::halpin_tsai, rubber};
  const Eigen::Matrix3d expected =
      ply_membrane_stiffness(polyester_carcass(), CordRubberRule::halpin_tsai) + rubber;
  EXPECT_LT((face_stiffness(face) - expected).norm(), 1e-12 * expected.norm());
  FaceLayup rubber_only{{}, CordRubberRule::halpin_tsai, rubber};
  EXPECT_EQ(face_stiffness(rubber_only), rubber);
  EXPECT_DOUBLE_EQ(cord_force(steel_belt(22.0), 0.01), 160000.0 * 0.196 * 0.01);
}

TEST(PlyStiffness, RejectsImpossibleVolumeFraction) {
  Ply p = steel_belt(22.0);
  p.thickness = 0.1;  // Vc = 1.57
  EXPECT_THROW(ply_properties(p, CordRubberRule::halpin_tsai), std::invalid_argument);
}

}  // namespace
}  // namespace tirefem
