#pragma once
// Shared set-up for the verification tests: the isotropic-shell emulation of VERIFICATION.md §2,
// meshes of the classic test geometries (plate, cylinder segment, hemisphere / sphere band, torus,
// closed cylinder) with the two faces offset along the mid-surface normal, and small solver helpers.
#include <cmath>
#include <functional>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>

#include "tirefem/element/section.hpp"
#include "tirefem/element/shape_functions.hpp"
#include "tirefem/element/three_layer_element.hpp"
#include "tirefem/forms/shell_internal_force.hpp"
#include "tirefem/mesh/revolution_mesh.hpp"
#include "tirefem/mesh/shell_mesh.hpp"
#include "tirefem/solver/linear_solver.hpp"
#include "tirefem/solver/newton.hpp"
#include "tirefem/solver/nonlinear_problem.hpp"

namespace tirefem::verification {

inline constexpr double kPi = std::numbers::pi;
inline double degrees(double deg) { return deg * kPi / 180.0; }

// ---- isotropic shell emulated by the three-layer element (VERIFICATION.md §2) -----------------------
// Faces at ±d/2 with d = t/√3 and membrane stiffness E(t/2)/(1 − ν²) each: the two faces are the
// two-point Gauss rule through the thickness, so membrane stiffness E t/(1 − ν²) and bending stiffness
// E t³/(12(1 − ν²)) are exact. Core shear modulus κ G √3 over the core thickness d gives the shear
// stiffness κ G t. Core normal modulus E: the faces carry no through-thickness Poisson coupling, so the
// core's normal stiffness only sets the (small) thickness change under transverse load; E is the
// modulus of the material through its thickness in uniaxial stress, which is the state the
// plane-stress shell assumes there.
struct IsotropicShell {
  double youngs_modulus = 0.0;
  double poisson = 0.0;
  double thickness = 0.0;
};

inline double face_distance(const IsotropicShell& s) { return s.thickness / std::sqrt(3.0); }

inline ElementSection emulated_section(const IsotropicShell& s) {
  constexpr double kappa = 5.0 / 6.0;
  const double g = s.youngs_modulus / (2.0 * (1.0 + s.poisson));
  ElementSection section;
  section.inner_face = isotropic_membrane(s.youngs_modulus, s.poisson, s.thickness / 2.0);
  section.outer_face = section.inner_face;
  section.core_shear_modulus = kappa * g * std::sqrt(3.0);
  section.core_normal_modulus = s.youngs_modulus;
  return section;
}

// ---- meshes -------------------------------------------------------------------------------------
// A mid-surface (point and unit normal as functions of the grid parameters); the inner face lies at
// `inner_offset`, the outer face at `outer_offset` along the normal.
using SurfaceMap = std::function<Eigen::Vector3d(double u, double v)>;

inline ShellMesh offset_mesh(std::vector<double> u, std::vector<double> v, bool closed_v,
                             const SurfaceMap& point, const SurfaceMap& normal, double inner_offset,
                             double outer_offset) {
  return build_grid_mesh(std::move(u), std::move(v), closed_v, [&](double a, double b) {
    const Eigen::Vector3d p = point(a, b), n = normal(a, b);
    return NodePairPosition{p + inner_offset * n, p + outer_offset * n};
  });
}

inline std::vector<double> uniform_values(double a, double b, int n) { return graded_values(a, b, n); }

// Flat plate [0, lx] × [0, ly] in the plane z = 0, normal +z; u along x, v along y.
inline ShellMesh plate_mesh(double lx, double ly, int nx, int ny, double inner_offset,
                            double outer_offset) {
  return offset_mesh(
      uniform_values(0, lx, nx), uniform_values(0, ly, ny), false,
      [](double x, double y) { return Eigen::Vector3d(x, y, 0.0); },
      [](double, double) { return Eigen::Vector3d(0, 0, 1); }, inner_offset, outer_offset);
}

// Cylinder segment of radius R about the x axis, crown on top: the point at axial position x and
// angle θ from the top is (x, R sin θ, R cos θ); normal outwards. u = x, v = θ.
inline ShellMesh cylinder_segment_mesh(double radius, std::vector<double> x, std::vector<double> theta,
                                       double inner_offset, double outer_offset) {
  return offset_mesh(
      std::move(x), std::move(theta), false,
      [radius](double a, double t) { return Eigen::Vector3d(a, radius * std::sin(t), radius * std::cos(t)); },
      [](double, double t) { return Eigen::Vector3d(0, std::sin(t), std::cos(t)); }, inner_offset,
      outer_offset);
}

// Shells of revolution about the x axis (build_revolution_mesh, axis_z = 0): a meridian point (x, r)
// at angle φ sits at (x, r sin φ, −r cos φ); the normal (−r', x') points outwards for the meridians
// below. Faces at constant offsets along it.
inline ShellMesh revolution_mesh(const Meridian& meridian, std::vector<double> s, std::vector<double> phi,
                                 bool closed, double inner_offset, double outer_offset) {
  RevolutionMeshSpec spec;
  spec.meridian = meridian;
  spec.s_values = std::move(s);
  spec.phi_values = std::move(phi);
  spec.closed = closed;
  spec.axis_z = 0.0;
  spec.inner_offset = [inner_offset](double) { return inner_offset; };
  spec.outer_offset = [outer_offset](double) { return outer_offset; };
  return build_revolution_mesh(spec);
}

// Cylinder r = R, meridian parameter s = x.
inline Meridian cylinder_meridian(double radius) {
  return {[radius](double s) { return Eigen::Vector2d(s, radius); },
          [](double) { return Eigen::Vector2d(1, 0); }};
}

// Sphere of radius R centred at the origin; s = R ψ with ψ the latitude measured from the equator
// x = 0 towards the pole on +x: (x, r) = (R sin ψ, R cos ψ). Outward normal.
inline Meridian sphere_meridian(double radius) {
  return {[radius](double s) {
            const double psi = s / radius;
            return Eigen::Vector2d(radius * std::sin(psi), radius * std::cos(psi));
          },
          [radius](double s) {
            const double psi = s / radius;
            return Eigen::Vector2d(std::cos(psi), -std::sin(psi));
          }};
}

// Torus: tube radius a, axis-to-tube-centre b; s = a ψ with ψ from the outer equator (r = b + a) over
// the crown x = a (r = b) to the inner equator (r = b − a): (x, r) = (a sin ψ, b + a cos ψ).
// The normal (−r', x') = (sin ψ, cos ψ) points away from the tube centre.
inline Meridian torus_meridian(double a, double b) {
  return {[a, b](double s) {
            const double psi = s / a;
            return Eigen::Vector2d(a * std::sin(psi), b + a * std::cos(psi));
          },
          [a](double s) {
            const double psi = s / a;
            return Eigen::Vector2d(std::cos(psi), -std::sin(psi));
          }};
}

// Closed (in φ) cylinder of radius R and length L about the x axis, nx × nphi elements.
inline ShellMesh closed_cylinder_mesh(double radius, double length, int nx, int nphi, double inner_offset,
                                      double outer_offset) {
  return revolution_mesh(cylinder_meridian(radius), uniform_values(0, length, nx),
                         uniform_values(-kPi, kPi, nphi), true, inner_offset, outer_offset);
}

// ---- DOF helpers -----------------------------------------------------------------------------------
// DOFs of component c (0 = x, 1 = y, 2 = z) of both faces of the given pairs.
inline std::vector<int> both_faces(const std::vector<int>& pairs, std::initializer_list<int> components) {
  std::vector<int> dofs;
  for (int p : pairs)
    for (int c : components) {
      dofs.push_back(inner_dof(p, c));
      dofs.push_back(outer_dof(p, c));
    }
  return dofs;
}

inline std::vector<int> all_elements(const ShellMesh& mesh) {
  std::vector<int> e(mesh.element_count());
  for (int i = 0; i < mesh.element_count(); ++i) e[i] = i;
  return e;
}

// Mean displacement of the two faces at pair p (the mid-surface displacement).
inline Eigen::Vector3d mid_displacement(const Eigen::VectorXd& u, int p) {
  Eigen::Vector3d d;
  for (int c = 0; c < 3; ++c) d[c] = 0.5 * (u[inner_dof(p, c)] + u[outer_dof(p, c)]);
  return d;
}

inline Eigen::Vector3d mean_mid_displacement(const Eigen::VectorXd& u, const std::vector<int>& pairs) {
  Eigen::Vector3d d = Eigen::Vector3d::Zero();
  for (int p : pairs) d += mid_displacement(u, p);
  return d / static_cast<double>(pairs.size());
}

// Adds the force f to pair p, half on each face.
inline void add_split_force(Eigen::VectorXd& forces, int p, const Eigen::Vector3d& f) {
  for (int c = 0; c < 3; ++c) {
    forces[inner_dof(p, c)] += 0.5 * f[c];
    forces[outer_dof(p, c)] += 0.5 * f[c];
  }
}

// ---- solving -------------------------------------------------------------------------------------------
// Newton iteration with some constrained DOFs held at the (non-zero) values they have in `u` on entry:
// a prescribed-displacement problem without loads, for the patch tests. Returns the number of solves;
// throws if it does not converge.
inline int solve_prescribed(NonlinearProblem& problem, Eigen::VectorXd& u, double force_scale,
                            double tolerance = 1e-12, int max_iterations = 20) {
  const DofMap& dofs = problem.dofs();
  SparseDirectSolver linear(problem.symmetric());
  for (int it = 0; it <= max_iterations; ++it) {
    problem.evaluate(u, 1.0, true);
    const Eigen::VectorXd r = dofs.gather(problem.system().residual());
    if (r.norm() <= tolerance * force_scale) return it;
    linear.factorize(problem.system().tangent());
    dofs.scatter_add(linear.solve(-r), u);
  }
  throw std::runtime_error("solve_prescribed: Newton did not converge");
}

// Geometrically linear problem: one Newton step from zero, checked.
inline Eigen::VectorXd solve_linear(NonlinearProblem& problem, double tolerance = 1e-9) {
  NewtonSettings settings;
  settings.residual_tolerance = tolerance;
  NewtonSolver newton(problem, settings);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(problem.dofs().dof_count());
  const NewtonOutcome out = newton.solve(u, 1.0);
  if (!out.converged)
    throw std::runtime_error("solve_linear: no convergence, residual " + std::to_string(out.relative_residual) +
                             " after " + std::to_string(out.iterations) + " solves");
  return u;
}

// Stability of an equilibrium by the inertia of its tangent (Sylvester: no negative LDLᵀ pivot). The
// equilibrium is Newton's from rest under the full load, left in `u`, for the buckling tests: the caller
// checks that it is the unbuckled one.
inline bool equilibrium_from_rest_is_stable(NonlinearProblem& problem, Eigen::VectorXd& u) {
  NewtonSettings settings;
  settings.residual_tolerance = 1e-10;
  NewtonSolver newton(problem, settings);
  u = Eigen::VectorXd::Zero(problem.dofs().dof_count());
  if (!newton.solve(u, 1.0).converged) throw std::runtime_error("equilibrium_from_rest_is_stable: no convergence");
  problem.evaluate(u, 1.0, true);
  const Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> ldlt(problem.system().tangent());
  if (ldlt.info() != Eigen::Success) throw std::runtime_error("equilibrium_from_rest_is_stable: LDLT failed");
  return (ldlt.vectorD().array() < 0.0).count() == 0;
}

}  // namespace tirefem::verification
