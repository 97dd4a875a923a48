#pragma once
// Value checks on the fields of a case, shared by the reader (which knows where each field is in the file)
// and validate_case (which does not). Every failure is a CaseError "WHERE: dotted.field.path: what".
#include <functional>
#include <string>

#include "tirefem/case/plausibility_bounds.hpp"

namespace tirefem::case_reading {

class FieldChecker {
 public:
  // Gives "file:line:col" (or just "file") for a field path.
  using Locate = std::function<std::string(const std::string& path)>;
  explicit FieldChecker(Locate locate) : locate_(std::move(locate)) {}

  [[noreturn]] void fail(const std::string& path, const std::string& what) const;

  void finite(double v, const std::string& path) const;
  void positive(double v, const std::string& path) const;
  void non_negative(double v, const std::string& path) const;
  void in_range(double v, double lo, double hi, const std::string& path) const;
  void at_most(double v, double hi, const std::string& path) const;
  void at_least(int v, int lo, const std::string& path) const;
  void int_range(int v, int lo, int hi, const std::string& path) const;
  // Within a plausibility bound: > 0 (≥ 0 if the bound starts at 0) and finite first, with the usual
  // messages; then within [lo, hi], saying that it is the plausibility bound.
  void plausible(double v, const Bound& b, const std::string& path) const;

 private:
  Locate locate_;
};

}  // namespace tirefem::case_reading
