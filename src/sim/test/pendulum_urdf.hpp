#pragma once
// The tests' small robot: a pendulum whose joint "hinge" (about y, +-3 rad, 50 N m, 10 rad/s)
// holds a 1 kg bob 0.5 m from a post 1 m above the world origin, with one simple transmission
// (actuator "m", the given reduction, effort interface), so that ticks go through actuator space.
// The bob hangs below the hinge, or starts level (swinging under gravity) with `level`.
// Used by the sim and ROS tests (include it by relative path where there is no include root).
#include <string>

namespace mechsim::test {

inline std::string pendulum_urdf(int reduction, bool level = false) {
  return std::string(R"(<robot name="pendulum">
  <link name="world"/>
  <joint name="fix" type="fixed"><parent link="world"/><child link="post"/><origin xyz="0 0 1"/></joint>
  <link name="post"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="hinge" type="revolute">
    <parent link="post"/><child link="bob"/><axis xyz="0 1 0"/>
    <limit lower="-3" upper="3" effort="50" velocity="10"/>
  </joint>
  <link name="bob"><inertial><origin xyz=")") +
         (level ? "0.5 0 0" : "0 0 -0.5") + R"("/><mass value="1"/>
    <inertia ixx="0.001" iyy="0.001" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <transmission name="t"><type>transmission_interface/SimpleTransmission</type>
    <joint name="hinge"><hardwareInterface>hardware_interface/EffortJointInterface</hardwareInterface></joint>
    <actuator name="m"><mechanicalReduction>)" +
         std::to_string(reduction) + R"(</mechanicalReduction></actuator></transmission>
</robot>)";
}

}  // namespace mechsim::test
