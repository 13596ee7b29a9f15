// Fuzz target: xacro expansion of a set of files (fuzz_files.hpp: the first is main.xacro; more
// files, reached by <xacro:include>, follow "=== NAME" lines). An input may fail only with
// XacroError (xacro's own errors and malformed XML), never crash, hang or exhaust memory.

#include <cstddef>
#include <cstdint>
#include <sstream>

#include "description/xacro/xacro.hpp"
#include "fuzz_files.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace d = mechsim::description;
  auto& dir = mechsim::fuzz::scratch();
  dir.write(mechsim::fuzz::split_files(data, size, "main.xacro"));
  std::ostringstream diagnostics;
  d::XacroOptions options;
  options.diagnostics = &diagnostics;
  options.args = {{"fuzz_arg", "1"}};
  try {
    (void)d::expand_xacro_file((dir.path() / "main.xacro").string(), options);
  } catch (const d::XacroError&) {
  }
  return 0;
}
