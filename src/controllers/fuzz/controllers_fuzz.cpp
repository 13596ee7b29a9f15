// Fuzz target: a controller YAML (as users load it with rosparam) read into parameters; every
// controller in it is loaded into a controller manager over a small robot's mechanism, started
// and ticked. An input may fail only with ParamsError (malformed YAML); a controller that does
// not load is refused by the manager with a message, and running ones must tick without
// crashing whatever their gains or limits are (NaN, Inf, huge, negative).

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "control/params.hpp"
#include "controller_fuzz_robot.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace c = mechsim::control;
  c::Params params;
  try {
    params = c::Params::from_yaml_string(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.yaml");
  } catch (const c::ParamsError&) {
    return 0;
  }
  mechsim::fuzz::run_controllers(params);
  return 0;
}
