// `mechsim ros2` refuses bad settings before it joins any network: a ROS_DOMAIN_ID outside
// 0..232 named with why, an unknown distro; and a build without the ROS 2 layer says why the
// command is unavailable. (What it serves is tested in a private network namespace:
// src/ros2/test/wire/.)
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "run_process.hpp"

namespace mechsim::apps::test {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

std::vector<std::string> ros2bot(const std::vector<std::string>& prefix) {
  const fs::path root = MECHSIM_SOURCE_DIR;
  std::vector<std::string> argv = prefix;
  argv.insert(argv.end(), {MECHSIM_EXE, "ros2", (root / "src/ros2/test/data/ros2bot.urdf.xacro").string(), "--package",
                           "mechsim_testbots=" + (root / "robots/testbots").string()});
  return argv;
}

TEST(Ros2Cli, RefusesADomainIdRmwWouldRefuse) {
  const ProcessResult r = run_process(ros2bot({"/usr/bin/env", "ROS_DOMAIN_ID=300"}), 60.0);
  ASSERT_TRUE(r.started);
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
#ifdef MECHSIM_HAS_ROS2
  EXPECT_THAT(r.err, HasSubstr("ROS_DOMAIN_ID '300' is not a domain id"));
#else
  EXPECT_THAT(r.err, HasSubstr("built without its ROS 2 layer"));
#endif
}

TEST(Ros2Cli, RefusesAnUnknownDistro) {
  std::vector<std::string> argv = ros2bot({});
  argv.insert(argv.end(), {"--ros-distro", "rolling"});
  const ProcessResult r = run_process(argv, 60.0);
  ASSERT_TRUE(r.started);
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_THAT(r.err, HasSubstr("--ros-distro"));
}

}  // namespace
}  // namespace mechsim::apps::test
