#pragma once
// A 1 kg pendulum hanging from a fixed hinge whose range is -1..0 rad: it rests at its upper
// limit, so a positive tuning step would leave its range. Shared by the tuning tests of the sim
// layer and the `mechsim tune` CLI tests.

namespace mechsim::sim::test {

inline constexpr const char* kTuningPendulumUrdf = R"(<robot name="pendulum">
  <link name="world"/>
  <link name="arm"><inertial><origin xyz="0 0 -0.5"/><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="hinge" type="revolute"><parent link="world"/><child link="arm"/><origin xyz="0 0 1"/><axis xyz="0 1 0"/>
    <limit lower="-1" upper="0" effort="20" velocity="5"/></joint>
  <transmission name="t"><type>transmission_interface/SimpleTransmission</type>
    <joint name="hinge"><hardwareInterface>hardware_interface/EffortJointInterface</hardwareInterface></joint>
    <actuator name="m"><mechanicalReduction>1</mechanicalReduction></actuator></transmission>
</robot>)";

}  // namespace mechsim::sim::test
