// Planar mode of the tread friction form (MODEL.md §7): the tread shear is a 2-vector along (t, b),
// t = ∇ξ/|∇ξ| along the support's motion and b = ∇η/|∇η| across it, carried along each line of tread
// points from its anchor A:
//     s = s_A + Rk (ψ − ψ_A) (1, d) − (ξ − ξ_A, η − η_A)                                   (eq. 16 in 2D)
// with isotropic Coulomb friction (eq. 15 in 2D): stick where (G/hp)|s| ≤ μ kp g, else slip with the
// traction μ kp g e, e = s/|s|, and the shear (μ kp g hp/G) e from which a point re-sticking behind starts.
//
// Writing c_A = s_A − Rk ψ_A (1, d) + (ξ_A, η_A) (the anchor's offset), s = c_A + Rk ψ (1, d) − (ξ, η). A slip
// point's offset depends on its own trial shear, hence on its anchor's offset: the march carries ∂c along
// the line as a dense 2 × 3W Jacobian over the positions of the line's W points from the patch entry on.
// ∂e = (I − e eᵀ) ∂s / |s|.
//
// Full slip (FrictionLaw::Mode::full_slip) keeps the 1D law: traction σ μ kp g t with σ = slip_sign, nothing
// across (a prescribed spin / lock state, not a Coulomb state: no trial shear is defined for it).
#include <algorithm>
#include <stdexcept>

#include "tirefem/forms/strip_blocks.hpp"
#include "tirefem/forms/tread_friction_form.hpp"

namespace tirefem {

struct TreadFrictionForm::PlanarPoint {
  TreadContact status = TreadContact::out;
  Eigen::Vector2d shear = Eigen::Vector2d::Zero();     // along (t, b), mm
  Eigen::Vector2d traction = Eigen::Vector2d::Zero();  // along (t, b), MPa
  Eigen::Vector3d force = Eigen::Vector3d::Zero();     // on the tyre, N
  Eigen::MatrixXd d_force;                             // 3 × 3W: ∂force/∂(positions of the line's points)
};

namespace {
// (ξ, η) of a point and their gradients as the rows of a 2 × 3 matrix.
Eigen::Vector2d coordinates(const TravelCoordinate& xi, const TravelCoordinate& eta) {
  return {xi.value, eta.value};
}
Eigen::Matrix<double, 2, 3> coordinate_gradients(const TravelCoordinate& xi, const TravelCoordinate& eta) {
  Eigen::Matrix<double, 2, 3> g;
  g.row(0) = xi.gradient.transpose();
  g.row(1) = eta.gradient.transpose();
  return g;
}
// ∂(∇c/|∇c|)/∂x = (I − n nᵀ) ∂²c / |∇c|.
Eigen::Matrix3d direction_derivative(const TravelCoordinate& c) {
  const double norm = c.gradient.norm();
  const Eigen::Vector3d n = c.gradient / norm;
  return (Eigen::Matrix3d::Identity() - n * n.transpose()) * c.hessian / norm;
}
}  // namespace

double entry_weight(double g_out, double g_in) {
  return g_in != g_out ? std::clamp(-g_out / (g_in - g_out), 0.0, 1.0) : 1.0;
}

double stick_tangent_weight(double shear_norm, double limit, double band) {
  if (!(band > 0.0)) return 0.0;
  return std::clamp(1.0 - (shear_norm / limit - 1.0) / band, 0.0, 1.0);
}

FrictionPlan TreadFrictionForm::plan_planar(const Eigen::VectorXd& u, const std::vector<char>& region) const {
  const Eigen::Vector2d along(1.0, drift_);
  FrictionPlan plan(points_.size());
  for (const auto& line : lines_) {
    int previous_out = -1;
    bool anchored = false;
    Eigen::Vector2d offset = Eigen::Vector2d::Zero(), previous_coordinates = Eigen::Vector2d::Zero();
    FrictionPlanPoint anchor;
    double previous_g = 0.0;
    for (int q : line) {
      const PointKinematics k = kinematics(q, u);
      const double g = k.penetration.value;
      const Eigen::Vector2d xy = coordinates(k.travel, k.lateral);
      const bool touching = region.empty() ? g > 0 : region[q] != 0;
      if (!touching || !window_[q]) {
        anchored = false;
        previous_out = q, previous_g = g, previous_coordinates = xy;
        continue;
      }
      FrictionPlanPoint& pp = plan[q];
      if (!anchored) {
        // Entry of the patch, as in 1D: where g crosses zero between the last point out and this one.
        anchor = FrictionPlanPoint{};
        anchor.anchor_a = previous_out >= 0 ? previous_out : q;
        anchor.anchor_b = q;
        anchor.anchor_weight = previous_out >= 0 ? entry_weight(previous_g, g) : 1.0;
        const double wa = 1.0 - anchor.anchor_weight, wb = anchor.anchor_weight;
        const double angle = previous_out >= 0 ? wa * flow_angle(previous_out) + wb * flow_angle(q) : flow_angle(q);
        const Eigen::Vector2d at = previous_out >= 0 ? Eigen::Vector2d(wa * previous_coordinates + wb * xy) : xy;
        offset = -rolling_radius_ * angle * along + at;  // s_A = 0
        anchored = true;
      }
      if (law_.mode == FrictionLaw::Mode::full_slip) {
        pp.status = TreadContact::slip;
        pp.sign = law_.slip_sign;
        continue;
      }
      const Eigen::Vector2d trial = offset + rolling_radius_ * flow_angle(q) * along - xy;
      const double norm = trial.norm();
      const bool sticks = law_.mode == FrictionLaw::Mode::full_stick ||
                          shear_modulus_ * norm / points_[q].height <= law_.friction * kp_ * g;
      pp = anchor;
      pp.status = sticks ? TreadContact::stick : TreadContact::slip;
      if (sticks) continue;
      pp.sign = trial.x() >= 0 ? 1.0 : -1.0;
      anchor = FrictionPlanPoint{};
      anchor.anchor_a = anchor.anchor_b = q;
      anchor.anchored_on_slip = true;
      anchor.sign = pp.sign;
      // Re-sticking further on starts from this point's friction-limited shear vector.
      offset = slip_shear(q, g, 1.0) * trial / norm - rolling_radius_ * flow_angle(q) * along + xy;
    }
  }
  return plan;
}

int TreadFrictionForm::march_planar(int l, const FrictionPlan& plan, const Eigen::VectorXd& u,
                                    bool derivatives, std::vector<PlanarPoint>& out) const {
  const std::vector<int>& line = lines_[l];
  const int n = static_cast<int>(line.size());
  const bool full_slip = law_.mode == FrictionLaw::Mode::full_slip;
  // Columns: the line's points from the first one a contact point depends on to the last in contact.
  int first = n, last = -1;
  for (int i = 0; i < n; ++i) {
    const FrictionPlanPoint& pp = plan[line[i]];
    if (pp.status == TreadContact::out) continue;
    first = std::min(first, pp.anchor_a >= 0 ? std::min(i, line_position_[pp.anchor_a]) : i);
    last = i;
  }
  out.resize(n);
  for (PlanarPoint& o : out) o.status = TreadContact::out;
  if (last < 0) return 0;
  const int width = 3 * (last - first + 1);
  const auto column = [&](int i) { return 3 * (i - first); };

  std::vector<PointKinematics> kin(n);
  std::vector<char> known(n, 0);
  const auto at = [&](int i) -> const PointKinematics& {
    if (!known[i]) kin[i] = kinematics(line[i], u), known[i] = 1;
    return kin[i];
  };
  const Eigen::Vector2d along(1.0, drift_);
  // Offsets c_p provided by slip points to the points anchored on them, and their derivatives (rows 2i, 2i+1).
  std::vector<Eigen::Vector2d> provided(n, Eigen::Vector2d::Zero());
  Eigen::MatrixXd provided_d;
  if (derivatives) provided_d.setZero(2 * n, width);
  Eigen::MatrixXd ds(2, derivatives ? width : 0);

  for (int i = first; i <= last; ++i) {
    const int q = line[i];
    const FrictionPlanPoint& pp = plan[q];
    PlanarPoint& o = out[i];
    o.status = pp.status;
    if (pp.status == TreadContact::out) continue;
    const TreadPoint& p = points_[q];
    const PointKinematics& k = at(i);
    const double g = k.penetration.value;
    Eigen::Matrix<double, 3, 2> frame;  // [t b]
    frame.col(0) = k.travel.gradient.normalized();
    frame.col(1) = k.lateral.gradient.normalized();
    const Eigen::Matrix3d dt = direction_derivative(k.travel), db = direction_derivative(k.lateral);
    if (derivatives) o.d_force.setZero(3, width);

    if (full_slip) {  // 1D law, see the head of the file
      const double m = pp.sign * law_.friction * kp_ * p.weight;
      o.shear = Eigen::Vector2d(slip_shear(q, g, pp.sign), 0.0);
      o.traction = Eigen::Vector2d(pp.sign * law_.friction * kp_ * g, 0.0);
      o.force = m * g * frame.col(0);
      if (derivatives)
        o.d_force.middleCols<3>(column(i)) = m * (frame.col(0) * k.penetration.gradient.transpose() + g * dt);
      continue;
    }

    // The anchor's offset c_A and its derivative.
    Eigen::Vector2d offset;
    if (derivatives) ds.setZero();
    if (pp.anchored_on_slip) {
      const int j = line_position_[pp.anchor_a];
      offset = provided[j];
      if (derivatives) ds = provided_d.middleRows<2>(2 * j);
    } else {
      const int a = line_position_[pp.anchor_a], b = line_position_[pp.anchor_b];
      const PointKinematics &ka = at(a), &kb = at(b);
      const double wb = a != b ? entry_weight(ka.penetration.value, kb.penetration.value) : pp.anchor_weight;
      const double wa = 1.0 - wb;
      const double angle = wa * flow_angle(pp.anchor_a) + wb * flow_angle(pp.anchor_b);
      offset = -rolling_radius_ * angle * along + wa * coordinates(ka.travel, ka.lateral) +
               wb * coordinates(kb.travel, kb.lateral);
      if (derivatives) {
        ds.middleCols<3>(column(a)) += wa * coordinate_gradients(ka.travel, ka.lateral);
        ds.middleCols<3>(column(b)) += wb * coordinate_gradients(kb.travel, kb.lateral);
        // The entry weight w = −g_a / (g_b − g_a) follows u too.
        if (a != b && wb > 0.0 && wb < 1.0) {
          const double ga = ka.penetration.value, gb = kb.penetration.value, d2 = (gb - ga) * (gb - ga);
          const Eigen::Vector2d dc_dw =
              -rolling_radius_ * (flow_angle(pp.anchor_b) - flow_angle(pp.anchor_a)) * along +
              coordinates(kb.travel, kb.lateral) - coordinates(ka.travel, ka.lateral);
          ds.middleCols<3>(column(a)) += dc_dw * (-gb / d2) * ka.penetration.gradient.transpose();
          ds.middleCols<3>(column(b)) += dc_dw * (ga / d2) * kb.penetration.gradient.transpose();
        }
      }
    }
    // Trial (stick) shear, eq. (16) in 2D.
    const Eigen::Vector2d s = offset + rolling_radius_ * flow_angle(q) * along - coordinates(k.travel, k.lateral);
    const Eigen::Matrix<double, 2, 3> grad = coordinate_gradients(k.travel, k.lateral);
    if (derivatives) ds.middleCols<3>(column(i)) -= grad;

    // A point the plan holds as sliding whose trial shear lies inside the friction limit (a frozen plan
    // met by an iterate that would stick there, or one of the single loop) takes the stick traction
    // (G/hp) s: the return mapping of eq. (15) as one continuous function of u, μ kp g s / max(|s|,
    // μ kp g hp/G). At a converged, self-consistent plan nothing changes (a sliding point's |s| exceeds
    // the limit); during the iteration no sliding point meets an undefined direction (|s| → 0), where
    // s/|s| would swing the traction round and stall Newton (measured: a frozen-plan Newton at α = 2°
    // crept by 2% per iteration).
    const double limit = slip_shear(q, g, 1.0);  // μ kp g hp/G
    const bool inside = pp.status == TreadContact::slip && limit > 0.0 && s.norm() <= limit;
    if (pp.status == TreadContact::stick || inside) {
      o.status = TreadContact::stick;
      // {Fst}, [Kst] in 2D: (G/hp) s along (t, b).
      const double c = shear_modulus_ / p.height * p.weight;
      o.shear = s;
      o.traction = shear_modulus_ / p.height * s;
      o.force = c * frame * s;
      if (derivatives) {
        o.d_force.noalias() = c * frame * ds;
        o.d_force.middleCols<3>(column(i)) += c * (s.x() * dt + s.y() * db);
      }
      if (inside) {  // passes its (unlimited) shear on to the points anchored on it
        provided[i] = s - rolling_radius_ * flow_angle(q) * along + coordinates(k.travel, k.lateral);
        if (derivatives) {
          auto row = provided_d.middleRows<2>(2 * i);
          row = ds;
          row.middleCols<3>(column(i)) += grad;
        }
      }
      continue;
    }
    // A sliding point of a frozen plan that has left the support (g ≤ 0) carries no friction and
    // passes on no shear (its direction s/|s| would be undefined as s → 0 there).
    if (limit <= 0.0) {
      o.shear.setZero();
      o.traction.setZero();
      o.force.setZero();
      provided[i] = -rolling_radius_ * flow_angle(q) * along + coordinates(k.travel, k.lateral);
      if (derivatives) provided_d.middleRows<2>(2 * i).middleCols<3>(column(i)) = grad;
      continue;
    }
    // Slip (eq. 15 in 2D): μ kp g e, e = s/|s|.
    const double norm = s.norm();
    const Eigen::Vector2d e = norm > 0.0 ? Eigen::Vector2d(s / norm) : Eigen::Vector2d::UnitX();
    const double m = law_.friction * kp_ * p.weight;
    o.shear = limit * e;
    o.traction = law_.friction * kp_ * g * e;
    o.force = m * g * frame * e;
    provided[i] = limit * e - rolling_radius_ * flow_angle(q) * along + coordinates(k.travel, k.lateral);
    if (derivatives) {
      // ∂e = (I − e eᵀ) ∂s / |s|
      Eigen::Matrix2d projector = Eigen::Matrix2d::Zero();
      if (norm > 0.0) projector = (Eigen::Matrix2d::Identity() - e * e.transpose()) / norm;
      const Eigen::MatrixXd de = projector * ds;  // 2 × 3W
      o.d_force.noalias() = m * g * frame * de;
      o.d_force.middleCols<3>(column(i)) +=
          m * (frame * e * k.penetration.gradient.transpose() + g * (e.x() * dt + e.y() * db));
      auto row = provided_d.middleRows<2>(2 * i);
      row = limit * de;
      row.middleCols<3>(column(i)) += slip_shear(q, 1.0, 1.0) * e * k.penetration.gradient.transpose() + grad;
      // Smoothed Jacobian (set_jacobian_smoothing): just past the friction limit, the stick tangent
      // blended in, its weight falling linearly from 1 at |s| = L to 0 at |s| = (1 + band) L
      // (stick_tangent_weight: 1 below L too, where a frozen plan's sliding point may lie).
      const double w = stick_tangent_weight(norm, limit, jacobian_smoothing_);
      if (w > 0.0) {  // (1 − w) slip + w stick, the stick tangent as in the stick branch above
        const double c = w * shear_modulus_ / p.height * p.weight;
        o.d_force *= 1.0 - w;
        o.d_force.noalias() += c * frame * ds;
        o.d_force.middleCols<3>(column(i)) += c * (s.x() * dt + s.y() * db);
        row *= 1.0 - w;
        row += w * ds;
        row.middleCols<3>(column(i)) += w * grad;
      }
    }
  }
  return first;
}

std::vector<std::vector<int>> TreadFrictionForm::planar_dependencies(const FrictionPlan& plan) const {
  std::vector<std::vector<int>> deps(points_.size());
  const bool full_slip = law_.mode == FrictionLaw::Mode::full_slip;
  for (const auto& line : lines_) {
    for (int q : line) {
      const FrictionPlanPoint& pp = plan[q];
      if (pp.status == TreadContact::out) continue;
      std::vector<int>& d = deps[q];
      d.push_back(points_[q].element);
      if (!full_slip) {
        if (pp.anchor_a < 0 || pp.anchor_b < 0)
          throw std::logic_error("planar tread friction: a point without an anchor (a plan made in 1D mode?)");
        if (pp.anchored_on_slip) {
          // A slip point's dependencies are those of the offset it provides (it is upstream: done).
          const std::vector<int>& from = deps[pp.anchor_a];
          d.insert(d.end(), from.begin(), from.end());
        } else {
          d.push_back(points_[pp.anchor_a].element);
          d.push_back(points_[pp.anchor_b].element);
        }
      }
      std::sort(d.begin() + 1, d.end());
      d.erase(std::unique(d.begin() + 1, d.end()), d.end());
      d.erase(std::remove(d.begin() + 1, d.end(), d.front()), d.end());
    }
  }
  return deps;
}

void TreadFrictionForm::assemble_planar(const FormInput& input, SparseSystem& system) const {
  const bool released = frozen_.empty();
  const FrictionPlan fresh = released ? plan(input.displacement) : FrictionPlan{};
  const FrictionPlan& plan = released ? fresh : frozen_;
  const std::vector<std::vector<int>> deps = planar_dependencies(plan);
  // Summed per pair of elements of a strip (forms/strip_blocks.hpp): rows on the element of a point in
  // contact, columns on the elements its force depends on (its own: the residual too).
  std::vector<std::vector<ElementPair>> pairs(strips_.size());
  for (std::size_t st = 0; st < strips_.size(); ++st)
    for (int l : strips_[st])
      for (int q : lines_[l]) {
        const int columns = input.with_tangent ? static_cast<int>(deps[q].size()) : std::min<int>(1, deps[q].size());
        for (int k = 0; k < columns; ++k) pairs[st].emplace_back(deps[q][0], deps[q][k]);
      }
  const StripSlots slots(std::move(pairs));
  BlockBatch& batch = system.batch(slots.slots());
#pragma omp parallel
  {
    std::vector<PlanarPoint> line_points;
    StripBlocks sums;
#pragma omp for schedule(dynamic, 1)
    for (int st = 0; st < slots.strips(); ++st) {
      if (slots.pairs(st).empty()) continue;
      sums.reset(slots, st);
      for (int l : strips_[st]) {
        const std::vector<int>& line = lines_[l];
        const int first = march_planar(l, plan, input.displacement, input.with_tangent, line_points);
        for (int i = 0; i < static_cast<int>(line.size()); ++i) {
          const PlanarPoint& o = line_points[i];
          if (o.status == TreadContact::out) continue;
          const TreadPoint& pt = points_[line[i]];
          sums.add_residual(pt.element, pt.shape, -o.force);
          if (!input.with_tangent) continue;
          // Columns of points this one does not depend on are exact zeros (and their pairs not slots).
          for (int j = first; j < first + static_cast<int>(o.d_force.cols()) / 3; ++j) {
            const auto d = o.d_force.middleCols<3>(3 * (j - first));
            if (d.isZero(0.0)) continue;
            const TreadPoint& pj = points_[line[j]];
            sums.add_tangent(pt.element, pt.shape, pj.element, pj.shape, -d);
          }
        }
      }
      sums.flush(mesh_, batch, input.with_tangent);
    }
  }
  system.add(batch);
}

std::vector<TreadTraction> TreadFrictionForm::evaluate_planar(const Eigen::VectorXd& u) const {
  const FrictionPlan plan = frozen_.empty() ? this->plan(u) : frozen_;
  std::vector<TreadTraction> out(points_.size());
  std::vector<PlanarPoint> line_points;
  for (int l = 0; l < static_cast<int>(lines_.size()); ++l) {
    march_planar(l, plan, u, false, line_points);
    for (int i = 0; i < static_cast<int>(lines_[l].size()); ++i) {
      const PlanarPoint& o = line_points[i];
      TreadTraction& tr = out[lines_[l][i]];
      tr.status = o.status;
      if (o.status == TreadContact::out) continue;
      tr.shear_vector = o.shear;
      tr.traction_vector = o.traction;
      tr.shear = o.shear.x();
      tr.traction = o.traction.x();
      tr.force = o.force;
    }
  }
  return out;
}

}  // namespace tirefem
