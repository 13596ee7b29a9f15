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
#include <utility>
#include <vector>

#include "physics/physics.hpp"
#include "physics/terramechanics.hpp"
#include "physics/test/physics_test_util.hpp"

namespace mechsim::physics {
namespace {

// world -> "tow" (prismatic x) -> "lift" (prismatic z) -> "spin" (continuous about y) -> wheel.
// `carriage_kg` loads the wheel. The wheel's spin inertia is large (0.05 kg m^2) so that its
// velocity servo can be stiff.
std::string rig_urdf(double carriage_kg, double radius = 0.09, double width = 0.12) {
  char text[3000];
  std::snprintf(text, sizeof text, R"(<robot name="rig">
  <link name="world"/>
  <link name="sled"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="carriage"><inertial><mass value="%g"/><inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="wheel"><inertial><mass value="1"/><inertia ixx="0.03" iyy="0.05" izz="0.03" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin rpy="1.5707963267948966 0 0"/><geometry><cylinder radius="%g" length="%g"/></geometry></collision></link>
  <joint name="tow" type="prismatic"><parent link="world"/><child link="sled"/><axis xyz="1 0 0"/>
    <limit lower="-100" upper="100" effort="2000" velocity="10"/></joint>
  <joint name="lift" type="prismatic"><parent link="sled"/><child link="carriage"/><origin xyz="0 0 %g"/><axis xyz="0 0 1"/>
    <limit lower="-0.2" upper="0.2" effort="0" velocity="10"/></joint>
  <joint name="spin" type="continuous"><parent link="carriage"/><child link="wheel"/><axis xyz="0 1 0"/>
    <limit effort="200" velocity="100"/></joint>
</robot>)", carriage_kg, radius, width, radius);
  return text;
}

struct RigRun {
  double slip = 0.0, sinkage = 0.0, load = 0.0, drawbar = 0.0;
  double kinematic_slip = 0.0;  // 1 - v / (r w) from the joints' velocities
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

// Two single-wheel rigs in tandem on one track: the rear one starts 0.6 m behind the front one,
// both towed at the same speed, 10 kg on each wheel, so after 2.5 s the rear wheel runs in the
// front wheel's rut. Wheels "a" (front) and "b" (rear).
std::string tandem_urdf() {
  std::string out = "<robot name=\"tandem\"><link name=\"world\"/>";
  for (const auto& [w, x] : {std::pair<std::string, std::string>{"a", "0"}, {"b", "-0.6"}}) {
    std::string rig = R"(
  <link name="sled_W"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="carriage_W"><inertial><mass value="9"/><inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="wheel_W"><inertial><mass value="1"/><inertia ixx="0.03" iyy="0.05" izz="0.03" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin rpy="1.5707963267948966 0 0"/><geometry><cylinder radius="0.09" length="0.12"/></geometry></collision></link>
  <joint name="tow_W" type="prismatic"><parent link="world"/><child link="sled_W"/><origin xyz="X 0 0"/><axis xyz="1 0 0"/>
    <limit lower="-100" upper="100" effort="2000" velocity="10"/></joint>
  <joint name="lift_W" type="prismatic"><parent link="sled_W"/><child link="carriage_W"/><origin xyz="0 0 0.09"/><axis xyz="0 0 1"/>
    <limit lower="-0.2" upper="0.2" effort="0" velocity="10"/></joint>
  <joint name="spin_W" type="continuous"><parent link="carriage_W"/><child link="wheel_W"/><axis xyz="0 1 0"/>
    <limit effort="200" velocity="100"/></joint>)";
    for (std::size_t at = rig.find("_W"); at != std::string::npos; at = rig.find("_W", at)) rig.replace(at + 1, 1, w);
    rig.replace(rig.find("xyz=\"X"), 6, "xyz=\"" + x);
    out += rig;
  }
  return out + "</robot>";
}

struct TandemRun {
  RigRun front, rear;
  double rear_rut = 0.0;  // m, the rut depth the rear wheel met (its reading)
};

// Both rigs at slip 0.2 (r w = 0.3 m/s), 6 s; averages over the last 1.5 s.
TandemRun run_tandem(const SoilParameters& soil) {
  const auto model = test::build(tandem_urdf());
  Physics physics(model);
  physics.set_soil(soil);
  EXPECT_EQ(model->wheels().size(), 2u);
  const double w = 0.3 / 0.09, slip = 0.2;
  TandemRun out;
  int samples = 0;
  for (int k = 0; k < 6000; ++k) {
    const double ramp = std::min(1.0, k / 500.0);
    for (const char* name : {"a", "b"}) {
      const std::size_t tow = *model->joint_index(std::string("tow_") + name), spin = *model->joint_index(std::string("spin_") + name);
      if (k == 0) {
        physics.set_mode(spin, JointMode::Velocity, {0.0, 40.0});
        physics.set_mode(tow, JointMode::Velocity, {0.0, 4000.0});
      }
      physics.set_velocity_command(spin, ramp * w);
      physics.set_velocity_command(tow, ramp * (1.0 - slip) * 0.09 * w);
    }
    EXPECT_TRUE(physics.step().ok());
    if (k < 4500) continue;
    for (std::size_t i = 0; i < 2; ++i) {
      const std::string name = model->wheels()[i].link == "wheel_a" ? "a" : "b";
      RigRun& run = name == "a" ? out.front : out.rear;
      const WheelSoilReading& r = physics.wheel_soil().at(i);
      run.slip += r.slip;
      run.sinkage += r.sinkage;
      run.load += r.normal_force;
      run.drawbar += -physics.actuator_effort(*model->joint_index("tow_" + name));
      if (name == "b") out.rear_rut += r.rut_depth;
    }
    ++samples;
  }
  for (RigRun* run : {&out.front, &out.rear}) {
    run->slip /= samples;
    run->sinkage /= samples;
    run->load /= samples;
    run->drawbar /= samples;
  }
  out.rear_rut /= samples;
  return out;
}

// Multi-pass on the rig (SoilParameters::multi_pass): the rear wheel meets the front wheel's rut
// (the front's sinkage), sinks further in all, and its sinkage and drawbar pull are within 15 % of
// the steady model for its load, slip and rut (terramechanics.hpp); with multi_pass off (the
// default) both wheels meet virgin soil and run alike.
TEST(WheelSoil, ARearWheelRunsInTheFrontWheelsRutAsTheSteadyModelHasIt) {
  for (const char* name : {"dry_sand", "lete_sand"}) {
    SoilParameters soil = *find_soil(name);
    EXPECT_FALSE(soil.multi_pass) << "opt-in";
    soil.multi_pass = true;
    const TandemRun run = run_tandem(soil);
    const SteadyWheel front = steady_wheel(soil, {0.09, 0.12}, run.front.load, run.front.slip);
    const SteadyWheel rear = steady_wheel(soil, {0.09, 0.12}, run.rear.load, run.rear.slip, run.rear_rut);
    std::printf("[ figures  ] %s tandem, slip %.3f/%.3f: front sinkage %.2f mm (model %.2f), drawbar %.2f N (model %.2f); "
                "rear in a %.2f mm rut: sinkage %.2f mm (model %.2f), drawbar %.2f N (model %.2f)\n",
                name, run.front.slip, run.rear.slip, 1000 * run.front.sinkage, 1000 * front.sinkage, run.front.drawbar,
                front.forces.drawbar, 1000 * run.rear_rut, 1000 * run.rear.sinkage, 1000 * rear.sinkage, run.rear.drawbar,
                rear.forces.drawbar);
    EXPECT_NEAR(run.rear_rut, run.front.sinkage, 0.1 * run.front.sinkage) << name << ": the rut is the front wheel's sinkage";
    EXPECT_GT(run.rear.sinkage, run.front.sinkage) << name;
    EXPECT_LT(run.rear.sinkage, 1.4 * run.front.sinkage) << name;
    EXPECT_NEAR(run.rear.sinkage, rear.sinkage, 0.15 * rear.sinkage) << name;
    EXPECT_NEAR(run.rear.drawbar, rear.forces.drawbar, 0.15 * std::abs(rear.forces.drawbar) + 0.01 * run.rear.load) << name;
    EXPECT_NEAR(run.front.sinkage, front.sinkage, 0.15 * front.sinkage) << name;

    const TandemRun off = run_tandem(*find_soil(name));
    EXPECT_EQ(off.rear_rut, 0.0);
    EXPECT_NEAR(off.rear.sinkage, off.front.sinkage, 0.03 * off.front.sinkage) << name;
    EXPECT_NEAR(off.rear.drawbar, off.front.drawbar, 0.03 * std::abs(off.front.drawbar) + 0.005 * off.front.load) << name;
  }
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

// The CMU sand's plate fit (two_stage, large box) under the Ding model with dry sand's shear
// values: robots/single_wheel_rig/soil/cmu_sand.soil.yaml.
SoilParameters cmu_sand() {
  SoilParameters s = *find_soil("dry_sand");
  s.name = "cmu_sand";
  s.n = 1.4765;
  s.k_c = -4.0648e5;
  s.k_phi = 1.973e7;
  s.model = WheelSoilModel::Ding;
  return s;
}

// A rig at a test rig's speed: towed at 10 mm/s, the wheel turning for slip `slip`; the means
// of the last `average` s of `seconds`.
RigRun run_slow_rig(const SoilParameters& soil, double radius, double width, double carriage_kg, double slip, double seconds,
                    double average, std::vector<WheelOverride> overrides = {}) {
  const auto model = test::build(rig_urdf(carriage_kg, radius, width));
  Physics physics(model);
  physics.set_soil(soil, std::move(overrides));
  const std::size_t tow = *model->joint_index("tow"), spin = *model->joint_index("spin");
  physics.set_mode(spin, JointMode::Velocity, {0.0, 0.0, true});  // a motor: holds its speed under load
  physics.set_mode(tow, JointMode::Velocity, {0.0, 0.0, true});
  const double v = 0.01;
  RigRun out;
  int samples = 0;
  const int steps = static_cast<int>(seconds * 1000), from = static_cast<int>((seconds - average) * 1000);
  for (int k = 0; k < steps; ++k) {
    physics.set_velocity_command(spin, v / (radius * (1.0 - slip)));
    physics.set_velocity_command(tow, v);
    EXPECT_TRUE(physics.step().ok());
    if (k < from) continue;
    const WheelSoilReading& r = physics.wheel_soil().at(0);
    EXPECT_TRUE(r.moving) << "a wheel at 10 mm/s moves: its slip is defined";
    out.slip += r.slip;
    out.sinkage += r.sinkage;
    out.load += r.normal_force;
    out.drawbar += r.traction;
    out.kinematic_slip += 1.0 - physics.velocity(tow) / (radius * physics.velocity(spin));
    ++samples;
  }
  out.slip /= samples;
  out.sinkage /= samples;
  out.load /= samples;
  out.drawbar /= samples;
  out.kinematic_slip /= samples;
  return out;
}

// A narrow wheel (b <= r: the CMU rig's, r 58 mm, b 50 mm; an ellipsoid to MuJoCo on rigid
// ground) is a soil wheel as a wide one (b 100 mm) is; at a test rig's 10 mm/s each reads the
// slip it is set to (not 0) and settles on the steady model for its own width: they differ by
// what the width explains.
TEST(WheelSoil, NarrowAndWideWheelsAreSoilWheelsAndDifferByTheirWidthAtRigSpeed) {
  for (const double width : {0.05, 0.10}) {
    const auto model = test::build(rig_urdf(2.0, 0.058, width));
    ASSERT_EQ(model->wheels().size(), 1u) << "width " << width;
    EXPECT_EQ(model->wheels()[0].narrow, width <= 0.058);
    EXPECT_DOUBLE_EQ(model->wheels()[0].radius, 0.058);
    EXPECT_DOUBLE_EQ(model->wheels()[0].width, width);
    for (const double slip : {0.0, 0.3}) {
      const RigRun rig = run_slow_rig(cmu_sand(), 0.058, width, 2.0, slip, 20.0, 4.0);
      const SteadyWheel steady = steady_wheel(cmu_sand(), {0.058, width}, rig.load, rig.slip);
      std::printf("[ figures  ] b %.2f m slip %.2f at 10 mm/s: read slip %.4f, load %.2f N, sinkage %.2f mm (model %.2f), DP %.3f N "
                  "(model %.3f)\n", width, slip, rig.slip, rig.load, 1000 * rig.sinkage, 1000 * steady.sinkage, rig.drawbar,
                  steady.forces.drawbar);
      EXPECT_NEAR(rig.slip, rig.kinematic_slip, 0.002) << "width " << width << ": the reading is the joints' slip";
      EXPECT_NEAR(rig.slip, slip, 0.02) << "width " << width << ": the servos hold it near the set slip";
      EXPECT_NEAR(rig.load, 9.81 * 3.0, 0.02 * 9.81 * 3.0);
      EXPECT_NEAR(rig.sinkage, steady.sinkage, 0.1 * steady.sinkage) << "width " << width << " slip " << slip;
      EXPECT_NEAR(rig.drawbar, steady.forces.drawbar, 0.15 * std::abs(steady.forces.drawbar) + 0.01 * rig.load)
          << "width " << width << " slip " << slip;
    }
  }
}

WheelOverride override_of(const std::string& link, bool wheel = true) {
  WheelOverride o;
  o.link = link;
  o.wheel = wheel;
  return o;
}

// The world's word on wheels (WheelOverride): a wheel taken out meets rigid ground and is named;
// a link the model does not count as a wheel (a sphere on the spin joint) becomes one with the
// dimensions given; grousers reach the soil; an unknown link, or a non-cylinder without
// dimensions, is refused with its name.
TEST(WheelSoil, TheWorldSaysWhichLinksAreWheels) {
  const auto model = test::build(rig_urdf(9.0));
  {
    Physics physics(model);
    physics.set_soil(*find_soil("dry_sand"), {override_of("wheel", false)});
    EXPECT_TRUE(physics.soil_wheels().empty());
    ASSERT_EQ(physics.soil_wheel_notes().size(), 1u);
    EXPECT_NE(physics.soil_wheel_notes()[0].find("'wheel' is not a soil wheel"), std::string::npos);
  }
  {
    Physics physics(model);
    WheelOverride lugs = override_of("wheel");
    lugs.grouser_height = 0.01;
    lugs.grouser_count = 12;
    physics.set_soil(*find_soil("dry_sand"), {lugs});
    ASSERT_EQ(physics.soil_wheels().size(), 1u);
    EXPECT_EQ(physics.soil_wheels()[0].shape.grouser_count, 12);
    EXPECT_DOUBLE_EQ(physics.soil_wheels()[0].shape.grouser_height, 0.01);
  }
  std::string sphere = rig_urdf(9.0);
  sphere.replace(sphere.find("<cylinder radius=\"0.09\" length=\"0.12\"/>"), std::string("<cylinder radius=\"0.09\" length=\"0.12\"/>").size(),
                 "<sphere radius=\"0.09\"/>");
  const auto ball = test::build(sphere);
  EXPECT_TRUE(ball->wheels().empty());
  ASSERT_EQ(ball->not_wheels().size(), 1u);
  EXPECT_NE(ball->not_wheels()[0].find("'wheel' on joint 'spin' is not a wheel: its collision is a sphere"), std::string::npos)
      << ball->not_wheels()[0];
  Physics physics(ball);
  try {
    physics.set_soil(*find_soil("dry_sand"), {override_of("wheel")});
    FAIL() << "a sphere without a width";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("give its radius and width"), std::string::npos) << e.what();
  }
  try {
    physics.set_soil(*find_soil("dry_sand"), {override_of("no_such_link")});
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'no_such_link'"), std::string::npos) << e.what();
  }
  WheelOverride made = override_of("wheel");
  made.radius = 0.09;
  made.width = 0.12;
  physics.set_soil(*find_soil("dry_sand"), {made});
  ASSERT_EQ(physics.soil_wheels().size(), 1u);
  EXPECT_TRUE(physics.soil_wheels()[0].axis_from_joint);
  // The sphere rolls in the soil as the cylinder did: it sinks to where the soil carries it.
  physics.set_mode(*ball->joint_index("tow"), JointMode::Velocity, {0.0, 4000.0});
  for (int k = 0; k < 2000; ++k) ASSERT_TRUE(physics.step().ok());
  const WheelSoilReading& r = physics.wheel_soil().at(0);
  EXPECT_TRUE(r.contact);
  EXPECT_NEAR(r.normal_force, 9.81 * 10.0, 0.03 * 9.81 * 10.0);
  EXPECT_NEAR(r.sinkage, steady_wheel(*find_soil("dry_sand"), {0.09, 0.12}, r.normal_force, 0.0).sinkage, 0.003);
  // A soil whose k_c < 0 cannot carry a wheel narrower than -k_c / k_phi: refused, naming it.
  SoilParameters sand = cmu_sand();
  WheelOverride thin = override_of("wheel");
  thin.radius = 0.09;
  thin.width = 0.015;
  try {
    physics.set_soil(sand, {thin});
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("under wheel 'wheel'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace mechsim::physics
