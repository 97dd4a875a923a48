// Cords softer in compression than in tension (Ply::cord_compression_modulus, element/section.hpp): the
// element's tangent against central differences of its force and its force against differences of its
// energy, with cord strains in compression, in the smoothing band and in tension; a face compressed and
// stretched along its cords carries (A11 − k) E11 and A11 E11 (reference: the bimodular law itself); the
// ply data give k = (E_t − E_c) × cord area × ends per mm, merged per cord direction; the case reader
// takes the modulus and names the field when it is out of range.
#include <cmath>

#include <gtest/gtest.h>

#include "case_reader_test_support.hpp"
#include "tirefem/element/three_layer_element.hpp"
#include "tirefem/tyre/ply_stiffness.hpp"
#include "../element_test_section.hpp"

namespace tirefem {
namespace {

// The anisotropic test section with radial cords in the inner face and a ±30° pair in the outer one that
// lose most of their stiffness in compression.
ElementSection softening_section(bool enhanced) {
  ElementSection s = anisotropic_test_section();
  s.enhanced_faces = enhanced;
  s.inner_cords = {{Eigen::Vector3d(1, 0, 0), 2500.0}};
  const double c = std::cos(0.5236), d = std::sin(0.5236);
  s.outer_cords = {{Eigen::Vector3d(c * c, d * d, c * d), 1500.0}, {Eigen::Vector3d(c * c, d * d, -c * d), 1500.0}};
  return s;
}

// Energy without the cord families minus energy with them: > 0 when some family is in compression.
double softening_energy(const NodeMatrix& x0, const NodeMatrix& x, const ElementSection& s) {
  ElementSection plain = s;
  plain.inner_cords.clear();
  plain.outer_cords.clear();
  return three_layer_element(x0, x, plain, Kinematics::nonlinear, false).energy -
         three_layer_element(x0, x, s, Kinematics::nonlinear, false).energy;
}

// Whether some family's compatible cord strain lies inside the smoothing band at some Gauss point.
bool some_cord_in_band(const NodeMatrix& x0, const NodeMatrix& x, ElementSection s) {
  s.enhanced_faces = false;  // the point state's strains are then the compatible ones the softening sees
  const double g = 1.0 / std::sqrt(3.0);
  for (double xi : {-g, g})
    for (double eta : {-g, g}) {
      const ElementPointState st = three_layer_point_state(x0, x, s, Kinematics::nonlinear, xi, eta);
      for (const CordSoftening& c : s.inner_cords)
        if (std::abs(c.direction.dot(st.inner_strain)) < kCordSofteningBand) return true;
      for (const CordSoftening& c : s.outer_cords)
        if (std::abs(c.direction.dot(st.outer_strain)) < kCordSofteningBand) return true;
    }
  return false;
}

TEST(CordSoftening, TangentMatchesFiniteDifferences) {
  const NodeMatrix x0 = curved_element();
  // Amplitudes giving cord strains of order 1e-1 (compression and tension) and 3e-4 (inside the band).
  for (double amplitude : {1.5, 0.004})
    for (bool enhanced : {false, true})
      for (unsigned seed : {1u, 2u, 3u}) {
        const ElementSection s = softening_section(enhanced);
        const NodeMatrix x = randomly_deformed(x0, amplitude, seed);
        ASSERT_GT(softening_energy(x0, x, s), 0.0) << "no cord in compression: the test would prove nothing";
        if (amplitude < 0.01) ASSERT_TRUE(some_cord_in_band(x0, x, s)) << "seed " << seed << ": no cord in the band";
        const ElementResponse r = three_layer_element(x0, x, s, Kinematics::nonlinear);
        const double h = amplitude * 1e-6;
        ElementMatrix fd;
        for (int j = 0; j < kElementDofs; ++j) {
          NodeMatrix xp = x, xm = x;
          xp(j % 3, j / 3) += h;
          xm(j % 3, j / 3) -= h;
          fd.col(j) = (three_layer_element(x0, xp, s, Kinematics::nonlinear, false).force -
                       three_layer_element(x0, xm, s, Kinematics::nonlinear, false).force) /
                      (2 * h);
        }
        EXPECT_LT((fd - r.tangent).norm() / r.tangent.norm(), 1e-6)
            << "amplitude " << amplitude << ", seed " << seed << (enhanced ? ", enhanced faces" : "");
        EXPECT_LT((r.tangent - r.tangent.transpose()).norm() / r.tangent.norm(), 1e-13);
      }
}

TEST(CordSoftening, ForceIsGradientOfEnergy) {
  const NodeMatrix x0 = curved_element();
  for (double amplitude : {1.0, 0.004})
    for (bool enhanced : {false, true}) {
      const ElementSection s = softening_section(enhanced);
      const NodeMatrix x = randomly_deformed(x0, amplitude, 11);
      ASSERT_GT(softening_energy(x0, x, s), 0.0);
      const ElementResponse r = three_layer_element(x0, x, s, Kinematics::nonlinear, false);
      const double h = amplitude * 1e-5;
      ElementVector fd;
      for (int j = 0; j < kElementDofs; ++j) {
        NodeMatrix xp = x, xm = x;
        xp(j % 3, j / 3) += h;
        xm(j % 3, j / 3) -= h;
        fd[j] = (three_layer_element(x0, xp, s, Kinematics::nonlinear, false).energy -
                 three_layer_element(x0, xm, s, Kinematics::nonlinear, false).energy) /
                (2 * h);
      }
      EXPECT_LT((fd - r.force).norm() / r.force.norm(), 1e-7)
          << "amplitude " << amplitude << (enhanced ? ", enhanced faces" : "");
    }
}

// A flat 10 × 10 mm element, both faces stretched by ε along axis 1 (the cords of the inner face).
NodeMatrix flat_element(double stretch) {
  NodeMatrix x;
  const double xs[4] = {0, 10, 10, 0}, ys[4] = {0, 0, 10, 10};
  for (int a = 0; a < 4; ++a) {
    x.col(a) = Eigen::Vector3d(xs[a] * (1 + stretch), ys[a], 0);
    x.col(a + 4) = Eigen::Vector3d(xs[a] * (1 + stretch), ys[a], 4);
  }
  return x;
}

TEST(CordSoftening, AFaceAlongItsCordsCarriesTheBimodularForce) {
  ElementSection s;
  s.inner_face << 2400, 8, 0, 8, 12, 0, 0, 0, 5;  // a radial carcass pair, N/mm
  s.outer_face = s.inner_face;
  s.core_shear_modulus = 1.0;
  s.core_normal_modulus = 100.0;
  s.enhanced_faces = true;
  const double k = 2300.0;  // what the cords lose in compression
  s.inner_cords = {{Eigen::Vector3d(1, 0, 0), k}};
  const NodeMatrix x0 = flat_element(0.0);
  for (double stretch : {-0.01, -0.002, 0.002, 0.01}) {
    const ElementPointState st =
        three_layer_point_state(x0, flat_element(stretch), s, Kinematics::nonlinear, 0.0, 0.0);
    const double e11 = stretch + 0.5 * stretch * stretch;  // Green–Lagrange
    ASSERT_GT(std::abs(e11), kCordSofteningBand);
    const double a11 = s.inner_face(0, 0) - (e11 < 0 ? k : 0.0);
    EXPECT_NEAR(st.inner_resultant[0], a11 * e11, 1e-9 * s.inner_face(0, 0)) << "stretch " << stretch;
    EXPECT_NEAR(st.outer_resultant[0], s.outer_face(0, 0) * e11, 1e-9 * s.inner_face(0, 0));
    // the energy: ½ A11 E11² per area over 100 mm², less ½ k E11² + k δ²/6 in compression
    const double lost = softening_energy(x0, flat_element(stretch), s);
    const double expected = e11 < 0 ? 100.0 * k * (0.5 * e11 * e11 + kCordSofteningBand * kCordSofteningBand / 6) : 0.0;
    EXPECT_NEAR(lost, expected, 1e-9 * (1 + expected)) << "stretch " << stretch;
  }
  // Linear theory keeps the linear face.
  const ElementPointState lin = three_layer_point_state(x0, flat_element(-0.01), s, Kinematics::linear, 0.0, 0.0);
  EXPECT_NEAR(lin.inner_resultant[0], s.inner_face(0, 0) * -0.01, 1e-9 * s.inner_face(0, 0));
}

Ply carcass_ply(std::optional<double> compression) {
  Ply p;
  p.name = "carcass";
  p.cord_modulus = 3500.0;
  p.cord_area = 0.33;
  p.ends_per_mm = 1.0;
  p.angle_deg = 90.0;
  p.thickness = 1.0;
  p.rubber_modulus = 4.0;
  p.cord_compression_modulus = compression;
  return p;
}

TEST(CordSoftening, PliesOfOneDirectionMergeIntoOneFamily) {
  FaceLayup face;
  face.plies = {carcass_ply(350.0), carcass_ply(350.0)};
  const std::vector<CordSoftening> f = face_cord_softening(face);
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].direction, Eigen::Vector3d(1, 0, 0));
  EXPECT_NEAR(f[0].stiffness, 2 * (3500.0 - 350.0) * 0.33 * 1.0, 1e-10);
  // unset (as in tension) or equal to the tension modulus: no family
  face.plies = {carcass_ply(std::nullopt), carcass_ply(3500.0)};
  EXPECT_TRUE(face_cord_softening(face).empty());
  // a cord's force in compression uses its compression modulus
  EXPECT_DOUBLE_EQ(cord_force(carcass_ply(350.0), -0.01), 350.0 * 0.33 * -0.01);
  EXPECT_DOUBLE_EQ(cord_force(carcass_ply(350.0), 0.01), 3500.0 * 0.33 * 0.01);
  EXPECT_DOUBLE_EQ(cord_force(carcass_ply(350.0), -0.01, /*bimodular=*/false), 3500.0 * 0.33 * -0.01);
}

TEST(CordSoftening, CaseReaderTakesTheCompressionModulusAndNamesItWhenOutOfRange) {
  using namespace case_test;
  const Case c = parse_case(edited("cord_modulus = 3500.0", "cord_modulus = 3500.0\ncord_compression_modulus = 350.0"),
                            "case.toml");
  ASSERT_TRUE(c.tyre.zones[0].inner.plies[0].cord_compression_modulus.has_value());
  EXPECT_EQ(*c.tyre.zones[0].inner.plies[0].cord_compression_modulus, 350.0);
  EXPECT_FALSE(c.tyre.zones[0].outer.plies[0].cord_compression_modulus.has_value());
  // without the key (the example), the cords are as stiff in compression as in tension
  EXPECT_FALSE(parse_case(example_text(), "case.toml").tyre.zones[0].inner.plies[0].cord_compression_modulus.has_value());
  EXPECT_CONTAINS(error_of(edited("cord_modulus = 3500.0", "cord_modulus = 3500.0\ncord_compression_modulus = 4000.0")),
                  "tyre.plies.carcass.cord_compression_modulus");
  EXPECT_CONTAINS(error_of(edited("cord_modulus = 3500.0", "cord_modulus = 3500.0\ncord_compression_modulus = -1.0")),
                  "tyre.plies.carcass.cord_compression_modulus");
}

}  // namespace
}  // namespace tirefem
