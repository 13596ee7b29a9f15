// The wire tests' network namespace, processes and JSON output (wire_util.hpp).
#include "wire_util.hpp"

#include <fcntl.h>
#include <sched.h>
#include <sys/prctl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include <mechsim_test_paths.hpp>

namespace mechsim::ros2::test {

namespace {

int run_quiet(const std::vector<std::string>& argv) {
  const pid_t pid = fork();
  if (pid == 0) {
    const int null = open("/dev/null", O_WRONLY);
    if (null >= 0) {
      dup2(null, 1);
      dup2(null, 2);
    }
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    execvp(args[0], args.data());
    _exit(127);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

PrivateNetwork::PrivateNetwork() {
  if (geteuid() != 0) {
    error_ = "not root: the ROS 2 wire tests make a private network namespace (unshare -n) for their DDS traffic";
    return;
  }
  original_ = open("/proc/thread-self/ns/net", O_RDONLY);
  if (original_ < 0) {
    error_ = std::string("cannot open /proc/thread-self/ns/net: ") + std::strerror(errno);
    return;
  }
  if (unshare(CLONE_NEWNET) != 0) {
    error_ = std::string("unshare(CLONE_NEWNET): ") + std::strerror(errno);
    return;
  }
  if (run_quiet({"ip", "link", "set", "lo", "up", "multicast", "on"}) != 0 ||
      run_quiet({"ip", "route", "add", "224.0.0.0/4", "dev", "lo"}) != 0) {
    error_ = "could not bring up lo with multicast in the test's network namespace (`ip` from iproute2)";
  }
}

PrivateNetwork::~PrivateNetwork() {
  if (original_ >= 0) {
    setns(original_, CLONE_NEWNET);
    close(original_);
  }
}

std::string PrivateNetwork::cyclone_uri() {
  return "<CycloneDDS><Domain><General><Interfaces><NetworkInterface name=\"lo\" multicast=\"true\"/></Interfaces>"
         "</General></Domain></CycloneDDS>";
}

Process::Process(const std::vector<std::string>& argv, const std::string& log, const std::map<std::string, std::string>& env)
    : log_(log) {
  pid_ = fork();
  if (pid_ == 0) {
    setpgid(0, 0);
    // Gone with the test: a test killed by its timeout leaves no mechsim or peer running.
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      dup2(fd, 1);
      dup2(fd, 2);
    }
    for (const auto& [k, v] : env) setenv(k.c_str(), v.c_str(), 1);
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    execvp(args[0], args.data());
    std::fprintf(stderr, "cannot run %s: %s\n", args[0], std::strerror(errno));
    _exit(127);
  }
}

Process::~Process() {
  if (pid_ > 0 && !status_) stop();
}

std::optional<int> Process::wait(std::chrono::duration<double> timeout) {
  if (status_) return status_;
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    int status = 0;
    const pid_t r = waitpid(pid_, &status, WNOHANG);
    if (r == pid_) {
      status_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
      return status_;
    }
    if (std::chrono::steady_clock::now() > deadline) return std::nullopt;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

int Process::stop() {
  if (status_) return *status_;
  kill(pid_, SIGTERM);
  if (auto s = wait(std::chrono::seconds(5))) return *s;
  kill(-pid_, SIGKILL);
  kill(pid_, SIGKILL);
  return wait(std::chrono::seconds(5)).value_or(-1);
}

std::string Process::output() const {
  std::ifstream in(log_);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

bool Process::wait_for_output(const std::string& text, std::chrono::duration<double> timeout) const {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < deadline) {
    if (output().find(text) != std::string::npos) return true;
    int status = 0;
    if (waitpid(pid_, &status, WNOHANG) == pid_) {
      // Ended: put the status back for wait() by re-reading later is not possible; report false.
      const_cast<Process*>(this)->status_ =
          WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
      return output().find(text) != std::string::npos;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

std::string test_dir(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(MECHSIM_BINARY_DIR) / "Testing" / "ros2_wire" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

std::vector<nlohmann::json> json_lines(const std::string& text) {
  std::vector<nlohmann::json> out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] != '{') continue;
    try {
      out.push_back(nlohmann::json::parse(line));
    } catch (const std::exception&) {
    }
  }
  return out;
}

nlohmann::json summary(const std::vector<nlohmann::json>& lines, const std::string& topic) {
  for (const auto& l : lines)
    if (l.value("topic", "") == topic && l.value("summary", false)) return l;
  return {};
}

nlohmann::json first_sample(const std::vector<nlohmann::json>& lines, const std::string& topic) {
  for (const auto& l : lines)
    if (l.value("topic", "") == topic && l.contains("sample")) return l["sample"];
  return {};
}

}  // namespace mechsim::ros2::test
