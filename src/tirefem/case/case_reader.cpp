#include "tirefem/case/case_reader.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

#include "tirefem/element/section.hpp"
#include "tirefem/tyre/meridian_profile.hpp"

namespace tirefem {
namespace {

// ---------------------------------------------------------------------------------------------- paths
std::string join(const std::string& path, std::string_view key) {
  const bool bare = !key.empty() && std::all_of(key.begin(), key.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
  });
  const std::string k = bare ? std::string(key) : fmt::format("\"{}\"", key);
  return path.empty() ? k : path + "." + k;
}
std::string index(const std::string& path, std::size_t i) { return fmt::format("{}[{}]", path, i); }

// Levenshtein distance, for "did you mean" on unknown keys.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

std::string type_name(toml::node_type t) {
  switch (t) {
    case toml::node_type::table:
      return "a table";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::string:
      return "a string";
    case toml::node_type::integer:
      return "an integer";
    case toml::node_type::floating_point:
      return "a floating-point number";
    case toml::node_type::boolean:
      return "a boolean";
    default:
      return "a date/time";
  }
}

// --------------------------------------------------------------------------------------- validation
constexpr int kMaxSurfacePower = 8;        // support surface terms: x^p y^q with p, q in [0, 8]
constexpr int kMaxQuadrature = 8;          // contact: Gauss points per direction
constexpr double kMaxLoadTolerance = 0.1;  // footprint: relative tolerance on the vertical load
constexpr double kMaxFriction = 5.0;       // rolling: Coulomb coefficient μ
constexpr double kMaxSlip = 10.0;          // rolling: longitudinal slip κ (> −1: −1 is a locked wheel)
constexpr int kMaxSweepPoints = 200;       // rolling: slips in a sweep

// Checks on values, shared by parse_case (which knows where each field is) and validate_case.
class Checker {
 public:
  using Locate = std::function<std::string(const std::string& path)>;
  explicit Checker(Locate locate) : locate_(std::move(locate)) {}

  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw CaseError(fmt::format("{}: {}: {}", locate_(path), path, what));
  }
  void finite(double v, const std::string& path) const {
    if (!std::isfinite(v)) fail(path, fmt::format("must be a finite number (got {})", v));
  }
  void positive(double v, const std::string& path) const {
    finite(v, path);
    if (!(v > 0)) fail(path, fmt::format("must be > 0 (got {})", v));
  }
  void non_negative(double v, const std::string& path) const {
    finite(v, path);
    if (!(v >= 0)) fail(path, fmt::format("must be ≥ 0 (got {})", v));
  }
  void in_range(double v, double lo, double hi, const std::string& path) const {
    finite(v, path);
    if (!(v >= lo && v <= hi)) fail(path, fmt::format("must be in [{}, {}] (got {})", lo, hi, v));
  }
  void at_least(int v, int lo, const std::string& path) const {
    if (v < lo) fail(path, fmt::format("must be ≥ {} (got {})", lo, v));
  }
  void int_range(int v, int lo, int hi, const std::string& path) const {
    if (v < lo || v > hi) fail(path, fmt::format("must be in [{}, {}] (got {})", lo, hi, v));
  }

  void ply(const Ply& p, const std::string& path) const {
    positive(p.cord_modulus, join(path, "cord_modulus"));
    positive(p.cord_area, join(path, "cord_area"));
    positive(p.ends_per_mm, join(path, "ends_per_mm"));
    in_range(p.angle_deg, -90.0, 90.0, join(path, "angle"));
    positive(p.thickness, join(path, "thickness"));
    positive(p.rubber_modulus, join(path, "rubber_modulus"));
    in_range(p.rubber_poisson, 0.0, 0.5, join(path, "rubber_poisson"));
    in_range(p.cord_poisson, 0.0, 0.5, join(path, "cord_poisson"));
    const double vc = p.cord_area * p.ends_per_mm / p.thickness;
    if (!(vc < 1.0))
      fail(path,
           fmt::format("cord volume fraction cord_area × ends_per_mm / thickness must be < 1 (got {})", vc));
  }

  void stiffness(const Eigen::Matrix3d& a, const std::string& path) const {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) finite(a(i, j), index(index(path, i), j));
    const double tol = 1e-9 * a.cwiseAbs().maxCoeff();
    for (int i = 0; i < 3; ++i)
      for (int j = i + 1; j < 3; ++j)
        if (std::abs(a(i, j) - a(j, i)) > tol)
          fail(path, fmt::format("must be symmetric (A[{}][{}] = {} but A[{}][{}] = {})", i, j, a(i, j), j, i,
                                 a(j, i)));
    if (a.llt().info() != Eigen::Success || !(a.diagonal().minCoeff() > 0))
      fail(path, "must be positive definite (N/mm, Voigt order [11, 22, 12])");
  }

  void face(const FaceLayup& f, const std::string& path) const {
    if (f.plies.empty() && !f.direct_stiffness)
      fail(path, "a face needs at least one of plies, rubber or stiffness");
    for (std::size_t i = 0; i < f.plies.size(); ++i) ply(f.plies[i], index(join(path, "plies"), i));
    if (f.direct_stiffness) stiffness(*f.direct_stiffness, join(path, "stiffness"));
  }

  void table(const Table& t, const std::string& path, bool allow_zero) const {
    if (t.s.empty()) fail(join(path, "s"), "must have at least one entry");
    if (t.s.size() != t.value.size())
      fail(join(path, "value"),
           fmt::format("must have as many entries as s ({}; got {})", t.s.size(), t.value.size()));
    for (std::size_t i = 0; i < t.s.size(); ++i) {
      finite(t.s[i], index(join(path, "s"), i));
      if (i > 0 && !(t.s[i] > t.s[i - 1]))
        fail(index(join(path, "s"), i),
             fmt::format("must be greater than s[{}] = {} (got {})", i - 1, t.s[i - 1], t.s[i]));
      if (allow_zero)
        non_negative(t.value[i], index(join(path, "value"), i));
      else
        positive(t.value[i], index(join(path, "value"), i));
    }
  }

  // Returns the profile's arc length.
  double profile(const std::vector<Eigen::Vector2d>& pts, const std::string& path) const {
    if (pts.size() < 2) fail(path, fmt::format("needs at least 2 points [x, r] (got {})", pts.size()));
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const std::string p = index(path, i);
      finite(pts[i].x(), p);
      finite(pts[i].y(), p);
      if (!(pts[i].x() >= 0)) fail(p, fmt::format("x must be ≥ 0 (got {})", pts[i].x()));
      if (!(pts[i].y() > 0)) fail(p, fmt::format("r must be > 0 (got {})", pts[i].y()));
    }
    if (pts[0].x() != 0.0)
      fail(index(path, 0),
           fmt::format("the profile must start on the equator, x = 0 (got x = {})", pts[0].x()));
    for (std::size_t i = 1; i < pts.size(); ++i) {
      const Eigen::Vector2d chord = pts[i] - pts[i - 1];
      if (!(chord.norm() > 1e-6))
        fail(index(path, i), fmt::format("same point as points[{}]: arc length must increase", i - 1));
      if (i >= 2 && chord.dot(pts[i - 1] - pts[i - 2]) <= 0)
        fail(
            index(path, i),
            fmt::format("the profile turns back at points[{}] (more than 90°): points out of order?", i - 1));
    }
    try {
      return MeridianProfile(pts).length();
    } catch (const std::exception& e) {
      fail(path, e.what());
    }
  }

  void mesh(const MeshSettings& m, const std::string& path, std::size_t zones) const {
    if (m.circumferential_elements < 3)
      fail(join(path, "circumferential_elements"), fmt::format("must be ≥ 3 (got {})", m.circumferential_elements));
    if (m.meridional_elements < static_cast<int>(zones))
      fail(join(path, "meridional_elements"),
           fmt::format("must be ≥ the number of zones, {} (got {})", zones, m.meridional_elements));
    finite(m.circumferential_refinement, join(path, "circumferential_refinement"));
    if (!(m.circumferential_refinement >= 1.0))
      fail(join(path, "circumferential_refinement"), fmt::format("must be ≥ 1 (got {})", m.circumferential_refinement));
  }
  void contact(const ContactSettings& s, const std::string& path) const {
    int_range(s.quadrature, 1, kMaxQuadrature, join(path, "quadrature"));
    at_least(s.max_contact_iterations, 1, join(path, "max_contact_iterations"));
    at_least(s.region_tolerance, 0, join(path, "region_tolerance"));
    at_least(s.max_newton_iterations, 1, join(path, "max_newton_iterations"));
    positive(s.residual_tolerance, join(path, "residual_tolerance"));
    positive(s.provisional_tolerance, join(path, "provisional_tolerance"));
  }

  void support(const SupportDescription& s, const std::string& path) const {
    if (s.kind == SupportDescription::Kind::drum) positive(s.drum_diameter, join(path, "diameter"));
    if (s.kind != SupportDescription::Kind::surface) return;
    const std::string tp = join(path, "terms");
    if (s.terms.empty()) fail(tp, "a surface needs at least one term { coefficient, x_power, y_power }");
    for (std::size_t i = 0; i < s.terms.size(); ++i) {
      const SupportDescription::Term& t = s.terms[i];
      const std::string p = index(tp, i);
      finite(t.coefficient, join(p, "coefficient"));
      int_range(t.x_power, 0, kMaxSurfacePower, join(p, "x_power"));
      int_range(t.y_power, 0, kMaxSurfacePower, join(p, "y_power"));
      if (t.x_power == 0 && t.y_power == 0 && t.coefficient != 0.0)
        fail(join(p, "coefficient"),
             fmt::format("a constant term (x_power = y_power = 0) must be zero (got {}): the road must pass "
                         "through the origin, where the undeformed tyre touches it",
                         t.coefficient));
    }
  }

  // Study names end up in file names: non-empty, [A-Za-z0-9_-], unique among all studies.
  void study_name(const std::string& name, const std::string& path,
                  std::map<std::string, std::string>& seen) const {
    if (name.empty()) fail(path, "must not be empty (it names the study's output files)");
    const bool plain = std::all_of(name.begin(), name.end(), [](char ch) {
      return (ch >= 'A' && ch <= 'Z') || (ch >= 'a' && ch <= 'z') || (ch >= '0' && ch <= '9') || ch == '_' ||
             ch == '-';
    });
    if (!plain)
      fail(path, fmt::format("may contain only letters A-Z a-z, digits 0-9, '_' and '-' (got \"{}\")", name));
    if (const auto [it, added] = seen.emplace(name, path); !added)
      fail(path,
           fmt::format("duplicate name \"{}\" (already used by {}); load curves, footprints and rolling "
                       "studies need distinct names",
                       name, it->second));
  }

  void load(double target_load, double load_tolerance, const std::string& path) const {
    positive(target_load, join(path, "target_load"));
    finite(load_tolerance, join(path, "load_tolerance"));
    if (!(load_tolerance > 0 && load_tolerance < kMaxLoadTolerance))
      fail(join(path, "load_tolerance"),
           fmt::format("must be > 0 and < {} (got {})", kMaxLoadTolerance, load_tolerance));
  }

  void at_most(double v, double hi, const std::string& path) const {
    if (!(v <= hi)) fail(path, fmt::format("must be ≤ {} (got {})", hi, v));
  }
  void slip(double v, const std::string& path) const {
    finite(v, path);
    if (!(v > -1)) fail(path, fmt::format("must be > -1 (got {})", v));
    at_most(v, kMaxSlip, path);
  }

  void rolling(const RollingStudy& s, const std::string& path) const {
    using Kind = RollingStateSpec::Kind;
    const std::string sp = join(path, "support");
    // The steady state is frozen in the road's frame: the road must look the same all along y.
    if (s.support.kind == SupportDescription::Kind::surface)
      for (std::size_t j = 0; j < s.support.terms.size(); ++j)
        if (const SupportDescription::Term& t = s.support.terms[j]; t.y_power > 0 && t.coefficient != 0.0)
          fail(
              join(index(join(sp, "terms"), j), "y_power"),
              fmt::format("must be 0 where the coefficient is not (got {}): steady rolling needs a road that "
                          "does not change along y",
                          t.y_power));
    load(s.target_load, s.load_tolerance, path);
    positive(s.friction, join(path, "friction"));
    at_most(s.friction, kMaxFriction, join(path, "friction"));
    if (s.states.empty() && !s.sweep)
      fail(path,
           "needs states or a sweep (states = [{ state = \"free\" }, ...] or sweep = { from, to, points })");
    std::map<std::string, std::string> seen;  // state name -> its path
    for (std::size_t k = 0; k < s.states.size(); ++k) {
      const RollingStateSpec& st = s.states[k];
      const std::string p = index(join(path, "states"), k);
      if (st.kind == Kind::given_slip || st.kind == Kind::full_stick) slip(st.slip, join(p, "slip"));
      if (st.kind == Kind::given_radius) positive(st.rolling_radius, join(p, "rolling_radius"));
      const std::string np = join(p, "name");
      if (st.name.empty())
        fail(np, "must not be empty (it names the state in tables, plots and the summary)");
      if (!std::all_of(st.name.begin(), st.name.end(), [](char ch) {
            return (ch >= 'A' && ch <= 'Z') || (ch >= 'a' && ch <= 'z') || (ch >= '0' && ch <= '9') ||
                   ch == '_' || ch == '.' || ch == '+' || ch == '-';
          }))
        fail(np,
             fmt::format("may contain only letters A-Z a-z, digits 0-9, '_', '.', '+' and '-' (got \"{}\")",
                         st.name));
      if (const auto [it, added] = seen.emplace(st.name, np); !added)
        fail(np, fmt::format("duplicate state name \"{}\" (already used by {}); the states of a study need "
                             "distinct names",
                             st.name, it->second));
    }
    if (s.sweep) {
      const std::string wp = join(path, "sweep");
      slip(s.sweep->from, join(wp, "from"));
      slip(s.sweep->to, join(wp, "to"));
      if (!(s.sweep->from < s.sweep->to))
        fail(join(wp, "to"),
             fmt::format("must be greater than from = {} (got {})", s.sweep->from, s.sweep->to));
      int_range(s.sweep->points, 2, kMaxSweepPoints, join(wp, "points"));
    }
  }

  void studies(const Case& c) const {
    std::map<std::string, std::string> seen;  // name -> path of the study that has it
    for (std::size_t i = 0; i < c.load_curves.size(); ++i) {
      const LoadCurveStudy& s = c.load_curves[i];
      const std::string p = index("load_curve", i);
      study_name(s.name, join(p, "name"), seen);
      support(s.support, join(p, "support"));
      positive(s.max_deflection, join(p, "max_deflection"));
      at_least(s.points, 1, join(p, "points"));
    }
    for (std::size_t i = 0; i < c.footprints.size(); ++i) {
      const FootprintStudy& s = c.footprints[i];
      const std::string p = index("footprint", i);
      study_name(s.name, join(p, "name"), seen);
      support(s.support, join(p, "support"));
      load(s.target_load, s.load_tolerance, p);
    }
    for (std::size_t i = 0; i < c.rolling.size(); ++i) {
      const std::string p = index("rolling", i);
      study_name(c.rolling[i].name, join(p, "name"), seen);
      support(c.rolling[i].support, join(p, "support"));
      rolling(c.rolling[i], p);
    }
  }

  void run(const Case& c) const {
    const TyreDescription& t = c.tyre;
    const double length = profile(t.profile, "tyre.profile.points");
    if (t.zones.empty()) fail("tyre.zones", "at least one zone is needed");
    double previous = 0.0;
    for (std::size_t k = 0; k < t.zones.size(); ++k) {
      const Zone& z = t.zones[k];
      const std::string p = index("tyre.zones", k);
      finite(z.s_end, join(p, "s_end"));
      if (!(z.s_end > previous))
        fail(join(p, "s_end"),
             k == 0 ? fmt::format("must be > 0 (got {})", z.s_end)
                    : fmt::format("must be greater than the previous zone's s_end = {} (got {})", previous,
                                  z.s_end));
      previous = z.s_end;
      face(z.inner, join(p, "inner"));
      face(z.outer, join(p, "outer"));
      positive(z.core_shear_modulus, join(p, "core_shear_modulus"));
      positive(z.core_normal_modulus, join(p, "core_normal_modulus"));
    }
    if (std::abs(previous - length) > kZoneEndTolerance)
      fail(join(index("tyre.zones", t.zones.size() - 1), "s_end"),
           fmt::format("the last zone must end at the bead, s = {:.3f} mm, the profile's arc length (within "
                       "{} mm; got {})",
                       length, kZoneEndTolerance, previous));
    table(t.interlayer_thickness, "tyre.interlayer.thickness", false);
    table(t.tread_height, "tyre.tread.height", true);
    in_range(t.tread_end_s, 0.0, length + kZoneEndTolerance, "tyre.tread.end_s");
    positive(t.tread_stiffness, "tyre.tread.stiffness");
    positive(t.tread_shear_modulus, "tyre.tread.shear_modulus");

    mesh(c.mesh, "mesh", t.zones.size());
    for (std::size_t i = 0; i < c.rolling.size(); ++i)
      if (c.rolling[i].mesh) mesh(*c.rolling[i].mesh, join(index("rolling", i), "mesh"), t.zones.size());

    if (c.inflation.enabled)
      positive(c.inflation.pressure, "inflation.pressure");
    else
      non_negative(c.inflation.pressure, "inflation.pressure");
    if (c.inflation.max_newton_iterations < 1)
      fail("inflation.max_newton_iterations",
           fmt::format("must be ≥ 1 (got {})", c.inflation.max_newton_iterations));
    positive(c.inflation.residual_tolerance, "inflation.residual_tolerance");

    contact(c.contact, "contact");
    studies(c);
  }

 private:
  Locate locate_;
};

// ------------------------------------------------------------------------------------------ reading
// Structure and types (missing fields, wrong types, unknown keys, unknown names); records where every
// field is so that the value checks can point at it.
class Reader {
 public:
  explicit Reader(std::string file)
      : file_(std::move(file)), checker_([this](const std::string& p) { return locate(p); }) {}

  const Checker& checker() const { return checker_; }

  std::string locate(const std::string& path) const {
    for (std::string p = path;;) {  // the field, else its nearest recorded parent
      if (const auto it = positions_.find(p); it != positions_.end() && it->second.line > 0)
        return fmt::format("{}:{}:{}", file_, it->second.line, it->second.column);
      const auto cut = p.find_last_of(".[");
      if (cut == std::string::npos || cut == 0) return file_;
      p.resize(cut);
    }
  }
  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    checker_.fail(path, what);
  }

  const toml::node* get(const toml::table& t, const std::string& path, std::string_view key) {
    const toml::node* n = t.get(key);
    if (n) positions_[join(path, key)] = n->source().begin;
    return n;
  }
  const toml::node& need(const toml::table& t, const std::string& path, std::string_view key,
                         std::string_view expected) {
    if (const toml::node* n = get(t, path, key)) return *n;
    fail(join(path, key), fmt::format("missing; expected {}", expected));
  }

  const toml::table& table(const toml::node& n, const std::string& path,
                           std::initializer_list<std::string_view> keys) {
    positions_[path] = n.source().begin;
    const toml::table* t = n.as_table();
    if (!t) fail(path, fmt::format("must be a table (got {})", type_name(n.type())));
    for (auto&& [k, v] : *t) {
      if (std::find(keys.begin(), keys.end(), k.str()) != keys.end()) continue;
      positions_[join(path, k.str())] = k.source().begin;
      std::string msg = "unknown key; expected one of";
      std::string_view close;
      std::size_t best = std::string_view::npos;
      for (std::string_view a : keys) {
        msg += fmt::format("{} {}", a == *keys.begin() ? ":" : ",", a);
        const std::size_t d = edit_distance(a, k.str());
        if (d < a.size() && d <= std::max<std::size_t>(2, a.size() / 4) && d < best) close = a, best = d;
      }
      if (!close.empty()) msg += fmt::format(" (did you mean '{}'?)", close);
      fail(join(path, k.str()), msg);
    }
    return *t;
  }
  const toml::array& array(const toml::node& n, const std::string& path, std::string_view of) {
    const toml::array* a = n.as_array();
    if (!a) fail(path, fmt::format("must be an array of {} (got {})", of, type_name(n.type())));
    for (std::size_t i = 0; i < a->size(); ++i) positions_[index(path, i)] = (*a)[i].source().begin;
    return *a;
  }
  double number(const toml::node& n, const std::string& path, std::string_view unit) {
    if (!n.is_number()) fail(path, fmt::format("must be a number{} (got {})", unit, type_name(n.type())));
    return *n.value<double>();
  }
  int integer(const toml::node& n, const std::string& path) {
    if (!n.is_integer()) fail(path, fmt::format("must be an integer (got {})", type_name(n.type())));
    const int64_t v = n.as_integer()->get();
    if (v < -1000000000 || v > 1000000000) fail(path, fmt::format("out of range (got {})", v));
    return static_cast<int>(v);
  }
  bool boolean(const toml::node& n, const std::string& path) {
    if (!n.is_boolean()) fail(path, fmt::format("must be true or false (got {})", type_name(n.type())));
    return n.as_boolean()->get();
  }
  std::string string(const toml::node& n, const std::string& path) {
    if (!n.is_string()) fail(path, fmt::format("must be a string (got {})", type_name(n.type())));
    return n.as_string()->get();
  }
  std::vector<double> numbers(const toml::node& n, const std::string& path, std::string_view unit) {
    std::vector<double> v;
    const toml::array& a = array(n, path, "numbers");
    for (std::size_t i = 0; i < a.size(); ++i) v.push_back(number(a[i], index(path, i), unit));
    return v;
  }
  // Optional fields: keep the default when absent.
  void opt_number(const toml::table& t, const std::string& path, std::string_view key, double& out,
                  std::string_view unit) {
    if (const toml::node* n = get(t, path, key)) out = number(*n, join(path, key), unit);
  }
  void opt_integer(const toml::table& t, const std::string& path, std::string_view key, int& out) {
    if (const toml::node* n = get(t, path, key)) out = integer(*n, join(path, key));
  }
  void opt_bool(const toml::table& t, const std::string& path, std::string_view key, bool& out) {
    if (const toml::node* n = get(t, path, key)) out = boolean(*n, join(path, key));
  }
  double req_number(const toml::table& t, const std::string& path, std::string_view key,
                    std::string_view unit) {
    return number(need(t, path, key, fmt::format("a number{}", unit)), join(path, key), unit);
  }

  // A string out of a fixed list; returns its index in `values`.
  std::size_t choice(const toml::node& n, const std::string& path,
                     std::initializer_list<std::string_view> values) {
    const std::string s = string(n, path);
    std::string list;
    std::size_t i = 0;
    for (std::string_view v : values) {
      if (v == s) return i;
      list += fmt::format("{}\"{}\"", i == 0 ? "" : i + 1 == values.size() ? " or " : ", ", v);
      ++i;
    }
    fail(path, fmt::format("must be {} (got \"{}\")", list, s));
  }

  CordRubberRule rule(const toml::node& n, const std::string& path) {
    const std::string s = string(n, path);
    if (s == "halpin_tsai") return CordRubberRule::halpin_tsai;
    if (s == "gough_tangorra") return CordRubberRule::gough_tangorra;
    fail(path, fmt::format("must be \"halpin_tsai\" or \"gough_tangorra\" (got \"{}\")", s));
  }

  Ply ply(const toml::node& n, const std::string& path, std::string name) {
    const toml::table& t = table(n, path,
                                 {"description", "cord_modulus", "cord_area", "ends_per_mm", "angle",
                                  "thickness", "rubber_modulus", "rubber_poisson", "cord_poisson"});
    if (const toml::node* d = get(t, path, "description")) string(*d, join(path, "description"));
    Ply p;
    p.name = std::move(name);
    p.cord_modulus = req_number(t, path, "cord_modulus", " (MPa)");
    p.cord_area = req_number(t, path, "cord_area", " (mm², one cord)");
    p.ends_per_mm = req_number(t, path, "ends_per_mm", " (cords per mm)");
    p.angle_deg = req_number(t, path, "angle", " (degrees to the circumferential direction, 90 = radial)");
    p.thickness = req_number(t, path, "thickness", " (mm)");
    p.rubber_modulus = req_number(t, path, "rubber_modulus", " (MPa)");
    opt_number(t, path, "rubber_poisson", p.rubber_poisson, "");
    opt_number(t, path, "cord_poisson", p.cord_poisson, "");
    checker_.ply(p, path);
    return p;
  }

  FaceLayup face(const toml::node& n, const std::string& path, const std::map<std::string, Ply>& plies,
                 CordRubberRule default_rule) {
    const toml::table& t = table(n, path, {"plies", "rubber", "stiffness", "rule"});
    FaceLayup f;
    f.rule = default_rule;
    if (const toml::node* r = get(t, path, "rule")) f.rule = rule(*r, join(path, "rule"));
    if (const toml::node* pl = get(t, path, "plies")) {
      const std::string pp = join(path, "plies");
      const toml::array& a = array(*pl, pp, "ply names or ply tables");
      for (std::size_t i = 0; i < a.size(); ++i) {
        if (a[i].is_table()) {
          f.plies.push_back(ply(a[i], index(pp, i), index(pp, i)));
          continue;
        }
        const std::string name = string(a[i], index(pp, i));
        const auto it = plies.find(name);
        if (it == plies.end()) {
          std::string known;
          for (const auto& [k, v] : plies) known += (known.empty() ? "" : ", ") + k;
          fail(index(pp, i), fmt::format("unknown ply \"{}\" (defined in [tyre.plies]: {})", name,
                                         known.empty() ? "none" : known));
        }
        f.plies.push_back(it->second);
      }
    }
    Eigen::Matrix3d direct = Eigen::Matrix3d::Zero();
    bool has_direct = false;
    if (const toml::node* r = get(t, path, "rubber")) {  // one layer, or an array of layers
      const std::string rp = join(path, "rubber");
      std::vector<std::pair<const toml::node*, std::string>> layers;
      if (r->is_array()) {
        const toml::array& a = array(*r, rp, "rubber layers { E, nu, thickness }");
        for (std::size_t i = 0; i < a.size(); ++i) layers.emplace_back(&a[i], index(rp, i));
      } else {
        layers.emplace_back(r, rp);
      }
      for (const auto& [node, lp] : layers) {
        const toml::table& lt = table(*node, lp, {"E", "nu", "thickness"});
        const double e = req_number(lt, lp, "E", " (MPa)");
        double nu = 0.49;
        opt_number(lt, lp, "nu", nu, "");
        const double h = req_number(lt, lp, "thickness", " (mm)");
        checker_.positive(e, join(lp, "E"));
        checker_.in_range(nu, 0.0, 0.5, join(lp, "nu"));
        checker_.positive(h, join(lp, "thickness"));
        direct += isotropic_membrane(e, nu, h);
        has_direct = true;
      }
    }
    if (const toml::node* s = get(t, path, "stiffness")) {
      const std::string sp = join(path, "stiffness");
      const toml::array& rows = array(*s, sp, "3 rows of 3 numbers (N/mm)");
      if (rows.size() != 3) fail(sp, fmt::format("must have 3 rows of 3 numbers (got {} rows)", rows.size()));
      Eigen::Matrix3d a;
      for (int i = 0; i < 3; ++i) {
        const std::vector<double> row = numbers(rows[i], index(sp, i), " (N/mm)");
        if (row.size() != 3) fail(index(sp, i), fmt::format("must have 3 numbers (got {})", row.size()));
        for (int j = 0; j < 3; ++j) a(i, j) = row[j];
      }
      checker_.stiffness(a, sp);
      direct += a;
      has_direct = true;
    }
    if (has_direct) f.direct_stiffness = direct;
    if (f.plies.empty() && !has_direct) fail(path, "a face needs at least one of plies, rubber or stiffness");
    return f;
  }

  Table table_in_s(const toml::node& n, const std::string& path, std::string_view unit) {
    if (n.is_number()) return Table::constant(number(n, path, unit));
    if (!n.is_table())
      fail(path, fmt::format("must be a number or a table {{ s = [...], value = [...] }} (got {})",
                             type_name(n.type())));
    const toml::table& t = table(n, path, {"s", "value"});
    Table tab;
    tab.s = numbers(need(t, path, "s", "an array of arc lengths (mm)"), join(path, "s"), " (mm)");
    tab.value = numbers(need(t, path, "value", "an array of numbers"), join(path, "value"), unit);
    return tab;
  }

  TyreDescription tyre(const toml::node& n, const std::string& path) {
    const toml::table& t =
        table(n, path, {"name", "cord_rubber_rule", "profile", "plies", "zones", "interlayer", "tread"});
    TyreDescription d;
    if (const toml::node* v = get(t, path, "name")) d.name = string(*v, join(path, "name"));
    CordRubberRule default_rule = CordRubberRule::halpin_tsai;
    if (const toml::node* v = get(t, path, "cord_rubber_rule"))
      default_rule = rule(*v, join(path, "cord_rubber_rule"));

    const std::string pp = join(path, "profile");
    const toml::table& prof =
        table(need(t, path, "profile", "a table with points = [[x, r], ...]"), pp, {"points"});
    const std::string ptp = join(pp, "points");
    const toml::array& pts =
        array(need(prof, pp, "points", "an array of [x, r] pairs (mm)"), ptp, "[x, r] pairs (mm)");
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const std::vector<double> xy = numbers(pts[i], index(ptp, i), " (mm)");
      if (xy.size() != 2)
        fail(index(ptp, i), fmt::format("must be a pair [x, r] (got {} numbers)", xy.size()));
      d.profile.emplace_back(xy[0], xy[1]);
    }

    std::map<std::string, Ply> plies;
    if (const toml::node* pl = get(t, path, "plies")) {
      const std::string plp = join(path, "plies");
      positions_[plp] = pl->source().begin;
      const toml::table* pt = pl->as_table();
      if (!pt) fail(plp, fmt::format("must be a table of named plies (got {})", type_name(pl->type())));
      for (auto&& [k, v] : *pt) {
        const std::string name(k.str());
        plies.emplace(name, ply(v, join(plp, name), name));
      }
    }

    const std::string zp = join(path, "zones");
    const toml::array& zones =
        array(need(t, path, "zones", "an array of tables [[tyre.zones]]"), zp, "tables [[tyre.zones]]");
    for (std::size_t k = 0; k < zones.size(); ++k) {
      const std::string p = index(zp, k);
      const toml::table& zt = table(
          zones[k], p, {"name", "s_end", "inner", "outer", "core_shear_modulus", "core_normal_modulus"});
      Zone z;
      z.name = fmt::format("zone {}", k);
      if (const toml::node* v = get(zt, p, "name")) z.name = string(*v, join(p, "name"));
      z.s_end = req_number(zt, p, "s_end", " (mm of arc length from the equator)");
      z.inner =
          face(need(zt, p, "inner", "a face table { plies = [...] }"), join(p, "inner"), plies, default_rule);
      z.outer = face(need(zt, p, "outer", "a face table { plies, rubber or stiffness }"), join(p, "outer"),
                     plies, default_rule);
      z.core_shear_modulus = req_number(zt, p, "core_shear_modulus", " (MPa)");
      z.core_normal_modulus = req_number(zt, p, "core_normal_modulus", " (MPa)");
      d.zones.push_back(std::move(z));
    }

    const std::string ip = join(path, "interlayer");
    const toml::table& il = table(need(t, path, "interlayer", "a table with thickness"), ip, {"thickness"});
    d.interlayer_thickness =
        table_in_s(need(il, ip, "thickness", "a number or { s = [...], value = [...] } (mm)"),
                   join(ip, "thickness"), " (mm)");

    const std::string tp = join(path, "tread");
    const toml::table& tr = table(need(t, path, "tread", "a table [tyre.tread]"), tp,
                                  {"height", "end_s", "stiffness", "shear_modulus"});
    d.tread_height = table_in_s(need(tr, tp, "height", "a number or { s = [...], value = [...] } (mm)"),
                                join(tp, "height"), " (mm)");
    d.tread_end_s = req_number(tr, tp, "end_s", " (mm of arc length from the equator)");
    d.tread_stiffness = req_number(tr, tp, "stiffness", " (N/mm³)");
    d.tread_shear_modulus = req_number(tr, tp, "shear_modulus", " (MPa)");
    return d;
  }

  ContactSettings contact(const toml::node& n, const std::string& path) {
    const toml::table& t = table(n, path,
                                 {"quadrature", "iteration", "max_contact_iterations", "region_tolerance",
                                  "max_newton_iterations", "residual_tolerance", "provisional_tolerance",
                                  "reuse_factorizations", "equilibrium"});
    ContactSettings s;
    opt_integer(t, path, "quadrature", s.quadrature);
    if (const toml::node* v = get(t, path, "iteration"))
      s.iteration = static_cast<ContactSettings::Iteration>(
          choice(*v, join(path, "iteration"), {"two_level", "single_loop"}));  // enum order
    opt_integer(t, path, "max_contact_iterations", s.max_contact_iterations);
    opt_integer(t, path, "region_tolerance", s.region_tolerance);
    opt_integer(t, path, "max_newton_iterations", s.max_newton_iterations);
    opt_number(t, path, "residual_tolerance", s.residual_tolerance, "");
    opt_number(t, path, "provisional_tolerance", s.provisional_tolerance, "");
    opt_bool(t, path, "reuse_factorizations", s.reuse_factorizations);
    if (const toml::node* v = get(t, path, "equilibrium"))
      s.equilibrium = static_cast<ContactSettings::Equilibrium>(
          choice(*v, join(path, "equilibrium"), {"nearest", "stable"}));  // enum order
    return s;
  }

  // { kind = "plane" }, { kind = "drum", diameter = mm } or { kind = "surface", terms = [...] }; the keys
  // allowed depend on the kind.
  SupportDescription support(const toml::node& n, const std::string& path) {
    using Kind = SupportDescription::Kind;
    positions_[path] = n.source().begin;
    const toml::table* raw = n.as_table();
    if (!raw)
      fail(path, fmt::format("must be a table {{ kind = \"plane\", \"drum\" or \"surface\", ... }} (got {})",
                             type_name(n.type())));
    if (!raw->contains("kind"))
      table(n, path, {"kind", "diameter", "terms"});  // a misspelt kind: "did you mean"
    SupportDescription s;
    s.kind = static_cast<Kind>(choice(need(*raw, path, "kind", "\"plane\", \"drum\" or \"surface\""),
                                      join(path, "kind"), {"plane", "drum", "surface"}));  // enum order
    static constexpr std::string_view kind_names[] = {"plane", "drum", "surface"};
    const std::string_view kind = kind_names[static_cast<int>(s.kind)];
    for (auto&& [k, v] : *raw) {  // a key of another kind: say which kind it belongs to
      const Kind owner = k.str() == "diameter" ? Kind::drum : k.str() == "terms" ? Kind::surface : s.kind;
      if (owner == s.kind) continue;
      positions_[join(path, k.str())] = k.source().begin;
      fail(join(path, k.str()),
           fmt::format("not allowed for kind \"{}\" ({} belongs to kind \"{}\"; a {} support takes {})", kind,
                       k.str(), kind_names[static_cast<int>(owner)], kind,
                       s.kind == Kind::plane  ? "no other keys"
                       : s.kind == Kind::drum ? "diameter"
                                              : "terms"));
    }
    if (s.kind == Kind::plane) {
      table(n, path, {"kind"});
    } else if (s.kind == Kind::drum) {
      const toml::table& t = table(n, path, {"kind", "diameter"});
      s.drum_diameter = req_number(t, path, "diameter", " (mm, the drum's outer diameter)");
    } else {
      const toml::table& t = table(n, path, {"kind", "terms"});
      const std::string tp = join(path, "terms");
      const toml::array& a =
          array(need(t, path, "terms",
                     "an array of terms { coefficient, x_power, y_power }, z = Σ coefficient · x^x_power · "
                     "y^y_power (mm)"),
                tp, "terms { coefficient, x_power, y_power }");
      for (std::size_t i = 0; i < a.size(); ++i) {
        const std::string p = index(tp, i);
        const toml::table& term = table(a[i], p, {"coefficient", "x_power", "y_power"});
        SupportDescription::Term tm;
        tm.coefficient = req_number(term, p, "coefficient", " (mm^(1 - x_power - y_power))");
        opt_integer(term, p, "x_power", tm.x_power);
        opt_integer(term, p, "y_power", tm.y_power);
        s.terms.push_back(tm);
      }
    }
    return s;
  }

  // Fields common to all studies; `theory` only where the study has a linear variant.
  template <class Study>
  void study_common(const toml::table& t, const std::string& path, Study& s) {
    s.name = string(need(t, path, "name", "a string ([A-Za-z0-9_-], unique among all studies)"),
                    join(path, "name"));
    s.support = support(need(t, path, "support",
                             "a table { kind = \"plane\" }, { kind = \"drum\", diameter = mm } or "
                             "{ kind = \"surface\", terms = [...] }"),
                        join(path, "support"));
    if constexpr (requires { s.linear; })
      if (const toml::node* v = get(t, path, "theory"))
        s.linear = choice(*v, join(path, "theory"), {"nonlinear", "linear"}) == 1;
  }

  LoadCurveStudy load_curve(const toml::node& n, const std::string& path) {
    const toml::table& t = table(n, path, {"name", "support", "theory", "max_deflection", "points"});
    LoadCurveStudy s;
    study_common(t, path, s);
    opt_number(t, path, "max_deflection", s.max_deflection, " (mm)");
    opt_integer(t, path, "points", s.points);
    return s;
  }

  FootprintStudy footprint(const toml::node& n, const std::string& path) {
    const toml::table& t = table(n, path, {"name", "support", "theory", "target_load", "load_tolerance"});
    FootprintStudy s;
    study_common(t, path, s);
    opt_number(t, path, "target_load", s.target_load, " (N)");
    opt_number(t, path, "load_tolerance", s.load_tolerance, " (relative)");
    return s;
  }

  // [[rolling]]: steady rolling at the deflection of a static footprint at target_load.
  //   name, support              as for [[footprint]]; a surface support must not depend on y
  //   target_load                N (default 3700); load_tolerance as for [[footprint]] (default 1e-3)
  //   friction                   Coulomb coefficient μ between tread and support, in (0, 5] (default 0.7)
  //   reverse                    true: the wheel travels in −y (default false)
  //   states                     [{ state = ..., name = ... }, ...], the state's keys by kind:
  //                                "free"                                   (Qy = 0)
  //                                "given_slip",   slip = κ (required)      κ in (−1, 10]
  //                                "given_radius", rolling_radius = mm (required)
  //                                "full_stick",   slip = κ (default 0)
  //                                "full_slip",    wheel = "spinning" (default) or "locked"
  //                              name: [A-Za-z0-9_.+-], unique in the study; default "free", "slip_0.05",
  //                              "radius_280", "full_stick", "full_slip_spinning" / "full_slip_locked"
  //   sweep                      { from = -0.1, to = 0.1, points = 15, hold = "deflection" | "load" }:
  //                              Qy(κ) at `points` (2..200) slips, at the footprint's deflection or at its load
  //                              evenly in [from, to], −1 < from < to ≤ 10
  // At least one state or a sweep.
  // [mesh], or a study's own mesh table (keys missing there are the case's).
  MeshSettings mesh(const toml::node& n, const std::string& path, MeshSettings m) {
    const toml::table& t =
        table(n, path, {"circumferential_elements", "meridional_elements", "half_model", "circumferential_refinement"});
    opt_integer(t, path, "circumferential_elements", m.circumferential_elements);
    opt_integer(t, path, "meridional_elements", m.meridional_elements);
    opt_bool(t, path, "half_model", m.half_model);
    opt_number(t, path, "circumferential_refinement", m.circumferential_refinement, "");
    return m;
  }

  RollingStudy rolling(const toml::node& n, const std::string& path, const MeshSettings& case_mesh) {
    const toml::table& t = table(
        n, path, {"name", "support", "target_load", "load_tolerance", "friction", "reverse", "states", "sweep", "mesh"});
    RollingStudy s;
    if (const toml::node* v = get(t, path, "mesh")) s.mesh = mesh(*v, join(path, "mesh"), case_mesh);
    study_common(t, path, s);
    opt_number(t, path, "target_load", s.target_load, " (N)");
    opt_number(t, path, "load_tolerance", s.load_tolerance, " (relative)");
    opt_number(t, path, "friction", s.friction, " (Coulomb coefficient μ)");
    opt_bool(t, path, "reverse", s.reverse);
    if (const toml::node* v = get(t, path, "states")) {
      const std::string sp = join(path, "states");
      const toml::array& a = array(*v, sp, "states { state = \"free\", ... }");
      for (std::size_t i = 0; i < a.size(); ++i) s.states.push_back(rolling_state(a[i], index(sp, i)));
    }
    if (const toml::node* v = get(t, path, "sweep")) {
      const std::string sp = join(path, "sweep");
      const toml::table& w = table(*v, sp, {"from", "to", "points", "hold"});
      SlipSweep sw;
      opt_number(w, sp, "from", sw.from, " (slip κ)");
      opt_number(w, sp, "to", sw.to, " (slip κ)");
      opt_integer(w, sp, "points", sw.points);
      if (const toml::node* h = get(w, sp, "hold"))
        sw.hold_load = choice(*h, join(sp, "hold"), {"deflection", "load"}) == 1;
      s.sweep = sw;
    }
    return s;
  }

  // The keys allowed depend on the state, as for supports.
  RollingStateSpec rolling_state(const toml::node& n, const std::string& path) {
    using Kind = RollingStateSpec::Kind;
    positions_[path] = n.source().begin;
    const toml::table* raw = n.as_table();
    if (!raw)
      fail(path, fmt::format("must be a table {{ state = \"free\", ... }} (got {})", type_name(n.type())));
    if (!raw->contains("state"))  // a misspelt state: "did you mean"
      table(n, path, {"state", "name", "slip", "rolling_radius", "wheel"});
    RollingStateSpec s;
    s.kind = static_cast<Kind>(
        choice(need(*raw, path, "state",
                    "\"free\", \"given_slip\", \"given_radius\", \"full_stick\" or \"full_slip\""),
               join(path, "state"),
               {"free", "given_slip", "given_radius", "full_stick", "full_slip"}));  // enum order
    static constexpr std::string_view kind_names[] = {"free", "given_slip", "given_radius", "full_stick",
                                                      "full_slip"};
    const std::string_view kind = kind_names[static_cast<int>(s.kind)];
    const std::string_view own = s.kind == Kind::given_slip || s.kind == Kind::full_stick ? "slip"
                                 : s.kind == Kind::given_radius                           ? "rolling_radius"
                                 : s.kind == Kind::full_slip                              ? "wheel"
                                                                                          : "";
    for (auto&& [k, v] : *raw) {  // a key of another state (typos: table() below)
      if (k.str() == own || (k.str() != "slip" && k.str() != "rolling_radius" && k.str() != "wheel"))
        continue;
      positions_[join(path, k.str())] = k.source().begin;
      fail(join(path, k.str()), fmt::format("not allowed in a \"{}\" state (it takes {})", kind,
                                            own.empty() ? std::string("only state and name")
                                                        : fmt::format("state, name and {}", own)));
    }
    const toml::table& t =
        own.empty() ? table(n, path, {"state", "name"}) : table(n, path, {"state", "name", own});
    switch (s.kind) {
      case Kind::free:
        s.name = "free";
        break;
      case Kind::given_slip:
        s.slip = req_number(t, path, "slip", " (slip κ)");
        s.name = fmt::format("slip_{:g}", s.slip);
        break;
      case Kind::given_radius:
        s.rolling_radius = req_number(t, path, "rolling_radius", " (mm)");
        s.name = fmt::format("radius_{:g}", s.rolling_radius);
        break;
      case Kind::full_stick:
        opt_number(t, path, "slip", s.slip, " (slip κ)");
        s.name = "full_stick";
        break;
      case Kind::full_slip:
        if (const toml::node* v = get(t, path, "wheel"))
          s.braking = choice(*v, join(path, "wheel"), {"spinning", "locked"}) == 1;
        s.name = s.braking ? "full_slip_locked" : "full_slip_spinning";
        break;
    }
    if (const toml::node* v = get(t, path, "name")) s.name = string(*v, join(path, "name"));
    return s;
  }

  Case read(const toml::table& root) {
    const toml::table& r = table(
        root, "", {"title", "tyre", "mesh", "inflation", "contact", "load_curve", "footprint", "rolling"});
    Case c;
    if (const toml::node* v = get(r, "", "title")) c.title = string(*v, "title");
    c.tyre = tyre(need(r, "", "tyre", "a table [tyre]"), "tyre");
    if (c.title.empty()) c.title = c.tyre.name;
    if (const toml::node* v = get(r, "", "mesh")) c.mesh = mesh(*v, "mesh", c.mesh);
    if (const toml::node* v = get(r, "", "inflation")) {
      const toml::table& m = table(
          *v, "inflation", {"enabled", "pressure", "linear", "max_newton_iterations", "residual_tolerance"});
      opt_bool(m, "inflation", "enabled", c.inflation.enabled);
      opt_number(m, "inflation", "pressure", c.inflation.pressure, " (MPa)");
      opt_bool(m, "inflation", "linear", c.inflation.linear);
      opt_integer(m, "inflation", "max_newton_iterations", c.inflation.max_newton_iterations);
      opt_number(m, "inflation", "residual_tolerance", c.inflation.residual_tolerance, "");
    }
    if (const toml::node* v = get(r, "", "contact")) c.contact = contact(*v, "contact");
    if (const toml::node* v = get(r, "", "load_curve")) {
      const toml::array& a = array(*v, "load_curve", "tables [[load_curve]]");
      for (std::size_t i = 0; i < a.size(); ++i)
        c.load_curves.push_back(load_curve(a[i], index("load_curve", i)));
    }
    if (const toml::node* v = get(r, "", "footprint")) {
      const toml::array& a = array(*v, "footprint", "tables [[footprint]]");
      for (std::size_t i = 0; i < a.size(); ++i)
        c.footprints.push_back(footprint(a[i], index("footprint", i)));
    }
    if (const toml::node* v = get(r, "", "rolling")) {
      const toml::array& a = array(*v, "rolling", "tables [[rolling]]");
      for (std::size_t i = 0; i < a.size(); ++i) c.rolling.push_back(rolling(a[i], index("rolling", i), c.mesh));
    }
    return c;
  }

 private:
  std::string file_;
  std::map<std::string, toml::source_position> positions_;
  Checker checker_;
};

// The last zone ends at the bead: snap its end to the profile's arc length (validated to be within 1 mm).
void snap_last_zone(Case& c) { c.tyre.zones.back().s_end = MeridianProfile(c.tyre.profile).length(); }

}  // namespace

Case parse_case(std::string_view toml_text, const std::filesystem::path& name_for_messages) {
  const std::string file = name_for_messages.string();
  toml::table root;
  try {
    root = toml::parse(toml_text, file);
  } catch (const toml::parse_error& e) {
    const auto& b = e.source().begin;
    throw CaseError(fmt::format("{}:{}:{}: TOML syntax error: {}", file, b.line, b.column, e.description()));
  }
  Reader reader(file);
  Case c = reader.read(root);
  c.source = name_for_messages;
  reader.checker().run(c);
  snap_last_zone(c);
  return c;
}

Case read_case(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw CaseError(fmt::format("{}: cannot open the case file", file.string()));
  std::ostringstream text;
  text << in.rdbuf();
  return parse_case(text.str(), file);
}

void validate_case(const Case& c) {
  const std::string file = c.source.empty() ? std::string("case") : c.source.string();
  Checker([&file](const std::string&) { return file; }).run(c);
}

}  // namespace tirefem
