#include "tirefem/io/results_folder.hpp"

#include <random>
#include <stdexcept>
#include <system_error>

#include <fmt/format.h>

namespace tirefem {
namespace fs = std::filesystem;

namespace {

// `final_dir` normalised to an absolute path without a trailing separator, so that parent_path() and
// filename() mean "the folder that holds it" and "its name".
fs::path normalised(const fs::path& final_dir) {
  if (final_dir.empty()) throw std::invalid_argument("ResultsFolder: the results folder path is empty");
  fs::path p = fs::absolute(final_dir).lexically_normal();
  if (!p.has_filename()) p = p.parent_path();
  if (!p.has_filename() || p == p.root_path())
    throw std::invalid_argument(
        fmt::format("ResultsFolder: '{}' is not a usable results folder", final_dir.string()));
  return p;
}

// Creates a new, uniquely named sibling `.<name>.<tag>-<hex>` of `dir` and returns it.
fs::path make_unique_sibling(const fs::path& dir, std::string_view tag, bool create) {
  std::random_device device;
  std::mt19937_64 rng((static_cast<std::uint64_t>(device()) << 32) ^ device());
  for (int attempt = 0; attempt < 100; ++attempt) {
    const fs::path candidate = dir.parent_path() / fmt::format(".{}.{}-{:08x}", dir.filename().string(), tag,
                                                               static_cast<std::uint32_t>(rng()));
    std::error_code ec;
    if (create) {
      if (fs::create_directory(candidate, ec)) return candidate;
      if (ec)
        throw std::runtime_error(
            fmt::format("cannot create temporary results folder '{}': {}", candidate.string(), ec.message()));
    } else if (!fs::exists(fs::symlink_status(candidate, ec))) {
      return candidate;
    }
  }
  throw std::runtime_error(fmt::format("cannot find a free temporary name next to '{}'", dir.string()));
}

}  // namespace

ResultsFolder::ResultsFolder(fs::path final_dir) : final_dir_(normalised(final_dir)) {
  std::error_code ec;
  fs::create_directories(final_dir_.parent_path(), ec);
  if (ec)
    throw std::runtime_error(fmt::format("cannot create folder '{}' for results: {}",
                                         final_dir_.parent_path().string(), ec.message()));
  temp_dir_ = make_unique_sibling(final_dir_, "tmp", true);
}

ResultsFolder::ResultsFolder(ResultsFolder&& other) noexcept
    : final_dir_(std::move(other.final_dir_)),
      temp_dir_(std::move(other.temp_dir_)),
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
  if (name.empty() || name.is_absolute() || name.has_root_path() || *name.begin() == "..")
    throw std::invalid_argument(fmt::format(
        "ResultsFolder: file name '{}' must be relative and stay inside the results folder", file_name));
  const fs::path full = (committed_ ? final_dir_ : temp_dir_) / name;
  if (name.has_parent_path()) {
    std::error_code ec;
    fs::create_directories(full.parent_path(), ec);
    if (ec)
      throw std::runtime_error(
          fmt::format("cannot create folder '{}': {}", full.parent_path().string(), ec.message()));
  }
  return full;
}

void ResultsFolder::commit() {
  if (committed_)
    throw std::logic_error(fmt::format("results folder '{}' was already committed", final_dir_.string()));
  std::error_code ec;
  // rename(2) cannot replace a non-empty directory, so the old results are moved aside first; they are
  // deleted only once the new ones are in place.
  fs::path old_aside;
  if (fs::exists(fs::symlink_status(final_dir_, ec))) {
    old_aside = make_unique_sibling(final_dir_, "old", false);
    fs::rename(final_dir_, old_aside, ec);
    if (ec)
      throw std::runtime_error(fmt::format("cannot move the old results folder '{}' aside: {}",
                                           final_dir_.string(), ec.message()));
  }
  fs::rename(temp_dir_, final_dir_, ec);
  if (ec) {
    const std::string reason = ec.message();
    if (!old_aside.empty()) fs::rename(old_aside, final_dir_, ec);
    throw std::runtime_error(fmt::format("cannot move the results from '{}' to '{}': {}", temp_dir_.string(),
                                         final_dir_.string(), reason));
  }
  committed_ = true;
  if (!old_aside.empty()) fs::remove_all(old_aside, ec);  // leftovers are harmless hidden folders
}

}  // namespace tirefem
