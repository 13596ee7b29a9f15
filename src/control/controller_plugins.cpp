#include "control/controller_plugins.hpp"

#include <dlfcn.h>
#include <tinyxml2.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <set>
#include <sstream>

#include <mechsim/controller_api.hpp>

#include "control/plugin_controller.hpp"
#include "description/package_path.hpp"

namespace mechsim::control {

namespace fs = std::filesystem;
namespace api = controller_api;

namespace {

std::string at(const std::string& file, int line) { return file + ":" + std::to_string(line); }

struct ResolvedLibrary {
  std::string path;
  std::string missing;  // the file beside the description, when it was not there
};

// pluginlib's library path: relative to the description's folder here, the platform's suffix added.
ResolvedLibrary resolve_library(const std::string& xml_path, const std::string& path) {
  fs::path library(path);
  if (!library.has_extension()) library += ".so";
  if (library.is_absolute()) return {library.string(), ""};
  std::error_code ec;
  const fs::path beside = fs::absolute(fs::path(xml_path).parent_path() / library, ec).lexically_normal();
  if (fs::exists(beside, ec)) return {beside.string(), ""};
  return {library.filename().string(), beside.string()};  // the dynamic loader's search path
}

void read_class(const tinyxml2::XMLElement& element, const std::string& xml_path, const ResolvedLibrary& library,
                ControllerPluginSet& set) {
  const std::string where = at(xml_path, element.GetLineNum());
  const char* type = element.Attribute("type");
  if (type == nullptr || *type == '\0') {
    set.errors.push_back(where + ": <class> has no 'type' attribute (the C++ class, e.g. my_pkg::MyController)");
    return;
  }
  const char* name = element.Attribute("name");
  ControllerPluginClass c{(name != nullptr && *name != '\0') ? name : type, type, library.path, library.missing, where};
  for (const ControllerPluginClass& other : set.classes) {
    if (other.name == c.name) {
      set.errors.push_back(where + ": controller type '" + c.name + "' is declared again (first at " + other.origin +
                           "; that one is used)");
      return;
    }
  }
  set.classes.push_back(std::move(c));
}

void read_library(const tinyxml2::XMLElement& element, const std::string& xml_path, ControllerPluginSet& set) {
  const char* path = element.Attribute("path");
  if (path == nullptr || *path == '\0') {
    set.errors.push_back(at(xml_path, element.GetLineNum()) + ": <library> has no 'path' attribute (e.g. lib/libmy_controllers)");
    return;
  }
  const ResolvedLibrary library = resolve_library(xml_path, path);
  bool any = false;
  for (const tinyxml2::XMLElement* c = element.FirstChildElement("class"); c != nullptr; c = c->NextSiblingElement("class")) {
    read_class(*c, xml_path, library, set);
    any = true;
  }
  if (!any) set.errors.push_back(at(xml_path, element.GetLineNum()) + ": <library path=\"" + path + "\"> declares no <class>");
}

std::vector<std::string> split_paths(const char* text) {
  std::vector<std::string> out;
  if (text == nullptr) return out;
  std::stringstream in(text);
  std::string entry;
  while (std::getline(in, entry, ':')) {
    if (!entry.empty()) out.push_back(entry);
  }
  return out;
}

}  // namespace

void read_controller_plugin_description(const std::string& xml_path, ControllerPluginSet& set) {
  set.files.push_back(xml_path);
  tinyxml2::XMLDocument doc;
  const tinyxml2::XMLError rc = doc.LoadFile(xml_path.c_str());
  if (rc == tinyxml2::XML_ERROR_FILE_NOT_FOUND || rc == tinyxml2::XML_ERROR_FILE_COULD_NOT_BE_OPENED ||
      rc == tinyxml2::XML_ERROR_FILE_READ_ERROR) {
    set.errors.push_back(xml_path + ": cannot read the controller plugin description");
    return;
  }
  if (rc != tinyxml2::XML_SUCCESS) {
    const char* what = doc.ErrorStr();
    set.errors.push_back(at(xml_path, doc.ErrorLineNum()) + ": malformed controller plugin description: " +
                         (what != nullptr ? what : "XML error"));
    return;
  }
  const tinyxml2::XMLElement* root = doc.RootElement();
  const std::string root_name = root != nullptr ? root->Name() : "";
  if (root_name == "library") {
    read_library(*root, xml_path, set);
  } else if (root_name == "class_libraries") {
    for (const tinyxml2::XMLElement* l = root->FirstChildElement("library"); l != nullptr; l = l->NextSiblingElement("library")) {
      read_library(*l, xml_path, set);
    }
  } else {
    set.errors.push_back(at(xml_path, root != nullptr ? root->GetLineNum() : 1) + ": <" + root_name +
                         "> is not a controller plugin description (expected <library> or <class_libraries>)");
  }
}

ControllerPluginSet find_controller_plugins() {
  ControllerPluginSet set;
  std::vector<std::string> files = split_paths(std::getenv("MECHSIM_CONTROLLER_PLUGINS"));
  for (const std::string& f : description::package_exports("controller_interface", "plugin")) files.push_back(f);
  std::set<std::string> seen;
  for (const std::string& f : files) {
    std::error_code ec;
    if (!seen.insert(fs::weakly_canonical(f, ec).string()).second) continue;
    read_controller_plugin_description(f, set);
  }
  return set;
}

std::unique_ptr<Controller> create_plugin_controller(const ControllerPluginClass& plugin) {
  const std::string what = "controller type '" + plugin.name + "' (declared at " + plugin.origin + ")";
  // RTLD_NODELETE: the code stays mapped after the last controller goes, so that nothing the
  // plugin handed out (a status reason, a vtable) can outlive it.
  void* raw = dlopen(plugin.library.c_str(), RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
  if (raw == nullptr) {
    const char* why = dlerror();
    const std::string searched = plugin.missing.empty() ? "" : " (not at " + plugin.missing + ", so looked up by name)";
    throw ControllerConfigError(what + ": cannot load library " + plugin.library + searched + ": " +
                                (why != nullptr ? why : "unknown error"));
  }
  std::shared_ptr<void> library(raw, [](void* h) { dlclose(h); });
  using Entry = const api::Library* (*)();
  void* symbol = dlsym(raw, MECHSIM_CONTROLLER_LIBRARY_SYMBOL);
  if (symbol == nullptr) {
    throw ControllerConfigError(what + ": library " + plugin.library + " has no " MECHSIM_CONTROLLER_LIBRARY_SYMBOL
                                "() entry point (declare one with MECHSIM_CONTROLLER_LIBRARY, mechsim/controller_api.hpp)");
  }
  const api::Library* info = reinterpret_cast<Entry>(symbol)();
  if (info == nullptr) throw ControllerConfigError(what + ": library " + plugin.library + ": its entry point returned nothing");
  // The version is the first field of every version's Library: read before anything else.
  if (info->api_version != api::kApiVersion) {
    throw ControllerConfigError(what + ": library " + plugin.library + " was built against mechsim controller API version " +
                                std::to_string(info->api_version) + ", this mechsim has version " +
                                std::to_string(api::kApiVersion) + ": rebuild it against this mechsim's include/mechsim");
  }
  if (info->library_size != sizeof(api::Library) || (info->class_count > 0 && info->classes == nullptr)) {
    throw ControllerConfigError(what + ": library " + plugin.library + " has a malformed class list (size " +
                                std::to_string(info->library_size) + ", expected " + std::to_string(sizeof(api::Library)) + ")");
  }
  std::string listed;
  for (std::size_t i = 0; i < info->class_count; ++i) {
    const api::ControllerClass& c = info->classes[i];
    if (c.type == nullptr) continue;
    if (std::strcmp(c.type, plugin.type.c_str()) != 0) {
      listed += (listed.empty() ? "" : ", ") + std::string(c.type);
      continue;
    }
    std::unique_ptr<api::Controller> object(c.create != nullptr ? c.create() : nullptr);
    if (!object) throw ControllerConfigError(what + ": library " + plugin.library + " made no '" + plugin.type + "'");
    return std::make_unique<PluginController>(std::move(library), std::move(object));
  }
  throw ControllerConfigError(what + ": library " + plugin.library + " has no class '" + plugin.type + "' (it has: " +
                              (listed.empty() ? std::string("none") : listed) + ")");
}

void register_controller_plugins(ControllerRegistry& registry, const ControllerPluginSet& set) {
  for (const std::string& error : set.errors) registry.add_note("controller plugins: " + error);
  for (const ControllerPluginClass& c : set.classes) {
    if (registry.has(c.name)) {
      registry.add_note("controller plugins: " + c.origin + ": '" + c.name + "' is a built-in type; the plugin's is not used");
      continue;
    }
    registry.add(c.name, [c] { return create_plugin_controller(c); });
  }
}

}  // namespace mechsim::control
