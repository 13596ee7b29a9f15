// parse_sdf_model and load_sdf_world through libmechsim_sdformat.so, loaded at the first call
// (sdf_module.hpp says why).
#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "description/sdf/sdf_model.hpp"
#include "description/sdf/sdf_module.hpp"

namespace mechsim::description {
namespace {

namespace fs = std::filesystem;
using sdf_detail::SdfModuleApi;

// The folder of the running program (symbolic links followed, as ros_package/ links to bin/).
fs::path program_dir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : exe.parent_path();
}

// Where the build puts the module: <build>/lib beside <build>/bin (the programs, tests and
// benchmarks), then beside the program itself; MECHSIM_SDFORMAT_MODULE names another file.
std::vector<std::string> module_candidates() {
  if (const char* env = std::getenv("MECHSIM_SDFORMAT_MODULE"); env != nullptr && *env != '\0') return {env};
  const fs::path dir = program_dir();
  if (dir.empty()) return {};
  return {(dir.parent_path() / "lib" / sdf_detail::kSdfModuleFile).string(), (dir / sdf_detail::kSdfModuleFile).string()};
}

// Loaded once per process, on first use; the module is immutable code.
const SdfModuleApi& module() {
  static const sdf_detail::SdfModuleLoad loaded = sdf_detail::load_sdf_module(module_candidates());
  if (loaded.api == nullptr) throw SdfError(loaded.error);
  return *loaded.api;
}

}  // namespace

sdf_detail::SdfModuleLoad sdf_detail::load_sdf_module(const std::vector<std::string>& files) {
  std::string tried;
  const auto passed_over = [&](const std::string& file, const std::string& why) {
    tried += (tried.empty() ? "" : ", ") + file + " (" + why + ")";
  };
  for (const std::string& file : files) {
    std::error_code ec;
    if (!fs::exists(file, ec)) {
      passed_over(file, "absent");
      continue;
    }
    void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
      const char* why = dlerror();
      passed_over(file, why != nullptr ? why : "dlopen failed");
      continue;
    }
    // A module found stays loaded for the process's life: libsdformat is not made to be unloaded.
    auto entry = reinterpret_cast<SdfModuleEntry>(dlsym(handle, kSdfModuleEntry));
    const SdfModuleApi* api = entry != nullptr ? entry() : nullptr;
    if (api == nullptr || api->version != kSdfModuleVersion || !api->parse_model || !api->load_world) {
      dlclose(handle);
      passed_over(file, "not this build's SDF module");
      continue;
    }
    return {api, {}};
  }
  return {nullptr, std::string("SDF support is unavailable: cannot load ") + kSdfModuleFile + " (" +
                       (tried.empty() ? "the program's folder is unknown" : tried) +
                       "); it is built with mechsim (target mechsim_sdformat)"};
}

bool is_sdf_world_file(const std::string& path) {
  const std::string ext = fs::path(path).extension().string();
  return ext == ".world" || ext == ".sdf";
}

SdfModel parse_sdf_model(const std::string& xml, const std::string& source, const SdfOptions& options) {
  SdfModel out;
  if (std::string error = module().parse_model(xml, source, options, out); !error.empty()) throw SdfError(error);
  return out;
}

SdfWorld load_sdf_world(const std::string& path, const SdfOptions& options) {
  SdfWorld out;
  if (std::string error = module().load_world(path, options, out); !error.empty()) throw SdfError(error);
  return out;
}

}  // namespace mechsim::description
