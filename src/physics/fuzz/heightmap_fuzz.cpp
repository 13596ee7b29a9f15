// Fuzz target: the height-map readers (PNG through libpng, TIFF through libtiff) and the checks
// after them. The first byte picks the format (even: PNG, odd: TIFF) so that mutations keep the
// rest a plausible file. An input may fail only with HeightmapError.

#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_files.hpp"
#include "physics/heightmap_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace p = mechsim::physics;
  if (size < 1) return 0;
  const std::string name = data[0] % 2 == 0 ? "map.png" : "map.tif";
  auto& dir = mechsim::fuzz::scratch();
  dir.write({{name, std::string(reinterpret_cast<const char*>(data + 1), size - 1)}});
  try {
    (void)p::load_heightmap(dir.path() / name);
  } catch (const p::HeightmapError&) {
  }
  return 0;
}
