#include "ros_fixture.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>

#include <xmlrpcpp/XmlRpcClient.h>

#include <rosgraph_msgs/Clock.h>
#include <controller_manager_msgs/ListControllers.h>

namespace mechsim::ros::test {

namespace {

struct State {
  std::string log_dir;
  int port = 0;
  std::unique_ptr<ChildProcess> master;
  std::unique_ptr<::ros::AsyncSpinner> spinner;
};

State& state() {
  static State s;
  return s;
}

// The pid of the master answering on 127.0.0.1:port (its getPid call), or -1 when none answers.
int master_pid(int port) {
  XmlRpc::XmlRpcClient client("127.0.0.1", port, "/");
  XmlRpc::XmlRpcValue args, result;
  args[0] = "/mechsim_ros_test";
  if (!client.execute("getPid", args, result) || client.isFault()) return -1;
  if (result.getType() != XmlRpc::XmlRpcValue::TypeArray || result.size() < 3) return -1;
  return static_cast<int>(result[2]);
}

// Starts `rosmaster --core` on a free loopback port and returns once it answers. Another test
// program may take the same port between the probe and the master's bind (ctest -j, other
// worktrees): the master that answers must be this one (its pid), else another port is tried.
std::unique_ptr<ChildProcess> start_master(const std::string& log_dir, int& port) {
  std::string failures;
  for (int attempt = 0; attempt < 5; ++attempt) {
    port = free_loopback_port();
    auto master = std::make_unique<ChildProcess>(
        std::vector<std::string>{"/usr/bin/python3", "/usr/bin/rosmaster", "--core", "-p", std::to_string(port)},
        log_dir + "/master.log");
    const pid_t own = master->pid();
    int answering = -1;
    wait_until([&] { return (answering = master_pid(port)) > 0 || !master->running(); }, 15.0);
    if (answering == own) return master;
    failures += "\n  port " + std::to_string(port) + ": " +
                (answering > 0 ? "another master (pid " + std::to_string(answering) + ") answers"
                               : "no answer; " + master->log());
    master->stop();
  }
  throw std::runtime_error("could not start a rosmaster of our own:" + failures);
}

class RosEnvironment : public ::testing::Environment {
 public:
  void SetUp() override {
    State& s = state();
    char dir[] = "/tmp/mechsim_ros_test.XXXXXX";
    if (!::mkdtemp(dir)) throw std::runtime_error("mkdtemp failed");
    s.log_dir = dir;
    s.master = start_master(s.log_dir, s.port);
    const std::string uri = "http://127.0.0.1:" + std::to_string(s.port);
    ::setenv("ROS_MASTER_URI", uri.c_str(), 1);
    ::setenv("ROS_IP", "127.0.0.1", 1);
    ::setenv("ROS_HOSTNAME", "127.0.0.1", 1);
    ::setenv("ROS_LOG_DIR", s.log_dir.c_str(), 1);
    ::setenv("ROS_HOME", s.log_dir.c_str(), 1);
    const std::string packages = std::string(MECHSIM_SOURCE_DIR) + "/robots:" + MECHSIM_BINARY_DIR + "/ros_package";
    ::setenv("ROS_PACKAGE_PATH", packages.c_str(), 1);
    // The ROS tools are Debian's Python programs: never a pyenv/venv interpreter's paths.
    ::unsetenv("PYTHONPATH");
    ::unsetenv("PYTHONHOME");
    int argc = 0;
    ::ros::init(argc, nullptr, "mechsim_ros_test",
                ::ros::init_options::AnonymousName | ::ros::init_options::NoSigintHandler);
    if (!wait_until([] { return ::ros::master::check(); }, 15.0)) {
      throw std::runtime_error("rosmaster did not come up on port " + std::to_string(s.port) + ": " +
                               s.master->log());
    }
    s.spinner = std::make_unique<::ros::AsyncSpinner>(2);
    s.spinner->start();
    std::printf("ROS master at %s, logs in %s\n", uri.c_str(), s.log_dir.c_str());
  }

  void TearDown() override {
    State& s = state();
    if (s.spinner) s.spinner->stop();
    ::ros::shutdown();
    if (s.master) s.master->stop();
    // Logs stay for a failing run (the path is printed at the start).
    if (::testing::UnitTest::GetInstance()->Passed()) {
      std::error_code ignored;
      std::filesystem::remove_all(s.log_dir, ignored);
    }
  }
};

const auto* const kEnvironment = ::testing::AddGlobalTestEnvironment(new RosEnvironment);

}  // namespace

const std::string& log_dir() { return state().log_dir; }
int master_port() { return state().port; }

int lookup_node(int port, const std::string& name) {
  XmlRpc::XmlRpcClient client("127.0.0.1", port, "/");
  XmlRpc::XmlRpcValue args, result;
  args[0] = "/mechsim_ros_test";
  args[1] = name;
  if (!client.execute("lookupNode", args, result) || client.isFault()) return 0;
  if (result.getType() != XmlRpc::XmlRpcValue::TypeArray || result.size() < 1) return 0;
  return static_cast<int>(result[0]) == 1 ? 1 : -1;
}

std::unique_ptr<ChildProcess> start_master_on(int port, const std::string& log) {
  auto master = std::make_unique<ChildProcess>(
      std::vector<std::string>{"/usr/bin/python3", "/usr/bin/rosmaster", "--core", "-p", std::to_string(port)}, log);
  // Up when it answers at all (a lookup of a node it cannot know yet).
  EXPECT_TRUE(wait_until([&] { return lookup_node(port, "/nobody") != 0 || !master->running(); }, 15.0))
      << master->log();
  EXPECT_TRUE(master->running()) << master->log();
  return master;
}

bool wait_until(const std::function<bool()>& done, double timeout) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout);
  while (!done()) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return true;
}

void CC8Node::SetUp() {
  ASSERT_TRUE(::ros::master::check()) << "no ROS master";
  const std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  // Paced at real time so that rates can be measured in wall-clock time; the physics' odom
  // frame is "world" so that it does not meet the rover drive's odom -> base_footprint.
  std::vector<std::string> argv{MECHSIM_NODE_EXE, "__name:=mechsim",
                                "_model:=" + std::string(MECHSIM_SOURCE_DIR) + "/robots/cc8/urdf/cc8.urdf.xacro",
                                "_real_time_factor:=1.0", "_publish_odom_tf:=true", "_odom_frame:=world"};
  for (const std::string& a : extra_node_args()) argv.push_back(a);
  node_ = std::make_unique<ChildProcess>(argv, log_dir() + "/node_" + name + ".log");
  clock_sub_ = nh_.subscribe<rosgraph_msgs::Clock>("/clock", 10, [this](const rosgraph_msgs::Clock::ConstPtr& m) {
    std::lock_guard<std::mutex> lock(clock_mutex_);
    clock_ = m->clock.toSec();
  });
  controller_manager_msgs::ListControllers list;
  ASSERT_TRUE(call("/cc8/controller_manager/list_controllers", list, 30.0))
      << "the node did not come up; its log:\n" << node_->log();
}

void CC8Node::TearDown() {
  for (auto it = spawners_.rbegin(); it != spawners_.rend(); ++it) (*it)->stop();
  spawners_.clear();
  clock_sub_.shutdown();
  if (node_) {
    const int status = node_->stop(10.0);
    EXPECT_EQ(status, 0) << "mechsim_node did not stop cleanly on SIGINT; its log:\n" << node_->log();
  }
}

ChildProcess& CC8Node::spawner(const std::vector<std::string>& args, const std::string& name) {
  std::vector<std::string> argv{MECHSIM_SPAWNER_EXE, "__ns:=/cc8", "__name:=" + name};
  argv.insert(argv.end(), args.begin(), args.end());
  spawners_.push_back(std::make_unique<ChildProcess>(argv, log_dir() + "/" + name + ".log"));
  return *spawners_.back();
}

void CC8Node::rosparam_load(const std::string& file) {
  ChildProcess p({"/usr/bin/python3", "/usr/bin/rosparam", "load", file}, log_dir() + "/rosparam.log");
  ASSERT_EQ(p.wait(30.0), 0) << "rosparam load " << file << ": " << p.log();
}

std::string CC8Node::write_file(const std::string& name, const std::string& text) {
  const std::string path = log_dir() + "/" + name;
  std::ofstream(path) << text;
  return path;
}

double CC8Node::clock_now() {
  double t = -1.0;
  wait_until(
      [&] {
        std::lock_guard<std::mutex> lock(clock_mutex_);
        t = clock_;
        return t >= 0.0;
      },
      5.0);
  return t >= 0.0 ? t : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace mechsim::ros::test
