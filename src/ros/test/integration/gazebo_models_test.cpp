// Models coming and going in gzserver mode in any order: SDF boxes (no controller manager) and a
// robot, the first spawned deleted while the rest stay, /gazebo/model_states subscribed from
// before anything is in.
#include <controller_manager_msgs/ListControllers.h>
#include <gazebo_msgs/DeleteModel.h>
#include <gazebo_msgs/GetWorldProperties.h>

#include "gazebo_world_fixture.hpp"

namespace mechsim::ros::test {
namespace {

// Models without a controller manager (SDF boxes) come in beside a robot in any order, and any
// model can go, the first spawned too: the others stay where the physics has them, the robot's
// controller manager answers on.
TEST_F(GazeboWorldNode, ModelsComeAndGoInAnyOrder) {
  start(false);
  // Subscribed before anything is in: the states are published through every spawn and delete
  // (the world's loop runs while a model is on its way in, with no model listed yet).
  ModelStatesWatch states(nh_);
  ASSERT_TRUE(wait_until([&] { return states.connected(); }, 5.0));
  auto box = [](const std::string& name) {
    return "<?xml version='1.0'?><sdf version='1.6'><model name='" + name + "'><link name='link'><inertial><mass>1</mass>"
           "<inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial><collision name='c'><geometry>"
           "<box><size>0.3 0.3 0.3</size></box></geometry></collision></link></model></sdf>";
  };
  auto spawn_sdf = [&](const std::string& name, double x) {
    gazebo_msgs::SpawnModel s;
    s.request.model_name = name;
    s.request.model_xml = box(name);
    s.request.initial_pose = pose_at(x, -2.0, 0.15);
    EXPECT_TRUE(call("/gazebo/spawn_sdf_model", s));
    return s;
  };
  auto s1 = spawn_sdf("box1", 0.0);
  ASSERT_TRUE(s1.response.success) << s1.response.status_message << "\n" << node_->log();
  ASSERT_TRUE(spawn("bot", kBot, pose_at(0, 0, 0.2)).response.success) << node_->log();
  auto s2 = spawn_sdf("box2", 1.0);
  ASSERT_TRUE(s2.response.success) << s2.response.status_message;
  gazebo_msgs::GetWorldProperties w;
  ASSERT_TRUE(call("/gazebo/get_world_properties", w));
  EXPECT_THAT(w.response.model_names, ::testing::ElementsAre("ground_plane", "box1", "bot", "box2"));
  gazebo_msgs::DeleteModel d;
  d.request.model_name = "box1";
  ASSERT_TRUE(call("/gazebo/delete_model", d));
  ASSERT_TRUE(d.response.success) << d.response.status_message;
  const double t = clock_now();
  EXPECT_TRUE(wait_until([&] { return clock_now() > t + 0.2; }, 5.0)) << "the clock stopped";
  ASSERT_TRUE(call("/gazebo/get_world_properties", w));
  EXPECT_THAT(w.response.model_names, ::testing::ElementsAre("ground_plane", "bot", "box2"));
  const auto g = model_state("box2");
  ASSERT_TRUE(g.response.success) << g.response.status_message;
  EXPECT_NEAR(g.response.pose.position.x, 1.0, 0.01);
  EXPECT_NEAR(g.response.pose.position.z, 0.15, 0.01) << "box2 rests on the ground";
  controller_manager_msgs::ListControllers list;
  EXPECT_TRUE(call("/bot/controller_manager/list_controllers", list, 5.0));
  EXPECT_FALSE(::ros::service::exists("/controller_manager/list_controllers", false))
      << "a model without gazebo_ros_control's plugin has no controller manager";
  ASSERT_TRUE(states.wait_for_more_than(states.count(), 5.0)) << node_->log();
  EXPECT_THAT(states.latest().name, ::testing::ElementsAre("ground_plane", "bot", "box2"));
}

}  // namespace
}  // namespace mechsim::ros::test
