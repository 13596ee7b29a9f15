#include "description/package_path.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>
#include <set>
#include <system_error>

#include <tinyxml2.h>

namespace mechsim::description {
namespace fs = std::filesystem;

namespace {

// The <name> element of a package.xml, or empty: the text between <name> and </name>, trimmed,
// when it is one word (a plain scan: std::regex cost more than the rest of a PR2 expansion).
std::string package_xml_name(const fs::path& manifest) {
  std::ifstream in(manifest, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  constexpr std::string_view open = "<name>", close = "</name>";
  const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; };
  for (std::size_t at = text.find(open); at != std::string::npos; at = text.find(open, at + 1)) {
    std::size_t b = at + open.size();
    while (b < text.size() && space(text[b])) ++b;
    std::size_t e = b;
    while (e < text.size() && text[e] != '<' && !space(text[e])) ++e;
    std::size_t c = e;
    while (c < text.size() && space(text[c])) ++c;
    if (e > b && text.compare(c, close.size(), close) == 0) return text.substr(b, e - b);
  }
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

// Every package folder under `root` (a package holds no other), at most `depth` levels down.
void collect_packages(const fs::path& root, int depth, std::vector<fs::path>& out) {
  std::error_code ec;
  if (!fs::is_directory(root, ec)) return;
  if (fs::exists(root / "package.xml", ec)) {
    out.push_back(root);
    return;
  }
  if (depth <= 0) return;
  std::vector<fs::path> children;
  for (const fs::directory_entry& entry : fs::directory_iterator(root, ec)) {
    if (entry.is_directory(ec) && !entry.path().filename().string().starts_with(".")) children.push_back(entry.path());
  }
  std::sort(children.begin(), children.end());  // the file system's order is no order
  for (const fs::path& child : children) collect_packages(child, depth - 1, out);
}

}  // namespace

std::vector<std::string> gazebo_ros_exports(const std::string& attribute) { return package_exports("gazebo_ros", attribute); }

std::vector<std::string> package_exports(const std::string& element, const std::string& attribute) {
  std::vector<std::string> out;
  const char* env = std::getenv("ROS_PACKAGE_PATH");
  if (env == nullptr) return out;
  std::vector<fs::path> packages;
  std::stringstream paths(env);
  std::string entry;
  while (std::getline(paths, entry, ':')) {
    if (!entry.empty()) collect_packages(entry, 6, packages);
  }
  std::set<std::string> seen;
  for (const fs::path& dir : packages) {
    std::error_code ec;
    const std::string canonical = fs::weakly_canonical(dir, ec).string();
    if (!seen.insert(canonical).second) continue;
    tinyxml2::XMLDocument doc;
    if (doc.LoadFile((dir / "package.xml").string().c_str()) != tinyxml2::XML_SUCCESS) continue;
    const tinyxml2::XMLElement* package = doc.FirstChildElement("package");
    const tinyxml2::XMLElement* exports = package != nullptr ? package->FirstChildElement("export") : nullptr;
    for (const tinyxml2::XMLElement* g = exports != nullptr ? exports->FirstChildElement(element.c_str()) : nullptr;
         g != nullptr; g = g->NextSiblingElement(element.c_str())) {
      const char* value = g->Attribute(attribute.c_str());
      if (value == nullptr) continue;
      std::string path = value;
      for (std::size_t at = path.find("${prefix}"); at != std::string::npos; at = path.find("${prefix}")) {
        path.replace(at, 9, dir.string());
      }
      out.push_back(path);
    }
  }
  return out;
}

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
