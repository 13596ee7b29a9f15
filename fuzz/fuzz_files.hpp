#pragma once
// What mechsim's fuzz targets (src/<layer>/fuzz/*_fuzz.cpp) share: mechsim reads robots, worlds
// and scenarios from files, so an input is written to files in one scratch folder per process
// (removed at exit) and read back through the same entry points users reach.
//
// An input may hold several files: the first is the main one, and a line "=== NAME" starts the
// next file NAME (a plain name: letters, digits, '.', '_' and '-', at most 32 characters; other
// lines starting "===" belong to the file before). xacro includes reach each other this way.

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

namespace mechsim::fuzz {

class ScratchDir {
 public:
  ScratchDir() {
    std::string pattern = (std::filesystem::temp_directory_path() / "mechsim_fuzz_XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("fuzz: cannot make a scratch folder in " + pattern);
    path_ = pattern;
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  const std::filesystem::path& path() const { return path_; }

  // Writes `files` (name, content) into the folder, removing the files of the previous input
  // (file names are plain: nothing else is ever made there).
  void write(const std::vector<std::pair<std::string, std::string>>& files) {
    std::error_code ec;
    for (const std::string& name : written_) std::filesystem::remove(path_ / name, ec);
    written_.clear();
    for (const auto& [name, content] : files) {
      std::ofstream(path_ / name, std::ios::binary) << content;
      written_.push_back(name);
    }
  }

 private:
  std::filesystem::path path_;
  std::vector<std::string> written_;
};

// The folder every call of this process uses (made at first use, removed at exit).
inline ScratchDir& scratch() {
  static ScratchDir dir;
  return dir;
}

inline bool plain_name(std::string_view name) {
  if (name.empty() || name.size() > 32 || name == "." || name == "..") return false;
  for (char c : name) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '_' || c == '-';
    if (!ok) return false;
  }
  return true;
}

// Splits an input into files; the first is named `main_name`.
inline std::vector<std::pair<std::string, std::string>> split_files(const std::uint8_t* data, std::size_t size,
                                                                    const std::string& main_name) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  std::vector<std::pair<std::string, std::string>> files{{main_name, ""}};
  std::size_t pos = 0;
  while (pos <= text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(pos, end - pos);
    const bool last = end == text.size();
    if (line.substr(0, 4) == "=== " && plain_name(line.substr(4)) && line.substr(4) != main_name) {
      files.emplace_back(std::string(line.substr(4)), "");
    } else {
      files.back().second.append(line);
      if (!last) files.back().second.push_back('\n');
    }
    if (last) break;
    pos = end + 1;
  }
  return files;
}

}  // namespace mechsim::fuzz
