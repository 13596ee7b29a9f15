#include "sim/test/scenario/scenario_util.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>
#include <stdexcept>

#include "description/urdf/urdf_parser.hpp"

namespace mechsim::sim {

description::RobotModel load_shared_cc8(const std::filesystem::path& shared) {
  description::UrdfOptions options;
  options.packages["cc8_description"] = (shared / "robots/cc8_description").string();
  return description::parse_urdf_file((shared / "robots/reference/cc8.urdf").string(), options);
}

control::Params cc8_controller_params(const std::filesystem::path& shared) {
  return control::Params::from_yaml_file((shared / "robots/cc8_description/config/controller.yaml").string())
      .child("cc8");
}

physics::Integrator cc8_test_integrator() {
  const char* env = std::getenv("MECHSIM_CC8_INTEGRATOR");
  if (env == nullptr || *env == '\0') return physics::BuildOptions{}.integrator;
  const auto parsed = physics::parse_integrator(env);
  if (!parsed) {
    throw std::runtime_error(std::string("MECHSIM_CC8_INTEGRATOR: expected 'implicit', 'euler' or 'rk4', got '") + env + "'");
  }
  return *parsed;
}

std::vector<std::string> cc8_controller_names() {
  std::vector<std::string> names{"joint_state_controller"};
  for (const char* c : {"FL", "FR", "RL", "RR"}) names.push_back(std::string("steering_") + c + "_position_controller");
  for (const char* c : {"FL", "FR", "ML", "MR", "RL", "RR"}) {
    names.push_back(std::string("wheel_joint_") + c + "_position_controller");
  }
  return names;
}

description::Pose link_pose(const Simulation& sim, const std::string& link) {
  const auto index = sim.physics().model().link_index(link);
  if (!index) throw std::runtime_error("no link '" + link + "' in the physics model");
  return sim.physics().link_pose(*index);
}

int count_wheel_contacts(const Simulation& sim) {
  std::vector<physics::Contact> contacts;
  sim.physics().contacts(contacts);
  std::set<std::string> wheels;
  for (const physics::Contact& c : contacts) {
    for (std::string_view link : {c.link_a, c.link_b}) {
      if (link.starts_with("wheel_") && c.normal_force > 0.0) wheels.insert(std::string(link));
    }
  }
  return static_cast<int>(wheels.size());
}

physics::Heightmap step_terrain(double size, double cell, const std::function<double(double, double)>& f) {
  physics::Heightmap map;
  map.rows = map.cols = static_cast<std::size_t>(std::lround(size / cell)) + 1;
  map.size_x = map.size_y = size;
  map.source = "test terrain";
  map.heights.resize(map.rows * map.cols);
  for (std::size_t r = 0; r < map.rows; ++r) {
    for (std::size_t c = 0; c < map.cols; ++c) {
      const double x = -size / 2 + static_cast<double>(c) * cell;
      const double y = -size / 2 + static_cast<double>(r) * cell;
      map.heights[r * map.cols + c] = static_cast<float>(f(x, y));
    }
  }
  return map;
}

}  // namespace mechsim::sim
