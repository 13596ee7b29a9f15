// Fuzz target: a URDF that parses (leniently) is planned into bodies, written as MJCF, compiled by
// MuJoCo and stepped: the path every robot takes into the physics. An input may fail only with
// DescriptionError (the URDF) or PhysicsError (the model cannot be built); a model that builds
// must step without crashing (a diverging step or a full arena is reported by the step's status).

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "description/urdf/urdf_parser.hpp"
#include "physics/physics.hpp"
#include "physics/physics_error.hpp"
#include "physics/physics_model.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace d = mechsim::description;
  namespace p = mechsim::physics;
  const std::string_view xml(reinterpret_cast<const char*>(data), size);
  d::UrdfOptions options;
  options.lenient = true;
  std::vector<std::string> warnings;
  try {
    const d::RobotModel robot = d::parse_urdf_string(xml, "fuzz.urdf", options, &warnings);
    // The arena may grow to 1000 constraints (the default allows 8000, ~0.8 GB zeroed): a
    // model whose every geom touches every other (a 1e9 m sphere) then takes its overflow path
    // within the fuzzer's second instead of a run's worth of memory.
    p::BuildOptions build;
    build.max_arena = p::ArenaSize{2000, 1000};
    p::Physics physics(p::PhysicsModel::build(robot, build));
    for (int i = 0; i < 20; ++i) (void)physics.step();
  } catch (const d::DescriptionError&) {
  } catch (const p::PhysicsError&) {
  }
  return 0;
}
