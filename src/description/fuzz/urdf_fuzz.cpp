// Fuzz target: URDF parsing and validation (structure, physics, references, transmissions,
// Gazebo tags and sensors), strict and lenient. An input may fail only with DescriptionError.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "description/urdf/urdf_parser.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace d = mechsim::description;
  const std::string_view xml(reinterpret_cast<const char*>(data), size);
  for (bool lenient : {false, true}) {
    d::UrdfOptions options;
    options.lenient = lenient;
    std::vector<std::string> warnings;
    try {
      (void)d::parse_urdf_string(xml, "fuzz.urdf", options, &warnings);
    } catch (const d::DescriptionError&) {
    }
  }
  return 0;
}
