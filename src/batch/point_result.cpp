#include "batch/point_result.hpp"

#include <cmath>
#include <fstream>
#include <numbers>

#include <nlohmann/json.hpp>

namespace mechsim::batch {
namespace {

namespace fs = std::filesystem;
constexpr double kRadToDeg = 180.0 / std::numbers::pi;

constexpr std::pair<PointStatus, const char*> kNames[] = {
    {PointStatus::Passed, "passed"},   {PointStatus::Failed, "failed"},   {PointStatus::Incomplete, "incomplete"},
    {PointStatus::Error, "error"},     {PointStatus::Crashed, "crashed"}, {PointStatus::Timeout, "timeout"},
    {PointStatus::Interrupted, "interrupted"}};

std::optional<std::pair<double, double>> goal_of(const sim::Scenario& s) {
  for (auto e = s.timeline.rbegin(); e != s.timeline.rend(); ++e) {
    if (e->kind == sim::TimelineEvent::Kind::Route && !e->route.waypoints.empty()) {
      return std::pair{e->route.waypoints.back()[0], e->route.waypoints.back()[1]};
    }
  }
  for (const sim::Check& c : s.checks) {
    if (c.kind == sim::Check::Kind::FinalPose) return std::pair{c.x, c.y};
  }
  for (auto c = s.checks.rbegin(); c != s.checks.rend(); ++c) {
    if (c->kind == sim::Check::Kind::Reach) return std::pair{c->x, c->y};
  }
  return std::nullopt;
}

}  // namespace

const char* status_name(PointStatus s) {
  for (const auto& [status, name] : kNames) {
    if (status == s) return name;
  }
  return "?";
}

std::optional<PointStatus> parse_status(const std::string& name) {
  for (const auto& [status, n] : kNames) {
    if (name == n) return status;
  }
  return std::nullopt;
}

bool is_final(PointStatus s) {
  return s == PointStatus::Passed || s == PointStatus::Failed || s == PointStatus::Incomplete || s == PointStatus::Error;
}

PointResult result_of_run(const sim::Scenario& scenario, const sim::ScenarioResult& run, double wall_time) {
  PointResult r;
  r.status = run.passed ? PointStatus::Passed : (run.completed ? PointStatus::Failed : PointStatus::Incomplete);
  if (!run.completed) r.error = run.error;
  auto& m = r.metrics;
  if (const auto goal = goal_of(scenario)) m["final_error"] = std::hypot(run.final_x - goal->first, run.final_y - goal->second);
  m["distance"] = run.distance;
  m["final_x"] = run.final_x;
  m["final_y"] = run.final_y;
  m["final_yaw_deg"] = run.final_yaw * kRadToDeg;
  m["max_tilt_deg"] = run.max_tilt * kRadToDeg;
  if (run.has_odometry) {
    m["odometry_error"] = run.odometry_error;
    m["odometry_yaw_error_deg"] = run.odometry_yaw_error * kRadToDeg;
  }
  m["sim_time"] = run.sim_time;
  m["real_time_factor"] = run.real_time_factor;
  m["wall_time"] = wall_time;
  for (const sim::TrackingError& t : run.tracking) m["tracking_rms." + t.controller] = t.rms;
  for (const sim::CheckOutcome& c : run.checks) r.checks.emplace_back(c.name, c.passed);
  return r;
}

void write_point_result(const fs::path& dir, const PointResult& r) {
  nlohmann::ordered_json j;
  j["index"] = r.index;
  j["status"] = status_name(r.status);
  j["error"] = r.error;
  j["exit_code"] = r.exit_code;
  j["signal"] = r.signal;
  nlohmann::ordered_json metrics = nlohmann::ordered_json::object();
  for (const auto& [k, v] : r.metrics) {
    if (std::isfinite(v)) metrics[k] = v;  // JSON has no NaN: an absent metric is left out
  }
  j["metrics"] = metrics;
  nlohmann::ordered_json checks = nlohmann::ordered_json::array();
  for (const auto& [name, passed] : r.checks) checks.push_back({{"check", name}, {"passed", passed}});
  j["checks"] = checks;
  fs::create_directories(dir);
  const fs::path tmp = dir / "point.json.tmp";
  {
    std::ofstream out(tmp);
    out << j.dump(2) << "\n";
    if (!out) throw std::runtime_error(tmp.string() + ": cannot write");
  }
  fs::rename(tmp, dir / "point.json");
}

std::optional<PointResult> read_point_result(const fs::path& dir) {
  std::ifstream in(dir / "point.json");
  if (!in) return std::nullopt;
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    PointResult r;
    r.index = j.at("index").get<std::size_t>();
    const auto status = parse_status(j.at("status").get<std::string>());
    if (!status) return std::nullopt;
    r.status = *status;
    r.error = j.value("error", "");
    r.exit_code = j.value("exit_code", 0);
    r.signal = j.value("signal", 0);
    for (const auto& [k, v] : j.at("metrics").items()) r.metrics[k] = v.get<double>();
    for (const auto& c : j.at("checks")) r.checks.emplace_back(c.at("check").get<std::string>(), c.at("passed").get<bool>());
    return r;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace mechsim::batch
