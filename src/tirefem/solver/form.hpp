#pragma once
// A form is one term of the nonlinear problem (internal force, pressure, loads, contact, ...): it adds
// its residual contribution (internal minus external force) and its tangent, and, when the term derives
// from a potential (MODEL.md §8), the change of its energy between two states. Nothing else.
#include <optional>

#include "tirefem/solver/sparse_system.hpp"

namespace tirefem {

struct FormInput {
  const Eigen::VectorXd& displacement;  // full length
  double load_factor;                   // λ ∈ [0, 1] scales the applied loads
  bool with_tangent;
};

// Π(to) − Π(from) of a term with a potential (its residual is ∂Π/∂u). `magnitude` is the size of the
// terms that were subtracted to get it (Σ |Π_e(to)| + |Π_e(from)| over its parts): a change below about
// 1e-13 of it is round-off.
struct EnergyChange {
  double change = 0.0;
  double magnitude = 0.0;
  EnergyChange& operator+=(const EnergyChange& o) {
    change += o.change;
    magnitude += o.magnitude;
    return *this;
  }
};

class Form {
 public:
  virtual ~Form() = default;
  virtual void add_pattern(PatternBuilder& pattern) const = 0;
  virtual void assemble(const FormInput& input, SparseSystem& system) const = 0;
  // False if the tangent this form adds is not symmetric (then an LU factorisation is used).
  virtual bool symmetric() const { return true; }
  // True when the term derives from a potential, so energy_change gives a value.
  virtual bool has_potential() const { return false; }
  // The energy change from `from` to `to` (full-length displacements) at load factor λ; nothing for a
  // term without a potential (friction, a follower pressure on an open surface).
  virtual std::optional<EnergyChange> energy_change(const Eigen::VectorXd& from, const Eigen::VectorXd& to,
                                                    double load_factor) const {
    (void)from, (void)to, (void)load_factor;
    return std::nullopt;
  }
};

}  // namespace tirefem
