#pragma once
// The fixture of the ROS 2 wire tests: a private network namespace, `mechsim ros2` on a robot, and
// peers written by others (Cyclone DDS, Fast DDS, @foxglove/ros2) in the same namespace.

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <mechsim_test_paths.hpp>

#include "wire_util.hpp"

namespace mechsim::ros2::test {

// The test robot (../data/ros2bot.urdf.xacro) and its controllers, as `mechsim ros2` arguments.
inline std::vector<std::string> ros2bot_args() {
  const std::string src = MECHSIM_SOURCE_DIR;
  return {src + "/src/ros2/test/data/ros2bot.urdf.xacro", "robot_ns:=/ros2bot",
          "--package", "mechsim_testbots=" + src + "/robots/testbots",
          "--controllers", src + "/src/ros2/test/data/ros2bot_controllers.yaml"};
}

class WireTest : public ::testing::Test {
 protected:
  void SetUp() override {
    net_ = std::make_unique<PrivateNetwork>();
    if (!net_->ok()) GTEST_SKIP() << net_->error();
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(info->test_suite_name()) + "." + info->name();
    for (char& c : name)
      if (c == '/') c = '_';
    dir_ = test_dir(name);
  }
  void TearDown() override {
    peers_.clear();
    mechsim_.reset();
    net_.reset();
  }

  // `mechsim ros2 ARGS...` on domain kDomain; returns once it serves its topics (at most 90 s: a
  // PR2 expands and builds in seconds, more on a loaded machine).
  Process& start_mechsim(const std::vector<std::string>& args) {
    std::vector<std::string> argv{MECHSIM_EXE, "ros2"};
    argv.insert(argv.end(), args.begin(), args.end());
    mechsim_ = std::make_unique<Process>(argv, dir_ + "/mechsim.log", std::map<std::string, std::string>{{"ROS_DOMAIN_ID", kDomain}});
    if (!mechsim_->wait_for_output("mechsim ros2: nodes:", std::chrono::seconds(90))) {
      ADD_FAILURE() << "mechsim ros2 did not come up:\n" << mechsim_->output();
    }
    return *mechsim_;
  }
  // Stops mechsim (SIGTERM) and returns its log; EXPECTs a clean exit.
  std::string stop_mechsim() {
    const int status = mechsim_->stop();
    const std::string log = mechsim_->output();
    EXPECT_EQ(status, 0) << log;
    return log;
  }

  // A Cyclone DDS peer (../peers/cyclone) of `distro`'s graph layout; runs to its end (--seconds).
  std::vector<nlohmann::json> run_cyclone(const std::string& distro, std::vector<std::string> args,
                                          const std::string& name = "cyclone") {
    Process& p = start_cyclone(distro, std::move(args), name);
    const auto status = p.wait(std::chrono::seconds(60));
    EXPECT_TRUE(status && *status == 0) << p.output();
    return json_lines(p.output());
  }
  Process& start_cyclone(const std::string& distro, std::vector<std::string> args, const std::string& name = "cyclone") {
    std::vector<std::string> argv{std::string(MECHSIM_BINARY_DIR) + "/bin/cyclone_peer_" + distro, "--domain", kDomain};
    argv.insert(argv.end(), args.begin(), args.end());
    peers_.push_back(std::make_unique<Process>(argv, dir_ + "/" + name + ".log",
                                               std::map<std::string, std::string>{{"CYCLONEDDS_URI", PrivateNetwork::cyclone_uri()}}));
    return *peers_.back();
  }

  // The Fast DDS peer (../peers/fastdds): same arguments and output as the Cyclone peer.
  std::vector<nlohmann::json> run_fastdds(const std::string& distro, std::vector<std::string> args,
                                          const std::string& name = "fastdds") {
    std::vector<std::string> argv{std::string(MECHSIM_BINARY_DIR) + "/bin/fastdds_peer", "--domain", kDomain, "--distro", distro};
    argv.insert(argv.end(), args.begin(), args.end());
    peers_.push_back(std::make_unique<Process>(argv, dir_ + "/" + name + ".log"));
    const auto status = peers_.back()->wait(std::chrono::seconds(60));
    EXPECT_TRUE(status && *status == 0) << peers_.back()->output();
    return json_lines(peers_.back()->output());
  }
  // The scripted clients (../peers/common/script.hpp): the Fast DDS peer (rmw_fastrtps' forms)
  // and the Cyclone DDS client (rmw_cyclonedds' forms), started with `steps`; `extra` more
  // arguments (the Fast DDS peer's --lease).
  Process& start_fastdds_script(const std::string& distro, const nlohmann::json& steps, const std::string& name,
                                std::vector<std::string> extra = {}) {
    std::vector<std::string> argv{std::string(MECHSIM_BINARY_DIR) + "/bin/fastdds_peer", "--domain", kDomain, "--distro",
                                  distro, "--seconds", "0", "--script", steps.dump()};
    argv.insert(argv.end(), extra.begin(), extra.end());
    peers_.push_back(std::make_unique<Process>(argv, dir_ + "/" + name + ".log"));
    return *peers_.back();
  }
  Process& start_cyclone_script(const std::string& distro, const nlohmann::json& steps, const std::string& name,
                                std::vector<std::string> extra = {}) {
    std::vector<std::string> argv{std::string(MECHSIM_BINARY_DIR) + "/bin/cyclone_client", "--domain", kDomain, "--distro",
                                  distro, "--script", steps.dump()};
    argv.insert(argv.end(), extra.begin(), extra.end());
    peers_.push_back(std::make_unique<Process>(argv, dir_ + "/" + name + ".log",
                                               std::map<std::string, std::string>{{"CYCLONEDDS_URI", PrivateNetwork::cyclone_uri()}}));
    return *peers_.back();
  }
  // The step lines of a finished scripted client (waits at most `timeout`), in order.
  static std::vector<nlohmann::json> steps_of(Process& p, std::chrono::seconds timeout = std::chrono::seconds(90)) {
    const auto status = p.wait(timeout);
    EXPECT_TRUE(status && *status == 0) << p.output();
    std::vector<nlohmann::json> out;
    for (const auto& l : json_lines(p.output()))
      if (l.contains("step")) out.push_back(l);
    return out;
  }

  // The @foxglove/ros2 peer (../peers/foxglove, node); empty with `skip` set when node or its
  // packages are not installed.
  std::vector<nlohmann::json> run_foxglove(const std::string& distro, std::vector<std::string> args, std::string* skip,
                                           const std::string& name = "foxglove") {
    const std::string dir = std::string(MECHSIM_SOURCE_DIR) + "/src/ros2/test/peers/foxglove";
    if (!std::filesystem::exists(dir + "/node_modules/@foxglove/ros2")) {
      *skip = dir + "/node_modules is missing: scripts/install-deps.sh --with-ros installs the @foxglove/ros2 peer";
      return {};
    }
    std::vector<std::string> argv{"node", dir + "/peer.js", "--domain", kDomain, "--distro", distro};
    argv.insert(argv.end(), args.begin(), args.end());
    peers_.push_back(std::make_unique<Process>(argv, dir_ + "/" + name + ".log"));
    const auto status = peers_.back()->wait(std::chrono::seconds(60));
    EXPECT_TRUE(status && *status == 0) << peers_.back()->output();
    return json_lines(peers_.back()->output());
  }

  static constexpr const char* kDomain = "7";
  std::unique_ptr<PrivateNetwork> net_;
  std::string dir_;
  std::unique_ptr<Process> mechsim_;
  std::vector<std::unique_ptr<Process>> peers_;
};

}  // namespace mechsim::ros2::test
