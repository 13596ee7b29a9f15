#include "controllers/drive/test/rover_drive_test_util.hpp"

#include <sstream>

namespace mechsim::control::testing {
namespace {

struct Corner {
  const char* wheel;
  const char* steering;  // "" for a fixed wheel
  double x, y;
  double side;  // +1 left, -1 right
  double axis_sign;
};

constexpr Corner kCorners[] = {
    {"wheel_joint_FL", "steering_FL", 0.5, 0.4, 1.0, 1.0},    {"wheel_joint_FR", "steering_FR", 0.5, -0.4, -1.0, -1.0},
    {"wheel_joint_ML", "", 0.0, 0.45, 1.0, -1.0},             {"wheel_joint_MR", "", 0.0, -0.45, -1.0, -1.0},
    {"wheel_joint_RL", "steering_RL", -0.5, 0.4, 1.0, 1.0},   {"wheel_joint_RR", "steering_RR", -0.5, -0.4, -1.0, -1.0},
};
constexpr const char* kSteering[] = {"steering_FL", "steering_FR", "steering_RL", "steering_RR"};

int steering_index(const char* name) {
  for (int s = 0; s < 4; ++s) {
    if (std::string(kSteering[s]) == name) return s;
  }
  return -1;
}

}  // namespace

RoverKinematics make_test_rover(double offset) {
  RoverKinematics k;
  k.wheel_radius = 0.1;
  for (const Corner& c : kCorners) {
    RoverWheel w;
    w.x = c.x;
    w.y = c.y;
    w.steering = steering_index(c.steering);
    w.offset = w.steering >= 0 ? c.side * offset : 0.0;
    w.axis_sign = c.axis_sign;
    k.wheels.push_back(w);
  }
  k.steering_axis_signs.assign(4, -1.0);
  finish_rover_kinematics(k);
  return k;
}

std::string test_rover_yaml(const std::string& extra, double offset) {
  std::ostringstream y;
  y << "rover:\n"
       "    type: mechsim/RoverDriveController\n"
       "    steering_joints: [steering_FL, steering_FR, steering_RL, steering_RR]\n"
       "    wheel_joints: [wheel_joint_FL, wheel_joint_FR, wheel_joint_ML, wheel_joint_MR, wheel_joint_RL, wheel_joint_RR]\n"
       "    wheel_radius: 0.1\n"
       "    steering_pid: {p: 50.0, d: 5.0}\n"
       "    wheel_pid: {p: 10.0}\n";
  y << "    wheel_positions:\n";
  for (const Corner& c : kCorners) {
    const double off = c.steering[0] != '\0' ? c.side * offset : 0.0;
    y << "      " << c.wheel << ": [" << c.x << ", " << c.y + off << ", 0.0]\n";
  }
  y << "    wheel_axis_signs:\n";
  for (const Corner& c : kCorners) y << "      " << c.wheel << ": " << c.axis_sign << "\n";
  y << "    wheel_steering:\n";
  for (const Corner& c : kCorners) {
    if (c.steering[0] != '\0') y << "      " << c.wheel << ": " << c.steering << "\n";
  }
  y << "    steering_positions:\n";
  for (const Corner& c : kCorners) {
    if (c.steering[0] != '\0') y << "      " << c.steering << ": [" << c.x << ", " << c.y << "]\n";
  }
  y << "    steering_axis_signs: {steering_FL: -1, steering_FR: -1, steering_RL: -1, steering_RR: -1}\n";
  std::istringstream lines(extra);
  for (std::string line; std::getline(lines, line);) y << "    " << line << "\n";
  return y.str();
}

std::unique_ptr<TestRobot> make_rover_robot() {
  std::vector<JointSpec> joints;
  for (const char* s : kSteering) {
    joints.push_back({s, description::JointType::Continuous, description::JointLimits{0.0, 0.0, 100.0, 3.0}});
  }
  for (const Corner& c : kCorners) {
    joints.push_back({c.wheel, description::JointType::Continuous, description::JointLimits{0.0, 0.0, 100.0, 20.0}});
  }
  return make_robot(joints);
}

}  // namespace mechsim::control::testing
