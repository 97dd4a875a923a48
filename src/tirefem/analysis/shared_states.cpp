#include "tirefem/analysis/shared_states.hpp"

#include "tirefem/analysis/mesh_transfer.hpp"

#include <stdexcept>

#include <fmt/format.h>

namespace tirefem {

InflatedTyres::Entry& InflatedTyres::entry(const MeshSettings& m) {
  return entries_[{m.circumferential_elements, m.meridional_elements, m.half_model, m.circumferential_refinement,
                    static_cast<int>(m.meridional_grading), static_cast<int>(m.faces)}];
}

const TyreMesh& InflatedTyres::mesh(const MeshSettings& m) {
  const std::lock_guard lock(mutex_);
  Entry& e = entry(m);
  if (!e.mesh) e.mesh = std::make_unique<TyreMesh>(build_tyre_mesh(case_.tyre, m));
  return *e.mesh;
}

const InflationResult& InflatedTyres::inflated(const MeshSettings& m) {
  const std::lock_guard lock(mutex_);
  Entry& e = entry(m);
  if (!e.inflated) {
    // Another mesh's inflated state on the same meridional stations is a close start (the inflated tyre
    // is axisymmetric), a half model's for a full one too (it is symmetric about the wheel plane).
    const TyreMesh& tm = mesh(m);
    // Of several, one on the same circumferential stations (its rows carried over without a turn, exact for
    // a half model's mirror image), else one of the same kind (half or full).
    const auto rank = [&](const Entry& other) {
      return 2 * (other.mesh->mesh.v_values == tm.mesh.v_values) + (other.mesh->half_model == tm.half_model);
    };
    const auto near_state = [&]() -> const Entry* {
      const Entry* found = nullptr;
      for (const auto& [key, other] : entries_)
        if (&other != &e && other.inflated && other.inflated->converged &&
            other.inflated->kinematics == Kinematics::nonlinear && turns_onto(*other.mesh, tm) &&
            (!found || rank(other) > rank(*found)))
          found = &other;
      return found;
    };
    const Entry* near = near_state();
    // A full model without one: its half model first (half the equations, itself perhaps started from
    // another half model), then its mirror image. Measured on the tyre-test example's 80 × 46 full
    // model: 14.1 s from the pressure ramp.
    if (!near && !tm.half_model) {
      MeshSettings half = m;
      half.half_model = true;
      try {
        inflated(half);
        near = near_state();
      } catch (const std::runtime_error&) {
      }
    }
    InflationSettings nonlinear = case_.inflation;
    nonlinear.linear = false;
    e.inflated = near ? run_inflation_from(tm, nonlinear, *near->mesh, near->inflated->displacement, progress_)
                      : inflate_for_contact(tm, case_.inflation, progress_);
    if (solved_) solved_(m, e.inflated->counters.wall_s);
  }
  if (!e.inflated->converged) throw std::runtime_error(e.inflated->failure);
  return *e.inflated;
}

void InflatedTyres::adopt(const MeshSettings& m, const InflationResult& r) {
  const std::lock_guard lock(mutex_);
  entry(m).inflated = r;
}

std::string SharedFootprints::key(const MeshSettings& m, const SupportDescription& s, double load,
                                  double tolerance) {
  std::string k = fmt::format("{} {} {} {:a} {} {} | {} {:a} | {:a} {:a}", m.circumferential_elements,
                              m.meridional_elements, m.half_model, m.circumferential_refinement,
                              static_cast<int>(m.meridional_grading), static_cast<int>(m.faces),
                              static_cast<int>(s.kind), s.drum_diameter, load, tolerance);
  for (const auto& t : s.terms) k += fmt::format(" {:a} {} {}", t.coefficient, t.x_power, t.y_power);
  return k;
}

const StaticContactResult* SharedFootprints::find(const std::string& key) const {
  const std::lock_guard lock(mutex_);
  const auto it = entries_.find(key);
  return it == entries_.end() ? nullptr : &it->second;
}

void SharedFootprints::keep(const std::string& key, const StaticContactResult& r) {
  const std::lock_guard lock(mutex_);
  if (r.completed) entries_.try_emplace(key, r);
}

std::vector<PathState> load_curve_states_near(const StaticContactResult& curve, const TyreMesh& curve_mesh,
                                              const TyreMesh& mesh, double load) {
  const bool mirror = mirrors_onto(curve_mesh, mesh);
  if (!mirror && !interpolates_onto(curve_mesh, mesh)) return {};
  const auto [below, above] = states_around_load(curve.path, load);
  if (!below) return {};
  std::vector<PathState> near;
  for (const PathState* p : {below, above})
    near.push_back({p->deflection_mm, p->Qz_N,
                    mirror ? mirrored_onto(curve_mesh, p->displacement, mesh)
                           : interpolated_onto(curve_mesh, p->displacement, mesh)});
  return near;
}

}  // namespace tirefem
