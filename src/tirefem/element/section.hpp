#pragma once
// Properties of one three-layer shell element: the two membrane faces and the interlayer (core).
#include <vector>

#include <Eigen/Dense>

namespace tirefem {

// Membrane stiffness of a face, N = A · E, Voigt order [11, 22, 12] with engineering shear (2 E12),
// in the element's local frame: axis 1 along the element's ξ direction (the meridian on a tyre),
// axis 2 = normal × axis 1 (the circumferential direction). Units N/mm.
using MembraneStiffness = Eigen::Matrix3d;

// Cords that carry less in compression than in tension (Ply::cord_compression_modulus): the face's A
// holds them at their tension modulus, and where a family's cord strain ε_c = m · [E11, E22, 2E12] is
// negative the face's energy loses ½ k ε_c², k = (E_tension − E_compression) × cord area × ends per mm
// (three_layer_element.cpp smooths the switch over |ε_c| < kCordSofteningBand). Nonlinear theory only.
struct CordSoftening {
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();  // m = [d1², d2², d1 d2], d the cord direction
  double stiffness = 0.0;                               // k, N/mm
};

// The rubber layers of a face under the neo-Hookean law (TyreDescription::rubber_law, rubber_membrane.hpp):
// on the compatible strains their share of the linear face, ½ Eᵀ A_r E, is replaced by the neo-Hookean
// membrane's energy. Nonlinear theory only; zero shear stiffness: the face stays linear.
struct RubberFaceLaw {
  double shear_stiffness = 0.0;                           // Σ μ t over the layers, N/mm
  MembraneStiffness linear = MembraneStiffness::Zero();   // A_r, their share of the face's A
};

struct ElementSection {
  MembraneStiffness inner_face = MembraneStiffness::Zero();  // carcass
  MembraneStiffness outer_face = MembraneStiffness::Zero();  // breaker / sidewall layer
  double core_shear_modulus = 0.0;   // transverse shear modulus G13 = G23 of the interlayer, MPa
  double core_normal_modulus = 0.0;  // through-thickness modulus of the interlayer, MPa
  // false: the paper's compatible bilinear faces. true: their in-plane strains enriched by enhanced
  // assumed strains (EAS-4), condensed per element: no parasitic shear when a face bends in its plane.
  bool enhanced_faces = false;
  // The faces' own bending stiffness D (N·mm = N·mm²/mm), along the meridian (u) and the circumference
  // (v); zero in the paper's membrane faces (forms/face_bending_form.hpp).
  Eigen::Vector2d inner_face_bending = Eigen::Vector2d::Zero();
  Eigen::Vector2d outer_face_bending = Eigen::Vector2d::Zero();
  // Their bending stiffness within their own plane (the cords', N·mm), of the meridional and the
  // circumferential mesh lines (element/line_bending.hpp, in-plane).
  Eigen::Vector2d inner_face_in_plane_bending = Eigen::Vector2d::Zero();
  Eigen::Vector2d outer_face_in_plane_bending = Eigen::Vector2d::Zero();
  // Cord families of each face softer in compression (empty: the paper's linear faces).
  std::vector<CordSoftening> inner_cords, outer_cords;
  // Rubber layers of each face under the neo-Hookean law (zero: the paper's linear faces).
  RubberFaceLaw inner_rubber, outer_rubber;
};

// Isotropic membrane of thickness t (plane stress): A = E t / (1 − ν²) [[1, ν, 0], [ν, 1, 0], [0, 0, (1 − ν)/2]].
inline MembraneStiffness isotropic_membrane(double youngs_modulus, double poisson, double thickness) {
  const double c = youngs_modulus * thickness / (1.0 - poisson * poisson);
  MembraneStiffness a;
  a << c, c * poisson, 0, c * poisson, c, 0, 0, 0, c * (1.0 - poisson) / 2.0;
  return a;
}

}  // namespace tirefem
