#pragma once
// Where the inflated tyre meets the support, from the inflated state alone (no contact solve): the
// deflection δz at which it first touches (MODEL.md §2 measures δz from the undeformed tyre, so the
// inflated tyre, ~0.5 mm larger, touches at δz < 0), and an estimate of the deflection that carries a
// given load, to start the footprint search from.
#include <vector>

#include <Eigen/Dense>

#include "tirefem/forms/winkler_contact_form.hpp"
#include "tirefem/road/support_surface.hpp"

namespace tirefem {

// δz at which the largest penetration of the tread points at `positions` into `support` is zero: the
// support's gap function at the inflated tread surface. The support moves along z, so g(x, δz) =
// g(x − δz e_z, 0) and ∂g/∂δz = −∂g/∂z: Newton on the deepest point (exact in one step on a plane or a
// road z = f(x, y), a few steps on a drum). Negative when the tyre presses on the support at δz = 0.
double first_touch_deflection(const std::vector<Eigen::Vector3d>& positions, const SupportSurface& support);

// The deflection at which a membrane of inflation pressure p would carry `load`: Qz ≈ p · A(δz), A the
// area the support cuts off the inflated tread surface (the breaker-face areas of the tread points with
// g > 0, doubled in a half model). It ignores the wall's own stiffness and the flattening of the patch, so
// it is an estimate for a first step only. Sought by bisection in [from, to]; `to` when the load is not
// reached there. Within 1e-3 mm above the deflection sought.
double estimated_deflection_for_load(const std::vector<TreadPoint>& points,
                                     const std::vector<Eigen::Vector3d>& positions, const SupportSurface& support,
                                     double pressure, bool half_model, double load, double from, double to);

}  // namespace tirefem
