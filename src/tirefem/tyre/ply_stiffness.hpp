#pragma once
// Cord–rubber plies → membrane stiffness of a face (MODEL.md §3, VERIFICATION.md §7): a cord–rubber rule
// gives the ply's engineering constants in its cord axes, classical lamination turns each ply into the
// meridional/circumferential frame and sums A = Σ Q̄ t.
//
// Frames: the tyre frame is axis 1 = meridional, axis 2 = circumferential (as in element/section.hpp);
// the ply frame is axis 1 = along the cords, axis 2 = across them in the ply's plane. A ply at angle θ to
// the circumferential direction has its cords along sin θ e1 + cos θ e2.
#include <Eigen/Dense>

#include "tirefem/case/case.hpp"
#include "tirefem/element/section.hpp"

namespace tirefem {

struct PlyProperties {
  double E1 = 0.0;               // along the cords, MPa
  double E2 = 0.0;               // across the cords, MPa
  double G12 = 0.0;              // in-plane shear, MPa
  double nu12 = 0.0;             // contraction across the cords for a pull along them
  double volume_fraction = 0.0;  // cord volume fraction Vc
};

// Vc = cord area × ends per mm / ply thickness.
double cord_volume_fraction(const Ply& ply);

PlyProperties ply_properties(const Ply& ply, CordRubberRule rule);

// Plane-stress reduced stiffness in the ply frame, Voigt [11, 22, 12-engineering], MPa.
Eigen::Matrix3d reduced_stiffness(const PlyProperties& p);

// Unit cord direction in the tyre frame (meridional, circumferential) for a cord angle θ (degrees) to the
// circumferential direction.
Eigen::Vector2d cord_direction(double angle_deg);

// Q̄ = Tᵀ Q T: the ply-frame stiffness seen in the tyre frame, T the engineering-strain transformation from
// the tyre frame to the ply frame.
Eigen::Matrix3d rotate_to_tyre_frame(const Eigen::Matrix3d& ply_frame_stiffness, double angle_deg);

// Membrane stiffness of one ply, Q̄ · thickness, N/mm.
MembraneStiffness ply_membrane_stiffness(const Ply& ply, CordRubberRule rule);

// A of a face: Σ over plies of Q̄ t, plus the direct stiffness if one is given.
MembraneStiffness face_stiffness(const FaceLayup& face);

// Strain along the cords from the face's membrane strain [E11, E22, 2E12] (tyre frame): ε_c = dᵀ E d.
double cord_strain(const Eigen::Vector3d& membrane_strain, double angle_deg);

// Tension in one cord, N: E_cord · A_cord · ε_c, with the compression modulus where ε_c < 0 unless
// `bimodular` is false (the linear theory keeps linear faces); the rubber's share of the ply force is not
// the cord's.
inline double cord_force(const Ply& ply, double cord_strain_value, bool bimodular = true) {
  const double modulus = bimodular && cord_strain_value < 0.0 ? ply.compression_modulus() : ply.cord_modulus;
  return modulus * ply.cord_area * cord_strain_value;
}

// The face's cord families softer in compression than in tension (element/section.hpp), plies of the
// same cord direction merged.
std::vector<CordSoftening> face_cord_softening(const FaceLayup& face);

}  // namespace tirefem
