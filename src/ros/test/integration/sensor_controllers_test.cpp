// ros_controllers' sensor publishers through mechsim_node with a real master, on the CC8 of
// robots/cc8: imu_sensor_controller publishes the ZED2 IMU's handle (zed2_imu_sensor) as
// sensor_msgs/Imu on /cc8/zed2_imu_sensor (the controller manager's namespace, as ros_controllers
// advertises it) at its publish_rate of sim time, in the plugin's frame, reading gravity on level
// ground; list_controllers names its interface; force_torque_sensor_controller is refused (the
// CC8 has no force-torque sensor) with a message naming it. Rates are judged on the stamps.
#include <gmock/gmock.h>

#include <algorithm>
#include <mutex>

#include <controller_manager_msgs/ListControllers.h>
#include <controller_manager_msgs/LoadController.h>
#include <sensor_msgs/Imu.h>

#include "ros_fixture.hpp"

namespace mechsim::ros::test {
namespace {

namespace cmm = controller_manager_msgs;

TEST_F(CC8Node, ImuSensorControllerPublishesTheZed2ImuAtItsRate) {
  const std::string yaml = write_file("imu_controller.yaml", R"(
imu_sensor_controller:
  type: imu_sensor_controller/ImuSensorController
  publish_rate: 40
)");
  std::mutex m;
  std::vector<double> stamps;
  sensor_msgs::Imu last;
  ::ros::Subscriber sub = nh_.subscribe<sensor_msgs::Imu>("/cc8/zed2_imu_sensor", 100,
                                                          [&](const sensor_msgs::Imu::ConstPtr& msg) {
                                                            std::lock_guard<std::mutex> l(m);
                                                            stamps.push_back(msg->header.stamp.toSec());
                                                            last = *msg;
                                                          });
  ChildProcess& sp = spawner({yaml}, "imu_spawner");
  const auto span = [&] {
    std::lock_guard<std::mutex> l(m);
    return stamps.size() < 2 ? 0.0 : stamps.back() - stamps.front();
  };
  ASSERT_TRUE(wait_until([&] { return span() > 2.0; }, 30.0)) << sp.log() << "\n" << node_->log();
  sub.shutdown();
  std::lock_guard<std::mutex> l(m);
  std::vector<double> d;
  for (std::size_t i = 1; i < stamps.size(); ++i) d.push_back(stamps[i] - stamps[i - 1]);
  std::nth_element(d.begin(), d.begin() + static_cast<long>(d.size() / 2), d.end());
  const double median = d[d.size() / 2];
  const double hz = static_cast<double>(stamps.size() - 1) / (stamps.back() - stamps.front());
  EXPECT_NEAR(median, 1.0 / 40.0, 1e-6);
  EXPECT_NEAR(hz, 40.0, 0.05 * 40.0);
  std::printf("/cc8/zed2_imu_sensor: %zu messages, %.3f Hz of sim time, median interval %.4f s\n", stamps.size(), hz,
              median);
  EXPECT_EQ(last.header.frame_id, "zed2_imu_link");
  EXPECT_NEAR(last.linear_acceleration.z, 9.81, 0.2) << "the rover stands on level ground";
  EXPECT_NEAR(last.orientation.w * last.orientation.w + last.orientation.z * last.orientation.z, 1.0, 0.01);

  cmm::ListControllers list;
  ASSERT_TRUE(call("/cc8/controller_manager/list_controllers", list));
  const auto c = std::find_if(list.response.controller.begin(), list.response.controller.end(),
                              [](const cmm::ControllerState& s) { return s.name == "imu_sensor_controller"; });
  ASSERT_NE(c, list.response.controller.end());
  EXPECT_EQ(c->state, "running");
  EXPECT_EQ(c->type, "imu_sensor_controller/ImuSensorController");
  ASSERT_EQ(c->claimed_resources.size(), 1u);
  EXPECT_EQ(c->claimed_resources[0].hardware_interface, "hardware_interface::ImuSensorInterface");
  EXPECT_TRUE(c->claimed_resources[0].resources.empty());
}

TEST_F(CC8Node, ForceTorqueSensorControllerIsRefusedOnARobotWithoutOne) {
  ::ros::param::set("/cc8/ft_sensor_controller/type", std::string("force_torque_sensor_controller/ForceTorqueSensorController"));
  ::ros::param::set("/cc8/ft_sensor_controller/publish_rate", 50.0);
  cmm::LoadController load;
  load.request.name = "ft_sensor_controller";
  ASSERT_TRUE(call("/cc8/controller_manager/load_controller", load));
  EXPECT_FALSE(load.response.ok);
  EXPECT_TRUE(wait_until([&] { return node_->log().find("has no force-torque sensor") != std::string::npos; }, 5.0))
      << node_->log();
  ::ros::param::del("/cc8/ft_sensor_controller");
}

}  // namespace
}  // namespace mechsim::ros::test
