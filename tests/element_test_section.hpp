#pragma once
// A fully anisotropic section for element tests (unit and verification): both faces with coupled
// normal and shear terms, so every stiffness entry of the element takes part.
#include "tirefem/element/section.hpp"

namespace tirefem {

inline ElementSection anisotropic_test_section() {
  ElementSection s;
  s.inner_face << 3000, 300, 50, 300, 900, -40, 50, -40, 400;
  s.outer_face << 5000, 2500, 0, 2500, 2000, 0, 0, 0, 2200;
  s.core_shear_modulus = 1.5;
  s.core_normal_modulus = 100;
  return s;
}

}  // namespace tirefem
