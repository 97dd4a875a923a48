#include "tirefem/io/results_folder_marker.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <signal.h>
#include <unistd.h>

#include <fmt/format.h>

namespace tirefem::results_marker {
namespace fs = std::filesystem;

namespace {
constexpr std::string_view kFirstLine = "tirefem results folder";

std::string host_name() {
  char name[256] = {};
  if (gethostname(name, sizeof name - 1) != 0) return "unknown";
  return name;
}

// True when `inner` is `outer` or lies inside it (both canonical).
bool contains(const fs::path& outer, const fs::path& inner) {
  auto o = outer.begin(), i = inner.begin();
  for (; o != outer.end(); ++o, ++i) {
    if (o->empty()) continue;  // a trailing separator
    if (i == inner.end() || *o != *i) return false;
  }
  return true;
}

fs::path canonical_or_self(const fs::path& p) {
  std::error_code ec;
  fs::path c = fs::weakly_canonical(fs::absolute(p, ec), ec);
  return ec ? fs::absolute(p).lexically_normal() : c;
}

[[noreturn]] void refuse(const fs::path& dir, std::string_view why) {
  throw ResultsFolderError(fmt::format("results folder '{}' {}", dir.string(), why));
}

bool process_gone(long pid) { return kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH; }
}  // namespace

std::optional<Marker> read(const fs::path& dir) {
  std::ifstream in(dir / kResultsMarker);
  std::string line;
  if (!in || !std::getline(in, line) || line != kFirstLine) return std::nullopt;
  Marker m;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string key;
    words >> key;
    if (key == "entry" && line.size() > 6) {
      m.entries.insert(line.substr(6));
    } else if (key == "pid") {
      long pid = 0;
      std::string host_key;
      if (words >> pid >> host_key >> m.host && host_key == "host") m.pid = pid;
    }
  }
  return m;
}

void write(const fs::path& dir, const Marker& marker) {
  const fs::path file = dir / kResultsMarker;
  const fs::path temp = dir / (std::string(kResultsMarker) + ".new");
  {
    std::ofstream out(temp);
    out << kFirstLine << '\n';
    if (marker.pid) out << "pid " << *marker.pid << " host " << marker.host << '\n';
    for (const std::string& e : marker.entries) out << "entry " << e << '\n';
    if (!out) throw std::runtime_error(fmt::format("cannot write '{}'", temp.string()));
  }
  std::error_code ec;
  fs::rename(temp, file, ec);
  if (ec) throw std::runtime_error(fmt::format("cannot write '{}': {}", file.string(), ec.message()));
}

Marker of_this_process() {
  Marker m;
  m.pid = static_cast<long>(getpid());
  m.host = host_name();
  return m;
}

std::set<std::string> entries_of(const fs::path& dir) {
  std::set<std::string> names;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    std::string name = e.path().filename().string();
    if (name != kResultsMarker) names.insert(std::move(name));
  }
  return names;
}

void check_usable(const fs::path& dir, const ResultsFolderPolicy& policy) {
  const fs::path real = canonical_or_self(dir);
  std::error_code ec;
  const fs::file_status status = fs::status(real, ec);
  if (fs::exists(status) && !fs::is_directory(status))
    refuse(dir, "is a file, not a folder: give the name of a new folder for the results");
  if (real == real.root_path()) refuse(dir, "is the root folder: give a folder of its own for the results");
  if (contains(real, canonical_or_self(fs::current_path(ec))))
    refuse(dir, "is the current folder or one of its parents: give a folder of its own for the results");
  if (const char* home = std::getenv("HOME"); home && *home && real == canonical_or_self(home))
    refuse(dir, "is the home folder: give a folder of its own for the results");
  if (!policy.case_file.empty() && contains(real, canonical_or_self(policy.case_file).parent_path()))
    refuse(dir, "holds the case file: give a folder of its own for the results");
  if (!fs::exists(status)) return;
  if (!read(real) && !fs::is_empty(real, ec) && (!policy.force || fs::exists(real / kResultsMarker, ec)))
    refuse(dir, fmt::format("is not empty and was not written by tirefem (it has no valid {} file): choose "
                            "a new or empty folder, or add --force to put the results beside its files (none "
                            "of them is deleted or overwritten)",
                            kResultsMarker));
  if (access(real.c_str(), W_OK | X_OK) != 0) refuse(dir, "cannot be written (permission denied)");
}

void remove_stale_siblings(const fs::path& dir) {
  const std::string prefix = "." + dir.filename().string() + ".";
  const std::string host = host_name();
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir.parent_path(), ec)) {
    const std::string name = e.path().filename().string();
    if (name.rfind(prefix + "tmp-", 0) != 0 && name.rfind(prefix + "old-", 0) != 0) continue;
    if (!e.is_directory(ec)) continue;
    const std::optional<Marker> m = read(e.path());
    if (!m) continue;  // not ours
    const bool ours_entirely =
        m->pid ? (m->host == host && process_gone(*m->pid))
               : std::ranges::includes(m->entries, entries_of(e.path()));  // a set-aside results folder
    if (ours_entirely) fs::remove_all(e.path(), ec);
  }
}

}  // namespace tirefem::results_marker
