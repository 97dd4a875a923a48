#pragma once
// Dotted field paths of a case ("tyre.zones[2].core_shear_modulus") and the "did you mean" suggestion for
// a misspelt key. Shared by the section readers (case_reader.cpp and the *_reader.cpp files beside it).
#include <cstddef>
#include <initializer_list>
#include <string>
#include <string_view>

namespace tirefem::case_reading {

// path.key (the key quoted when it is not a bare TOML key); just key at the root (empty path).
std::string join(const std::string& path, std::string_view key);
// path[i]
std::string index(const std::string& path, std::size_t i);

// Levenshtein distance.
std::size_t edit_distance(std::string_view a, std::string_view b);
// The candidate `key` most likely misspells (close enough to be a typo), or empty.
std::string_view closest_key(std::string_view key, std::initializer_list<std::string_view> candidates);

}  // namespace tirefem::case_reading
