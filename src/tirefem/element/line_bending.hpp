#pragma once
// Bending of a face along one mesh line, rotation-free (the faces keep their 3 translational DOFs per
// node). At a node c with neighbours p (before) and n (after) along the line and m, q across it, the
// line's normal curvature is the second difference along the line projected on the face normal:
//   κ = ν · d,   d = w_p x_p + w_c x_c + w_n x_n  (the second derivative in the reference arc length),
//   ν = c / |c|, c = (x_n − x_p) × (x_q − x_m),
// the Koiter bending strain b_ss of the line. Its change from the reference, ρ = κ − κ0, stores
//   W = ½ k ρ²,   k = D · (tributary area of the node),
// D the face's bending stiffness along the line (N·mm). W is invariant under rigid motions (d's weights
// sum to zero, ν rotates with the face). Its gradient and Hessian are exact (closed form below).
//
// In-plane (geodesic) bending, for the cords of a ply: the same second difference projected on the unit
// normal to the line within the face, m = ν × a/|a| (a = x_n − x_p along the line):
//   κ_g = m · d = [(a·a)(b·d) − (a·b)(a·d)] / (|a| |a × b|),   b = x_q − x_m across it,
// the curvature of the line within the surface. A cord bends in the ply's plane as it bends out of it; a
// ply whose cords are compressed beyond what the rubber's in-plane shear holds kinks in its own plane,
// and without this stiffness the kink has no width of its own but the mesh's
// (docs/studies/carcass-kinking.md).
#include <array>

#include <Eigen/Dense>

namespace tirefem {

// The five nodes of a stencil, in this order.
enum LineNode { line_before = 0, line_centre = 1, line_after = 2, across_before = 3, across_after = 4 };

struct LineBendingStencil {
  std::array<double, 3> weights{};  // w_p, w_c, w_n: d = Σ w x over the three line nodes
  double reference_curvature = 0.0;  // κ0 of the reference positions
  double stiffness = 0.0;            // k = D × tributary area, N·mm³
  bool in_plane = false;             // the geodesic curvature κ_g instead of the normal one
};

// The weights of the second difference in arc length for reference chords h1 = |X_c − X_p| and
// h2 = |X_n − X_c| (exact for a quadratic in arc length).
std::array<double, 3> second_difference_weights(double h1, double h2);

// κ = ν · d (in_plane: κ_g = m · d) for node positions x (columns in LineNode order).
double line_curvature(const LineBendingStencil& stencil, const Eigen::Matrix<double, 3, 5>& x);

struct LineBendingResponse {
  double energy = 0.0;
  Eigen::Matrix<double, 15, 1> force = Eigen::Matrix<double, 15, 1>::Zero();    // ∂W/∂x
  Eigen::Matrix<double, 15, 15> tangent = Eigen::Matrix<double, 15, 15>::Zero();  // ∂²W/∂x²
};

// W, its gradient and (with_tangent) its Hessian over the 15 coordinates (node-major, LineNode order).
LineBendingResponse line_bending(const LineBendingStencil& stencil, const Eigen::Matrix<double, 3, 5>& x,
                                 bool with_tangent);

}  // namespace tirefem
