// `mechsim sweep SWEEP.yaml -o DIR`: parameter sweeps and Monte Carlo batches of a scenario,
// locally (-j N processes) or as a Slurm job array (--slurm); `sweep collect DIR` builds the
// table and plots, `sweep status DIR` tells how far a sweep is. `run-point` and `run-task` are
// what the sweep's own processes run (a point; a Slurm array task's block of points).

#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <thread>

#include "apps/commands.hpp"
#include "apps/stop_on_signals.hpp"
#include "batch/local_runner.hpp"
#include "batch/point_result.hpp"
#include "batch/point_run.hpp"
#include "batch/results_table.hpp"
#include "batch/slurm.hpp"
#include "batch/sweep_folder.hpp"
#include "batch/sweep_plots.hpp"

namespace mechsim::apps {
namespace {

namespace fs = std::filesystem;

struct SweepArgs {
  std::string sweep_file;
  std::string output;
  int jobs = 0;
  bool resume = false;
  bool force = false;
  bool no_plots = false;
  bool slurm = false;
  batch::SlurmOptions slurm_options;
  std::size_t points_per_task = 0;
  std::string dir;  // collect, status, run-point, run-task
  std::size_t index = 0;
};

std::string this_binary() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) throw UserError("cannot find the mechsim binary (/proc/self/exe): " + ec.message());
  return exe.string();
}

// Test only: MECHSIM_SWEEP_TEST_FAULT="crash@3,hang@5" makes point 3 end on SIGSEGV and point 5
// hang (ignoring the stop request), for the failure tests of the sweep machinery.
void inject_test_fault(std::size_t index) {
  const char* spec = std::getenv("MECHSIM_SWEEP_TEST_FAULT");
  if (spec == nullptr) return;
  std::istringstream items(spec);
  std::string item;
  while (std::getline(items, item, ',')) {
    const auto at = item.find('@');
    if (at == std::string::npos || std::to_string(index) != item.substr(at + 1)) continue;
    const std::string fault = item.substr(0, at);
    std::cerr << "MECHSIM_SWEEP_TEST_FAULT: " << fault << " at point " << index << "\n" << std::flush;
    if (fault == "crash") {
      std::signal(SIGSEGV, SIG_DFL);
      std::raise(SIGSEGV);
    }
    if (fault == "hang") {
      for (;;) pause();
    }
  }
}

void collect(const fs::path& dir, const batch::Plan& plan, bool plots) {
  const batch::Table table = batch::collect_table(dir, plan);
  batch::write_table(dir, plan, table);
  std::cout << "sweep " << plan.name << ": " << plan.points.size() << " points: " << table.passed << " passed, "
            << table.not_passed << " not passed";
  if (table.missing > 0) std::cout << ", " << table.missing << " without a result yet";
  std::cout << "\ntable: " << fs::absolute(dir / "results.csv").lexically_normal().string() << ", results.json\n";
  if (!plots) return;
  std::vector<std::string> errors;
  const std::vector<std::string> written = batch::write_plots(dir, plan, errors);
  if (!written.empty()) {
    std::cout << "plots:";
    for (const std::string& p : written) std::cout << " " << p;
    std::cout << "\n";
  }
  for (const std::string& e : errors) std::cerr << "warning: " << e << "\n";
}

void run_sweep(const SweepArgs& args, CommandResult& result) {
  if (args.sweep_file.empty()) throw UserError("give a sweep file (mechsim sweep SWEEP.yaml -o DIR), or collect/status DIR");
  const batch::SweepSpec spec = batch::load_sweep(args.sweep_file, args.force);
  const batch::Plan plan = batch::make_plan(spec);
  batch::check_plan(plan);
  const fs::path dir = args.output.empty() ? fs::path("out") / ("sweep_" + plan.name) : fs::path(args.output);
  if (fs::exists(dir / "plan.json")) {
    if (!args.resume) {
      throw UserError(dir.string() + " already holds a sweep: give --resume to continue it, or another -o folder");
    }
    if (!batch::same_points(batch::read_plan(dir), plan)) {
      throw UserError(dir.string() + " holds another sweep (its points differ from what " + args.sweep_file +
                      " gives now): use another -o folder");
    }
    batch::write_plan(dir, plan);  // the metrics, maps and time limit may have changed
  } else {
    batch::write_plan(dir, plan);
    fs::copy_file(spec.file, dir / "sweep.yaml", fs::copy_options::overwrite_existing);
  }
  const std::string exe = this_binary();
  if (args.slurm) {
    batch::SlurmOptions o = args.slurm_options;
    o.exe = exe;
    o.points_per_task = args.points_per_task;
    const std::size_t per_task = batch::points_per_task(plan.points.size(), o);
    const std::vector<std::size_t> tasks = batch::tasks_to_run(dir, plan, per_task);
    if (tasks.empty()) {
      std::cout << "sweep " << plan.name << ": every point has a result; nothing to submit\n";
      return;
    }
    const batch::Submission s = batch::submit(dir, plan, tasks, per_task, o);
    std::cout << "sweep " << plan.name << ": " << plan.points.size() << " points; submitted array job " << s.array_job << " ("
              << tasks.size() << " tasks of up to " << per_task << " points, --array=" << batch::array_spec(tasks, o.array_limit)
              << ") and collect job " << s.collect_job << "\nstatus: mechsim sweep status " << dir.string()
              << "\ntable when done: " << (fs::absolute(dir) / "results.csv").lexically_normal().string() << "\n";
    return;
  }
  const std::vector<std::size_t> todo = batch::unfinished_points(dir, plan);
  batch::LocalOptions o;
  o.exe = exe;
  o.jobs = args.jobs > 0 ? args.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  o.interrupt = &g_stop_signal;
  o.progress = &std::cerr;
  o.tty = isatty(fileno(stderr)) != 0;
  std::cout << "sweep " << plan.name << ": " << plan.points.size() << " points, " << todo.size() << " to run ("
            << plan.points.size() - todo.size() << " have a result), " << o.jobs << " at a time, time limit "
            << plan.time_limit << " s per point\nfolder: " << fs::absolute(dir).lexically_normal().string() << "\n" << std::flush;
  const StopOnSignals stop_on_signals;
  const batch::Tally tally = batch::run_points_locally(dir, plan, todo, o);
  std::cout << "ran " << tally.ran << " points in " << tally.wall_time << " s: " << tally.passed << " passed, " << tally.not_passed
            << " not passed\n";
  collect(dir, plan, !args.no_plots);
  if (tally.interrupted) {
    std::cout << "interrupted: continue with mechsim sweep " << args.sweep_file << " -o " << dir.string() << " --resume\n";
    result.exit_code = 128 + g_stop_signal.load();
  }
}

void run_task(const SweepArgs& args, CommandResult& result) {
  const fs::path dir = args.dir;
  const batch::Plan plan = batch::read_plan(dir);
  if (args.points_per_task == 0) throw UserError("--points-per-task must be >= 1");
  const std::size_t first = args.index * args.points_per_task;
  const std::vector<std::size_t> todo = batch::unfinished_points(dir, plan, first, first + args.points_per_task);
  std::cout << "task " << args.index << ": points " << first << " to " << first + args.points_per_task - 1 << ", " << todo.size()
            << " to run\n" << std::flush;
  batch::LocalOptions o;
  o.exe = this_binary();
  o.jobs = std::max(1, args.jobs);
  o.interrupt = &g_stop_signal;
  o.progress = &std::cout;
  const StopOnSignals stop_on_signals;
  const batch::Tally tally = batch::run_points_locally(dir, plan, todo, o);
  // A task with a point that crashed or timed out fails, so that sacct shows which to resubmit.
  const std::vector<std::size_t> left = batch::unfinished_points(dir, plan, first, first + args.points_per_task);
  if (tally.interrupted) result.exit_code = 128 + g_stop_signal.load();
  else if (!left.empty()) result.exit_code = 1;
}

void status(const SweepArgs& args) {
  const fs::path dir = args.dir;
  const batch::Plan plan = batch::read_plan(dir);
  std::map<std::string, std::size_t> counts;
  for (const batch::Point& p : plan.points) {
    const auto r = batch::read_point_result(batch::point_dir(dir, p.index));
    ++counts[r ? batch::status_name(r->status) : "not run yet"];
  }
  std::cout << "sweep " << plan.name << ": " << plan.points.size() << " points:";
  bool first = true;
  for (const auto& [name, n] : counts) {
    std::cout << (first ? " " : ", ") << n << " " << name;
    first = false;
  }
  std::cout << "\n" << batch::slurm_status(dir);
  const std::vector<batch::Submission> subs = batch::read_submissions(dir);
  if (!subs.empty()) {
    // Known from the points themselves (sacct needs the cluster's accounting).
    const std::vector<std::size_t> tasks = batch::tasks_to_run(dir, plan, subs.back().points_per_task);
    if (!tasks.empty()) {
      std::cout << "array tasks with points crashed, timed out or not run: " << batch::array_spec(tasks, 0)
                << " (once the jobs have ended: mechsim sweep SWEEP.yaml -o " << dir.string() << " --slurm --resume)\n";
    }
  }
  if (fs::exists(dir / "results.csv")) std::cout << "table: " << (dir / "results.csv").string() << "\n";
}

}  // namespace

void add_sweep_command(CLI::App& app, CommandResult& result) {
  auto args = std::make_shared<SweepArgs>();
  CLI::App* cmd = app.add_subcommand("sweep", "Parameter sweeps and Monte Carlo batches of a scenario, locally or on Slurm");
  cmd->require_subcommand(0, 1);
  cmd->add_option("sweep", args->sweep_file, "Sweep file (YAML): base scenario, axes, metrics");
  cmd->add_option("-o,--output", args->output, "Sweep folder (default: out/sweep_<name>)");
  cmd->add_option("-j,--jobs", args->jobs, "Points run at once (default: all cores)")->check(CLI::Range(1, 4096));
  cmd->add_flag("--resume", args->resume, "Continue the sweep in the folder: run only the points without a result");
  cmd->add_flag("--force", args->force, "Run a sweep of more than 100000 points");
  cmd->add_flag("--no-plots", args->no_plots, "Write the table but no plots");
  cmd->add_flag("--slurm", args->slurm, "Submit a Slurm job array (sbatch) instead of running here");
  cmd->add_option("--partition", args->slurm_options.partition, "Slurm partition");
  cmd->add_option("--time", args->slurm_options.time, "Slurm time limit per array task (sbatch --time)");
  cmd->add_option("--array-limit", args->slurm_options.array_limit, "Array tasks running at once (sbatch --array=...%K)")
      ->check(CLI::Range(1, 1000000));
  cmd->add_option("--points-per-task", args->points_per_task, "Points per array task (default: enough to stay under --max-array-size tasks)");
  cmd->add_option("--max-array-size", args->slurm_options.max_array_size, "Most array tasks the cluster takes (MaxArraySize - 1; default 1000)")
      ->check(CLI::Range(1, 4000000));
  cmd->add_option("--cpus-per-task", args->slurm_options.cpus_per_task, "Cores per array task (its points run that many at once)")
      ->check(CLI::Range(1, 4096));
  cmd->add_option("--sbatch-arg", args->slurm_options.sbatch_args, "Passed to sbatch as it is (repeat: --sbatch-arg=--account=A)");
  cmd->callback([cmd, args, &result] {
    if (cmd->get_subcommands().empty()) run_sweep(*args, result);
  });

  CLI::App* collect_cmd = cmd->add_subcommand("collect", "Build the sweep's table (results.csv, results.json) and plots");
  collect_cmd->add_option("dir", args->dir, "Sweep folder")->required();
  collect_cmd->add_flag("--no-plots", args->no_plots, "Write the table but no plots");
  collect_cmd->callback([args] { collect(args->dir, batch::read_plan(args->dir), !args->no_plots); });

  CLI::App* status_cmd = cmd->add_subcommand("status", "How far a sweep is: points by outcome, Slurm jobs by state");
  status_cmd->add_option("dir", args->dir, "Sweep folder")->required();
  status_cmd->callback([args] { status(*args); });

  // What the sweep's own processes run; not for users (hidden from --help).
  CLI::App* point_cmd = cmd->add_subcommand("run-point", "Run one point of a sweep in this process")->group("");
  point_cmd->add_option("dir", args->dir, "Sweep folder")->required();
  point_cmd->add_option("index", args->index, "Point")->required();
  point_cmd->callback([args, &result] {
    const batch::Plan plan = batch::read_plan(args->dir);
    if (args->index >= plan.points.size()) throw UserError("the sweep has no point " + std::to_string(args->index));
    const StopOnSignals stop_on_signals;
    inject_test_fault(args->index);
    result.exit_code = batch::run_point(args->dir, plan, args->index, &g_stop_signal);
  });
  CLI::App* task_cmd = cmd->add_subcommand("run-task", "Run a Slurm array task's points")->group("");
  task_cmd->add_option("dir", args->dir, "Sweep folder")->required();
  task_cmd->add_option("task", args->index, "Array task id")->required();
  task_cmd->add_option("--points-per-task", args->points_per_task, "Points per task")->required();
  task_cmd->add_option("-j,--jobs", args->jobs, "Points at once");
  task_cmd->callback([args, &result] { run_task(*args, result); });
}

}  // namespace mechsim::apps
