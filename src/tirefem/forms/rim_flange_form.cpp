#include "tirefem/forms/rim_flange_form.hpp"

namespace tirefem {

namespace {
constexpr int kQuadrature = 3;  // per direction, on each element near the flange
}

RimFlangeForm::RimFlangeForm(const ShellMesh& mesh, RimFlange flange, double stiffness)
    : flange_(std::move(flange)),
      contact_(mesh, make_tread_points(mesh, elements_near_flange(mesh, flange_), kQuadrature, [](double) { return 0.0; }),
               stiffness, flange_) {}

}  // namespace tirefem
