#include "tirefem/case/field_checker.hpp"

#include <fmt/format.h>

#include <cmath>

#include "tirefem/case/case_reader.hpp"

namespace tirefem::case_reading {

void FieldChecker::fail(const std::string& path, const std::string& what) const {
  throw CaseError(fmt::format("{}: {}: {}", locate_(path), path, what));
}

void FieldChecker::finite(double v, const std::string& path) const {
  if (!std::isfinite(v)) fail(path, fmt::format("must be a finite number (got {})", v));
}

void FieldChecker::positive(double v, const std::string& path) const {
  finite(v, path);
  if (!(v > 0)) fail(path, fmt::format("must be > 0 (got {})", v));
}

void FieldChecker::non_negative(double v, const std::string& path) const {
  finite(v, path);
  if (!(v >= 0)) fail(path, fmt::format("must be ≥ 0 (got {})", v));
}

void FieldChecker::in_range(double v, double lo, double hi, const std::string& path) const {
  finite(v, path);
  if (!(v >= lo && v <= hi)) fail(path, fmt::format("must be in [{}, {}] (got {})", lo, hi, v));
}

void FieldChecker::at_most(double v, double hi, const std::string& path) const {
  if (!(v <= hi)) fail(path, fmt::format("must be ≤ {} (got {})", hi, v));
}

void FieldChecker::at_least(int v, int lo, const std::string& path) const {
  if (v < lo) fail(path, fmt::format("must be ≥ {} (got {})", lo, v));
}

void FieldChecker::int_range(int v, int lo, int hi, const std::string& path) const {
  if (v < lo || v > hi) fail(path, fmt::format("must be in [{}, {}] (got {})", lo, hi, v));
}

void FieldChecker::plausible(double v, const Bound& b, const std::string& path) const {
  if (b.lo > 0)
    positive(v, path);
  else
    non_negative(v, path);
  if (!(v >= b.lo && v <= b.hi))
    fail(path, fmt::format("must be in [{:g}, {:g}] {} (the plausibility bound for any real tyre; got {:g})",
                           b.lo, b.hi, b.unit, v));
}

}  // namespace tirefem::case_reading
