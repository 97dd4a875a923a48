#pragma once
// The run summary as JSON, built as a toml::table (so numbers keep their type: integers stay integers,
// doubles are written as JSON numbers with round-trip precision, e.g. 0.1 → 0.10000000000000001).
//
// Key order: toml::table is a sorted map, so every object's keys come out in byte-wise ascending order
// (uppercase before lowercase: "Qz_N" before "deflection_mm"), whatever order they were inserted in.
// Array elements keep their order.
#include <filesystem>

#include <toml++/toml.h>

namespace tirefem {

// Throws std::invalid_argument naming the file and the key path (e.g. "steps[3].Qz_N") if any double is
// NaN or infinite (JSON has no such numbers; toml++ would write them as strings), and std::runtime_error
// naming the file when it cannot be written. The file ends with a newline.
void write_json(const std::filesystem::path& file, const toml::table& table);

}  // namespace tirefem
