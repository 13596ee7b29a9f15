#pragma once
// Helpers for the xacro unit tests: expand inline documents, write temporary files.

#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "description/xacro/xacro.hpp"

namespace mechsim::description::test {

// The output without the XML declaration and the 4-line banner.
inline std::string strip_banner(const std::string& out) {
  std::size_t pos = 0;
  for (int i = 0; i < 5 && pos != std::string::npos; ++i) pos = out.find('\n', pos) + 1;
  return out.substr(pos);
}

inline std::string expand_body(const std::string& doc, XacroOptions options = {}) {
  std::ostringstream diagnostics;
  if (options.diagnostics == nullptr) options.diagnostics = &diagnostics;
  return strip_banner(expand_xacro_string(doc, "test.xacro", options));
}

inline std::string expansion_error(const std::string& doc, XacroOptions options = {}) {
  std::ostringstream diagnostics;
  options.diagnostics = &diagnostics;
  try {
    expand_xacro_string(doc, "test.xacro", options);
  } catch (const XacroError& e) {
    return e.what();
  }
  return "no error";
}

// A temporary folder removed at the end of the test.
class TempDir {
 public:
  TempDir() {
    path_ = std::filesystem::temp_directory_path() /
            ("mechsim_xacro_test_" + std::to_string(::getpid()) + "_" +
             std::to_string(reinterpret_cast<std::uintptr_t>(this)));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::filesystem::path write(const std::string& name, const std::string& content) const {
    const auto p = path_ / name;
    std::filesystem::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << content;
    return p;
  }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace mechsim::description::test
