// Test library: an entry point that says it was built against controller API version 999, as a
// plugin built against another mechsim would. mechsim must refuse it by the version alone.
#include <mechsim/controller_api.hpp>

extern "C" __attribute__((visibility("default"))) const mechsim::controller_api::Library* mechsim_controller_library() {
  static const mechsim::controller_api::Library library{999, 0, nullptr, 0};
  return &library;
}
