#include "sim/test/scenario/pr2_util.hpp"

#include <cstdlib>
#include <stdexcept>

#include "control/params.hpp"
#include "description/urdf/urdf_parser.hpp"

namespace mechsim::sim {

namespace fs = std::filesystem;

physics::Integrator pr2_test_integrator() {
  const char* env = std::getenv("MECHSIM_PR2_INTEGRATOR");
  if (env == nullptr || *env == '\0') return kPr2DefaultIntegrator;
  const auto parsed = physics::parse_integrator(env);
  if (!parsed) {
    throw std::runtime_error(std::string("MECHSIM_PR2_INTEGRATOR: expected 'implicit', 'euler' or 'rk4', got '") + env + "'");
  }
  return *parsed;
}

bool pr2_shared_data_present() { return fs::exists(fs::path(MECHSIM_SHARED_DIR) / "robots/reference/pr2.urdf"); }

std::unique_ptr<Simulation> make_pr2_simulation(const std::vector<std::string>& start, const World* world) {
  const fs::path shared = MECHSIM_SHARED_DIR;
  description::UrdfOptions urdf_options;
  urdf_options.lenient = true;  // two sensor mounts break the inertia triangle inequality
  urdf_options.packages["pr2_description"] = (shared / "robots/pr2_description").string();
  description::RobotModel pr2 = description::parse_urdf_file((shared / "robots/reference/pr2.urdf").string(), urdf_options);
  const control::Params root =
      control::Params::from_yaml_file((fs::path(MECHSIM_SOURCE_DIR) / "robots/pr2/config/controllers.yaml").string());
  SimulationOptions options;
  options.spawn.z = 0.01;
  options.integrator = pr2_test_integrator();
  const World empty = make_world({});
  auto sim = std::make_unique<Simulation>(std::move(pr2), world != nullptr ? *world : empty, root.child("pr2"), options);
  sim->load_and_start(start);
  return sim;
}

std::size_t pr2_physics_joint(const Simulation& sim, const std::string& joint) {
  const auto j = sim.physics().model().joint_index(joint);
  if (!j) throw std::runtime_error("the PR2 physics has no joint '" + joint + "'");
  return *j;
}

}  // namespace mechsim::sim
