// pr2_controller_manager's services (pr2_mechanism_msgs) on a node told it drives a PR2 (~pr2),
// over the same controller manager as <ns>/controller_manager.
#include <gmock/gmock.h>

#include <pr2_mechanism_msgs/ListControllerTypes.h>
#include <pr2_mechanism_msgs/ListControllers.h>
#include <pr2_mechanism_msgs/LoadController.h>
#include <pr2_mechanism_msgs/SwitchController.h>
#include <pr2_mechanism_msgs/UnloadController.h>

#include "ros_fixture.hpp"

namespace mechsim::ros::test {
namespace {

namespace pmm = pr2_mechanism_msgs;

class CC8NodeAsPr2 : public CC8Node {
 protected:
  std::vector<std::string> extra_node_args() const override { return {"_pr2:=true"}; }
};

TEST_F(CC8NodeAsPr2, Pr2ControllerManagerServicesLoadSwitchListUnload) {
  rosparam_load(std::string(MECHSIM_SOURCE_DIR) + "/robots/cc8/config/controllers.yaml");
  const std::string cm = "/pr2_controller_manager/";
  pmm::ListControllerTypes types;
  ASSERT_TRUE(call(cm + "list_controller_types", types));
  EXPECT_THAT(types.response.types, ::testing::Contains("robot_mechanism_controllers/JointTrajectoryActionController"));

  pmm::LoadController load;
  load.request.name = "wheel_joint_FL_velocity_controller";
  ASSERT_TRUE(call(cm + "load_controller", load));
  EXPECT_TRUE(load.response.ok);
  load.request.name = "no_such_controller";
  ASSERT_TRUE(call(cm + "load_controller", load));
  EXPECT_FALSE(load.response.ok);

  pmm::SwitchController sw;
  sw.request.start_controllers = {"wheel_joint_FL_velocity_controller"};
  sw.request.strictness = pmm::SwitchController::Request::STRICT;
  ASSERT_TRUE(call(cm + "switch_controller", sw));
  EXPECT_TRUE(sw.response.ok);

  pmm::ListControllers list;
  ASSERT_TRUE(call(cm + "list_controllers", list));
  EXPECT_THAT(list.response.controllers, ::testing::ElementsAre("wheel_joint_FL_velocity_controller"));
  EXPECT_THAT(list.response.state, ::testing::ElementsAre("running"));

  pmm::UnloadController unload;
  unload.request.name = "wheel_joint_FL_velocity_controller";
  ASSERT_TRUE(call(cm + "unload_controller", unload));
  EXPECT_FALSE(unload.response.ok) << "running";
  sw.request.start_controllers.clear();
  sw.request.stop_controllers = {"wheel_joint_FL_velocity_controller"};
  ASSERT_TRUE(call(cm + "switch_controller", sw));
  EXPECT_TRUE(sw.response.ok);
  ASSERT_TRUE(call(cm + "unload_controller", unload));
  EXPECT_TRUE(unload.response.ok);
  ASSERT_TRUE(call(cm + "list_controllers", list));
  EXPECT_TRUE(list.response.controllers.empty());
}

}  // namespace
}  // namespace mechsim::ros::test
