#pragma once
// The gzserver-mode tests' fixture (gazebo_api_test.cpp, gazebo_models_test.cpp): mechsim_node
// with ~gazebo:=true on the test's master, a small robot to spawn, and /gazebo/* helpers.

#include <gmock/gmock.h>

#include <fstream>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <gazebo_msgs/GetModelState.h>
#include <gazebo_msgs/ModelStates.h>
#include <gazebo_msgs/SetPhysicsProperties.h>
#include <gazebo_msgs/SpawnModel.h>
#include <mechsim_msgs/StepSimulation.h>
#include <rosgraph_msgs/Clock.h>

#include "param_snapshot.hpp"
#include "ros_fixture.hpp"

namespace mechsim::ros::test {

// 2.5 kg in all: a 2 kg box and a 0.5 kg arm 0.15 m above its centre.
inline const char* const kBot = R"(<robot name="bot">
  <link name="base">
    <inertial><mass value="2"/><inertia ixx="0.0134" iyy="0.0134" izz="0.0134" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision>
  </link>
  <joint name="arm_joint" type="revolute">
    <parent link="base"/><child link="arm"/><origin xyz="0 0 0.15"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="10" velocity="5"/>
  </joint>
  <link name="arm">
    <inertial><origin xyz="0.1 0 0"/><mass value="0.5"/>
      <inertia ixx="0.0001" iyy="0.0017" izz="0.0017" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin xyz="0.1 0 0"/><geometry><box size="0.2 0.04 0.04"/></geometry></collision>
  </link>
  <transmission name="arm_transmission">
    <type>transmission_interface/SimpleTransmission</type>
    <joint name="arm_joint"><hardwareInterface>hardware_interface/EffortJointInterface</hardwareInterface></joint>
    <actuator name="arm_motor"><mechanicalReduction>1</mechanicalReduction></actuator>
  </transmission>
  <gazebo><plugin name="gazebo_ros_control" filename="libgazebo_ros_control.so"><robotNamespace>/bot</robotNamespace></plugin></gazebo>
</robot>)";

inline geometry_msgs::Pose pose_at(double x, double y, double z) {
  geometry_msgs::Pose p;
  p.position.x = x;
  p.position.y = y;
  p.position.z = z;
  p.orientation.w = 1.0;
  return p;
}

class GazeboWorldNode : public ::testing::Test {
 protected:
  void start(bool paused, const std::string& world = "") {
    const std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    std::vector<std::string> argv{MECHSIM_NODE_EXE, "__name:=gazebo", "_gazebo:=true", "_real_time_factor:=1.0",
                                  std::string("_paused:=") + (paused ? "true" : "false")};
    if (!world.empty()) argv.push_back("_world:=" + world);
    node_ = std::make_unique<ChildProcess>(argv, log_dir() + "/gazebo_" + name + ".log");
    clock_sub_ = nh_.subscribe<rosgraph_msgs::Clock>("/clock", 10, [this](const rosgraph_msgs::Clock::ConstPtr& m) {
      std::lock_guard<std::mutex> lock(mutex_);
      clock_ = m->clock.toSec();
    });
    ASSERT_TRUE(::ros::service::waitForService("/gazebo/spawn_urdf_model", ::ros::Duration(20.0)))
        << "the node did not come up; its log:\n" << node_->log();
  }

  void TearDown() override {
    clock_sub_.shutdown();
    if (node_) {
      EXPECT_EQ(node_->stop(10.0), 0) << "mechsim_node did not stop cleanly; its log:\n" << node_->log();
    }
    params_.forget_new();
  }

  double clock_now() {
    double t = -1.0;
    wait_until(
        [&] {
          std::lock_guard<std::mutex> lock(mutex_);
          t = clock_;
          return t >= 0.0;
        },
        5.0);
    return t;
  }

  gazebo_msgs::SpawnModel spawn(const std::string& name, const std::string& xml, const geometry_msgs::Pose& pose) {
    gazebo_msgs::SpawnModel s;
    s.request.model_name = name;
    s.request.model_xml = xml;
    s.request.initial_pose = pose;
    EXPECT_TRUE(call("/gazebo/spawn_urdf_model", s));
    return s;
  }

  gazebo_msgs::GetModelState model_state(const std::string& name, const std::string& frame = "") {
    gazebo_msgs::GetModelState g;
    g.request.model_name = name;
    g.request.relative_entity_name = frame;
    EXPECT_TRUE(call("/gazebo/get_model_state", g));
    return g;
  }

  double step(std::uint64_t steps) {
    mechsim_msgs::StepSimulation s;
    s.request.steps = steps;
    EXPECT_TRUE(call("/mechsim/step_simulation", s));
    EXPECT_TRUE(s.response.success) << s.response.status_message;
    return s.response.sim_time;
  }

  void zero_gravity() {
    gazebo_msgs::SetPhysicsProperties p;
    p.request.time_step = 0.001;
    p.request.max_update_rate = 1000.0;
    ASSERT_TRUE(call("/gazebo/set_physics_properties", p));
    ASSERT_TRUE(p.response.success) << p.response.status_message;
  }

  std::unique_ptr<ChildProcess> node_;
  ParamSnapshot params_;
  ::ros::NodeHandle nh_;
  ::ros::Subscriber clock_sub_;
  std::mutex mutex_;
  double clock_ = -1.0;
};

// Writes `text` into the test program's log folder (removed when the suite ends); its path.
inline std::string write_world(const std::string& name, const std::string& text) {
  const std::string path = log_dir() + "/" + name;
  std::ofstream(path) << text;
  return path;
}

// The latest message on a topic, and how many came.
template <class M>
struct Latest {
  Latest(::ros::NodeHandle& nh, const std::string& topic)
      : sub(nh.subscribe<M>(topic, 5, [this](const typename M::ConstPtr& m) {
          std::lock_guard<std::mutex> l(mutex);
          msg = *m;
          ++count;
        })) {}
  M get() {
    std::lock_guard<std::mutex> l(mutex);
    return msg;
  }
  int received() {
    std::lock_guard<std::mutex> l(mutex);
    return count;
  }
  std::mutex mutex;
  M msg;
  int count = 0;
  ::ros::Subscriber sub;
};

// The latest /gazebo/model_states message, and how many came.
class ModelStatesWatch {
 public:
  explicit ModelStatesWatch(::ros::NodeHandle& nh)
      : sub_(nh.subscribe<gazebo_msgs::ModelStates>("/gazebo/model_states", 1,
                                                    [this](const gazebo_msgs::ModelStates::ConstPtr& msg) {
                                                      std::lock_guard<std::mutex> l(mutex_);
                                                      latest_ = *msg;
                                                      ++count_;
                                                    })) {}
  bool connected() const { return sub_.getNumPublishers() > 0; }
  int count() {
    std::lock_guard<std::mutex> l(mutex_);
    return count_;
  }
  gazebo_msgs::ModelStates latest() {
    std::lock_guard<std::mutex> l(mutex_);
    return latest_;
  }
  // Waits (at most `timeout` s) for a message after the `after`-th.
  bool wait_for_more_than(int after, double timeout) {
    return wait_until([&] { return count() > after; }, timeout);
  }

 private:
  std::mutex mutex_;
  gazebo_msgs::ModelStates latest_;
  int count_ = 0;
  ::ros::Subscriber sub_;
};

}  // namespace mechsim::ros::test
