#pragma once
// The marker file of a results folder (kResultsMarker) and the checks built on it, for ResultsFolder.
//
// The marker is a short text file:
//   tirefem results folder
//   pid <n> host <name>     only while a run writes the folder (a temporary or set-aside folder)
//   entry <name>            one line per top-level entry tirefem wrote
#include <filesystem>
#include <optional>
#include <set>
#include <string>

#include "tirefem/io/results_folder.hpp"

namespace tirefem::results_marker {

struct Marker {
  std::set<std::string> entries;
  std::optional<long> pid;  // of the run writing it
  std::string host;
};

// The marker of `dir`, or nothing when `dir` has none (or an unreadable one: then it is not ours).
std::optional<Marker> read(const std::filesystem::path& dir);
// Writes the marker atomically (a temporary file renamed over it). Throws std::runtime_error.
void write(const std::filesystem::path& dir, const Marker& marker);
// A marker for a folder this process is writing.
Marker of_this_process();

// The top-level entries of `dir` other than the marker.
std::set<std::string> entries_of(const std::filesystem::path& dir);

// Throws ResultsFolderError when `dir` (absolute, normalised) cannot be a results folder under `policy`.
void check_usable(const std::filesystem::path& dir, const ResultsFolderPolicy& policy);

// Removes `.<name>.tmp-*` / `.<name>.old-*` siblings of `dir` that carry a marker whose process is no
// longer running on this host (left by a killed run). Never throws.
void remove_stale_siblings(const std::filesystem::path& dir);

}  // namespace tirefem::results_marker
