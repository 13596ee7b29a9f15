// /clock as gazebo_ros publishes it: on every world step unless ~pub_clock_frequency is set
// (gazebo_ros_api_plugin's pub_clock_frequency_ starts at 0; empty_world.launch sets it only with
// use_clock_frequency), then every 1/pub_clock_frequency of simulation time; mechsim's earlier
// ~clock_publish_rate is the same. Checked on the stamps, not on arrival times: the spacing of
// consecutive stamps does not depend on how loaded the machine is.
#include <gmock/gmock.h>

#include <mutex>

#include <rosgraph_msgs/Clock.h>

#include "ros_fixture.hpp"

namespace mechsim::ros::test {
namespace {

// Collects /clock stamps for `seconds` of wall time; returns the gaps between consecutive ones (s).
std::vector<double> clock_gaps(double seconds) {
  ::ros::NodeHandle nh;
  std::mutex m;
  std::vector<double> stamps;
  ::ros::Subscriber sub = nh.subscribe<rosgraph_msgs::Clock>(
      "/clock", 1000, [&](const rosgraph_msgs::Clock::ConstPtr& c) {
        std::lock_guard<std::mutex> lock(m);
        stamps.push_back(c->clock.toSec());
      });
  wait_until([&] { std::lock_guard<std::mutex> lock(m); return stamps.size() > 2; }, 10.0);
  std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
  sub.shutdown();
  std::lock_guard<std::mutex> lock(m);
  std::vector<double> gaps;
  for (std::size_t i = 1; i < stamps.size(); ++i) gaps.push_back(stamps[i] - stamps[i - 1]);
  return gaps;
}

void expect_every_gap(const std::vector<double>& gaps, double period) {
  ASSERT_GT(gaps.size(), 20u) << "too few /clock messages";
  std::size_t off = 0;
  for (double g : gaps) off += std::abs(g - period) > 1e-6 ? 1 : 0;
  // A subscriber queue overflow under load drops one now and then (1 kHz); a few per hundred.
  EXPECT_LE(off, gaps.size() / 50) << off << " of " << gaps.size() << " gaps differ from " << period << " s";
}

TEST_F(CC8Node, ClockIsPublishedOnEveryStepByDefault) { expect_every_gap(clock_gaps(2.0), 0.001); }

class CC8NodeClockAt100Hz : public CC8Node {
  std::vector<std::string> extra_node_args() const override { return {"_pub_clock_frequency:=100"}; }
};

TEST_F(CC8NodeClockAt100Hz, ClockFollowsPubClockFrequency) { expect_every_gap(clock_gaps(2.0), 0.01); }

class CC8NodeClockAt50Hz : public CC8Node {
  std::vector<std::string> extra_node_args() const override { return {"_clock_publish_rate:=50"}; }
};

TEST_F(CC8NodeClockAt50Hz, ClockFollowsClockPublishRate) { expect_every_gap(clock_gaps(2.0), 0.02); }

}  // namespace
}  // namespace mechsim::ros::test
