#include "batch/local_runner.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "batch/point_result.hpp"
#include "batch/process_pool.hpp"

namespace mechsim::batch {
namespace {

namespace fs = std::filesystem;

std::string duration_text(double s) {
  char buf[32];
  if (s >= 3600) {
    std::snprintf(buf, sizeof buf, "%dh%02dm", static_cast<int>(s / 3600), static_cast<int>(std::fmod(s, 3600) / 60));
  } else if (s >= 60) {
    std::snprintf(buf, sizeof buf, "%dm%02ds", static_cast<int>(s / 60), static_cast<int>(std::fmod(s, 60)));
  } else {
    std::snprintf(buf, sizeof buf, "%.0fs", s);
  }
  return buf;
}

// What the parent knows of a point whose process left no result of its own.
PointResult outcome_without_result(const JobOutcome& o, double time_limit, const fs::path& log) {
  PointResult r;
  r.index = o.id;
  r.exit_code = o.exit_code;
  r.signal = o.signal;
  if (!o.started) {
    r.status = PointStatus::Crashed;
    r.error = "could not start the point's process";
  } else if (o.timed_out) {
    r.status = PointStatus::Timeout;
    r.error = "exceeded the time limit of " + duration_text(time_limit) + " (killed)";
  } else if (o.interrupted) {
    r.status = PointStatus::Interrupted;
    r.error = "interrupted";
  } else if (o.signal != 0) {
    r.status = PointStatus::Crashed;
    r.error = describe_signal(o.signal);
  } else {
    r.status = PointStatus::Crashed;
    r.error = "exited with status " + std::to_string(o.exit_code) + " without a result";
  }
  r.error += "; log: " + log.string();
  return r;
}

}  // namespace

std::string describe_signal(int signal) {
  return "killed by signal " + std::to_string(signal) + " (" + strsignal(signal) + ")";
}

std::vector<std::size_t> unfinished_points(const fs::path& dir, const Plan& plan, std::size_t first, std::size_t last) {
  std::vector<std::size_t> out;
  for (std::size_t i = first; i < std::min(last, plan.points.size()); ++i) {
    const auto r = read_point_result(point_dir(dir, i));
    if (!r || !is_final(r->status)) out.push_back(i);
  }
  return out;
}

Tally run_points_locally(const fs::path& dir, const Plan& plan, const std::vector<std::size_t>& points,
                         const LocalOptions& options) {
  std::vector<Job> jobs;
  const fs::path abs_dir = fs::absolute(dir);
  for (std::size_t i : points) {
    const fs::path folder = point_dir(abs_dir, i);
    fs::create_directories(folder);
    fs::remove(folder / "point.json");  // a crash before the point removes it must not leave the old one
    jobs.push_back({i, {options.exe, "sweep", "run-point", abs_dir.string(), std::to_string(i)}, (folder / "log.txt").string()});
  }
  PoolOptions pool;
  pool.jobs = options.jobs;
  pool.time_limit = plan.time_limit;
  pool.interrupt = options.interrupt;
  Tally tally;
  std::size_t crashed = 0;
  const auto start = std::chrono::steady_clock::now();
  run_jobs(jobs, pool, [&](const JobOutcome& o) {
    const fs::path folder = point_dir(abs_dir, o.id);
    std::optional<PointResult> r = read_point_result(folder);
    const bool own = r && o.exit_code == 0 && o.signal == 0 && !o.timed_out;
    if (!own) {
      r = outcome_without_result(o, plan.time_limit, folder / "log.txt");
      write_point_result(folder, *r);
    }
    if (r->status == PointStatus::Interrupted) {
      tally.interrupted = true;
    } else {
      ++tally.ran;
      ++(r->status == PointStatus::Passed ? tally.passed : tally.not_passed);
      if (!is_final(r->status)) ++crashed;
    }
    if (options.progress == nullptr) return;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::size_t remaining = points.size() - tally.ran;
    const double eta = tally.ran > 0 ? elapsed / static_cast<double>(tally.ran) * static_cast<double>(remaining) : 0.0;
    std::ostream& out = *options.progress;
    if (r->status != PointStatus::Passed && r->status != PointStatus::Failed && r->status != PointStatus::Interrupted) {
      out << (options.tty ? "\r\033[K" : "") << "point " << o.id << ": " << status_name(r->status) << ": " << r->error << "\n";
    }
    char line[200];
    const int width = 30;
    const double fraction = points.empty() ? 1.0 : static_cast<double>(tally.ran) / static_cast<double>(points.size());
    const int filled = static_cast<int>(fraction * width + 0.5);
    std::snprintf(line, sizeof line, "[%.*s%*s] %zu/%zu points, %zu passed, %zu not passed (%zu crashed or timed out), %s, ETA %s",
                  filled, "##############################", width - filled, "", tally.ran, points.size(), tally.passed,
                  tally.not_passed, crashed, duration_text(elapsed).c_str(), duration_text(eta).c_str());
    out << (options.tty ? "\r\033[K" : "") << line << (options.tty ? "" : "\n") << std::flush;
  });
  if (options.progress != nullptr && options.tty) *options.progress << "\n";
  // A stop that came between two points interrupted no running point, but points were left.
  if (options.interrupt != nullptr && options.interrupt->load() != 0 && tally.ran < points.size()) tally.interrupted = true;
  tally.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return tally;
}

}  // namespace mechsim::batch
