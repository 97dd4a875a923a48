#include "tirefem/analysis/static_contact_run.hpp"

#include <stdexcept>

#include <fmt/format.h>

#include "tirefem/analysis/first_touch.hpp"
#include "tirefem/analysis/tyre_shell_forms.hpp"
#include "tirefem/forms/linearized_form.hpp"
#include "tirefem/forms/pressure_form.hpp"

namespace tirefem {

namespace {

// Shell and inflation pressure linearised about the inflated state u0.
std::unique_ptr<Form> linearized_tyre(const TyreMesh& tm, double pressure, const Eigen::VectorXd& u0) {
  DofMap dofs(tm.mesh.dof_count());
  dofs.fix(tm.fixed_dofs);
  std::vector<std::unique_ptr<Form>> forms;
  add_tyre_shell_forms(forms, tm, Kinematics::nonlinear);
  forms.push_back(std::make_unique<PressureForm>(tm.mesh, tm.pressure_elements, pressure, Kinematics::nonlinear,
                                                 /*symmetrize=*/true));
  NonlinearProblem tyre(dofs, std::move(forms));
  tyre.evaluate(u0, 1.0, true);
  return std::make_unique<LinearizedForm>(dofs, tyre.system().tangent(), tyre.system().residual(), u0);
}

}  // namespace

StaticContactRun::StaticContactRun(const TyreMesh& tm, const TyreDescription& tyre, const InflationSettings& inflation,
                                   const ContactSettings& settings, const SupportDescription& support_description,
                                   Kinematics kinematics, DeflectionOrigin origin, StaticContactResult& result,
                                   const ProgressSink& progress, const InflationResult* inflated)
    : tm_(tm), settings_(settings), result_(result), progress_(progress),
      support_(make_support(support_description)) {
  result_.deflection_from = origin;
  result_.inflation = inflated ? *inflated : inflate_for_contact(tm, inflation, progress);
  if (!result_.inflation.converged) throw std::runtime_error("inflation did not converge");
  if (result_.inflation.kinematics != Kinematics::nonlinear || result_.inflation.pressure != inflation.pressure)
    throw std::invalid_argument("a contact study needs the nonlinear inflated state at its pressure");
  // Sought from an unstable inflated state, a stable equilibrium is a buckle of the mesh, which Newton hunts
  // for at length (a 205/55R16 on 80 × 46 with 38 mm elements round the crown: the first contact state took
  // 130–150 s and 6 cut-backs to fail): the study stops at once, saying why.
  if (kinematics == Kinematics::nonlinear && settings.equilibrium == ContactSettings::Equilibrium::stable &&
      result_.inflation.tangent_shift > 0.0)
    throw std::runtime_error(result_.inflation.instability +
                             "; contact.equilibrium = \"stable\" finds no stable state near it (\"nearest\" "
                             "solves on this mesh anyway, its states then reported unstable)");
  result_.tread_points = tyre_tread_points(tm, tyre, settings.quadrature);

  DofMap dofs(tm.mesh.dof_count());
  dofs.fix(tm.fixed_dofs);
  std::vector<std::unique_ptr<Form>> forms;
  if (kinematics == Kinematics::nonlinear) {
    add_tyre_shell_forms(forms, tm, kinematics);
    forms.push_back(std::make_unique<PressureForm>(tm.mesh, tm.pressure_elements, inflation.pressure,
                                                   kinematics, /*symmetrize=*/true));
  } else {
    forms.push_back(linearized_tyre(tm, inflation.pressure, result_.inflation.displacement));
  }
  auto contact = std::make_unique<WinklerContactForm>(tm.mesh, result_.tread_points,
                                                      tyre.tread_stiffness, *support_);
  contact_ = contact.get();
  forms.push_back(std::move(contact));
  problem_ = std::make_unique<NonlinearProblem>(std::move(dofs), std::move(forms));
  problem_->load_scale();  // the inflation load (no contact at δz = 0, u = 0) sets the residual scale
  NewtonSettings ns;
  ns.max_iterations = settings.max_newton_iterations;
  ns.residual_tolerance = settings.residual_tolerance;
  ns.reuse_factorization = settings.reuse_factorizations;
  ns.adaptive_krylov_tolerance = true;
  // The linearised tyre's tangent is the inflated state's (positive definite: its factorisations in
  // the inflation needed no shift, and the first one here would show a shift) plus the contact springs.
  ns.known_stable = kinematics == Kinematics::linear;
  ns.stable_equilibrium = settings.equilibrium == ContactSettings::Equilibrium::stable;
  newton_ = std::make_unique<NewtonSolver>(*problem_, ns);
  for (const TreadPointState& p : contact_->evaluate(result_.inflation.displacement))
    inflated_tread_.push_back(p.position);
  result_.first_touch_deflection_mm = first_touch_deflection(inflated_tread_, *support_);
  if (progress_)
    progress_(fmt::format("  the inflated tyre first touches the support at δz = {:.3f} mm (from the undeformed "
                          "tyre)",
                          result_.first_touch_deflection_mm));
  // δz is measured from the undeformed tyre (MODEL.md §2), so the inflated tyre, grown by about
  // 0.5 mm, already presses on the support at δz = 0: the first load point is solved like the others.
  // From the first touch, the first point is the inflated state itself, touching the support.
  start_ = origin == DeflectionOrigin::first_touch ? result_.first_touch_deflection_mm : 0.0;
  path_ = std::make_unique<DeflectionPath>(*newton_, *contact_, settings, result_.inflation.displacement, start_);
  if (!solve_at(start_))
    throw std::runtime_error(fmt::format(
        "the first contact state (δz = {:.3g}) did not converge: {}; check tyre.tread.stiffness (kp) and the "
        "contact settings (max_newton_iterations, residual_tolerance)",
        start_, result_.failure));
}

bool StaticContactRun::solve_at(double deflection, int max_cutbacks) {
  const auto t0 = StaticContactClock::now();
  const int factorizations_before = newton_->linear_stats().factorizations;
  const DeflectionPath::Step step = path_->advance_to(deflection, max_cutbacks);
  if (!step.converged) {
    result_.failure = step.failure;
    return false;
  }
  record(deflection, step, seconds_since(t0), newton_->linear_stats().factorizations - factorizations_before);
  const LoadPoint& p = result_.points.back();
  const std::string where =
      result_.deflection_from == DeflectionOrigin::first_touch
          ? fmt::format("δ {:6.2f} mm from first touch (δz {:6.2f} mm)", deflection_from_origin(result_, deflection),
                        deflection)
          : fmt::format("δz {:6.2f} mm", deflection);
  if (progress_)
    progress_(fmt::format("  {}: Qz {:8.1f} N, patch {:5.1f} × {:5.1f} mm, pmax {:.3f} MPa "
                          "({} contact, {} Newton iterations{}, {:.2f} s){}{}",
                          where, p.patch.Qz_N, p.patch.patch_length_mm, p.patch.patch_width_mm,
                          p.patch.max_pressure_MPa, p.contact_iterations, p.newton_iterations,
                          step.cutbacks ? fmt::format(", {} cut-backs", step.cutbacks) : "", p.time_s,
                          stable(p.tangent_shift)
                              ? ""
                              : std::string(" UNSTABLE: its tangent is indefinite"),
                          p.escapes ? fmt::format(" PASSED AN INSTABILITY: left an unstable equilibrium "
                                                  "(tangent shift {:.0e}) for this stable state",
                                                  p.escaped_shift)
                                    : ""));
  return true;
}

void StaticContactRun::finish() {
  result_.final_state.deflection_mm = path_->deflection();
  result_.final_state.displacement = path_->displacement();
  contact_->set_deflection(path_->deflection());
  result_.final_state.tread = contact_->evaluate(path_->displacement());
  SolveCounters& c = result_.counters;
  c.load_steps = static_cast<int>(result_.points.size()) - 1;
  add_counters(c, *newton_, *problem_);
}

void StaticContactRun::record(double deflection, const DeflectionPath::Step& step, double time, int factorizations) {
  LoadPoint p;
  p.deflection_mm = deflection;
  contact_->set_deflection(deflection);
  p.patch = patch_figures(result_.tread_points, contact_->evaluate(path_->displacement()), tm_.half_model);
  p.contact_iterations = step.last.contact_iterations;
  p.newton_iterations = step.newton_iterations;
  p.factorizations = factorizations;
  p.increments = step.increments;
  p.tangent_shift = step.last.tangent_shift;
  p.escapes = step.last.escapes;
  p.escaped_shift = step.last.escaped_shift;
  p.time_s = time;
  result_.points.push_back(p);
  result_.counters.cutbacks += step.cutbacks;
}

}  // namespace tirefem
