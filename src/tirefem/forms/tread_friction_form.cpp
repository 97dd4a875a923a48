#include "tirefem/forms/tread_friction_form.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "tirefem/forms/strip_blocks.hpp"

namespace tirefem {

namespace {
void append_outer_dofs(const std::array<int, 4>& pairs, std::vector<int>& dofs) {
  for (int a = 0; a < 4; ++a)
    for (int c = 0; c < 3; ++c) dofs.push_back(outer_dof(pairs[a], c));
}
}  // namespace

TreadFrictionForm::TreadFrictionForm(const ShellMesh& mesh, std::vector<TreadPoint> points,
                                     double tread_stiffness, double shear_modulus, const SupportSurface& support,
                                     int support_direction, std::vector<char> window)
    : mesh_(mesh), points_(std::move(points)), kp_(tread_stiffness), shear_modulus_(shear_modulus),
      support_(support), direction_(support_direction >= 0 ? 1.0 : -1.0), window_(std::move(window)) {
  if (!(kp_ > 0) || !(shear_modulus_ > 0))
    throw std::invalid_argument("tread friction: the tread stiffness and shear modulus must be > 0");
  if (window_.size() != points_.size()) throw std::invalid_argument("tread friction: window of the wrong size");
  std::map<double, std::vector<int>> by_u;  // lines: points of equal s
  for (int q = 0; q < static_cast<int>(points_.size()); ++q) by_u[points_[q].u].push_back(q);
  for (auto& [u, line] : by_u) {
    std::sort(line.begin(), line.end(), [this](int a, int b) { return flow_angle(a) < flow_angle(b); });
    lines_.push_back(std::move(line));
  }
  line_position_.assign(points_.size(), -1);
  for (const auto& line : lines_)
    for (int i = 0; i < static_cast<int>(line.size()); ++i) line_position_[line[i]] = i;
  std::map<std::vector<int>, int> strip_of;  // a line's elements → its strip
  for (int l = 0; l < static_cast<int>(lines_.size()); ++l) {
    std::vector<int> elements;
    for (int q : lines_[l]) elements.push_back(points_[q].element);
    std::sort(elements.begin(), elements.end());
    elements.erase(std::unique(elements.begin(), elements.end()), elements.end());
    const auto [it, added] = strip_of.try_emplace(std::move(elements), static_cast<int>(strips_.size()));
    if (added) strips_.emplace_back();
    strips_[it->second].push_back(l);
  }
}

void TreadFrictionForm::add_pattern(PatternBuilder& pattern) const {
  // A stick point's shear depends on its anchor anywhere upstream on its line: couple all elements of a
  // line inside the window (lines of one strip of elements give the same block).
  std::vector<std::vector<int>> seen;
  for (const auto& line : lines_) {
    // The window's points and their neighbours on the line (an entry anchor may lie just outside).
    std::vector<int> elements;
    for (std::size_t i = 0; i < line.size(); ++i) {
      const bool near = window_[line[i]] || (i > 0 && window_[line[i - 1]]) ||
                        (i + 1 < line.size() && window_[line[i + 1]]);
      if (near) elements.push_back(points_[line[i]].element);
    }
    std::sort(elements.begin(), elements.end());
    elements.erase(std::unique(elements.begin(), elements.end()), elements.end());
    if (elements.empty() || std::find(seen.begin(), seen.end(), elements) != seen.end()) continue;
    std::vector<int> dofs;
    for (int e : elements) append_outer_dofs(mesh_.elements[e], dofs);
    std::sort(dofs.begin(), dofs.end());
    dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
    pattern.add_block(dofs);
    seen.push_back(std::move(elements));
  }
}

TreadFrictionForm::PointKinematics TreadFrictionForm::kinematics(int q, const Eigen::VectorXd& u) const {
  const TreadPoint& p = points_[q];
  PointKinematics k;
  k.position = p.reference;
  for (int a = 0; a < 4; ++a) k.position += p.shape[a] * u.segment<3>(outer_dof(p.pairs[a], 0));
  k.travel = support_.travel(k.position, deflection_);
  k.travel.value *= direction_;
  k.travel.gradient *= direction_;
  k.travel.hessian *= direction_;
  if (planar_) k.lateral = support_.lateral(k.position, deflection_);
  k.penetration = support_.penetration(k.position, deflection_);
  return k;
}

double TreadFrictionForm::slip_shear(int q, double penetration, double sign) const {
  // The largest shear friction allows: G |s| / hp = μ kp g (eq. 15).
  return sign * law_.friction * kp_ * penetration * points_[q].height / shear_modulus_;
}

FrictionPlan TreadFrictionForm::plan(const Eigen::VectorXd& u, const std::vector<char>& region) const {
  if (planar_) return plan_planar(u, region);
  FrictionPlan plan(points_.size());
  for (const auto& line : lines_) {
    int previous_out = -1;
    bool anchored = false;
    double anchor_shear = 0.0, anchor_angle = 0.0, anchor_travel = 0.0;
    FrictionPlanPoint anchor;
    double previous_g = 0.0, previous_angle = 0.0, previous_travel = 0.0;
    for (int q : line) {
      const PointKinematics k = kinematics(q, u);
      const double g = k.penetration.value;
      const bool touching = region.empty() ? g > 0 : region[q] != 0;
      if (!touching || !window_[q]) {
        anchored = false;
        previous_out = q, previous_g = g, previous_angle = flow_angle(q), previous_travel = k.travel.value;
        continue;
      }
      FrictionPlanPoint& pp = plan[q];
      if (!anchored) {
        // Entry of the patch: where g crosses zero between the last point out and this one.
        anchor = FrictionPlanPoint{};
        anchor.anchor_a = previous_out >= 0 ? previous_out : q;
        anchor.anchor_b = q;
        anchor.anchor_weight = previous_out >= 0 ? entry_weight(previous_g, g) : 1.0;
        const double wa = 1.0 - anchor.anchor_weight, wb = anchor.anchor_weight;
        anchor_shear = 0.0;
        anchor_angle = previous_out >= 0 ? wa * previous_angle + wb * flow_angle(q) : flow_angle(q);
        anchor_travel = previous_out >= 0 ? wa * previous_travel + wb * k.travel.value : k.travel.value;
        anchored = true;
      }
      if (law_.mode == FrictionLaw::Mode::full_slip) {
        pp.status = TreadContact::slip;
        pp.sign = law_.slip_sign;
        continue;
      }
      // Would-be stick shear (eq. 16 from the anchor) and the Coulomb test (eq. 15).
      const double trial =
          anchor_shear + rolling_radius_ * (flow_angle(q) - anchor_angle) - (k.travel.value - anchor_travel);
      const bool sticks = law_.mode == FrictionLaw::Mode::full_stick ||
                          shear_modulus_ * std::abs(trial) / points_[q].height <= law_.friction * kp_ * g;
      if (sticks) {
        pp = anchor;
        pp.status = TreadContact::stick;
        continue;
      }
      pp.status = TreadContact::slip;
      pp.sign = trial >= 0 ? 1.0 : -1.0;
      // Re-sticking further on starts from this point's friction-limited shear.
      anchor = FrictionPlanPoint{};
      anchor.anchor_a = anchor.anchor_b = q;
      anchor.anchored_on_slip = true;
      anchor.sign = pp.sign;
      anchor_shear = slip_shear(q, g, pp.sign);
      anchor_angle = flow_angle(q);
      anchor_travel = k.travel.value;
    }
  }
  return plan;
}

void TreadFrictionForm::freeze_plan(FrictionPlan plan) {
  if (plan.size() != points_.size()) throw std::invalid_argument("friction plan of the wrong size");
  frozen_ = std::move(plan);
}

int TreadFrictionForm::contact_outside_window(const Eigen::VectorXd& u) const {
  int n = 0;
  for (int q = 0; q < static_cast<int>(points_.size()); ++q)
    if (!window_[q] && kinematics(q, u).penetration.value > 0) ++n;
  return n;
}

TreadFrictionForm::PointForce TreadFrictionForm::point_force(int q, const FrictionPlanPoint& pp,
                                                               const Eigen::VectorXd& u) const {
  PointForce out;
  const TreadPoint& p = points_[q];
  const PointKinematics k = kinematics(q, u);
  const double norm = k.travel.gradient.norm();
  const Eigen::Vector3d t = k.travel.gradient / norm;  // unit, along the support's motion
  // ∂t/∂x = (I − t tᵀ) ∂²ξ / |∇ξ|
  const Eigen::Matrix3d dt = (Eigen::Matrix3d::Identity() - t * t.transpose()) * k.travel.hessian / norm;
  double magnitude = 0.0;  // traction × area: the force on the tyre is magnitude · t
  // ∂(magnitude)/∂x at up to three points: this one, and the anchor's a and b.
  Eigen::Vector3d d_self = Eigen::Vector3d::Zero(), d_other[2] = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  if (pp.status == TreadContact::slip) {
    // eq. (17) {Fsl}, [Ksl]: σ μ kp g, depending on the normal displacement only.
    const double c = pp.sign * law_.friction * kp_ * p.weight;
    magnitude = c * k.penetration.value;
    d_self = c * k.penetration.gradient;
  } else {
    // eq. (17) {Fst}, [Kst]: (G/hp) s, with s from the anchor (eq. 16).
    const double c = shear_modulus_ / p.height * p.weight;
    const PointKinematics ka = kinematics(pp.anchor_a, u);
    const PointKinematics kb = pp.anchor_b == pp.anchor_a ? ka : kinematics(pp.anchor_b, u);
    const bool entry = !pp.anchored_on_slip && pp.anchor_a != pp.anchor_b;
    const double wb = entry ? entry_weight(ka.penetration.value, kb.penetration.value) : pp.anchor_weight;
    const double wa = 1.0 - wb;
    double anchor_shear = 0.0;
    Eigen::Vector3d d_anchor_shear = Eigen::Vector3d::Zero();
    if (pp.anchored_on_slip) {
      anchor_shear = slip_shear(pp.anchor_a, ka.penetration.value, pp.sign);
      d_anchor_shear = slip_shear(pp.anchor_a, 1.0, pp.sign) * ka.penetration.gradient;
    }
    const double anchor_angle = wa * flow_angle(pp.anchor_a) + wb * flow_angle(pp.anchor_b);
    const double anchor_travel = wa * ka.travel.value + wb * kb.travel.value;
    const double shear =
        anchor_shear + rolling_radius_ * (flow_angle(q) - anchor_angle) - (k.travel.value - anchor_travel);
    magnitude = c * shear;
    d_self = -c * k.travel.gradient;
    // The entry weight w = −g_a / (g_b − g_a) follows u too.
    Eigen::Vector3d dw_a = Eigen::Vector3d::Zero(), dw_b = Eigen::Vector3d::Zero();
    if (entry && wb > 0.0 && wb < 1.0) {
      const double ga = ka.penetration.value, gb = kb.penetration.value, d2 = (gb - ga) * (gb - ga);
      const double ds_dw = -rolling_radius_ * (flow_angle(pp.anchor_b) - flow_angle(pp.anchor_a)) +
                           (kb.travel.value - ka.travel.value);
      dw_a = c * ds_dw * (-gb / d2) * ka.penetration.gradient;
      dw_b = c * ds_dw * (ga / d2) * kb.penetration.gradient;
    }
    out.other[0] = pp.anchor_a;
    d_other[0] = c * (wa * ka.travel.gradient + d_anchor_shear) + dw_a;
    if (pp.anchor_b != pp.anchor_a) {
      out.other[1] = pp.anchor_b;
      d_other[1] = c * wb * kb.travel.gradient + dw_b;
    } else {
      d_other[0] += c * wb * ka.travel.gradient;
    }
  }
  out.force = magnitude * t;
  out.d_self = t * d_self.transpose() + magnitude * dt;
  for (int j = 0; j < 2; ++j) out.d_other[j] = t * d_other[j].transpose();
  return out;
}

void TreadFrictionForm::assemble(const FormInput& input, SparseSystem& system) const {
  if (planar_) return assemble_planar(input, system);
  const bool released = frozen_.empty();
  const FrictionPlan fresh = released ? plan(input.displacement) : FrictionPlan{};
  const FrictionPlan& plan = released ? fresh : frozen_;
  // Residual = −force on the tyre, spread over each point's element; tangent rows on that element,
  // columns on the elements of the point and of its anchor (a stick point), summed per pair of elements
  // of a strip (forms/strip_blocks.hpp).
  std::vector<std::vector<ElementPair>> pairs(strips_.size());
  for (std::size_t st = 0; st < strips_.size(); ++st)
    for (int l : strips_[st])
      for (int q : lines_[l]) {
        const FrictionPlanPoint& pp = plan[q];
        if (pp.status == TreadContact::out) continue;
        const int own = points_[q].element;
        pairs[st].emplace_back(own, own);
        if (!input.with_tangent || pp.status != TreadContact::stick) continue;
        pairs[st].emplace_back(own, points_[pp.anchor_a].element);
        pairs[st].emplace_back(own, points_[pp.anchor_b].element);
      }
  const StripSlots slots(std::move(pairs));
  BlockBatch& batch = system.batch(slots.slots());
#pragma omp parallel
  {
    StripBlocks sums;
#pragma omp for schedule(dynamic, 1)
    for (int st = 0; st < slots.strips(); ++st) {
      if (slots.pairs(st).empty()) continue;
      sums.reset(slots, st);
      for (int l : strips_[st])
        for (int q : lines_[l]) {
          const FrictionPlanPoint& pp = plan[q];
          if (pp.status == TreadContact::out) continue;
          const TreadPoint& p = points_[q];
          const PointForce f = point_force(q, pp, input.displacement);
          sums.add_residual(p.element, p.shape, -f.force);
          if (!input.with_tangent) continue;
          sums.add_tangent(p.element, p.shape, p.element, p.shape, -f.d_self);
          for (int j = 0; j < 2; ++j)
            if (f.other[j] >= 0) {
              const TreadPoint& po = points_[f.other[j]];
              sums.add_tangent(p.element, p.shape, po.element, po.shape, -f.d_other[j]);
            }
        }
      sums.flush(mesh_, batch, input.with_tangent);
    }
  }
  system.add(batch);
}

std::vector<TreadTraction> TreadFrictionForm::evaluate(const Eigen::VectorXd& u) const {
  if (planar_) return evaluate_planar(u);
  const FrictionPlan plan = frozen_.empty() ? this->plan(u) : frozen_;
  std::vector<TreadTraction> out(points_.size());
  for (int q = 0; q < static_cast<int>(points_.size()); ++q) {
    const FrictionPlanPoint& pp = plan[q];
    TreadTraction& tr = out[q];
    tr.status = pp.status;
    if (pp.status == TreadContact::out) continue;
    const TreadPoint& p = points_[q];
    const PointKinematics k = kinematics(q, u);
    if (pp.status == TreadContact::slip) {
      tr.shear = slip_shear(q, k.penetration.value, pp.sign);
    } else {
      const PointKinematics ka = kinematics(pp.anchor_a, u);
      const PointKinematics kb = kinematics(pp.anchor_b, u);
      const bool entry = !pp.anchored_on_slip && pp.anchor_a != pp.anchor_b;
      const double wb = entry ? entry_weight(ka.penetration.value, kb.penetration.value) : pp.anchor_weight;
      const double wa = 1.0 - wb;
      const double anchor_shear = pp.anchored_on_slip ? slip_shear(pp.anchor_a, ka.penetration.value, pp.sign) : 0.0;
      tr.shear = anchor_shear +
                 rolling_radius_ * (flow_angle(q) - wa * flow_angle(pp.anchor_a) - wb * flow_angle(pp.anchor_b)) -
                 (k.travel.value - wa * ka.travel.value - wb * kb.travel.value);
    }
    tr.traction = shear_modulus_ * tr.shear / p.height;
    tr.shear_vector = Eigen::Vector2d(tr.shear, 0.0);
    tr.traction_vector = Eigen::Vector2d(tr.traction, 0.0);
    tr.force = tr.traction * p.weight * k.travel.gradient.normalized();
  }
  return out;
}

}  // namespace tirefem
