#pragma once
// The parameters ros_control's two-actuator, two-joint transmissions (Differential and
// FourBarLinkage) read from the URDF: each <joint> and <actuator> has a <role> (joint1/joint2,
// actuator1/actuator2; document order when absent), actuators a <mechanicalReduction> (1 when
// absent, as Gazebo's default ros_control plugin ignores it), joints an optional
// <mechanicalReduction> (1) and <offset> (0).

#include <array>

namespace mechsim::mechanism {

class TransmissionBuilder;

struct TwoByTwoParams {
  std::array<int, 2> joints{-1, -1};     // mechanism indices of joint1, joint2
  std::array<int, 2> actuators{-1, -1};  // of actuator1, actuator2
  std::array<double, 2> actuator_reduction{1.0, 1.0};
  std::array<double, 2> joint_reduction{1.0, 1.0};
  std::array<double, 2> joint_offset{0.0, 0.0};  // rad or m
};

TwoByTwoParams read_two_by_two(TransmissionBuilder& b);

}  // namespace mechsim::mechanism
