// Several robots in one world (OtherRobot): two CC8s, each with its own controller manager and
// rover drive, driven with different twists; each one's odometry follows its own motion, and the
// first drives as it does alone.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>

#include "controllers/drive/rover_drive_ports.hpp"
#include "control/ports.hpp"
#include "sim/simulation.hpp"
#include "sim/test/scenario/scenario_util.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;

constexpr double kPi = 3.14159265358979323846;

template <class P>
P* port_of(Simulation& sim, const std::string& controller, control::PortKind kind) {
  control::Controller* c = sim.controllers().controller(controller);
  if (c == nullptr) return nullptr;
  for (control::Port* p : c->ports())
    if (p->kind() == kind) return dynamic_cast<P*>(p);
  return nullptr;
}

double yaw_of(const description::Quat& q) {
  return std::atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z));
}

struct Drive {
  double distance = 0.0;       // m, path length of the base in the world
  double odometry_error = 0.0; // m, odometry's position against the base's, in the start frame
  double yaw_error = 0.0;      // rad
  description::Pose final_pose;
};

// Runs `seconds` with `twist` held on `sim`'s rover drive (already started); the odometry against
// the base's motion from where the drive started.
struct Tracker {
  Simulation* sim = nullptr;
  description::Pose start, last;
  double distance = 0.0;
  void begin(Simulation& s) {
    sim = &s;
    start = last = s.base_pose();
  }
  void observe() {
    const description::Pose now = sim->base_pose();
    distance += std::hypot(now.position.x - last.position.x, now.position.y - last.position.y);
    last = now;
  }
  Drive result() {
    auto* odom = port_of<control::StatePort<control::OdometrySnapshot>>(*sim, "rover_drive_controller",
                                                                      control::PortKind::Odometry);
    Drive d;
    d.distance = distance;
    d.final_pose = last;
    if (odom == nullptr) return d;
    const control::OdometrySnapshot o = odom->read();
    const double yaw0 = yaw_of(start.orientation);
    const double dx = last.position.x - start.position.x, dy = last.position.y - start.position.y;
    // The base's displacement in the start frame (the odometry's frame).
    const double fx = std::cos(yaw0) * dx + std::sin(yaw0) * dy, fy = -std::sin(yaw0) * dx + std::cos(yaw0) * dy;
    d.odometry_error = std::hypot(o.x - fx, o.y - fy);
    d.yaw_error = std::remainder(o.yaw - (yaw_of(last.orientation) - yaw0), 2 * kPi);
    return d;
  }
};

// Holds a twist on the robot's rover drive: written again every tick, as a teleop node streams
// cmd_vel within the drive's command timeout.
void command(Simulation& sim, double vx, double wz) {
  auto* port = port_of<control::TwistCommandPort>(sim, "rover_drive_controller", control::PortKind::TwistCommand);
  ASSERT_NE(port, nullptr);
  control::Twist t;
  t.linear.x = vx;
  t.angular.z = wz;
  sim.add_control_observer([port, t](const Simulation&) { port->write(t); });
}

const std::vector<std::string> kDrive = {"joint_state_controller", "rover_drive_controller"};

// mechsim's CC8 controllers (robots/cc8/config), which add the rover drive to the package's own.
control::Params drive_params() {
  return control::Params::from_yaml_file(std::string(MECHSIM_SOURCE_DIR) + "/robots/cc8/config/controllers.yaml").child("cc8");
}

class SeveralRobots : public testing::Test {
 protected:
  const fs::path shared = MECHSIM_SHARED_DIR;
  void SetUp() override {
    if (!fs::exists(shared / "robots/reference/cc8.urdf")) GTEST_SKIP() << "shared data absent: " << shared;
    options.integrator = cc8_test_integrator();
    options.spawn.z = 0.02;
  }
  // A CC8 with mechsim's controllers as an other robot named `name` at (x, y, yaw).
  OtherRobot cc8(const std::string& name, double x, double y, double yaw) const {
    OtherRobot o;
    o.name = name;
    o.robot = load_shared_cc8(shared);
    o.controllers = drive_params();
    o.spawn.x = x;
    o.spawn.y = y;
    o.spawn.z = 0.02;
    o.spawn.yaw = yaw;
    return o;
  }
  // The first CC8 (with `others`), every drive started, settled for 1 s; then the first holds
  // 0.3 m/s straight on, its motion tracked by `t` from there.
  std::unique_ptr<Simulation> first_driving(Tracker& t, std::vector<OtherRobot> others = {}) const {
    auto sim = std::make_unique<Simulation>(load_shared_cc8(shared), make_world({}), drive_params(), options, std::move(others));
    sim->load_and_start(kDrive);
    for (std::size_t i = 0; i < sim->other_count(); ++i) sim->other(i).load_and_start(kDrive);
    EXPECT_TRUE(sim->run_for(1.0));
    t.begin(*sim);
    sim->add_observer([&t](const Simulation&) { t.observe(); });
    command(*sim, 0.3, 0.0);
    return sim;
  }
  SimulationOptions options;
};

TEST_F(SeveralRobots, TwoCc8sDriveTheirOwnTwistsAndTheirOdometriesFollow) {
  // The first CC8 alone, for its figures undisturbed.
  Drive alone;
  {
    Tracker t;
    auto sim = first_driving(t);
    ASSERT_TRUE(sim->run_for(10.0));
    alone = t.result();
  }

  Tracker t1, t2;
  auto sim = first_driving(t1, {cc8("cc8_2", 0.0, 4.0, kPi / 2)});
  ASSERT_EQ(sim->other_count(), 1u);
  Simulation* two = sim->find_other("cc8_2");
  ASSERT_NE(two, nullptr);
  EXPECT_EQ(two->robot_name_in_world(), "cc8_2");
  EXPECT_EQ(two->mechanism().joints.size(), sim->mechanism().joints.size());
  EXPECT_THROW(two->run_for(0.1), std::logic_error);
  EXPECT_NEAR(two->time(), sim->time(), 1e-12);
  const description::Pose spawned2 = two->base_pose();
  EXPECT_NEAR(spawned2.position.x, 0.0, 0.02);
  EXPECT_NEAR(spawned2.position.y, 4.0, 0.02);
  EXPECT_NEAR(yaw_of(spawned2.orientation), kPi / 2, 0.02);

  t2.begin(*two);
  two->add_observer([&](const Simulation&) { t2.observe(); });
  command(*two, 0.2, 0.1);  // an arc to its left, starting along world +y
  ASSERT_TRUE(sim->run_for(10.0));
  const Drive d1 = t1.result(), d2 = t2.result();
  std::cout << "[ figures  ] first CC8: " << d1.distance << " m (alone " << alone.distance << " m), odometry error "
            << d1.odometry_error << " m, yaw " << d1.yaw_error << " rad; second: " << d2.distance
            << " m, odometry error " << d2.odometry_error << " m, yaw " << d2.yaw_error << " rad, heading turned "
            << std::remainder(yaw_of(d2.final_pose.orientation) - kPi / 2, 2 * kPi) << " rad\n";
  // Each drove what it was told: ~3 m straight; ~2 m turning ~1 rad to the left.
  EXPECT_NEAR(d1.distance, 3.0, 0.3);
  EXPECT_NEAR(d2.distance, 2.0, 0.3);
  EXPECT_NEAR(std::remainder(yaw_of(d2.final_pose.orientation) - kPi / 2, 2 * kPi), 1.0, 0.2);
  EXPECT_LT(std::abs(yaw_of(d1.final_pose.orientation)), 0.05);
  // Each odometry follows its own robot within 3 % of the distance (the CC8's crab tolerance).
  EXPECT_LT(d1.odometry_error, 0.03 * d1.distance);
  EXPECT_LT(d2.odometry_error, 0.03 * d2.distance);
  EXPECT_LT(std::abs(d1.yaw_error), 0.05);
  EXPECT_LT(std::abs(d2.yaw_error), 0.05);
  // The first drove as it does alone.
  EXPECT_NEAR(d1.final_pose.position.x, alone.final_pose.position.x, 0.01);
  EXPECT_NEAR(d1.final_pose.position.y, alone.final_pose.position.y, 0.01);

  // A world reset puts both back where they spawned; time goes on.
  const double before = sim->time();
  sim->reset();
  EXPECT_NEAR(sim->time(), before, 1e-12);
  EXPECT_NEAR(two->base_pose().position.y, 4.0, 0.05);
  EXPECT_NEAR(two->base_pose().position.x, 0.0, 0.05);
  EXPECT_NEAR(sim->base_pose().position.x, 0.0, 0.05);
}

// Spawned into the running world, a second CC8 drives its own twist; deleted, it is gone. The
// first drives on through both, its controllers never restarted, to where it gets alone.
TEST_F(SeveralRobots, ASpawnAndADeleteDuringARunLeaveTheFirstDrivingUndisturbed) {
  const auto run_first = [&](bool with_second) {
    Tracker t;
    auto sim = first_driving(t);
    EXPECT_TRUE(sim->run_for(3.0));
    if (with_second) {
      const double before = sim->time();
      const std::uint64_t generation = sim->physics_generation();
      OtherRobot second = cc8("cc8_2", 0.0, 4.0, 0.0);
      second.initial_joints["steering_FL"] = 0.2;
      Simulation& two = sim->add_other(second);
      EXPECT_EQ(sim->physics_generation(), generation + 1) << "indices into the old physics are stale";
      EXPECT_EQ(two.physics_generation(), sim->physics_generation());
      EXPECT_EQ(&two.world_host(), sim.get());
      EXPECT_TRUE(two.floating());
      EXPECT_EQ(sim->time(), before);
      EXPECT_EQ(two.time(), before);
      EXPECT_NEAR(two.physics().position(*two.physics().model().joint_index("cc8_2::steering_FL")), 0.2, 1e-12);
      EXPECT_THROW(sim->add_other(second), std::invalid_argument);  // the name is taken
      two.load_and_start(kDrive);
      command(two, -0.2, 0.0);
      const double y0 = two.base_pose().position.y, x0 = two.base_pose().position.x;
      EXPECT_TRUE(sim->run_for(3.0));
      const description::Pose p2 = two.base_pose();
      std::cout << "[ figures  ] the spawned CC8 drove " << p2.position.x - x0 << " m along x, " << p2.position.y - y0
                << " m along y in 3 s\n";
      EXPECT_NEAR(p2.position.x - x0, -0.6, 0.1);
      EXPECT_NEAR(p2.position.y - y0, 0.0, 0.05);
      EXPECT_TRUE(sim->remove_other("cc8_2"));
      EXPECT_FALSE(sim->remove_other("cc8_2"));
      EXPECT_EQ(sim->other_count(), 0u);
      EXPECT_EQ(sim->physics().model().joints().size(), 14u);
    } else {
      EXPECT_TRUE(sim->run_for(3.0));
    }
    EXPECT_TRUE(sim->run_for(3.0));
    for (const control::ControllerInfo& info : sim->controllers().list_controllers())
      EXPECT_EQ(info.state, control::ControllerLifecycle::Running) << info.name;
    return t.result();
  };
  const Drive alone = run_first(false), with = run_first(true);
  std::cout << "[ figures  ] the first CC8 alone " << alone.final_pose.position.x << ", " << alone.final_pose.position.y
            << " m; with a CC8 spawned and deleted on the way " << with.final_pose.position.x << ", "
            << with.final_pose.position.y << " m; odometry error " << with.odometry_error << " m of " << with.distance
            << " m\n";
  EXPECT_NEAR(with.final_pose.position.x, alone.final_pose.position.x, 0.01);
  EXPECT_NEAR(with.final_pose.position.y, alone.final_pose.position.y, 0.01);
  // Its odometry went on (a restarted drive would count from the spawn instant).
  EXPECT_LT(with.odometry_error, 0.03 * with.distance);
}

// Each robot's sensors are its own: another robot's IMU (the ZED2's, world-referenced) reports its
// own heading, and still does once a robot spawned before it is deleted (its links move in the
// rebuilt physics, and the sensors look them up again).
TEST_F(SeveralRobots, OtherRobotsSensorsReadTheirOwnLinksThroughADelete) {
  Simulation sim(load_shared_cc8(shared), make_world({}), drive_params(), options,
                 {cc8("cc8_2", 0.0, 3.0, -kPi / 2), cc8("cc8_3", 0.0, 6.0, kPi / 2)});
  const auto imu = [](const Simulation& s, std::uint64_t* count = nullptr) {
    const auto i = s.sensors().find("zed2_imu_sensor");
    EXPECT_TRUE(i.has_value()) << "robot '" << s.robot_name_in_world() << "' has no ZED2 IMU";
    const sensors::SensorReading& r = s.sensors().reading(i.value_or(0));
    if (count != nullptr) *count = r.count;
    return std::get<sensors::ImuReading>(r.value);
  };
  const auto yaw = [](const sensors::ImuReading& m) {
    const auto& q = m.orientation;
    return std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
  };
  ASSERT_TRUE(sim.run_for(0.5));
  EXPECT_EQ(sim.other(0).sensors().size(), sim.sensors().size());
  const double host = yaw(imu(sim));
  EXPECT_NEAR(std::remainder(yaw(imu(sim.other(0))) - host, 2 * kPi), -kPi / 2, 0.02);
  EXPECT_NEAR(std::remainder(yaw(imu(sim.other(1))) - host, 2 * kPi), kPi / 2, 0.02);
  EXPECT_NEAR(imu(sim.other(1)).linear_acceleration.z, 9.81, 0.3) << "at rest: the specific force of gravity";
  std::uint64_t before = 0, after = 0;
  imu(sim.other(1), &before);
  ASSERT_TRUE(sim.remove_other("cc8_2"));
  ASSERT_TRUE(sim.run_for(0.5));
  ASSERT_EQ(sim.other(0).robot_name_in_world(), "cc8_3");
  const sensors::ImuReading third = imu(sim.other(0), &after);
  EXPECT_GT(after, before) << "cc8_3's IMU stopped sampling after the delete";
  EXPECT_NEAR(std::remainder(yaw(third) - host, 2 * kPi), kPi / 2, 0.02);
  EXPECT_NEAR(third.linear_acceleration.z, 9.81, 0.3);
}

// With settle_on_ground (scenarios' default), robots given at the start and a CC8 spawned into the
// running world on a 10-degree slope stand on it as the first one does: the same tilt, and the
// spawned one stays where it was put (no drop, no slide while its drive holds it).
TEST_F(SeveralRobots, ASpawnOnASlopeIsFittedToItAsTheFirstRobotIs) {
  WorldConfig slope;
  slope.name = "slope";
  options.settle_on_ground = true;
  Simulation sim(load_shared_cc8(shared), make_world(slope), drive_params(), options, {cc8("cc8_1", 0.0, -3.0, 0.0)});
  sim.load_and_start(kDrive);
  ASSERT_TRUE(sim.run_for(0.2));
  Simulation& two = sim.add_other(cc8("cc8_2", 0.0, 3.0, 0.0));
  two.load_and_start(kDrive);
  const auto pitch = [](const description::Pose& p) {
    const auto& q = p.orientation;
    return std::asin(std::clamp(2.0 * (q.w * q.y - q.z * q.x), -1.0, 1.0));
  };
  const description::Pose first = sim.spawn_pose(), spawned = two.base_pose();
  std::cout << "[ figures  ] on the 10-degree slope: first robot pitch " << pitch(first) * 180 / kPi
            << " deg, spawned robot pitch " << pitch(spawned) * 180 / kPi << " deg\n";
  EXPECT_NEAR(pitch(spawned), pitch(first), 0.5 * kPi / 180);
  EXPECT_NEAR(pitch(sim.other(0).spawn_pose()), pitch(first), 0.5 * kPi / 180) << "the robot given at the start";
  EXPECT_GT(std::abs(pitch(spawned)), 5.0 * kPi / 180) << "the spawned robot stands level on the slope";
  ASSERT_TRUE(sim.run_for(1.0));
  const description::Pose later = two.base_pose();
  // Both were put spawn.z (2 cm) clear of the ground and settle onto their suspensions alike.
  const double drop_first = first.position.z - sim.base_pose().position.z;
  const double drop_spawned = spawned.position.z - later.position.z;
  std::cout << "[ figures  ] settling: first robot " << drop_first * 1000 << " mm, spawned robot " << drop_spawned * 1000
            << " mm\n";
  EXPECT_NEAR(drop_spawned, drop_first, 0.01) << "it dropped or bounced";
  EXPECT_NEAR(later.position.x, spawned.position.x, 0.02) << "it slid";
  EXPECT_NEAR(pitch(later), pitch(spawned), 1.0 * kPi / 180);
}

// A second robot whose name cannot be a namespace, or clashes with another's, is an error naming it.
TEST_F(SeveralRobots, BadNamesAreErrors) {
  for (const std::vector<std::string>& names : std::vector<std::vector<std::string>>{{""}, {"a::b"}, {"r", "r"}}) {
    std::vector<OtherRobot> others;
    for (const std::string& n : names) others.push_back(cc8(n, 0.0, 3.0 * static_cast<double>(others.size() + 1), 0.0));
    try {
      Simulation sim(load_shared_cc8(shared), make_world({}), drive_params(), options, others);
      ADD_FAILURE() << "accepted other robots named '" << names.front() << "'";
    } catch (const std::exception& e) {
      EXPECT_NE(std::string(e.what()).find("'" + names.back() + "'"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace mechsim::sim
