#include "controllers/drive/test/pr2_base_test_util.hpp"

#include <vector>

namespace mechsim::control::testing {
namespace {

struct Corner {
  const char* prefix;
  double x, y;
};
constexpr Corner kCorners[] = {{"fl", kPr2CasterXY, kPr2CasterXY},
                               {"fr", kPr2CasterXY, -kPr2CasterXY},
                               {"bl", -kPr2CasterXY, kPr2CasterXY},
                               {"br", -kPr2CasterXY, -kPr2CasterXY}};

std::string caster(const Corner& c) { return std::string(c.prefix) + "_caster_rotation_joint"; }
std::string wheel(const Corner& c, const char* side) { return std::string(c.prefix) + "_caster_" + side + "_wheel_joint"; }

}  // namespace

Pr2BaseKinematics make_pr2_base() {
  Pr2BaseKinematics k;
  k.wheel_radius = kPr2WheelRadius;
  for (std::size_t i = 0; i < 4; ++i) {
    k.casters.push_back({kCorners[i].x, kCorners[i].y, 1.0});
    k.wheels.push_back({i, kPr2WheelOffset, 1.0});
    k.wheels.push_back({i, -kPr2WheelOffset, 1.0});
  }
  return k;
}

std::string pr2_base_geometry_yaml(int indent) {
  const std::string pad(static_cast<std::size_t>(indent), ' ');
  std::string casters, wheels, positions, wheel_casters, offsets;
  for (const Corner& c : kCorners) {
    casters += (casters.empty() ? "" : ", ") + caster(c);
    positions += pad + "  " + caster(c) + ": [" + std::to_string(c.x) + ", " + std::to_string(c.y) + "]\n";
    for (const char* side : {"l", "r"}) {
      wheels += (wheels.empty() ? "" : ", ") + wheel(c, side);
      wheel_casters += pad + "  " + wheel(c, side) + ": " + caster(c) + "\n";
      offsets += pad + "  " + wheel(c, side) + ": " + (side[0] == 'l' ? "0.049" : "-0.049") + "\n";
    }
  }
  return pad + "caster_joints: [" + casters + "]\n" + pad + "wheel_joints: [" + wheels + "]\n" + pad +
         "wheel_radius: 0.074792\n" + pad + "caster_positions:\n" + positions + pad + "wheel_casters:\n" +
         wheel_casters + pad + "wheel_offsets:\n" + offsets;
}

std::string pr2_base_yaml(const std::string& extra) {
  return "base:\n  base_controller:\n    type: pr2_mechanism_controllers/Pr2BaseController2\n" +
         pr2_base_geometry_yaml(4) +
         "    caster_pid: {p: 20.0, d: 1.0}\n    wheel_pid: {p: 2.0}\n" + extra +
         "  odometry:\n    type: pr2_mechanism_controllers/Pr2Odometry\n" + pr2_base_geometry_yaml(4);
}

std::unique_ptr<TestRobot> make_pr2_base_robot() {
  std::vector<JointSpec> joints;
  for (const Corner& c : kCorners) {
    joints.push_back({caster(c), description::JointType::Continuous, description::JointLimits{0.0, 0.0, 100.0, 10.0}});
    for (const char* side : {"l", "r"}) {
      joints.push_back({wheel(c, side), description::JointType::Continuous, description::JointLimits{0.0, 0.0, 100.0, 15.0}});
    }
  }
  return make_robot(joints);
}

}  // namespace mechsim::control::testing
