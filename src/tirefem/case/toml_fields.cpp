#include "tirefem/case/toml_fields.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>

namespace tirefem::case_reading {

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

TomlFields::TomlFields(std::string file)
    : file_(std::move(file)), checker_([this](const std::string& p) { return locate(p); }) {}

std::string TomlFields::locate(const std::string& path) const {
  for (std::string p = path;;) {  // the field, else its nearest recorded parent
    if (const auto it = positions_.find(p); it != positions_.end() && it->second.line > 0)
      return fmt::format("{}:{}:{}", file_, it->second.line, it->second.column);
    const auto cut = p.find_last_of(".[");
    if (cut == std::string::npos || cut == 0) return file_;
    p.resize(cut);
  }
}

const toml::node* TomlFields::get(const toml::table& t, const std::string& path, std::string_view key) {
  const toml::node* n = t.get(key);
  if (n) positions_[join(path, key)] = n->source().begin;
  return n;
}

const toml::node& TomlFields::need(const toml::table& t, const std::string& path, std::string_view key,
                                   std::string_view expected) {
  if (const toml::node* n = get(t, path, key)) return *n;
  fail(join(path, key), fmt::format("missing; expected {}", expected));
}

const toml::table& TomlFields::table(const toml::node& n, const std::string& path,
                                     std::initializer_list<std::string_view> keys) {
  positions_[path] = n.source().begin;
  const toml::table* t = n.as_table();
  if (!t) fail(path, fmt::format("must be a table (got {})", type_name(n.type())));
  for (auto&& [k, v] : *t) {
    if (std::find(keys.begin(), keys.end(), k.str()) != keys.end()) continue;
    positions_[join(path, k.str())] = k.source().begin;
    std::string msg = "unknown key; expected one of";
    for (std::string_view a : keys) msg += fmt::format("{} {}", a == *keys.begin() ? ":" : ",", a);
    if (const std::string_view close = closest_key(k.str(), keys); !close.empty())
      msg += fmt::format(" (did you mean '{}'?)", close);
    fail(join(path, k.str()), msg);
  }
  return *t;
}

const toml::array& TomlFields::array(const toml::node& n, const std::string& path, std::string_view of) {
  const toml::array* a = n.as_array();
  if (!a) fail(path, fmt::format("must be an array of {} (got {})", of, type_name(n.type())));
  for (std::size_t i = 0; i < a->size(); ++i) positions_[index(path, i)] = (*a)[i].source().begin;
  return *a;
}

double TomlFields::number(const toml::node& n, const std::string& path, std::string_view unit) {
  if (!n.is_number()) fail(path, fmt::format("must be a number{} (got {})", unit, type_name(n.type())));
  return *n.value<double>();
}

int TomlFields::integer(const toml::node& n, const std::string& path) {
  if (!n.is_integer()) fail(path, fmt::format("must be an integer (got {})", type_name(n.type())));
  const int64_t v = n.as_integer()->get();
  if (v < -1000000000 || v > 1000000000) fail(path, fmt::format("out of range (got {})", v));
  return static_cast<int>(v);
}

bool TomlFields::boolean(const toml::node& n, const std::string& path) {
  if (!n.is_boolean()) fail(path, fmt::format("must be true or false (got {})", type_name(n.type())));
  return n.as_boolean()->get();
}

std::string TomlFields::string(const toml::node& n, const std::string& path) {
  if (!n.is_string()) fail(path, fmt::format("must be a string (got {})", type_name(n.type())));
  return n.as_string()->get();
}

std::vector<double> TomlFields::numbers(const toml::node& n, const std::string& path, std::string_view unit) {
  std::vector<double> v;
  const toml::array& a = array(n, path, "numbers");
  for (std::size_t i = 0; i < a.size(); ++i) v.push_back(number(a[i], index(path, i), unit));
  return v;
}

void TomlFields::opt_number(const toml::table& t, const std::string& path, std::string_view key, double& out,
                            std::string_view unit) {
  if (const toml::node* n = get(t, path, key)) out = number(*n, join(path, key), unit);
}

void TomlFields::opt_integer(const toml::table& t, const std::string& path, std::string_view key, int& out) {
  if (const toml::node* n = get(t, path, key)) out = integer(*n, join(path, key));
}

void TomlFields::opt_bool(const toml::table& t, const std::string& path, std::string_view key, bool& out) {
  if (const toml::node* n = get(t, path, key)) out = boolean(*n, join(path, key));
}

double TomlFields::req_number(const toml::table& t, const std::string& path, std::string_view key,
                              std::string_view unit) {
  return number(need(t, path, key, fmt::format("a number{}", unit)), join(path, key), unit);
}

std::size_t TomlFields::choice(const toml::node& n, const std::string& path,
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

}  // namespace tirefem::case_reading
