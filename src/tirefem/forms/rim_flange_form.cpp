#include "tirefem/forms/rim_flange_form.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "tirefem/element/shape_functions.hpp"

namespace tirefem {

namespace {
constexpr int kQuadrature = 3;  // per direction, on each element near the flange

// The Gauss points of the outer face, lifted onto the wall's surface of revolution. A bilinear element's
// points lie on its chords round the axis, inside the surface through its nodes by up to the sag h²/8ρ
// (h the element's length round the axis): 0.4 mm for the 25 mm elements at the back of an 80-element
// graded mesh, comparable to the flange's indentation, and varying with h round the circumference, so the
// curl would press hardest where the elements are longest and the flange's forces would not cancel round
// an axisymmetric state. Each point keeps its angle and axial position and takes the radius interpolated
// from its element's nodes: a fixed reference offset, like the tread height (eq. 3). Its weight is the
// area of the round wall it stands for (the lifted map's |∂X/∂ξ × ∂X/∂η|), so that a uniform pressure
// sums to the round wall's force.
std::vector<TreadPoint> points_on_the_round_wall(const ShellMesh& mesh, const RimFlange& flange) {
  std::vector<TreadPoint> points =
      make_tread_points(mesh, elements_near_flange(mesh, flange), kQuadrature, [](double) { return 0.0; });
  const Eigen::Vector3d axis_point(0.0, 0.0, flange.axis_z());
  const auto across = [](const Eigen::Vector3d& a) { return Eigen::Vector3d(0.0, a.y(), a.z()); };  // ⟂ to the axis
  const auto radial = [&](const Eigen::Vector3d& x) { return across(x - axis_point); };
  for (TreadPoint& p : points) {
    const int iu = p.element % mesh.u_elements(), jv = p.element / mesh.u_elements();
    const double xi = 2 * (p.u - mesh.u_values[iu]) / (mesh.u_values[iu + 1] - mesh.u_values[iu]) - 1;
    const double eta = 2 * (p.v - mesh.v_values[jv]) / (mesh.v_values[jv + 1] - mesh.v_values[jv]) - 1;
    const BilinearShape sh = bilinear_shape(xi, eta);
    const Eigen::Matrix<double, 3, 4> outer = mesh.element_reference(p.element).rightCols<4>();
    const Eigen::Vector3d x = outer * sh.n, a1 = outer * sh.dn_dxi, a2 = outer * sh.dn_deta;
    Eigen::Vector4d node_radius;
    for (int k = 0; k < 4; ++k) node_radius[k] = radial(mesh.outer_nodes[p.pairs[k]]).norm();
    const double r = radial(x).norm(), rho = sh.n.dot(node_radius);
    if (r <= 0.0) continue;
    const Eigen::Vector3d e = radial(x) / r;
    // X = (x_axial, ρ e) with e = the chord point's radial direction: ∂X = ∂x_axial + (ρ/r)(I − e eᵀ) ∂x_radial + e ∂ρ.
    const auto lifted = [&](const Eigen::Vector3d& a, double drho) -> Eigen::Vector3d {
      const Eigen::Vector3d ar = across(a);
      return Eigen::Vector3d(a.x(), 0.0, 0.0) + (rho / r) * (ar - e * e.dot(ar)) + e * drho;
    };
    const Eigen::Vector3d b1 = lifted(a1, sh.dn_dxi.dot(node_radius)), b2 = lifted(a2, sh.dn_deta.dot(node_radius));
    p.weight *= b1.cross(b2).norm() / a1.cross(a2).norm();
    p.reference = Eigen::Vector3d(x.x(), 0.0, 0.0) + axis_point + rho * e;
  }
  return points;
}
}  // namespace

RimFlangeForm::RimFlangeForm(const ShellMesh& mesh, RimFlange flange, double stiffness)
    : flange_(std::move(flange)),
      contact_(mesh, points_on_the_round_wall(mesh, flange_), stiffness, flange_),
      u_elements_(mesh.u_elements()), v_elements_(mesh.v_elements()) {}

std::vector<RimFlangeLoad> RimFlangeForm::loads(const Eigen::VectorXd& u) const {
  const std::vector<TreadPoint>& points = contact_.points();
  const std::vector<TreadPointState> states = contact_.evaluate(u);
  struct Side {
    bool present = false;
    Eigen::Vector3d force = Eigen::Vector3d::Zero();  // the flange's on the tyre
    double peak = 0.0;
    std::vector<char> touched;
  };
  std::array<Side, 2> sides;  // x > 0, x < 0
  for (std::size_t q = 0; q < points.size(); ++q) {
    Side& side = sides[points[q].reference.x() < 0.0];
    if (!side.present) side.present = true, side.touched.assign(v_elements_, 0);
    side.force += states[q].force;
    side.peak = std::max(side.peak, states[q].pressure);
    if (states[q].pressure > 0.0) side.touched[points[q].element / u_elements_] = 1;
  }
  std::vector<RimFlangeLoad> out;
  for (int k = 0; k < 2; ++k) {
    const Side& side = sides[k];
    if (!side.present) continue;
    RimFlangeLoad load;
    load.side = k == 0 ? 1 : -1;
    load.axial_force_N = -load.side * side.force.x();
    load.radial_force_N = side.force.tail<2>().norm();
    load.peak_pressure_MPa = side.peak;
    load.contact_fraction =
        static_cast<double>(std::count(side.touched.begin(), side.touched.end(), 1)) / v_elements_;
    out.push_back(load);
  }
  return out;
}

}  // namespace tirefem
