#include "tirefem/analysis/standing_stiffness.hpp"

#include <chrono>

#include "tirefem/analysis/tyre_shell_forms.hpp"
#include "tirefem/forms/pressure_form.hpp"
#include "tirefem/forms/stuck_tread_form.hpp"
#include "tirefem/solver/linear_solver.hpp"
#include "tirefem/solver/nonlinear_problem.hpp"

namespace tirefem {

std::optional<StandingStiffness> standing_stiffness(const TyreMesh& tm, const TyreDescription& tyre,
                                                    double pressure, const SupportSurface& support,
                                                    double deflection, const std::vector<TreadPoint>& points,
                                                    const Eigen::VectorXd& u,
                                                    std::vector<Eigen::VectorXd>* responses) {
  const auto t0 = std::chrono::steady_clock::now();
  StandingStiffness s;
  // The points in contact (with tread on them), where they stand, and the road's normal there.
  std::vector<TreadPoint> stuck;
  std::vector<Eigen::Vector3d> anchors, normals;
  auto winkler = std::make_unique<WinklerContactForm>(tm.mesh, points, tyre.tread_stiffness, support);
  winkler->set_deflection(deflection);
  const std::vector<TreadPoint>& all = winkler->points();  // the form's order (by element)
  const std::vector<TreadPointState> states = winkler->evaluate(u);
  double normal_force = 0.0;
  for (std::size_t q = 0; q < all.size(); ++q) {
    if (!(states[q].penetration > 0) || !(all[q].height > 0)) continue;
    const Penetration g = support.penetration(states[q].position, deflection);
    stuck.push_back(all[q]);
    anchors.push_back(states[q].position);
    normals.push_back(-g.gradient.normalized());
    const double fn = states[q].force.norm();
    s.centre_mm += fn * states[q].position;
    normal_force += fn;
  }
  if (stuck.empty() || !(normal_force > 0)) return std::nullopt;
  s.centre_mm /= normal_force;
  if (tm.half_model) s.centre_mm.x() = 0.0;  // the whole patch's centre lies in the symmetry plane
  s.contact_points = static_cast<int>(stuck.size());
  winkler->freeze_region(winkler->region(u));

  DofMap dofs(tm.mesh.dof_count());
  dofs.fix(tm.fixed_dofs);
  std::vector<std::unique_ptr<Form>> forms;
  add_tyre_shell_forms(forms, tm, Kinematics::nonlinear);
  forms.push_back(std::make_unique<PressureForm>(tm.mesh, tm.pressure_elements, pressure, Kinematics::nonlinear,
                                                 /*symmetrize=*/true));
  forms.push_back(std::move(winkler));
  auto glued = std::make_unique<StuckTreadForm>(std::move(stuck), std::move(anchors), std::move(normals),
                                                tyre.tread_shear_modulus);
  StuckTreadForm& tread = *glued;
  forms.push_back(std::move(glued));
  const double half = tm.half_model ? 2.0 : 1.0;  // a half model's forces stand for the whole tyre's
  for (int q = 0; q < static_cast<int>(tread.points().size()); ++q) s.tread_shear_N_per_mm += half * tread.spring(q);
  NonlinearProblem problem(std::move(dofs), std::move(forms));
  problem.evaluate(u, 1.0, true);
  SparseDirectSolver solver(problem.symmetric());
  solver.factorize(problem.system().tangent());
  s.factorizations = solver.stats().factorizations;
  s.stable = solver.stats().failed_cholesky == 0;
  s.assembly_s = problem.stats().assembly_s;
  s.analysis_s = solver.stats().analysis_s;
  s.factorization_s = solver.stats().factorization_s;

  // The response to a road motion: the load it puts on the tyre where the tyre has not moved yet (x = a),
  // the tyre's displacement under it, and the road's force and moment on the tyre then.
  const auto respond = [&](const RoadMotion& motion) {
    tread.set_road_motion(motion);
    Eigen::VectorXd load = Eigen::VectorXd::Zero(u.size());
    for (int q = 0; q < static_cast<int>(tread.points().size()); ++q) {
      const TreadPoint& p = tread.points()[q];
      const Eigen::Vector3d f = tread.point_force(q, u);
      for (int a = 0; a < 4; ++a) load.segment<3>(outer_dof(p.pairs[a], 0)) += p.shape[a] * f;
    }
    Eigen::VectorXd du = Eigen::VectorXd::Zero(u.size());
    problem.dofs().scatter_add(solver.solve(problem.dofs().gather(load)), du);
    if (responses) responses->push_back(du);
    return tread.resultant(u + du, s.centre_mm);
  };
  RoadMotion along;
  along.translation = Eigen::Vector3d::UnitY();  // 1 mm along the travel
  s.longitudinal_N_per_mm = half * respond(along).first.y();
  if (!tm.half_model) {
    RoadMotion across;
    across.translation = Eigen::Vector3d::UnitX();
    s.lateral_N_per_mm = respond(across).first.x();
    RoadMotion turn;
    turn.turn = 1.0;  // per radian (the response is linear)
    turn.centre = s.centre_mm;
    const Eigen::Vector3d n = -support.penetration(s.centre_mm, deflection).gradient.normalized();
    s.yaw_Nmm_per_rad = respond(turn).second.dot(n);
  }
  s.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return s;
}

}  // namespace tirefem
