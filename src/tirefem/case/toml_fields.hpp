#pragma once
// Typed access to the fields of a parsed TOML case, for the section readers: every getter records where
// the field is, so that a later value check can point at its line and column; wrong types, missing keys
// and unknown keys (with "did you mean") are CaseErrors naming the full field path.
#include <toml++/toml.h>

#include <initializer_list>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "tirefem/case/field_checker.hpp"
#include "tirefem/case/field_path.hpp"

namespace tirefem::case_reading {

// "a table", "an integer", ... for messages.
std::string type_name(toml::node_type t);

class TomlFields {
 public:
  explicit TomlFields(std::string file);
  TomlFields(const TomlFields&) = delete;  // the checker refers back to this object
  TomlFields& operator=(const TomlFields&) = delete;

  const FieldChecker& checker() const { return checker_; }
  // "file:line:col" of the field, else of its nearest recorded parent, else "file".
  std::string locate(const std::string& path) const;
  [[noreturn]] void fail(const std::string& path, const std::string& what) const { checker_.fail(path, what); }
  // Records where `path` is.
  void mark(const std::string& path, const toml::source_position& where) { positions_[path] = where; }

  const toml::node* get(const toml::table& t, const std::string& path, std::string_view key);
  const toml::node& need(const toml::table& t, const std::string& path, std::string_view key,
                         std::string_view expected);
  // The node as a table whose keys are all in `keys` (else "unknown key", with a suggestion).
  const toml::table& table(const toml::node& n, const std::string& path,
                           std::initializer_list<std::string_view> keys);
  const toml::array& array(const toml::node& n, const std::string& path, std::string_view of);
  double number(const toml::node& n, const std::string& path, std::string_view unit);
  int integer(const toml::node& n, const std::string& path);
  bool boolean(const toml::node& n, const std::string& path);
  std::string string(const toml::node& n, const std::string& path);
  std::vector<double> numbers(const toml::node& n, const std::string& path, std::string_view unit);
  // Optional fields keep `out` (the default) when absent.
  void opt_number(const toml::table& t, const std::string& path, std::string_view key, double& out,
                  std::string_view unit);
  void opt_integer(const toml::table& t, const std::string& path, std::string_view key, int& out);
  void opt_bool(const toml::table& t, const std::string& path, std::string_view key, bool& out);
  double req_number(const toml::table& t, const std::string& path, std::string_view key, std::string_view unit);
  // A string out of a fixed list; returns its index in `values`.
  std::size_t choice(const toml::node& n, const std::string& path, std::initializer_list<std::string_view> values);

 private:
  std::string file_;
  std::map<std::string, toml::source_position> positions_;
  FieldChecker checker_;
};

}  // namespace tirefem::case_reading
