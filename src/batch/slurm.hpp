#pragma once
// A sweep on a Slurm cluster: one job array (`sbatch --array=...%K`) whose tasks each run a
// contiguous block of points with the same mechsim binary (`mechsim sweep run-task DIR TASK`,
// each point in its own process as locally), and a collect job that depends on the array
// (`--dependency=afterany`) and builds the table and plots. The sweep folder must be on a file
// system every node sees; the binary's absolute path must be valid on every node.
//
//   DIR/slurm/task.sh, collect.sh       the job scripts
//   DIR/slurm/logs/task_<job>_<task>.out, collect_<job>.out
//   DIR/slurm/jobs.json                 every submission: array job id, collect job id, tasks

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "batch/sweep_folder.hpp"

namespace mechsim::batch {

struct SlurmOptions {
  std::string exe;            // absolute path of the mechsim binary the tasks run
  std::string partition;      // sbatch --partition (empty: the cluster's default)
  std::string time;           // sbatch --time per task (empty: the partition's default)
  int array_limit = 0;        // %K: tasks running at once (0: no throttle)
  std::size_t points_per_task = 0;  // 0: as few as keep the array within max_array_size tasks
  std::size_t max_array_size = 1000;  // the cluster's MaxArraySize - 1 (Slurm's default is 1001)
  int cpus_per_task = 1;      // points a task runs at once
  std::vector<std::string> sbatch_args;  // passed to both sbatch calls as they are (--account=..., --qos=...)
};

struct Submission {
  std::string array_job;    // Slurm job id of the array
  std::string collect_job;  // of the collect job
  std::vector<std::size_t> tasks;
  std::size_t points_per_task = 1;
};

// Points per task for `points` points under `options`.
std::size_t points_per_task(std::size_t points, const SlurmOptions& options);

// The array tasks holding points without a final result (all of them for a new sweep).
std::vector<std::size_t> tasks_to_run(const std::filesystem::path& dir, const Plan& plan, std::size_t per_task);

// "0-19%4", "3,7,12%4": sbatch's --array for these task ids.
std::string array_spec(const std::vector<std::size_t>& tasks, int limit);

// Writes the job scripts, submits the array and the collect job, appends to jobs.json. Throws
// SweepError with sbatch's message when a submission fails.
Submission submit(const std::filesystem::path& dir, const Plan& plan, const std::vector<std::size_t>& tasks,
                  std::size_t per_task, const SlurmOptions& options);

std::vector<Submission> read_submissions(const std::filesystem::path& dir);

// The jobs' states from squeue and sacct (where accounting is on), for `mechsim sweep status`.
std::string slurm_status(const std::filesystem::path& dir);

// Runs a program and returns its exit status (-1: could not start) and its standard output;
// standard error goes to `err`.
int run_capture(const std::vector<std::string>& argv, std::string& out, std::string& err);

}  // namespace mechsim::batch
