#pragma once
// Test helpers for writers: a fresh scratch folder per test (removed afterwards) and reading a file back.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <unistd.h>

namespace tirefem::test {

// <temp>/tirefem_<tag>_<pid>, emptied on construction and removed on destruction.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& tag)
      : path(std::filesystem::temp_directory_path() / ("tirefem_" + tag + "_" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~ScratchDir() { std::filesystem::remove_all(path); }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  std::filesystem::path path;
};

inline std::string read_file(const std::filesystem::path& file) {
  std::ifstream in(file);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace tirefem::test
