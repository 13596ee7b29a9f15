#include "batch/slurm.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "batch/point_result.hpp"

extern char** environ;

namespace mechsim::batch {
namespace {

namespace fs = std::filesystem;

std::string shell_quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

void write_script(const fs::path& file, const std::string& text) {
  {
    std::ofstream out(file);
    out << text;
    if (!out) throw SweepError(file.string() + ": cannot write");
  }
  fs::permissions(file, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec | fs::perms::others_read |
                            fs::perms::others_exec);
}

std::string trim(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ' || s.back() == '\r')) s.pop_back();
  return s;
}

// sbatch --parsable prints "jobid" or "jobid;cluster".
std::string sbatch(const std::vector<std::string>& argv) {
  std::string out, err;
  const int rc = run_capture(argv, out, err);
  std::string command;
  for (const std::string& a : argv) command += (command.empty() ? "" : " ") + a;
  if (rc != 0) {
    throw SweepError("sbatch failed (" + (rc < 0 ? std::string("not found: is Slurm installed?") : std::string("status ") + std::to_string(rc)) +
                     "): " + trim(err) + "\n  command: " + command);
  }
  std::string id = trim(out);
  id = id.substr(0, id.find(';'));
  if (id.empty() || id.find_first_not_of("0123456789") != std::string::npos) {
    throw SweepError("sbatch printed no job id: '" + trim(out) + "' " + trim(err));
  }
  return id;
}

void write_submissions(const fs::path& dir, const std::vector<Submission>& subs) {
  nlohmann::ordered_json j = nlohmann::ordered_json::array();
  for (const Submission& s : subs) {
    j.push_back({{"array_job", s.array_job}, {"collect_job", s.collect_job}, {"tasks", s.tasks}, {"points_per_task", s.points_per_task}});
  }
  std::ofstream out(dir / "slurm" / "jobs.json");
  out << j.dump(1) << "\n";
}

}  // namespace

int run_capture(const std::vector<std::string>& argv, std::string& out, std::string& err) {
  int out_pipe[2], err_pipe[2];
  if (pipe(out_pipe) != 0) return -1;
  if (pipe(err_pipe) != 0) {
    close(out_pipe[0]);
    close(out_pipe[1]);
    return -1;
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, out_pipe[1], STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, err_pipe[1], STDERR_FILENO);
  posix_spawn_file_actions_addclose(&actions, out_pipe[0]);
  posix_spawn_file_actions_addclose(&actions, err_pipe[0]);
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = -1;
  const int rc = posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(out_pipe[1]);
  close(err_pipe[1]);
  // Both pipes drained in turn is enough for these commands' small outputs (< a pipe's 64 KiB).
  const auto drain = [](int fd, std::string& to) {
    char buf[4096];
    ssize_t n;
    while ((n = read(fd, buf, sizeof buf)) > 0) to.append(buf, static_cast<std::size_t>(n));
    close(fd);
  };
  drain(out_pipe[0], out);
  drain(err_pipe[0], err);
  if (rc != 0) return -1;
  int status = 0;
  if (waitpid(pid, &status, 0) != pid) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

std::size_t points_per_task(std::size_t points, const SlurmOptions& o) {
  if (o.points_per_task > 0) return o.points_per_task;
  const std::size_t tasks = std::max<std::size_t>(1, o.max_array_size);
  return std::max<std::size_t>(1, (points + tasks - 1) / tasks);
}

std::vector<std::size_t> tasks_to_run(const fs::path& dir, const Plan& plan, std::size_t per_task) {
  std::vector<std::size_t> tasks;
  for (std::size_t first = 0, task = 0; first < plan.points.size(); first += per_task, ++task) {
    for (std::size_t i = first; i < std::min(first + per_task, plan.points.size()); ++i) {
      const auto r = read_point_result(point_dir(dir, i));
      if (!r || !is_final(r->status)) {
        tasks.push_back(task);
        break;
      }
    }
  }
  return tasks;
}

std::string array_spec(const std::vector<std::size_t>& tasks, int limit) {
  std::string s;
  for (std::size_t i = 0; i < tasks.size();) {
    std::size_t j = i;
    while (j + 1 < tasks.size() && tasks[j + 1] == tasks[j] + 1) ++j;
    if (!s.empty()) s += ',';
    s += std::to_string(tasks[i]);
    if (j > i) s += std::string("-") + std::to_string(tasks[j]);
    i = j + 1;
  }
  if (limit > 0) s += std::string("%") + std::to_string(limit);
  return s;
}

Submission submit(const fs::path& dir_in, const Plan& plan, const std::vector<std::size_t>& tasks, std::size_t per_task,
                  const SlurmOptions& o) {
  const fs::path dir = fs::absolute(dir_in).lexically_normal();
  const fs::path slurm = dir / "slurm";
  fs::create_directories(slurm / "logs");
  write_script(slurm / "task.sh", "#!/bin/bash\n# mechsim sweep " + plan.name +
                                      ": one array task runs its block of points (written by mechsim sweep --slurm)\nexec " +
                                      shell_quoted(o.exe) + " sweep run-task " + shell_quoted(dir.string()) +
                                      " \"$SLURM_ARRAY_TASK_ID\" --points-per-task " + std::to_string(per_task) + " -j " +
                                      std::to_string(o.cpus_per_task) + "\n");
  write_script(slurm / "collect.sh", "#!/bin/bash\n# mechsim sweep " + plan.name +
                                         ": the table and plots once the array has ended (written by mechsim sweep --slurm)\nexec " +
                                         shell_quoted(o.exe) + " sweep collect " + shell_quoted(dir.string()) + "\n");
  std::vector<std::string> common;
  if (!o.partition.empty()) common.push_back("--partition=" + o.partition);
  for (const std::string& a : o.sbatch_args) common.push_back(a);
  std::vector<std::string> array{"sbatch", "--parsable", "--job-name=mechsim_" + plan.name, std::string("--array=") + array_spec(tasks, o.array_limit),
                                 std::string("--cpus-per-task=") + std::to_string(o.cpus_per_task),
                                 std::string("--output=") + (slurm / "logs" / "task_%A_%a.out").string()};
  if (!o.time.empty()) array.push_back("--time=" + o.time);
  array.insert(array.end(), common.begin(), common.end());
  array.push_back((slurm / "task.sh").string());
  Submission s;
  s.tasks = tasks;
  s.points_per_task = per_task;
  s.array_job = sbatch(array);
  std::vector<std::string> collect{"sbatch", "--parsable", "--job-name=mechsim_" + plan.name + "_collect",
                                   "--dependency=afterany:" + s.array_job, "--kill-on-invalid-dep=yes",
                                   std::string("--output=") + (slurm / "logs" / "collect_%j.out").string()};
  collect.insert(collect.end(), common.begin(), common.end());
  collect.push_back((slurm / "collect.sh").string());
  s.collect_job = sbatch(collect);
  std::vector<Submission> all = read_submissions(dir);
  all.push_back(s);
  write_submissions(dir, all);
  return s;
}

std::vector<Submission> read_submissions(const fs::path& dir) {
  std::vector<Submission> out;
  std::ifstream in(dir / "slurm" / "jobs.json");
  if (!in) return out;
  try {
    for (const auto& j : nlohmann::json::parse(in)) {
      Submission s;
      s.array_job = j.at("array_job").get<std::string>();
      s.collect_job = j.at("collect_job").get<std::string>();
      s.tasks = j.at("tasks").get<std::vector<std::size_t>>();
      s.points_per_task = j.at("points_per_task").get<std::size_t>();
      out.push_back(s);
    }
  } catch (const std::exception& e) {
    throw SweepError((dir / "slurm" / "jobs.json").string() + ": " + e.what());
  }
  return out;
}

std::string slurm_status(const fs::path& dir) {
  std::ostringstream text;
  for (const Submission& s : read_submissions(dir)) {
    text << "slurm array job " << s.array_job << " (" << s.tasks.size() << " tasks of " << s.points_per_task
         << " points), collect job " << s.collect_job << ":\n";
    std::map<std::string, std::vector<std::string>> states;  // state -> tasks
    std::string out, err;
    if (run_capture({"squeue", "-h", "-r", "-j", s.array_job + "," + s.collect_job, "-o", "%i %T"}, out, err) == 0) {
      std::istringstream lines(out);
      std::string id, state;
      while (lines >> id >> state) states[state].push_back(id);
    }
    out.clear();
    err.clear();
    const int rc = run_capture({"sacct", "-n", "-P", "-X", "-j", s.array_job + "," + s.collect_job, "-o", "JobID,State,ExitCode"}, out, err);
    if (rc == 0) {
      std::istringstream lines(out);
      std::string line;
      while (std::getline(lines, line)) {
        std::istringstream f(line);
        std::string id, state;
        std::getline(f, id, '|');
        std::getline(f, state, '|');
        if (id.empty() || state == "PENDING" || state == "RUNNING") continue;  // squeue's
        states[state.substr(0, state.find(' '))].push_back(id);
      }
    } else {
      text << "  (sacct: " << trim(err.empty() ? out : err) << ": finished tasks are known from the points' results only)\n";
    }
    if (states.empty()) text << "  no job in the queue\n";
    for (const auto& [state, ids] : states) {
      text << "  " << state << ": " << ids.size();
      if (state != "COMPLETED" && state != "PENDING" && state != "RUNNING") {
        text << " (";
        for (std::size_t i = 0; i < ids.size(); ++i) text << (i ? " " : "") << ids[i];
        text << ")";
      }
      text << "\n";
    }
  }
  return text.str();
}

}  // namespace mechsim::batch
