#include "sim/replay_recorder.hpp"

#include <algorithm>
#include <variant>
#include <cmath>

#include <nlohmann/json.hpp>

#include "description/sensor_spec.hpp"
#include "sim/replay_assets.hpp"

namespace mechsim::sim {

namespace fs = std::filesystem;

ReplayRecorder::ReplayRecorder(const Simulation& sim, const Scenario& scenario, const std::string& dir, const std::string& urdf)
    : scenario_name_(scenario.name) {
  if (dir.empty() || !(scenario.replay_rate > 0.0)) return;
  active_ = true;
  dir_ = fs::path(dir) / "replay";
  every_ = std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::llround(1.0 / (scenario.replay_rate * scenario.period))));
  rate_ = 1.0 / (static_cast<double>(every_) * scenario.period);  // what the frames' spacing is (30 Hz at 1 kHz: 30.3)
  for (const TimelineEvent& e : scenario.timeline) {
    if (e.kind == TimelineEvent::Kind::Route) waypoints_.insert(waypoints_.end(), e.route.waypoints.begin(), e.route.waypoints.end());
  }
  // A manifest left by an earlier run in this folder would describe poses.bin before it is whole.
  std::error_code ec;
  fs::remove(dir_ / "manifest.json", ec);
  write_replay_assets(sim, dir_, urdf);
  // Free objects (a world box that is not fixed: its own body "box:<name>", at its shape).
  for (const physics::WorldBox& b : sim.world().spec.boxes) {
    if (b.fixed) continue;
    const int body = sim.physics().model().body_index("box:" + b.name);
    if (body < 1) continue;
    object_bodies_.push_back(body);
    object_names_.push_back(b.name);
  }
  // The passive models' moving bodies (world.json "bodies"; "world" stays where it is).
  for (const physics::PassiveShape& s : sim.physics().model().passive_shapes()) {
    if (s.body < 1 || std::find(object_bodies_.begin(), object_bodies_.end(), s.body) != object_bodies_.end()) continue;
    object_bodies_.push_back(s.body);
    object_names_.push_back(s.body_name);
  }
  frame_.assign(1 + 7 * (sim.physics().model().links().size() + object_bodies_.size()), 0.0f);
  buffer_.resize(1 << 16);
  poses_.rdbuf()->pubsetbuf(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
  poses_.open(dir_ / "poses.bin", std::ios::binary | std::ios::trunc);
  if (!poses_) throw ScenarioError("replay: cannot write " + (dir_ / "poses.bin").string());
}

void ReplayRecorder::observe(const Simulation& sim, std::uint64_t last_tick) {
  if (!active_) return;
  const std::uint64_t tick = sim.ticks();
  if (tick % every_ != 0 && tick != last_tick) return;
  const physics::Physics& physics = sim.physics();
  frame_[0] = static_cast<float>(sim.time());
  const std::size_t links = (frame_.size() - 1) / 7 - object_bodies_.size();
  for (std::size_t i = 0; i < links + object_bodies_.size(); ++i) {
    const description::Pose X_WL = i < links ? physics.link_pose(i) : physics.body_pose(object_bodies_[i - links]);
    float* f = &frame_[1 + 7 * i];
    f[0] = static_cast<float>(X_WL.position.x);
    f[1] = static_cast<float>(X_WL.position.y);
    f[2] = static_cast<float>(X_WL.position.z);
    f[3] = static_cast<float>(X_WL.orientation.w);
    f[4] = static_cast<float>(X_WL.orientation.x);
    f[5] = static_cast<float>(X_WL.orientation.y);
    f[6] = static_cast<float>(X_WL.orientation.z);
  }
  poses_.write(reinterpret_cast<const char*>(frame_.data()), static_cast<std::streamsize>(frame_.size() * sizeof(float)));
  ++frames_;
}

void ReplayRecorder::finish(const Simulation& sim, const std::vector<std::string>& report_files, bool has_odometry,
                            const std::vector<std::string>& sensor_files) {
  if (!active_) return;
  poses_.close();
  if (!poses_) throw ScenarioError("replay: cannot write " + (dir_ / "poses.bin").string());
  nlohmann::ordered_json j;
  j["format"] = kReplayFormatName;
  j["version"] = kReplayFormatVersion;
  j["scenario"] = scenario_name_;
  j["robot"] = sim.robot().name;
  j["world"] = sim.world().name;
  j["rate_hz"] = rate_;
  j["frames"] = frames_;
  j["duration_s"] = sim.time();
  nlohmann::ordered_json links = nlohmann::ordered_json::array();
  for (const physics::LinkInfo& l : sim.physics().model().links()) links.push_back(l.name);
  j["links"] = links;
  j["root_link"] = sim.robot().root_link;
  j["objects"] = object_names_;
  j["poses"] = {{"file", "poses.bin"}, {"type", "float32le"}, {"stride", frame_.size()},
                {"layout", "t (s), then per link, then per object: x y z (m), qw qx qy qz (world frame)"}};
  j["robot_file"] = "robot.json";
  j["urdf_file"] = "robot.urdf";
  j["world_file"] = "world.json";
  j["waypoints"] = waypoints_;
  nlohmann::ordered_json plots = nlohmann::ordered_json::array();
  for (const std::string& f : report_files) {
    if (f.size() < 4 || f.compare(f.size() - 4, 4, ".png") != 0 || f.find("..") != std::string::npos) continue;
    nlohmann::ordered_json p = {{"file", "../" + f}};
    const std::string axes = f.substr(0, f.size() - 4) + ".axes.jsonl";
    if (fs::exists(dir_.parent_path() / axes)) p["axes"] = "../" + axes;
    plots.push_back(p);
  }
  j["plots"] = plots;
  // base.csv's odom_x, odom_y (world frame, m) at record_rate: the page's odometry trace.
  if (has_odometry && fs::exists(dir_.parent_path() / "base.csv")) {
    j["odometry"] = {{"file", "../base.csv"}, {"x", "odom_x"}, {"y", "odom_y"}};
  }
  // Lasers whose scans the report has (sensors/<name>.csv: t, then the ranges, rows of the
  // vertical axis one after the other): drawn as points from the sensor's pose on its link.
  nlohmann::ordered_json lasers = nlohmann::ordered_json::array();
  const sensors::SensorSet& set = sim.sensors();
  for (std::size_t i = 0; i < set.size() && i < sensor_files.size(); ++i) {
    const description::SensorSpec& spec = set.spec(i);
    const auto* ray = std::get_if<description::RaySpec>(&spec.details);
    const auto link = sim.physics().model().link_index(spec.link);
    if (ray == nullptr || !link || std::find(report_files.begin(), report_files.end(), sensor_files[i]) == report_files.end()) continue;
    const auto axis = [](const description::RayAxis& a) {
      return nlohmann::ordered_json{{"min", a.min_angle}, {"max", a.max_angle}, {"count", a.count()}};
    };
    const description::Pose& X_LS = spec.pose;
    lasers.push_back({{"name", spec.name}, {"link", *link}, {"file", "../" + sensor_files[i]},
                      {"origin", {{"p", {X_LS.position.x, X_LS.position.y, X_LS.position.z}},
                                  {"q", {X_LS.orientation.w, X_LS.orientation.x, X_LS.orientation.y, X_LS.orientation.z}}}},
                      {"horizontal", axis(ray->horizontal)}, {"vertical", axis(ray->vertical)},
                      {"range_min", ray->range_min}, {"range_max", ray->range_max}});
  }
  j["lasers"] = lasers;
  std::ofstream out(dir_ / "manifest.json");
  out << j.dump(1) << '\n';
  out.close();
  if (!out) throw ScenarioError("replay: cannot write " + (dir_ / "manifest.json").string());
}

}  // namespace mechsim::sim
