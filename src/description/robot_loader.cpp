#include "description/robot_loader.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace mechsim::description {

namespace {

// A file needs expanding when it is named *.xacro or holds xacro elements (xacro's namespace or a
// xacro: prefix), as some packages ship *.urdf files that are really xacro.
bool needs_xacro(const std::string& path, const std::string& text) {
  return path.ends_with(".xacro") || text.find("xmlns:xacro") != std::string::npos ||
         text.find("<xacro:") != std::string::npos;
}

}  // namespace

LoadedRobot load_robot(const std::string& path, const LoadOptions& options) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw DescriptionError(path + ": is a directory, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw DescriptionError(path + ": cannot open the file");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  std::string text = buffer.str();

  LoadedRobot loaded;
  std::string source = path;
  if (needs_xacro(path, text)) {
    // xacro's own warnings (and xacro.message output) become load warnings, not console noise.
    std::ostringstream diagnostics;
    XacroOptions xacro;
    xacro.args = options.xacro_args;
    xacro.packages = options.packages;
    xacro.diagnostics = &diagnostics;
    loaded.urdf = expand_xacro_file(path, xacro);
    std::istringstream lines(diagnostics.str());
    for (std::string line; std::getline(lines, line);)
      if (!line.empty()) loaded.warnings.push_back(path + ": xacro: " + line);
    // Lines in later messages count in the expanded document, not in the xacro source.
    source = path + " (expanded)";
  } else {
    loaded.urdf = std::move(text);
  }
  UrdfOptions urdf;
  urdf.lenient = options.lenient;
  urdf.packages = options.packages;
  loaded.model = parse_urdf_string(loaded.urdf, source, urdf, &loaded.warnings);
  return loaded;
}

}  // namespace mechsim::description
