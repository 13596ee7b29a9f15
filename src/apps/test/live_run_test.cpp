// `mechsim run --live`: a Foxglove WebSocket client (live/test/foxglove_test_client.hpp) against a
// real run of the CC8 on loopback. Each test starts one `mechsim run` and stops it (a killed one
// too) before it ends; report folders go to a temporary folder removed afterwards.

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "apps/test/run_process.hpp"
#include "live/foxglove_server.hpp"
#include "live/test/foxglove_test_client.hpp"
#include "mechsim_test_paths.hpp"

extern char** environ;

namespace mechsim::apps::test {
namespace {

namespace fs = std::filesystem;

// A `mechsim run --live` in the background: its stdout read until it names its address; killed
// by the destructor if it is still running.
class LiveRun {
 public:
  explicit LiveRun(std::vector<std::string> argv) {
    int out[2];
    if (pipe(out) != 0) return;
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
    posix_spawn_file_actions_addclose(&actions, out[0]);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    std::vector<char*> args;
    for (std::string& a : argv) args.push_back(a.data());
    args.push_back(nullptr);
    if (posix_spawn(&pid_, argv[0].c_str(), &actions, nullptr, args.data(), environ) != 0) pid_ = -1;
    posix_spawn_file_actions_destroy(&actions);
    close(out[1]);
    out_ = out[0];
  }
  ~LiveRun() {
    if (pid_ > 0 && !exited_) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
    if (out_ >= 0) close(out_);
  }

  // The port of the "live: ws://127.0.0.1:PORT" line (0: none within `timeout_s`).
  unsigned short port(double timeout_s) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
    const std::regex line("live: ws://127\\.0\\.0\\.1:([0-9]+)");
    std::smatch m;
    while (std::chrono::steady_clock::now() < end) {
      if (std::regex_search(output_, m, line)) return static_cast<unsigned short>(std::stoi(m[1]));
      if (read_some(0.1) < 0) break;  // the run ended
    }
    return 0;
  }

  // Waits for the exit (true) within `timeout_s`; the output is then complete.
  bool wait(double timeout_s, int* exit_code) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
    while (std::chrono::steady_clock::now() < end) {
      read_some(0.05);
      int status = 0;
      if (waitpid(pid_, &status, WNOHANG) == pid_) {
        exited_ = true;
        while (read_some(0.05) > 0) {
        }
        *exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        return true;
      }
    }
    return false;
  }

  const std::string& output() const { return output_; }

 private:
  // 1: read some output, 0: none within the timeout, -1: the output ended.
  int read_some(double timeout_s) {
    pollfd fd{out_, POLLIN, 0};
    if (poll(&fd, 1, static_cast<int>(timeout_s * 1000)) <= 0) return 0;
    char buffer[4096];
    const ssize_t n = read(out_, buffer, sizeof buffer);
    if (n <= 0) return -1;
    output_.append(buffer, static_cast<std::size_t>(n));
    return 1;
  }

  pid_t pid_ = -1;
  int out_ = -1;
  bool exited_ = false;
  std::string output_;
};

class LiveRunTest : public ::testing::Test {
 protected:
  void SetUp() override {
    char pattern[] = "/tmp/mechsim_live_XXXXXX";
    ASSERT_NE(mkdtemp(pattern), nullptr);
    dir_ = pattern;
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::vector<std::string> run_args(const std::string& duration, std::vector<std::string> extra) {
    std::vector<std::string> argv = {MECHSIM_EXE, "run", std::string(MECHSIM_SOURCE_DIR) + "/robots/cc8/scenarios/straight_5m.yaml",
                                     "--duration", duration, "--no-plots", "-o", dir_.string() + "/report", "--live"};
    argv.insert(argv.end(), extra.begin(), extra.end());
    return argv;
  }

  fs::path dir_;
};

double wall_rate(const std::vector<live::test::ReceivedMessage>& messages, const std::string& topic, std::size_t* count) {
  std::vector<std::chrono::steady_clock::time_point> times;
  for (const auto& m : messages) {
    if (m.topic == topic) times.push_back(m.received);
  }
  *count = times.size();
  if (times.size() < 2) return 0.0;
  return static_cast<double>(times.size() - 1) / std::chrono::duration<double>(times.back() - times.front()).count();
}

TEST_F(LiveRunTest, StreamsTfAndJointStatesAtThirtyHertzWhileTheRoverDrives) {
  LiveRun run(run_args("6", {"--port", "0"}));
  const unsigned short port = run.port(20.0);
  ASSERT_NE(port, 0) << run.output();
  live::test::FoxgloveTestClient client(port);
  EXPECT_EQ(client.subprotocol(), "foxglove.websocket.v1");
  for (const char* topic : {"/tf", "/joint_states", "/odom", "/robot_description"}) {
    EXPECT_EQ(client.channels().count(topic), 1u) << topic;
  }
  EXPECT_EQ(client.channels().at("/tf").at("schemaName"), "foxglove.FrameTransforms");
  client.subscribe({"/tf", "/joint_states", "/robot_description"});
  const std::vector<live::test::ReceivedMessage> got = client.read_for(3.0);
  std::size_t tf_count = 0, js_count = 0;
  const double tf_rate = wall_rate(got, "/tf", &tf_count);
  const double js_rate = wall_rate(got, "/joint_states", &js_count);
  EXPECT_NEAR(tf_rate, 30.0, 6.0) << tf_count << " /tf messages";
  EXPECT_NEAR(js_rate, 30.0, 6.0) << js_count << " /joint_states messages";

  // Decoded: the transforms form the CC8's tree under world, the joint states name its joints,
  // simulation time advances by 1/30 s between messages, and the rover drives forward (+x).
  std::vector<double> base_x, tf_times;
  std::size_t descriptions = 0;
  for (const auto& m : got) {
    const nlohmann::json j = nlohmann::json::parse(m.payload);
    if (m.topic == "/tf") {
      const nlohmann::json& root = j.at("transforms").at(0);
      EXPECT_EQ(root.at("parent_frame_id"), "world");
      EXPECT_GT(j.at("transforms").size(), 10u);
      base_x.push_back(root.at("translation").at("x").get<double>());
      tf_times.push_back(static_cast<double>(m.timestamp_ns) * 1e-9);
    } else if (m.topic == "/joint_states") {
      EXPECT_EQ(j.at("name").size(), j.at("position").size());
      EXPECT_GT(j.at("name").size(), 6u);
    } else if (m.topic == "/robot_description") {
      ++descriptions;
      EXPECT_NE(j.at("data").get<std::string>().find("<robot"), std::string::npos);
    }
  }
  EXPECT_EQ(descriptions, 1u);
  // Snapshots every 33 ticks (1 kHz): a whole number of them between messages, almost always one
  // (a loaded machine may delay the server past a snapshot: the newest wins).
  ASSERT_GT(tf_times.size(), 10u);
  std::size_t single = 0;
  for (std::size_t k = 1; k < tf_times.size(); ++k) {
    const double steps = (tf_times[k] - tf_times[k - 1]) / 0.033;
    EXPECT_NEAR(steps, std::round(steps), 1e-6) << "message " << k;
    EXPECT_GE(std::round(steps), 1.0) << "message " << k;
    single += std::round(steps) == 1.0 ? 1 : 0;
  }
  EXPECT_GE(static_cast<double>(single), 0.9 * static_cast<double>(tf_times.size() - 1));
  EXPECT_GT(base_x.back() - base_x.front(), 0.3);  // 0.5 m/s from t = 1 s
  int exit_code = -1;
  ASSERT_TRUE(run.wait(20.0, &exit_code)) << run.output();
  EXPECT_NE(run.output().find("live: 1 clients"), std::string::npos) << run.output();
}

// A client that subscribes and never reads again: the run finishes, its messages are
// dropped for that client, and the client's queue stays within the server's bound (4 MB).
TEST_F(LiveRunTest, StalledClientNeitherStopsTheRunNorGrowsMemory) {
  // 300 Hz of /tf and /joint_states at 4 times real time: far more than the client's buffers hold.
  LiveRun run(run_args("8", {"--port", "0", "--real-time-factor", "4", "--live-rate", "300"}));
  const unsigned short port = run.port(20.0);
  ASSERT_NE(port, 0) << run.output();
  live::test::FoxgloveTestClient client(port, 4096);
  client.subscribe({"/tf", "/joint_states"});
  int exit_code = -1;
  ASSERT_TRUE(run.wait(25.0, &exit_code)) << "the run did not finish with a stalled client\n" << run.output();
  EXPECT_TRUE(exit_code == 0 || exit_code == 1) << run.output();  // passed or failed its checks, not crashed
  EXPECT_TRUE(fs::exists(dir_ / "report" / "summary.json"));
  std::smatch m;
  const std::string out = run.output();
  ASSERT_TRUE(std::regex_search(out, m, std::regex("live: 1 clients, ([0-9]+) messages sent, ([0-9]+) dropped, peak client queue ([0-9]+) bytes")))
      << out;
  EXPECT_GT(std::stoull(m[2]), 10u) << out;
  EXPECT_LE(std::stoull(m[3]), 4u << 20) << out;
}

TEST_F(LiveRunTest, BusyPortFailsBeforeTheRunStarts) {
  live::ServerOptions options;
  options.port = 0;
  const live::FoxgloveServer taken(options);
  const std::string port = std::to_string(taken.port());
  const ProcessResult r = run_process(run_args("2", {"--port", port}), 30.0);
  ASSERT_TRUE(r.started);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("cannot listen on 127.0.0.1:" + port), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("choose another --port"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "report" / "summary.json"));  // nothing ran
}

TEST_F(LiveRunTest, LiveOptionsWithoutLiveAreAnError) {
  const ProcessResult r = run_process({MECHSIM_EXE, "run", std::string(MECHSIM_SOURCE_DIR) + "/robots/cc8/scenarios/straight_5m.yaml",
                                       "--port", "9000", "-o", dir_.string() + "/report"},
                                      30.0);
  ASSERT_TRUE(r.started);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("--port requires --live"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "report" / "summary.json"));
}

}  // namespace
}  // namespace mechsim::apps::test
