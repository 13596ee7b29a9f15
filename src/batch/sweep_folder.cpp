#include "batch/sweep_folder.hpp"

#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

namespace mechsim::batch {
namespace {

namespace fs = std::filesystem;

const char* kind_name(Axis::Kind k) {
  switch (k) {
    case Axis::Kind::List: return "list";
    case Axis::Kind::Grid: return "grid";
    case Axis::Kind::Uniform: return "uniform";
    case Axis::Kind::Normal: return "normal";
    case Axis::Kind::LogUniform: return "log_uniform";
    case Axis::Kind::Lhs: return "lhs";
  }
  return "?";
}

std::string origin(const std::string& location, const std::string& what) {
  return (location.empty() ? std::string() : location + ": ") + what;
}

}  // namespace

Plan make_plan(const SweepSpec& spec, std::size_t limit) {
  Plan plan;
  plan.name = spec.name;
  plan.sweep_file = spec.file;
  plan.scenario = spec.scenario;
  plan.set = spec.set;
  for (const Axis& a : spec.axes) plan.axes.push_back({a.path, kind_name(a.kind), a.location});
  plan.points = plan_points(spec, limit);
  plan.time_limit = spec.time_limit;
  plan.plots_per_point = spec.plots_per_point;
  plan.metrics = spec.metrics;
  plan.maps = spec.maps;
  return plan;
}

std::vector<Override> point_overrides(const Plan& plan, std::size_t index) {
  std::vector<Override> out;
  for (const FixedValue& f : plan.set) out.push_back({f.path, f.value, origin(f.location, "set: " + f.path)});
  const Point& p = plan.points.at(index);
  for (std::size_t a = 0; a < plan.axes.size(); ++a) {
    out.push_back({plan.axes[a].path, p.values[a], origin(plan.axes[a].location, "axis " + plan.axes[a].path)});
  }
  return out;
}

void check_plan(const Plan& plan) {
  if (plan.points.empty()) return;
  // The first point checks every path; then each axis's other values, one at a time.
  std::vector<Override> base = point_overrides(plan, 0);
  load_with_overrides(plan.scenario, base);
  const std::size_t first_axis = plan.set.size();
  for (std::size_t a = 0; a < plan.axes.size(); ++a) {
    std::set<std::string> seen{plan.points[0].values[a]};
    for (const Point& p : plan.points) {
      if (!seen.insert(p.values[a]).second) continue;
      // Random axes: every value is new; checking a few of them (the type and the range) is enough.
      if (seen.size() > 16) break;
      std::vector<Override> o = base;
      o[first_axis + a].value = p.values[a];
      load_with_overrides(plan.scenario, o);
    }
  }
}

std::string plan_json(const Plan& plan) {
  nlohmann::ordered_json j;
  j["name"] = plan.name;
  j["sweep_file"] = plan.sweep_file;
  j["scenario"] = plan.scenario;
  nlohmann::ordered_json set = nlohmann::ordered_json::array();
  for (const FixedValue& f : plan.set) set.push_back({{"path", f.path}, {"value", f.value}, {"location", f.location}});
  j["set"] = set;
  nlohmann::ordered_json axes = nlohmann::ordered_json::array();
  for (const PlanAxis& a : plan.axes) axes.push_back({{"path", a.path}, {"kind", a.kind}, {"location", a.location}});
  j["axes"] = axes;
  j["time_limit"] = plan.time_limit;
  j["plots_per_point"] = plan.plots_per_point;
  j["metrics"] = plan.metrics;
  j["maps"] = plan.maps;
  nlohmann::ordered_json points = nlohmann::ordered_json::array();
  for (const Point& p : plan.points) points.push_back(p.values);
  j["points"] = points;
  return j.dump(1) + "\n";
}

bool same_points(const Plan& a, const Plan& b) {
  Plan x = a, y = b;
  for (Plan* p : {&x, &y}) {
    p->time_limit = 0;
    p->plots_per_point = false;
    p->metrics.clear();
    p->maps.clear();
    // Where the axes are written does not change what they give.
    for (FixedValue& f : p->set) f.location.clear();
    for (PlanAxis& ax : p->axes) ax.location.clear();
  }
  return plan_json(x) == plan_json(y);
}

void write_plan(const fs::path& dir, const Plan& plan) {
  fs::create_directories(dir / "points");
  const fs::path tmp = dir / "plan.json.tmp";
  {
    std::ofstream out(tmp);
    out << plan_json(plan);
    if (!out) throw SweepError((dir / "plan.json").string() + ": cannot write");
  }
  fs::rename(tmp, dir / "plan.json");
}

Plan read_plan(const fs::path& dir) {
  std::ifstream in(dir / "plan.json");
  if (!in) throw SweepError(dir.string() + ": no sweep here (no plan.json)");
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    Plan plan;
    plan.name = j.at("name").get<std::string>();
    plan.sweep_file = j.at("sweep_file").get<std::string>();
    plan.scenario = j.at("scenario").get<std::string>();
    for (const auto& f : j.at("set")) {
      plan.set.push_back({f.at("path").get<std::string>(), f.at("value").get<std::string>(), f.at("location").get<std::string>()});
    }
    for (const auto& a : j.at("axes")) {
      plan.axes.push_back({a.at("path").get<std::string>(), a.at("kind").get<std::string>(), a.at("location").get<std::string>()});
    }
    plan.time_limit = j.at("time_limit").get<double>();
    plan.plots_per_point = j.at("plots_per_point").get<bool>();
    plan.metrics = j.at("metrics").get<std::vector<std::string>>();
    plan.maps = j.at("maps").get<std::vector<std::string>>();
    std::size_t index = 0;
    for (const auto& p : j.at("points")) {
      plan.points.push_back({index++, p.get<std::vector<std::string>>()});
      if (plan.points.back().values.size() != plan.axes.size()) throw SweepError("a point has the wrong number of values");
    }
    return plan;
  } catch (const std::exception& e) {
    throw SweepError((dir / "plan.json").string() + ": " + e.what());
  }
}

fs::path point_dir(const fs::path& dir, std::size_t index) {
  char name[32];
  std::snprintf(name, sizeof name, "%05zu", index);
  return dir / "points" / name;
}

}  // namespace mechsim::batch
