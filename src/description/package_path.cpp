#include "description/package_path.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <system_error>

namespace mechsim::description {
namespace fs = std::filesystem;

namespace {

// The <name> element of a package.xml, or empty.
std::string package_xml_name(const fs::path& manifest) {
  std::ifstream in(manifest);
  std::stringstream buffer;
  buffer << in.rdbuf();
  static const std::regex name_re(R"(<name>\s*([^<\s]+)\s*</name>)");
  std::smatch m;
  const std::string text = buffer.str();
  if (std::regex_search(text, m, name_re)) return m[1].str();
  return {};
}

std::optional<std::string> search_tree(const fs::path& root, const std::string& name, int depth) {
  std::error_code ec;
  if (!fs::is_directory(root, ec)) return std::nullopt;
  const fs::path manifest = root / "package.xml";
  if (fs::exists(manifest, ec)) {
    // A package does not contain other packages (as rospack assumes).
    if (package_xml_name(manifest) == name) return root.string();
    return std::nullopt;
  }
  if (depth <= 0) return std::nullopt;
  for (const fs::directory_entry& entry : fs::directory_iterator(root, ec)) {
    if (!entry.is_directory(ec) || entry.path().filename().string().starts_with(".")) continue;
    if (auto found = search_tree(entry.path(), name, depth - 1)) return found;
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> find_package(const std::string& name, const PackageMap& explicit_packages) {
  // Absolute, as rospack returns it: includes resolve relative names against the including file.
  if (auto it = explicit_packages.find(name); it != explicit_packages.end()) {
    std::error_code ec;
    const fs::path absolute = fs::absolute(it->second, ec);
    return ec ? it->second : absolute.lexically_normal().string();
  }
  const char* env = std::getenv("ROS_PACKAGE_PATH");
  if (env == nullptr) return std::nullopt;
  std::stringstream paths(env);
  std::string entry;
  while (std::getline(paths, entry, ':')) {
    if (entry.empty()) continue;
    if (auto found = search_tree(entry, name, 6)) return found;
  }
  return std::nullopt;
}

std::optional<std::string> resolve_uri(const std::string& uri, const PackageMap& explicit_packages,
                                       const std::string& base_dir) {
  static const std::string package_scheme = "package://";
  static const std::string file_scheme = "file://";
  if (uri.starts_with(package_scheme)) {
    const std::string rest = uri.substr(package_scheme.size());
    const std::size_t slash = rest.find('/');
    const std::string pkg = rest.substr(0, slash);
    auto dir = find_package(pkg, explicit_packages);
    if (!dir) return std::nullopt;
    if (slash == std::string::npos) return *dir;
    return (fs::path(*dir) / rest.substr(slash + 1)).string();
  }
  if (uri.starts_with(file_scheme)) return uri.substr(file_scheme.size());
  const fs::path p(uri);
  if (p.is_absolute() || base_dir.empty()) return uri;
  return (fs::path(base_dir) / p).string();
}

}  // namespace mechsim::description
