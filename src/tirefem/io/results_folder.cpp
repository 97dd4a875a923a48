#include "tirefem/io/results_folder.hpp"

#include <random>
#include <system_error>
#include <vector>

#include <fmt/format.h>

#include "tirefem/io/results_folder_marker.hpp"

namespace tirefem {
namespace fs = std::filesystem;
namespace marker = results_marker;

namespace {

// `final_dir` normalised to an absolute path without a trailing separator, so that parent_path() and
// filename() mean "the folder that holds it" and "its name".
fs::path normalised(const fs::path& final_dir) {
  if (final_dir.empty()) throw ResultsFolderError("the results folder path is empty");
  fs::path p = fs::absolute(final_dir).lexically_normal();
  if (!p.has_filename()) p = p.parent_path();
  if (!p.has_filename() || p == p.root_path())
    throw ResultsFolderError(fmt::format("'{}' is not a usable results folder", final_dir.string()));
  return p;
}

// A new, uniquely named sibling `.<name>.<tag>-<hex>` of `dir` (created, with this process's marker).
fs::path make_unique_sibling(const fs::path& dir, std::string_view tag) {
  std::random_device device;
  std::mt19937_64 rng((static_cast<std::uint64_t>(device()) << 32) ^ device());
  for (int attempt = 0; attempt < 100; ++attempt) {
    const fs::path candidate = dir.parent_path() / fmt::format(".{}.{}-{:08x}", dir.filename().string(), tag,
                                                               static_cast<std::uint32_t>(rng()));
    std::error_code ec;
    if (fs::create_directory(candidate, ec)) {
      marker::write(candidate, marker::of_this_process());
      return candidate;
    }
    if (ec)
      throw ResultsFolderError(
          fmt::format("cannot create a temporary folder beside '{}': {}", dir.string(), ec.message()));
  }
  throw ResultsFolderError(fmt::format("cannot find a free temporary name beside '{}'", dir.string()));
}

void rename_or_throw(const fs::path& from, const fs::path& to) {
  std::error_code ec;
  fs::rename(from, to, ec);
  if (ec)
    throw std::runtime_error(fmt::format("cannot move '{}' to '{}': {}", from.string(), to.string(), ec.message()));
}

// Where results meant for `target` can go: `target` itself unless a result's name collides with an entry
// tirefem did not write (or `target` is a file), else the first `target-2`, `-3`, … that does not exist.
fs::path usable_target(const fs::path& target, const std::set<std::string>& new_entries, bool force) {
  std::error_code ec;
  auto usable = [&](const fs::path& t) {
    if (!fs::exists(fs::symlink_status(t, ec))) return true;
    if (!fs::is_directory(fs::status(t, ec))) return false;
    const auto old = marker::read(t);
    const std::set<std::string> present = marker::entries_of(t);
    if (!old && fs::exists(t / kResultsMarker, ec)) return false;  // a file of that name, not ours
    if (!old && !present.empty() && !force) return false;
    for (const std::string& e : present)
      if (new_entries.contains(e) && !(old && old->entries.contains(e))) return false;
    return true;
  };
  if (usable(target)) return target;
  for (int n = 2;; ++n) {
    const fs::path t = target.parent_path() / fmt::format("{}-{}", target.filename().string(), n);
    if (!fs::exists(fs::symlink_status(t, ec))) return t;
  }
}

}  // namespace

ResultsFolder::ResultsFolder(fs::path final_dir, const ResultsFolderPolicy& policy)
    : final_dir_(normalised(final_dir)), force_(policy.force) {
  marker::check_usable(final_dir_, policy);
  std::error_code ec;
  fs::create_directories(final_dir_.parent_path(), ec);
  if (ec)
    throw ResultsFolderError(fmt::format("cannot create folder '{}' for results: {}",
                                         final_dir_.parent_path().string(), ec.message()));
  marker::remove_stale_siblings(final_dir_);
  temp_dir_ = make_unique_sibling(final_dir_, "tmp");
}

ResultsFolder::ResultsFolder(ResultsFolder&& other) noexcept
    : final_dir_(std::move(other.final_dir_)),
      temp_dir_(std::move(other.temp_dir_)),
      committed_dir_(std::move(other.committed_dir_)),
      force_(other.force_),
      committed_(other.committed_) {
  other.temp_dir_.clear();
  other.committed_ = true;  // the moved-from object owns nothing to clean up
}

ResultsFolder::~ResultsFolder() {
  if (committed_ || temp_dir_.empty()) return;
  std::error_code ec;
  fs::remove_all(temp_dir_, ec);  // best effort: a destructor must not throw
}

fs::path ResultsFolder::path(std::string_view file_name) const {
  const fs::path name = fs::path(file_name).lexically_normal();
  if (name.empty() || name.is_absolute() || name.has_root_path() || *name.begin() == ".." ||
      name == kResultsMarker)
    throw std::invalid_argument(fmt::format(
        "ResultsFolder: file name '{}' must be relative and stay inside the results folder", file_name));
  const fs::path full = (committed_ ? committed_dir_ : temp_dir_) / name;
  if (name.has_parent_path()) {
    std::error_code ec;
    fs::create_directories(full.parent_path(), ec);
    if (ec)
      throw std::runtime_error(
          fmt::format("cannot create folder '{}': {}", full.parent_path().string(), ec.message()));
  }
  return full;
}

fs::path ResultsFolder::commit(std::string_view suffix) {
  if (committed_)
    throw std::logic_error(fmt::format("results folder '{}' was already committed", final_dir_.string()));
  marker::Marker manifest;
  manifest.entries = marker::entries_of(temp_dir_);
  const fs::path target =
      usable_target(final_dir_.parent_path() / (final_dir_.filename().string() + std::string(suffix)),
                    manifest.entries, force_);
  std::error_code ec;
  const auto old = fs::exists(fs::symlink_status(target, ec)) ? marker::read(target) : std::nullopt;
  std::set<std::string> foreign = fs::exists(target, ec) ? marker::entries_of(target) : std::set<std::string>{};
  if (old) std::erase_if(foreign, [&](const std::string& e) { return old->entries.contains(e); });

  if (!fs::exists(fs::symlink_status(target, ec))) {
    rename_or_throw(temp_dir_, target);
  } else if (foreign.empty()) {
    // Only tirefem's own entries (or nothing): swap the folders, delete the old one once the new is in.
    const fs::path aside = make_unique_sibling(target, "old");
    fs::remove_all(aside, ec);  // rename(2) needs the name free
    rename_or_throw(target, aside);
    fs::rename(temp_dir_, target, ec);
    if (ec) {
      const std::string reason = ec.message();
      fs::rename(aside, target, ec);
      throw std::runtime_error(fmt::format("cannot move the results from '{}' to '{}': {}", temp_dir_.string(),
                                           target.string(), reason));
    }
    fs::remove_all(aside, ec);
  } else {
    // The user's files stay: set aside the entries an earlier run wrote, move the new ones in.
    const fs::path aside = make_unique_sibling(target, "old");
    std::vector<std::string> moved_aside, moved_in;
    try {
      if (old)
        for (const std::string& e : old->entries)
          if (fs::exists(fs::symlink_status(target / e, ec))) {
            rename_or_throw(target / e, aside / e);
            moved_aside.push_back(e);
          }
      for (const std::string& e : manifest.entries) {
        rename_or_throw(temp_dir_ / e, target / e);
        moved_in.push_back(e);
      }
    } catch (const std::exception&) {
      for (const std::string& e : moved_in) fs::rename(target / e, temp_dir_ / e, ec);
      for (const std::string& e : moved_aside) fs::rename(aside / e, target / e, ec);
      fs::remove_all(aside, ec);
      throw;
    }
    fs::remove_all(aside, ec);
    fs::remove_all(temp_dir_, ec);
  }
  marker::write(target, manifest);  // the final list, without the writing process
  committed_ = true;
  committed_dir_ = target;
  return target;
}

}  // namespace tirefem
