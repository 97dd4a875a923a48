#pragma once
// [inflation] and [contact]: how the inflation and the contact problems are solved, and their checks.
#include <string>

#include "tirefem/case/case.hpp"
#include "tirefem/case/toml_fields.hpp"

namespace tirefem::case_reading {

InflationSettings read_inflation(TomlFields& f, const toml::node& n, const std::string& path);
ContactSettings read_contact(TomlFields& f, const toml::node& n, const std::string& path);

void check_inflation(const FieldChecker& c, const InflationSettings& s, const std::string& path);
void check_contact(const FieldChecker& c, const ContactSettings& s, const std::string& path);

}  // namespace tirefem::case_reading
