#pragma once
// A temporary folder for a test, removed when the test ends (also when it fails).

#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace mechsim::batch::test {

class TempDir {
 public:
  TempDir() {
    std::string pattern = (std::filesystem::temp_directory_path() / "mechsim_batch_test.XXXXXX").string();
    path_ = mkdtemp(pattern.data());
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  // Writes `text` to `name` inside the folder; returns its path.
  std::string write(const std::string& name, const std::string& text) const {
    const auto file = path_ / name;
    std::filesystem::create_directories(file.parent_path());
    std::ofstream(file) << text;
    return file.string();
  }

 private:
  std::filesystem::path path_;
};

// The sweep tests' scenario (flat ground, 2 s), from the source tree.
inline std::string test_scenario() { return std::string(MECHSIM_SOURCE_DIR) + "/src/batch/test/data/cc8_short_drive.yaml"; }

}  // namespace mechsim::batch::test
