// The wheel-soil model inside the physics step (Physics::set_soil) on a single-wheel test rig, as
// terramechanics laboratories run one: a wheel (the CC8's: r 9 cm, b 12 cm) on a carriage that
// is free to sink and is towed at a set speed while the wheel spins at a set rate, so the slip
// is set; the carriage's tow force is the wheel's drawbar pull. Measured against the steady
// Wong-Reece solution (terramechanics.hpp, steady_wheel) for the same load and slip: the step's
// shear states must settle on it. A wheel held still under a side pull holds like a spring.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "physics/physics.hpp"
#include "physics/terramechanics.hpp"
#include "physics/test/physics_test_util.hpp"

namespace mechsim::physics {
namespace {

// world -> "tow" (prismatic x) -> "lift" (prismatic z) -> "spin" (continuous about y) -> wheel.
// `carriage_kg` loads the wheel. The wheel's spin inertia is large (0.05 kg m^2) so that its
// velocity servo can be stiff.
std::string rig_urdf(double carriage_kg) {
  char text[3000];
  std::snprintf(text, sizeof text, R"(<robot name="rig">
  <link name="world"/>
  <link name="sled"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="carriage"><inertial><mass value="%g"/><inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="wheel"><inertial><mass value="1"/><inertia ixx="0.03" iyy="0.05" izz="0.03" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin rpy="1.5707963267948966 0 0"/><geometry><cylinder radius="0.09" length="0.12"/></geometry></collision></link>
  <joint name="tow" type="prismatic"><parent link="world"/><child link="sled"/><axis xyz="1 0 0"/>
    <limit lower="-100" upper="100" effort="2000" velocity="10"/></joint>
  <joint name="lift" type="prismatic"><parent link="sled"/><child link="carriage"/><origin xyz="0 0 0.09"/><axis xyz="0 0 1"/>
    <limit lower="-0.2" upper="0.2" effort="0" velocity="10"/></joint>
  <joint name="spin" type="continuous"><parent link="carriage"/><child link="wheel"/><axis xyz="0 1 0"/>
    <limit effort="200" velocity="100"/></joint>
</robot>)", carriage_kg);
  return text;
}

struct RigRun {
  double slip = 0.0, sinkage = 0.0, load = 0.0, drawbar = 0.0;
};

// Tows the rig at (1 - slip) r w with the wheel at w = 3.33 rad/s (r w = 0.3 m/s), and averages
// the last second of 4.
RigRun run_rig(const SoilParameters& soil, double carriage_kg, double slip) {
  const auto model = test::build(rig_urdf(carriage_kg));
  Physics physics(model);
  physics.set_soil(soil);
  const std::size_t tow = *model->joint_index("tow"), spin = *model->joint_index("spin");
  const double w = 0.3 / 0.09;
  physics.set_mode(spin, JointMode::Velocity, {0.0, 40.0});
  physics.set_mode(tow, JointMode::Velocity, {0.0, 4000.0});
  RigRun out;
  int samples = 0;
  for (int k = 0; k < 4000; ++k) {
    const double ramp = std::min(1.0, k / 500.0);  // half a second to speed
    physics.set_velocity_command(spin, ramp * w);
    physics.set_velocity_command(tow, ramp * (1.0 - slip) * 0.09 * w);
    EXPECT_TRUE(physics.step().ok());
    if (k < 3000) continue;
    const WheelSoilReading& r = physics.wheel_soil().at(0);
    out.slip += r.slip;
    out.sinkage += r.sinkage;
    out.load += r.normal_force;
    out.drawbar += -physics.actuator_effort(tow);  // the tow holds back what the wheel pulls
    ++samples;
  }
  out.slip /= samples;
  out.sinkage /= samples;
  out.load /= samples;
  out.drawbar /= samples;
  return out;
}

// Drawbar pull and sinkage against slip 0.1-0.6 for a rigid wheel on Wong's dry sand (Table 2.3,
// Land Locomotion Laboratory) and on Bekker's lunar regolith, 10 and 20 kg on the wheel: within
// 15 % of the steady Wong-Reece solution (drawbar: 15 % or 1 % of the load, for the pull crosses
// zero). This checks the dynamic implementation against the published model (Wong and Reece
// 1967); it is not a comparison with a measured figure (see physics/README.md).
TEST(WheelSoil, ASingleWheelRigSettlesOnTheWongReeceSolution) {
  for (const char* name : {"dry_sand", "lunar_regolith"}) {
    const SoilParameters soil = *find_soil(name);
    for (const double carriage : {9.0, 19.0}) {
      for (const double slip : {0.1, 0.2, 0.4, 0.6}) {
        const RigRun rig = run_rig(soil, carriage, slip);
        const SteadyWheel model = steady_wheel(soil, {0.09, 0.12}, rig.load, rig.slip);
        std::printf("[ figures  ] %s load %.1f N slip %.3f: drawbar %.2f N (model %.2f), sinkage %.2f mm (model %.2f)\n", name,
                    rig.load, rig.slip, rig.drawbar, model.forces.drawbar, 1000 * rig.sinkage, 1000 * model.sinkage);
        EXPECT_NEAR(rig.slip, slip, 0.05) << name << ": the rig's servos set the slip";
        EXPECT_NEAR(rig.load, 9.81 * (carriage + 1.0), 0.02 * 9.81 * (carriage + 1.0)) << "the soil carries the carriage";
        EXPECT_NEAR(rig.sinkage, model.sinkage, 0.15 * model.sinkage) << name << " slip " << slip;
        EXPECT_NEAR(rig.drawbar, model.forces.drawbar, 0.15 * std::abs(model.forces.drawbar) + 0.01 * rig.load)
            << name << " slip " << slip;
      }
    }
  }
}

// A braked wheel (a position servo holds its angle), its carriage pulled along x by 30 % of the
// load: the soil's shear takes it within millimetres (Janosi-Hanamoto's curve) and the wheel does
// not creep.
TEST(WheelSoil, AHeldWheelHoldsAPullWithoutCreeping) {
  const auto model = test::build(rig_urdf(9.0));
  Physics physics(model);
  physics.set_soil(*find_soil("dry_sand"));
  const std::size_t tow = *model->joint_index("tow"), spin = *model->joint_index("spin");
  physics.set_mode(spin, JointMode::Position, {500.0, 5.0});  // a brake: holds the angle
  physics.set_position_command(spin, 0.0);
  double at_1s = 0.0;
  for (int k = 0; k < 11000; ++k) {
    physics.set_effort(tow, k < 1000 ? 0.0 : 0.3 * 9.81 * 10.0);
    ASSERT_TRUE(physics.step().ok());
    if (k == 1999) at_1s = physics.position(tow);
  }
  const double end = physics.position(tow);
  std::printf("[ figures  ] held wheel, 29 N pull: %.2f mm after 1 s, %.3f mm more in the next 9 s\n", 1000 * at_1s,
              1000 * (end - at_1s));
  EXPECT_GT(at_1s, 0.0);
  EXPECT_LT(at_1s, 0.01);
  EXPECT_LT(std::abs(end - at_1s), 0.001);
}

TEST(WheelSoil, TheModelsWheelsAreItsTurningCylindersAndBadSoilIsRefused) {
  const auto model = test::build(rig_urdf(9.0));
  ASSERT_EQ(model->wheels().size(), 1u);
  EXPECT_EQ(model->wheels()[0].link, "wheel");
  EXPECT_DOUBLE_EQ(model->wheels()[0].radius, 0.09);
  EXPECT_DOUBLE_EQ(model->wheels()[0].width, 0.12);
  Physics physics(model);
  EXPECT_TRUE(physics.wheel_soil().empty()) << "rigid ground by default";
  SoilParameters bad = *find_soil("dry_sand");
  bad.shear_modulus = -1.0;
  try {
    physics.set_soil(bad);
    FAIL() << "accepted a negative shear modulus";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("shear modulus"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(physics.soil());
}

}  // namespace
}  // namespace mechsim::physics
