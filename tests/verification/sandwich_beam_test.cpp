// Sandwich beams with membrane faces and a shear-only core (VERIFICATION.md §2, Allen, Analysis and
// Design of Structural Sandwich Panels): D = b d² (Et)1 (Et)2 / ((Et)1 + (Et)2), S = G b d; e.g. the
// cantilever tip deflection under P is PL³/(3D) + PL/S. Faces with ν = 0, so a strip of the plate is
// exactly a beam. Tolerance 2%: the discretisation error of 40 bilinear elements along the span.
// The thick-core (shear-dominated) and thin-core (bending-dominated, L/d = 1000, element length 25 d)
// cases show that the interlayer's assumed transverse shear does not lock.
#include <cstdio>

#include <gtest/gtest.h>

#include "tirefem/forms/nodal_load_form.hpp"
#include "verification_support.hpp"

namespace tirefem::verification {
namespace {

struct SandwichBeam {
  double length = 100.0, width = 10.0, core = 10.0;  // core = distance between the faces
  double face_et = 1000.0;                           // Et of each face, N/mm
  double core_shear = 1.0;
  int nx = 40, ny = 1;

  double bending_stiffness() const { return width * core * core * face_et * face_et / (2 * face_et); }
  double shear_stiffness() const { return core_shear * width * core; }
};

enum class Support { cantilever, simply_supported };
enum class Loading { tip_or_centre_point, uniform };

struct BeamRun {
  double deflection = 0.0;  // tip (cantilever) or centre (simply supported), mid-surface, along +z
  bool converged = false;
};

BeamRun solve_beam(const SandwichBeam& beam, Support support, Loading loading, double load,
                   Kinematics kinematics) {
  const ShellMesh mesh = plate_mesh(beam.length, beam.width, beam.nx, beam.ny, 0.0, beam.core);
  ElementSection section;
  section.inner_face = isotropic_membrane(beam.face_et, 0.0, 1.0);
  section.outer_face = section.inner_face;
  section.core_shear_modulus = beam.core_shear;
  // Allen's core does not change thickness: a through-thickness modulus 100 × G makes it so.
  section.core_normal_modulus = 100 * beam.core_shear;
  const std::vector<ElementSection> sections(mesh.element_count(), section);

  DofMap dofs(mesh.dof_count());
  const auto root = mesh.edge_pairs(GridEdge::u_min);
  const auto end = mesh.edge_pairs(GridEdge::u_max);
  if (support == Support::cantilever) {
    dofs.fix(both_faces(root, {0, 1, 2}));  // both faces clamped at x = 0
  } else {
    dofs.fix(both_faces(root, {2}));        // w = 0 on both faces at both ends; the section turns
    dofs.fix(both_faces(end, {2}));         // freely (the faces slide relative to each other)
    dofs.fix(inner_dof(root.front(), 0));   // axial rigid translation
    std::vector<int> all_pairs(mesh.pair_count());
    for (int p = 0; p < mesh.pair_count(); ++p) all_pairs[p] = p;
    dofs.fix(both_faces(all_pairs, {1}));   // plane problem (ν = 0: no lateral motion anyway)
  }

  // Loads and the measuring section: consistent weights across the width (½ at the edges).
  const int i_measure = support == Support::cantilever ? beam.nx : beam.nx / 2;
  std::vector<int> measure;
  for (int j = 0; j <= beam.ny; ++j) measure.push_back(mesh.pair_index(i_measure, j));
  Eigen::VectorXd f = Eigen::VectorXd::Zero(mesh.dof_count());
  if (loading == Loading::tip_or_centre_point) {
    for (int j = 0; j <= beam.ny; ++j) {
      const double w = (j == 0 || j == beam.ny ? 0.5 : 1.0) / beam.ny;
      add_split_force(f, measure[j], Eigen::Vector3d(0, 0, load * w));
    }
  } else {  // load = q per unit length of the beam, half on each face
    const Eigen::Vector3d traction(0, 0, 0.5 * load / beam.width);
    f += surface_load_vector(mesh, all_elements(mesh), Face::inner, traction);
    f += surface_load_vector(mesh, all_elements(mesh), Face::outer, traction);
  }

  std::vector<std::unique_ptr<Form>> forms;
  forms.push_back(std::make_unique<ShellInternalForce>(mesh, sections, kinematics));
  forms.push_back(std::make_unique<NodalLoadForm>(f));
  NonlinearProblem problem(dofs, std::move(forms));
  // Round-off floor of the residual: nodal positions X + u are stored with an absolute error of
  // ε|X| (|X| up to 100 here), which becomes a strain error of about ε|X|/h; at the tiny load of the
  // nonlinear case that is about 5e-7 of the applied load, so the default 1e-8 cannot be reached.
  NewtonSettings settings;
  settings.residual_tolerance = kinematics == Kinematics::nonlinear ? 1e-5 : 1e-8;
  NewtonSolver newton(problem, settings);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(mesh.dof_count());
  const NewtonOutcome out = newton.solve(u, 1.0);
  return {mean_mid_displacement(u, measure).z(), out.converged};
}

void expect_deflection(const char* label, const SandwichBeam& beam, Support support, Loading loading,
                       double load, Kinematics kinematics, double exact) {
  const BeamRun run = solve_beam(beam, support, loading, load, kinematics);
  ASSERT_TRUE(run.converged) << label;
  const double error = run.deflection / exact - 1.0;
  std::printf("  %-52s FE %.6g  Allen %.6g  error %+.3f%%\n", label, run.deflection, exact, 100 * error);
  EXPECT_NEAR(run.deflection, exact, 0.02 * std::abs(exact))
      << label << ": Allen's sandwich beam formula (VERIFICATION.md §2), tolerance 2%";
}

TEST(SandwichBeam, CantileverTipLoadExample) {
  const SandwichBeam beam;  // b = 10, d = 10, Et = 1000, G = 1, L = 100
  const double d = beam.bending_stiffness(), s = beam.shear_stiffness(), l = beam.length;
  const double exact = l * l * l / (3 * d) + l / s;  // P = 1
  ASSERT_NEAR(exact, 1.6667, 1e-4);
  expect_deflection("cantilever P=1, linear, 40x1", beam, Support::cantilever,
                    Loading::tip_or_centre_point, 1.0, Kinematics::linear, exact);
  SandwichBeam wide = beam;
  wide.nx = 20;
  wide.ny = 2;
  expect_deflection("cantilever P=1, linear, 20x2", wide, Support::cantilever,
                    Loading::tip_or_centre_point, 1.0, Kinematics::linear, exact);
  // Geometrically nonlinear at a tiny load (deflection 1.7e-5 L): the same answer.
  expect_deflection("cantilever P=1e-3, nonlinear, 40x1", beam, Support::cantilever,
                    Loading::tip_or_centre_point, 1e-3, Kinematics::nonlinear, 1e-3 * exact);
}

TEST(SandwichBeam, CantileverUniformLoad) {
  const SandwichBeam beam;
  const double q = 0.01, l = beam.length;
  const double exact = q * std::pow(l, 4) / (8 * beam.bending_stiffness()) + q * l * l / (2 * beam.shear_stiffness());
  expect_deflection("cantilever uniform q=0.01, linear, 40x1", beam, Support::cantilever,
                    Loading::uniform, q, Kinematics::linear, exact);
}

TEST(SandwichBeam, SimplySupportedCentralLoad) {
  const SandwichBeam beam;
  const double l = beam.length;
  const double exact = l * l * l / (48 * beam.bending_stiffness()) + l / (4 * beam.shear_stiffness());
  expect_deflection("simply supported central P=1, linear, 40x1", beam, Support::simply_supported,
                    Loading::tip_or_centre_point, 1.0, Kinematics::linear, exact);
}

TEST(SandwichBeam, ThickCoreShearDominated) {
  SandwichBeam beam;
  beam.core_shear = 0.05;  // PL/S = 20 against PL³/(3D) = 0.667: 97% of the deflection is core shear
  const double l = beam.length;
  const double exact = l * l * l / (3 * beam.bending_stiffness()) + l / beam.shear_stiffness();
  expect_deflection("cantilever, shear-dominated core G=0.05, linear", beam, Support::cantilever,
                    Loading::tip_or_centre_point, 1.0, Kinematics::linear, exact);
}

TEST(SandwichBeam, ThinCoreBendingDominatedDoesNotLock) {
  SandwichBeam beam;
  beam.core = 0.1;        // L/d = 1000, element length / d = 25
  beam.core_shear = 100;  // PL/S = 1 against PL³/(3D) = 6667: bending dominates
  const double l = beam.length;
  const double exact = l * l * l / (3 * beam.bending_stiffness()) + l / beam.shear_stiffness();
  expect_deflection("cantilever, thin core d=0.1, linear, 40x1", beam, Support::cantilever,
                    Loading::tip_or_centre_point, 1.0, Kinematics::linear, exact);
  SandwichBeam coarse = beam;
  coarse.nx = 10;  // element length 100 d: a locking element would be orders of magnitude too stiff
  expect_deflection("cantilever, thin core d=0.1, linear, 10x1", coarse, Support::cantilever,
                    Loading::tip_or_centre_point, 1.0, Kinematics::linear, exact);
}

}  // namespace
}  // namespace tirefem::verification
