#pragma once
// A form is one term of the nonlinear problem (internal force, pressure, loads, contact, ...): it adds
// its residual contribution (internal minus external force) and its tangent. Nothing else.
#include "tirefem/solver/sparse_system.hpp"

namespace tirefem {

struct FormInput {
  const Eigen::VectorXd& displacement;  // full length
  double load_factor;                   // λ ∈ [0, 1] scales the applied loads
  bool with_tangent;
};

class Form {
 public:
  virtual ~Form() = default;
  virtual void add_pattern(PatternBuilder& pattern) const = 0;
  virtual void assemble(const FormInput& input, SparseSystem& system) const = 0;
  // False if the tangent this form adds is not symmetric (then an LU factorisation is used).
  virtual bool symmetric() const { return true; }
};

}  // namespace tirefem
