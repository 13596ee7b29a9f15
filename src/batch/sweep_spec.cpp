#include "batch/sweep_spec.hpp"

#include <cmath>
#include <filesystem>
#include <limits>

#include "control/params.hpp"
#include "control/params_keys.hpp"

namespace mechsim::batch {
namespace {

namespace fs = std::filesystem;
using control::Params;

[[noreturn]] void fail(const Params& at, const std::string& what) {
  const std::string where = at.location().empty() ? "" : at.location() + ": ";
  throw SweepError(where + at.path() + ": " + what);
}

void only_keys(const Params& p, std::initializer_list<const char*> allowed) {
  if (!p.is_map()) fail(p, "expected a map");
  if (const auto unknown = control::unknown_key(p, allowed)) fail(p.child(unknown->key), unknown->message);
}

double finite(const Params& p, const char* key) {
  const double v = p.get<double>(key);
  if (!std::isfinite(v)) fail(p.child(key), "must be finite");
  return v;
}

// [a, b] with a < b.
void read_range(const Params& p, Axis& axis) {
  const auto v = p.as<std::vector<double>>();
  if (v.size() != 2 || !std::isfinite(v[0]) || !std::isfinite(v[1]) || !(v[0] < v[1])) {
    fail(p, "expected [low, high] with low < high");
  }
  axis.a = v[0];
  axis.b = v[1];
}

std::string scalar_text(const Params& p) {
  if (!p.is_scalar()) fail(p, "expected a scalar value");
  return p.as<std::string>();
}

void check_path(const Params& p, const std::string& path) {
  if (path.empty() || path.front() == '.' || path.back() == '.' || path.find("..") != std::string::npos ||
      path.find('/') != std::string::npos) {
    fail(p, "'" + path + "' is not a dotted scenario path (e.g. spawn.yaw, timeline.0.route.speed)");
  }
}

Axis read_axis(const Params& p) {
  only_keys(p, {"path", "list", "grid", "uniform", "normal", "log_uniform", "lhs", "integer"});
  Axis axis;
  axis.location = p.location();
  axis.path = p.get<std::string>("path");
  check_path(p.child("path"), axis.path);
  axis.integer = p.get<bool>("integer", false);
  int kinds = 0;
  for (const char* k : {"list", "grid", "uniform", "normal", "log_uniform", "lhs"}) kinds += p.has(k) ? 1 : 0;
  if (kinds != 1) fail(p, "needs exactly one of list, grid, uniform, normal, log_uniform, lhs");
  if (auto list = p.find("list")) {
    axis.kind = Axis::Kind::List;
    if (!list->is_list()) fail(*list, "expected a list of values");
    if (list->size() == 0) fail(*list, "is empty: an axis needs at least one value");
    for (const Params& v : list->items()) axis.values.push_back(scalar_text(v));
    if (axis.integer) fail(p.child("integer"), "goes with grid and random axes (write integers in the list)");
  } else if (auto grid = p.find("grid")) {
    axis.kind = Axis::Kind::Grid;
    only_keys(*grid, {"from", "to", "steps"});
    axis.a = finite(*grid, "from");
    axis.b = finite(*grid, "to");
    axis.steps = grid->get<int>("steps");
    if (axis.steps < 1) fail(grid->child("steps"), "must be >= 1 (the axis would be empty)");
    if (axis.steps == 1 && axis.a != axis.b) fail(grid->child("steps"), "1 step needs from == to");
  } else if (auto u = p.find("uniform")) {
    axis.kind = Axis::Kind::Uniform;
    read_range(*u, axis);
  } else if (auto n = p.find("normal")) {
    axis.kind = Axis::Kind::Normal;
    only_keys(*n, {"mean", "stddev"});
    axis.a = finite(*n, "mean");
    axis.b = finite(*n, "stddev");
    if (!(axis.b > 0.0)) fail(n->child("stddev"), "must be > 0");
  } else if (auto l = p.find("log_uniform")) {
    axis.kind = Axis::Kind::LogUniform;
    read_range(*l, axis);
    if (!(axis.a > 0.0)) fail(*l, "bounds must be > 0");
  } else if (auto h = p.find("lhs")) {
    axis.kind = Axis::Kind::Lhs;
    read_range(*h, axis);
  }
  return axis;
}

}  // namespace

const std::vector<std::string>& known_metrics() {
  static const std::vector<std::string> metrics = {
      "final_error", "distance", "final_x", "final_y", "final_yaw_deg", "max_tilt_deg", "odometry_error",
      "odometry_yaw_error_deg", "sim_time", "real_time_factor", "wall_time"};
  return metrics;
}

std::size_t point_count(const SweepSpec& spec) {
  std::size_t n = spec.samples;
  for (const Axis& a : spec.axes) {
    if (!a.discrete()) continue;
    const std::size_t k = a.size();
    if (k != 0 && n > std::numeric_limits<std::size_t>::max() / k) return std::numeric_limits<std::size_t>::max();
    n *= k;
  }
  return n;
}

SweepSpec load_sweep(const std::string& path, bool force) {
  if (!fs::exists(path)) throw SweepError(path + ": no such sweep file");
  Params root;
  try {
    root = Params::from_yaml_file(path);
  } catch (const std::exception& e) {
    throw SweepError(e.what());
  }
  SweepSpec spec;
  spec.file = fs::absolute(path).lexically_normal().string();
  try {
    only_keys(root, {"name", "scenario", "set", "samples", "seed", "time_limit", "plots_per_point", "metrics", "maps", "axes"});
    spec.name = root.get<std::string>("name", fs::path(path).stem().string());
    const fs::path scenario = root.get<std::string>("scenario");
    spec.scenario = (scenario.is_absolute() ? scenario : fs::path(spec.file).parent_path() / scenario).lexically_normal().string();
    if (!fs::exists(spec.scenario)) fail(root.child("scenario"), "no such scenario file: " + spec.scenario);
    if (auto set = root.find("set")) {
      if (!set->is_map()) fail(*set, "expected a map of scenario path -> value");
      for (const std::string& k : set->keys()) {
        check_path(set->child(k), k);
        spec.set.push_back({k, scalar_text(set->child(k)), set->child(k).location()});
      }
    }
    const Params axes = root.child("axes");
    spec.axes_location = axes.location();
    if (!axes.is_list() || axes.size() == 0) fail(axes, "expected a non-empty list of axes");
    for (const Params& a : axes.items()) {
      spec.axes.push_back(read_axis(a));
      for (std::size_t i = 0; i + 1 < spec.axes.size(); ++i) {
        if (spec.axes[i].path == spec.axes.back().path) fail(a.child("path"), "path '" + spec.axes.back().path + "' has two axes");
      }
      for (const FixedValue& f : spec.set) {
        if (f.path == spec.axes.back().path) fail(a.child("path"), "path '" + f.path + "' is also under set:");
      }
    }
    bool random = false;
    for (const Axis& a : spec.axes) random = random || !a.discrete();
    if (root.has("samples")) {
      const int samples = root.get<int>("samples");
      if (samples < 1) fail(root.child("samples"), "must be >= 1");
      if (!random) fail(root.child("samples"), "goes with random or lhs axes (there are none)");
      spec.samples = static_cast<std::size_t>(samples);
    } else if (random) {
      fail(root, "random and lhs axes need `samples` (how many draws)");
    }
    const int seed = root.get<int>("seed", 1);
    if (seed < 0) fail(root.child("seed"), "must be >= 0");
    spec.seed = static_cast<std::uint64_t>(seed);
    spec.time_limit = root.get<double>("time_limit", spec.time_limit);
    if (!(spec.time_limit > 0.0) || !std::isfinite(spec.time_limit)) fail(root.child("time_limit"), "must be > 0 s");
    spec.plots_per_point = root.get<bool>("plots_per_point", false);
    spec.metrics = root.get<std::vector<std::string>>("metrics", known_metrics());
    for (const std::string& m : spec.metrics) {
      bool known = m.starts_with("tracking_rms.");
      for (const std::string& k : known_metrics()) known = known || k == m;
      if (!known) {
        std::string list;
        for (const std::string& k : known_metrics()) list += k + ", ";
        fail(root.child("metrics"), "unknown metric '" + m + "' (expected one of: " + list + "tracking_rms.<controller>)");
      }
    }
    if (root.has("maps")) {
      spec.maps = root.get<std::vector<std::string>>("maps");
      if (spec.maps.size() != 2) fail(root.child("maps"), "expected two axis paths");
      for (const std::string& m : spec.maps) {
        bool found = false;
        for (const Axis& a : spec.axes) found = found || a.path == m;
        if (!found) fail(root.child("maps"), "'" + m + "' is not the path of an axis");
      }
    } else {
      for (std::size_t i = 0; i < spec.axes.size() && i < 2; ++i) spec.maps.push_back(spec.axes[i].path);
    }
    const std::size_t n = point_count(spec);
    if (n > kMaxPointsWithoutForce && !force) {
      fail(axes, std::to_string(n) + " points (more than " + std::to_string(kMaxPointsWithoutForce) +
                     "): check the axes, or give --force to run them all");
    }
  } catch (const SweepError&) {
    throw;
  } catch (const std::exception& e) {
    throw SweepError(e.what());
  }
  return spec;
}

}  // namespace mechsim::batch
