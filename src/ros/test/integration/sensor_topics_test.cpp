// The simulated sensors on ROS, as their Gazebo plugins publish them, with a real master:
// - the reference PR2 (mechsim_node as fast as it runs): base_scan at 20 Hz and tilt_scan at
//   40 Hz of simulated time with the Hokuyo's 640 ranges and the plugin's frames, the torso IMU at
//   100 Hz reading gravity, ground truth (p3d) on base_pose_ground_truth;
// - the CC8 (paced at real time): the ZED2 IMU at 100 Hz; a ZED2 camera renders and publishes its
//   1280x720 rgb8 image and its camera_info only while its image has a subscriber.
// Rates are judged on the messages' stamps (sim time): the median interval is the period, and the
// count over the stamps' span is the rate within 5 % (a loaded machine may drop a message).
// Wall-clock bounds are timeouts only; the fixtures stop the nodes also on failure.
#include <gmock/gmock.h>

#include <algorithm>
#include <cstdlib>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <mutex>

#include <nav_msgs/Odometry.h>
#include <pr2_mechanism_msgs/ListControllers.h>
#include <rosgraph_msgs/Clock.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/LaserScan.h>
#include <std_srvs/Empty.h>

#include "ros_fixture.hpp"

namespace mechsim::ros::test {
namespace {

const std::string kPr2Urdf = std::string(MECHSIM_SHARED_DIR) + "/robots/reference/pr2.urdf";

// The stamps (s) of one topic's messages, and its last message.
template <class M>
class Stamps {
 public:
  Stamps(::ros::NodeHandle& nh, const std::string& topic) {
    sub_ = nh.subscribe<M>(topic, 1000, [this](const typename M::ConstPtr& msg) {
      std::lock_guard<std::mutex> l(m_);
      stamps_.push_back(msg->header.stamp.toSec());
      last_ = *msg;
    });
  }
  // The subscription ends before the members its callback writes (roscpp's shutdown waits for
  // a callback in progress).
  ~Stamps() { sub_.shutdown(); }
  Stamps(const Stamps&) = delete;
  Stamps& operator=(const Stamps&) = delete;
  std::vector<double> stamps() {
    std::lock_guard<std::mutex> l(m_);
    return stamps_;
  }
  std::size_t count() {
    std::lock_guard<std::mutex> l(m_);
    return stamps_.size();
  }
  M last() {
    std::lock_guard<std::mutex> l(m_);
    return last_;
  }
  double span() {  // sim seconds between the first and the last stamp
    std::lock_guard<std::mutex> l(m_);
    return stamps_.size() < 2 ? 0.0 : stamps_.back() - stamps_.front();
  }
  void shutdown() { sub_.shutdown(); }

 private:
  ::ros::Subscriber sub_;
  std::mutex m_;
  std::vector<double> stamps_;
  M last_;
};

struct Rate {
  double median_interval = 0.0;  // s of sim time
  double hz = 0.0;               // messages per sim second over the stamps' span
  std::size_t count = 0;
};

Rate rate_of(const std::vector<double>& stamps) {
  Rate r;
  r.count = stamps.size();
  if (stamps.size() < 3) return r;
  std::vector<double> d;
  for (std::size_t i = 1; i < stamps.size(); ++i) d.push_back(stamps[i] - stamps[i - 1]);
  std::nth_element(d.begin(), d.begin() + static_cast<long>(d.size() / 2), d.end());
  r.median_interval = d[d.size() / 2];
  r.hz = static_cast<double>(stamps.size() - 1) / (stamps.back() - stamps.front());
  return r;
}

// The node's own account of what publishing cost, written when it stops (sim_node.cpp).
void print_publish_cost(const std::string& log) {
  const auto at = log.find("mechsim: sensor publishing");
  if (at != std::string::npos) std::printf("%s\n", log.substr(at, log.find('\n', at) - at).c_str());
}

void expect_rate(const Rate& r, double hz, const char* topic) {
  EXPECT_NEAR(r.median_interval, 1.0 / hz, 1e-6) << topic;
  EXPECT_NEAR(r.hz, hz, 0.05 * hz) << topic;
  std::printf("%s: %zu messages, %.3f Hz of sim time, median interval %.4f s\n", topic, r.count, r.hz,
              r.median_interval);
}

class Pr2Sensors : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::filesystem::exists(kPr2Urdf)) GTEST_SKIP() << "the shared data folder has no PR2 (" << kPr2Urdf << ")";
    ASSERT_TRUE(::ros::master::check()) << "no ROS master";
    node_ = std::make_unique<ChildProcess>(
        std::vector<std::string>{MECHSIM_NODE_EXE, "__name:=mechsim_pr2_sensors", "_model:=" + kPr2Urdf, "_lenient:=true",
                                 "_robot_namespace:=/pr2"},
        log_dir() + "/node_pr2_sensors.log");
    pr2_mechanism_msgs::ListControllers list;
    ASSERT_TRUE(call("/pr2_controller_manager/list_controllers", list, 30.0))
        << "the node did not come up; its log:\n" << node_->log();
  }
  void TearDown() override {
    if (node_) {
      EXPECT_EQ(node_->stop(10.0), 0) << "mechsim_node did not stop cleanly; its log:\n" << node_->log();
      print_publish_cost(node_->log());
    }
  }
  std::unique_ptr<ChildProcess> node_;
  ::ros::NodeHandle nh_;
};

TEST_F(Pr2Sensors, LasersImuAndGroundTruthAtTheirRatesInSimTime) {
  Stamps<sensor_msgs::LaserScan> base(nh_, "/base_scan"), tilt(nh_, "/tilt_scan");
  Stamps<sensor_msgs::Imu> imu(nh_, "/torso_lift_imu/data");
  Stamps<nav_msgs::Odometry> truth(nh_, "/base_pose_ground_truth");
  ASSERT_TRUE(wait_until([&] { return base.span() > 3.0 && tilt.span() > 3.0 && imu.span() > 3.0 && truth.count() > 10; },
                         60.0))
      << "base_scan " << base.count() << ", tilt_scan " << tilt.count() << ", imu " << imu.count()
      << ", ground truth " << truth.count() << " messages; the node's log:\n"
      << node_->log();

  expect_rate(rate_of(base.stamps()), 20.0, "base_scan");
  expect_rate(rate_of(tilt.stamps()), 40.0, "tilt_scan");
  expect_rate(rate_of(imu.stamps()), 100.0, "torso_lift_imu/data");

  const sensor_msgs::LaserScan scan = base.last();
  EXPECT_EQ(scan.header.frame_id, "base_laser_link");
  EXPECT_EQ(scan.ranges.size(), 640u);
  EXPECT_NEAR(scan.angle_min, -2.2689, 1e-4);
  EXPECT_NEAR(scan.angle_max, 2.2689, 1e-4);
  EXPECT_FLOAT_EQ(scan.range_min, 0.08f);
  EXPECT_FLOAT_EQ(scan.range_max, 10.0f);
  const sensor_msgs::LaserScan t = tilt.last();
  EXPECT_EQ(t.header.frame_id, "laser_tilt_link");
  EXPECT_EQ(t.ranges.size(), 640u);
  EXPECT_NEAR(t.angle_max, 1.396, 1e-3);
  // The tilting laser, level, looks over an empty floor: some rays end on the robot's own arms or
  // nowhere (+inf), none is NaN.
  EXPECT_EQ(std::count_if(t.ranges.begin(), t.ranges.end(), [](float r) { return std::isnan(r); }), 0);

  const sensor_msgs::Imu m = imu.last();
  EXPECT_EQ(m.header.frame_id, "imu_link");
  const double g = std::sqrt(m.linear_acceleration.x * m.linear_acceleration.x +
                             m.linear_acceleration.y * m.linear_acceleration.y +
                             m.linear_acceleration.z * m.linear_acceleration.z);
  EXPECT_NEAR(g, 9.81, 0.2) << "the PR2 stands still: its IMU reads gravity's reaction";
  // imu_link is mounted upside down on the torso: the reaction points along its -z.
  EXPECT_LT(m.linear_acceleration.z, -9.5);
  std::printf("torso IMU linear_acceleration (%.3f, %.3f, %.3f) m/s^2\n", m.linear_acceleration.x,
              m.linear_acceleration.y, m.linear_acceleration.z);
  // gazebo_ros_imu's calibration service (the PR2 names /default_imu): answered at once.
  std_srvs::Empty calibrate;
  EXPECT_TRUE(::ros::service::call("/default_imu", calibrate)) << "the IMU plugin's <serviceName>";

  const nav_msgs::Odometry o = truth.last();
  EXPECT_EQ(o.header.frame_id, "map");
  EXPECT_EQ(o.child_frame_id, "base_link");
  EXPECT_NEAR(o.pose.pose.position.x, 0.0, 0.05);
  EXPECT_GT(o.header.stamp.toSec(), 3.0);
}

// The laser is not sampled while nobody listens; a subscriber that comes later gets fresh scans,
// stamped after it subscribed, not the reading the sensor kept from before it was switched off.
TEST_F(Pr2Sensors, NewSubscriberGetsFreshScansNotTheStaleOne) {
  auto first = std::make_unique<Stamps<sensor_msgs::LaserScan>>(nh_, "/base_scan");
  ASSERT_TRUE(wait_until([&] { return first->count() > 5; }, 30.0)) << node_->log();
  first->shutdown();
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  std::atomic<double> now{-1.0};
  ::ros::Subscriber clock = nh_.subscribe<rosgraph_msgs::Clock>(
      "/clock", 1, [&now](const rosgraph_msgs::Clock::ConstPtr& c) { now.store(c->clock.toSec()); });
  ASSERT_TRUE(wait_until([&] { return now.load() > 0.0; }, 10.0));
  const double before = now.load();
  Stamps<sensor_msgs::LaserScan> second(nh_, "/base_scan");
  ASSERT_TRUE(wait_until([&] { return second.count() > 2; }, 30.0)) << node_->log();
  EXPECT_GE(second.stamps().front(), before) << "a stale scan from before the subscription";
}

// pr2_gazebo's own rostest of the Hokuyo rates (test/sensors/hztest_pr2_scan.launch: rostest's
// hztest, 25 +- 20 Hz over 10 s of ROS time on /base_scan and /tilt_scan) with mechsim's PR2
// launch in place of gazebo_ros' (robots/pr2/test/hztest_pr2_scan.test), run by Debian's rostest
// on this program's master. At most 150 s (wall); rostest stops what it launched.
TEST(Pr2Hztest, PassesPr2GazebosScanRateTest) {
  const char* const rostest = "/usr/bin/rostest";
  if (!std::filesystem::exists(rostest)) GTEST_SKIP() << rostest << " is missing (Debian's python3-rostest)";
  ASSERT_TRUE(::ros::master::check()) << "no ROS master";
  // rostest --reuse-master wants the run id that roscore (not a bare rosmaster) sets.
  ::ros::param::set("/run_id", std::string("mechsim_hztest"));
  // hztest starts with "#!/usr/bin/env python3": Debian's interpreter first on PATH.
  const char* path = std::getenv("PATH");
  ChildProcess run({"/usr/bin/env", "PATH=/usr/bin:" + std::string(path != nullptr ? path : ""), "/usr/bin/python3",
                    rostest, "--reuse-master", "mechsim_pr2", "hztest_pr2_scan.test"},
                   log_dir() + "/rostest_hztest_pr2_scan.log");
  const int status = run.wait(150.0);
  const std::string log = run.log();
  EXPECT_EQ(status, 0) << log.substr(log.size() > 4000 ? log.size() - 4000 : 0);
  EXPECT_THAT(log, ::testing::HasSubstr("* TESTS: 2"));
  EXPECT_THAT(log, ::testing::HasSubstr("RESULT: SUCCESS"));
}

// The ZED2's IMU and one of its cameras on the CC8.
class Cc8Sensors : public CC8Node {
 protected:
  void TearDown() override {
    CC8Node::TearDown();
    if (node_) print_publish_cost(node_->log());
  }
};

TEST_F(Cc8Sensors, Zed2ImuAt100HzReadsGravity) {
  Stamps<sensor_msgs::Imu> imu(nh_, "/cc8/zed2/imu/data");
  ASSERT_TRUE(wait_until([&] { return imu.span() > 2.0; }, 30.0)) << imu.count() << " messages\n" << node_->log();
  expect_rate(rate_of(imu.stamps()), 100.0, "zed2/imu/data");
  const sensor_msgs::Imu m = imu.last();
  EXPECT_EQ(m.header.frame_id, "zed2_imu_link");
  EXPECT_NEAR(m.linear_acceleration.z, 9.81, 0.2) << "the rover stands on level ground";
}

TEST_F(Cc8Sensors, Zed2CameraInfoAloneComesAtItsRateAndImagesWhileSubscribed) {
  const std::string camera = "/cc8/zed2/right/";
  // camera_info alone comes at the camera's rate, as gazebo_ros_camera_utils publishes it (a
  // camera_info subscriber activates the camera there); mechsim sends it without rendering.
  Stamps<sensor_msgs::CameraInfo> info(nh_, camera + "camera_info");
  const double start = clock_now();
  ASSERT_FALSE(std::isnan(start));
  ASSERT_TRUE(wait_until([&] { return clock_now() > start + 1.0; }, 20.0));
  EXPECT_GE(info.count(), 5u) << "camera_info without an image subscriber, 1 s of simulated time";
  if (info.count() > 0) {
    EXPECT_EQ(info.last().width, 1280u);
    EXPECT_EQ(info.last().header.frame_id, "zed2_right_camera_optical_frame");
  }

  Stamps<sensor_msgs::Image> image(nh_, camera + "image_rect_color");
  ASSERT_TRUE(wait_until([&] { return image.count() >= 4 && info.count() >= 4; }, 60.0))
      << image.count() << " images, " << info.count() << " camera_info; the node's log:\n"
      << node_->log();
  const sensor_msgs::Image im = image.last();
  EXPECT_EQ(im.width, 1280u);
  EXPECT_EQ(im.height, 720u);
  EXPECT_EQ(im.encoding, "rgb8");
  EXPECT_EQ(im.step, 1280u * 3);
  ASSERT_EQ(im.data.size(), 1280u * 720u * 3);
  EXPECT_EQ(im.header.frame_id, "zed2_right_camera_optical_frame");
  // A rendered scene, not a blank buffer: the picture has more than one colour.
  const auto [lo, hi] = std::minmax_element(im.data.begin(), im.data.end());
  EXPECT_GT(*hi - *lo, 50) << "a flat image";
  const sensor_msgs::CameraInfo ci = info.last();
  EXPECT_EQ(ci.width, 1280u);
  EXPECT_EQ(ci.height, 720u);
  EXPECT_EQ(ci.distortion_model, "plumb_bob");
  EXPECT_GT(ci.K[0], 0.0);
  EXPECT_DOUBLE_EQ(ci.K[0], ci.P[0]);
  EXPECT_EQ(ci.header.frame_id, im.header.frame_id);
  // Frames at the camera's 15 Hz of simulated time: after the first (at the first tick after the
  // subscription), each at the first 1 ms tick at or after a multiple of 1/15 s.
  const std::vector<double> stamps = image.stamps();
  for (std::size_t i = 1; i < stamps.size(); ++i)
    EXPECT_LT(stamps[i] * 15.0 - std::floor(stamps[i] * 15.0 + 1e-9), 0.016) << "frame at " << stamps[i] << " s";
  std::printf("zed2 right image %ux%u %s, K[0] = %.2f, %zu frames\n", im.width, im.height, im.encoding.c_str(), ci.K[0],
              stamps.size());
}

}  // namespace
}  // namespace mechsim::ros::test
