#include "sim/report.hpp"

#include "sim/gnuplot.hpp"
#include "sim/pose_math.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

#include <nlohmann/json.hpp>

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;


// The command the joint's hardware interface carries: effort (N m, N), or the set point of its
// position (rad, m) or velocity (rad/s, m/s) servo.
double command_of(const mechanism::JointState& j) {
  switch (j.command_mode) {
    case mechanism::HardwareInterface::Position: return j.commanded_position;
    case mechanism::HardwareInterface::Velocity: return j.commanded_velocity;
    case mechanism::HardwareInterface::Effort: break;
  }
  return j.commanded_effort;
}

}  // namespace

Recorder::Recorder(const Simulation& sim, const std::string& dir, const std::vector<std::string>& trajectory_controllers)
    : sim_(sim) {
  // Joints no transmission drives (the CC8's rocker and bogies, the parts of a planar joint)
  // are recorded from the physics.
  const std::vector<physics::JointInfo>& physics_joints = sim.physics().model().joints();
  for (std::size_t p = 0; p < physics_joints.size(); ++p) {
    if (sim.mechanism().joint_index(physics_joints[p].name) < 0) passive_joints_.push_back(p);
  }
  auto& manager = const_cast<Simulation&>(sim).controllers();
  for (const std::string& name : trajectory_controllers) {
    control::Controller* c = manager.controller(name);
    if (c == nullptr) continue;
    for (control::Port* p : c->ports()) {
      if (p->kind() != control::PortKind::JointTrajectoryState) continue;
      const auto* state = dynamic_cast<const control::StatePort<control::JointTrajectoryControllerState>*>(p);
      trajectory_states_.push_back(state);
      for (const std::string& joint : state->read().joint_names) trajectory_columns_.push_back(name + "/" + joint);
    }
  }
  for (const control::ControllerInfo& info : manager.list_controllers()) {
    control::Controller* c = manager.controller(info.name);
    if (c == nullptr) continue;
    for (control::Port* p : c->ports()) {
      if (p->kind() == control::PortKind::JointControllerState) {
        Channel ch;
        ch.controller = info.name;
        ch.single = dynamic_cast<const control::StatePort<control::JointControllerState>*>(p);
        channels_.push_back(ch);
      } else if (p->kind() == control::PortKind::JointGroupState) {
        const auto* group = dynamic_cast<const control::StatePort<control::JointGroupControllerState>*>(p);
        const control::JointGroupControllerState snapshot = group->read();
        for (std::size_t k = 0; k < snapshot.joint_names.size(); ++k) {
          Channel ch;
          ch.controller = info.name;
          ch.joint = snapshot.joint_names[k];
          ch.group = group;
          ch.index = k;
          channels_.push_back(ch);
        }
      }
    }
  }
  if (dir.empty()) return;
  fs::create_directories(dir);
  joints_.open(fs::path(dir) / "joints.csv");
  controllers_.open(fs::path(dir) / "controllers.csv");
  base_.open(fs::path(dir) / "base.csv");
  if (!trajectory_states_.empty()) {
    trajectory_.open(fs::path(dir) / "trajectory.csv");
    trajectory_ << std::setprecision(9) << "time";
    for (const std::string& c : trajectory_columns_) trajectory_ << ',' << c << "/desired," << c << "/actual";
    trajectory_ << '\n';
  }
  for (std::ofstream* f : {&joints_, &controllers_, &base_}) *f << std::setprecision(9);
  joints_ << "time";
  for (const mechanism::JointInfo& j : sim.mechanism().joints) {
    joints_ << ',' << j.name << "/position," << j.name << "/velocity," << j.name << "/effort," << j.name << "/command";
  }
  for (const std::size_t p : passive_joints_) {
    const std::string& name = sim.physics().model().joints()[p].name;
    joints_ << ',' << name << "/position," << name << "/velocity";
  }
  joints_ << '\n';
  controllers_ << "time";
  for (const Channel& ch : channels_) {
    const std::string n = ch.joint.empty() ? ch.controller : ch.controller + "/" + ch.joint;
    controllers_ << ',' << n << "/set_point," << n << "/process_value," << n << "/error," << n << "/command";
  }
  controllers_ << '\n';
  base_ << "time,x,y,z,roll,pitch,yaw,odom_x,odom_y,odom_yaw\n";
  if (sim.other_count() > 0) {
    others_.open(fs::path(dir) / "others.csv");
    others_ << std::setprecision(9) << "time";
    for (std::size_t i = 0; i < sim.other_count(); ++i) {
      const std::string& n = sim.other(i).robot_name_in_world();
      others_ << ',' << n << "/x," << n << "/y," << n << "/z," << n << "/yaw";
    }
    others_ << '\n';
  }
}

void Recorder::sample(const control::StatePort<control::OdometrySnapshot>* odometry) {
  const double t = sim_.time();
  const bool files = controllers_.is_open();
  if (files) controllers_ << t;
  for (Channel& ch : channels_) {
    control::JointControllerState s;
    if (ch.single != nullptr) {
      s = ch.single->read();
    } else {
      const control::JointGroupControllerState g = ch.group->read();
      if (ch.index < g.joints.size()) s = g.joints[ch.index];
    }
    if (ch.single == nullptr || ch.single->sequence() > 0) {
      ch.sum_sq += s.error * s.error;
      ch.max_abs = std::max(ch.max_abs, std::abs(s.error));
      ++ch.samples;
    }
    if (files) controllers_ << ',' << s.set_point << ',' << s.process_value << ',' << s.error << ',' << s.command;
  }
  if (!files) return;
  controllers_ << '\n';
  if (others_.is_open()) {
    others_ << t;
    for (std::size_t i = 0; i < sim_.other_count(); ++i) {
      const description::Pose X = sim_.other(i).base_pose();
      others_ << ',' << X.position.x << ',' << X.position.y << ',' << X.position.z << ',' << yaw_of(X.orientation);
    }
    others_ << '\n';
  }
  if (trajectory_.is_open()) {
    trajectory_ << t;
    for (const auto* state : trajectory_states_) {
      const control::JointTrajectoryControllerState s = state->read();
      for (std::size_t j = 0; j < s.joint_names.size(); ++j) {
        trajectory_ << ',' << (j < s.desired.positions.size() ? s.desired.positions[j] : 0.0) << ','
                    << (j < s.actual.positions.size() ? s.actual.positions[j] : 0.0);
      }
    }
    trajectory_ << '\n';
  }
  joints_ << t;
  for (const mechanism::JointState& j : sim_.mechanism_state().joints) {
    joints_ << ',' << j.position << ',' << j.velocity << ',' << j.measured_effort << ',' << command_of(j);
  }
  for (const std::size_t p : passive_joints_) joints_ << ',' << sim_.physics().position(p) << ',' << sim_.physics().velocity(p);
  joints_ << '\n';
  const description::Pose X_WB = sim_.physics().base_pose();
  base_ << t << ',' << X_WB.position.x << ',' << X_WB.position.y << ',' << X_WB.position.z << ','
        << roll_of(X_WB.orientation) << ',' << pitch_of(X_WB.orientation) << ',' << yaw_of(X_WB.orientation);
  if (odometry != nullptr) {
    const control::OdometrySnapshot o = odometry->read();
    const physics::SpawnPose& sp = sim_.options().spawn;
    const double c = std::cos(sp.yaw), s = std::sin(sp.yaw);
    base_ << ',' << sp.x + c * o.x - s * o.y << ',' << sp.y + s * o.x + c * o.y << ',' << o.yaw + sp.yaw << '\n';
  } else {
    base_ << ",,,\n";
  }
}

std::vector<TrackingError> Recorder::tracking() const {
  std::vector<TrackingError> out;
  for (const Channel& ch : channels_) {
    TrackingError t;
    t.controller = ch.joint.empty() ? ch.controller : ch.controller + "/" + ch.joint;
    t.samples = ch.samples;
    t.rms = ch.samples > 0 ? std::sqrt(ch.sum_sq / static_cast<double>(ch.samples)) : 0.0;
    t.max = ch.max_abs;
    out.push_back(t);
  }
  return out;
}

void Recorder::close() {
  joints_.close();
  controllers_.close();
  base_.close();
  trajectory_.close();
  others_.close();
}

namespace {

// Written aside and renamed over the old file: a reader sees the old summary or the new one,
// never half of one.
void write_summary(const fs::path& dir, const nlohmann::ordered_json& j) {
  const fs::path tmp = dir / "summary.json.partial";
  {
    std::ofstream out(tmp);
    out << j.dump(2) << '\n';
    out.close();
    if (!out) throw ScenarioError("cannot write " + tmp.string() + " (disk full?)");
  }
  fs::rename(tmp, dir / "summary.json");
}

}  // namespace

void prepare_report_folder(const Scenario& s, const std::string& dir_name) {
  if (dir_name.empty()) return;
  const fs::path dir = dir_name;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw ScenarioError("cannot create the report folder '" + dir_name + "': " + ec.message());
  // 16 MiB: the CSVs of a minute of a PR2 run at the report's rate with room to spare.
  constexpr std::uintmax_t kNeeded = 16u << 20;
  const fs::space_info space = fs::space(dir, ec);
  if (!ec && space.available < kNeeded) {
    throw ScenarioError("the report folder '" + dir_name + "' has " + std::to_string(space.available >> 20) +
                        " MiB free; a report needs at least " + std::to_string(kNeeded >> 20) + " MiB");
  }
  nlohmann::ordered_json j;
  j["scenario"] = s.name;
  j["file"] = s.file;
  j["completed"] = false;
  j["passed"] = false;
  j["status"] = "running";
  try {
    write_summary(dir, j);
  } catch (const std::exception& e) {
    throw ScenarioError("cannot write in the report folder '" + dir_name + "': " + e.what());
  }
}

void write_report(const Scenario& s, const Simulation& sim, const Recorder& recorder, ScenarioResult& result,
                  const RunOptions& options) {
  const fs::path dir = options.output_dir;
  fs::create_directories(dir);
  result.files.insert(result.files.end(), {"joints.csv", "controllers.csv", "base.csv"});
  if (!result.others.empty()) result.files.push_back("others.csv");
  if (!recorder.trajectory_columns().empty()) result.files.push_back("trajectory.csv");

  std::vector<std::array<double, 2>> waypoints;
  for (const TimelineEvent& e : s.timeline) {
    if (e.kind == TimelineEvent::Kind::Route) waypoints.insert(waypoints.end(), e.route.waypoints.begin(), e.route.waypoints.end());
  }

  if (options.plots) {
    // The path over the terrain (or the ground grid). Every data file is comma separated.
    std::ostringstream gp;
    gp << "set terminal pngcairo size 1200,900 font 'DejaVu Sans,11'\nset output " << quoted((dir / "path.png").string()) << "\n"
       << "set datafile separator ','\nset size ratio -1\nset xlabel 'x (m)'\nset ylabel 'y (m)'\n"
       << "set key outside bottom center horizontal\n"
       << "set title " << quoted(s.name + ": path of the base over " + fs::path(sim.world().name).filename().string()) << " noenhanced\n";
    std::string plots;
    if (const auto& terrain = sim.world().spec.terrain) {
      double z0 = 0, z1 = 0;
      write_terrain(*terrain, dir / "terrain.csv", z0, z1);
      gp << "set cblabel 'height (m)'\nset palette defined (0 '#3b1a0f', 0.5 '#a0522d', 1 '#f4c28f')\n"
         << "set xrange [" << -terrain->size_x / 2 << ":" << terrain->size_x / 2 << "]\nset yrange [" << -terrain->size_y / 2
         << ":" << terrain->size_y / 2 << "]\n";
      plots += quoted((dir / "terrain.csv").string()) + " using 1:2:3 with image notitle, ";
    } else {
      // Flat ground: frame the path and waypoints with a 1 m margin, square.
      double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
      auto extend = [&](double x, double y) {
        x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
      };
      std::ifstream csv(dir / "base.csv");
      std::string line;
      std::getline(csv, line);
      while (std::getline(csv, line)) {
        double t = 0, x = 0, y = 0;
        if (std::sscanf(line.c_str(), "%lf,%lf,%lf", &t, &x, &y) == 3) extend(x, y);
      }
      std::ifstream others(dir / "others.csv");
      std::getline(others, line);
      while (std::getline(others, line)) {
        std::istringstream row(line);
        std::string cell;
        std::vector<double> v;
        while (std::getline(row, cell, ',')) v.push_back(std::atof(cell.c_str()));
        for (std::size_t k = 1; k + 1 < v.size(); k += 4) extend(v[k], v[k + 1]);
      }
      for (const auto& w : waypoints) extend(w[0], w[1]);
      const double cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
      const double half = std::max({x1 - x0, y1 - y0, 1.0}) / 2 + 1.0;
      gp << "set grid\nset xrange [" << cx - half << ":" << cx + half << "]\nset yrange [" << cy - half << ":" << cy + half << "]\n";
    }
    std::ofstream wp(dir / "waypoints.csv");
    wp << "x,y\n";
    for (const auto& w : waypoints) wp << w[0] << ',' << w[1] << '\n';
    wp.close();
    const std::string base = quoted((dir / "base.csv").string());
    if (!waypoints.empty()) {
      plots += quoted((dir / "waypoints.csv").string()) + " using 1:2 with linespoints lw 1 pt 7 ps 1.5 lc rgb '#00c000' title 'waypoints', ";
    }
    if (result.has_odometry) plots += base + " using 8:9 with lines lw 2 dt 2 lc rgb '#ff00ff' title 'odometry', ";
    plots += base + " using 2:3 with lines lw 3 lc rgb '#0050ff' title 'true path', ";
    static const char* const kOtherColours[] = {"#e07000", "#008080", "#8000c0", "#a0a000"};
    for (std::size_t i = 0; i < result.others.size(); ++i) {
      const std::string others = quoted((dir / "others.csv").string());
      plots += others + " using " + std::to_string(2 + 4 * i) + ":" + std::to_string(3 + 4 * i) +
               " with lines lw 3 lc rgb '" + kOtherColours[i % 4] + "' title " + quoted(result.others[i].name + " path") + " noenhanced, ";
      plots += others + " every ::1::1 using " + std::to_string(2 + 4 * i) + ":" + std::to_string(3 + 4 * i) +
               " with points pt 5 ps 2 lc rgb '#000000' notitle, ";
    }
    if (const auto& u = sim.world().usable) {
      std::ofstream(dir / "usable.csv") << "x,y\n" << u->x_min << ',' << u->y_min << '\n' << u->x_max << ',' << u->y_min << '\n'
                                        << u->x_max << ',' << u->y_max << '\n' << u->x_min << ',' << u->y_max << '\n'
                                        << u->x_min << ',' << u->y_min << '\n';
      plots += quoted((dir / "usable.csv").string()) + " using 1:2 with lines lw 2 dt 2 lc rgb '#ffcc00' title 'usable ground', ";
    }
    if (!result.events.empty()) {
      std::ofstream events(dir / "events.csv");
      events << "x,y\n";
      for (const RunEvent& e : result.events) events << e.x << ',' << e.y << '\n';
      events.close();
      plots += quoted((dir / "events.csv").string()) + " using 1:2 with points pt 2 ps 3 lw 3 lc rgb '#e00000' title " +
               quoted(result.events.front().kind == "left_terrain" ? "left the usable ground" : result.events.front().kind) + ", ";
    }
    plots += base + " every ::1::1 using 2:3 with points pt 5 ps 2 lc rgb '#000000' title 'start'\n";
    const std::string script = gp.str() + "plot " + plots + axes_record(dir / "path.axes.jsonl", true);
    if (const std::string err = run_gnuplot(dir, "path", script); !err.empty()) {
      result.warnings.push_back(err);
    } else {
      result.files.push_back("path.png");
    }

    // Tracking: set point and process value of each channel, and the errors.
    const std::size_t n = result.tracking.size();
    if (n > 0) {
      const std::string csv = quoted((dir / "controllers.csv").string());
      const int cols = n > 6 ? 3 : 2;
      const int rows = static_cast<int>((n + static_cast<std::size_t>(cols) - 1) / static_cast<std::size_t>(cols));
      std::ostringstream tr;
      tr << "set terminal pngcairo size " << 560 * cols << "," << 260 * rows + 60 << " font 'DejaVu Sans,9'\nset output "
         << quoted((dir / "tracking.png").string()) << "\nset datafile separator ','\nset key top left\nset grid\n"
         << "set multiplot layout " << rows << "," << cols << " title " << quoted(s.name + ": set point vs measured") << " noenhanced\n";
      std::ostringstream er;
      er << "set terminal pngcairo size 1200,700 font 'DejaVu Sans,10'\nset output " << quoted((dir / "errors.png").string())
         << "\nset datafile separator ','\nset key outside right\nset grid\nset xlabel 'time (s)'\nset ylabel 'error'\n"
         << "set title " << quoted(s.name + ": controller errors") << " noenhanced\nplot ";
      for (std::size_t k = 0; k < n; ++k) {
        const std::size_t col = 2 + 4 * k;
        tr << "set title " << quoted(result.tracking[k].controller) << " noenhanced\nplot " << csv << " using 1:" << col
           << " with lines lw 2 title 'set point', " << csv << " using 1:" << col + 1 << " with lines lw 1.5 title 'measured'\n"
           << axes_record(dir / "tracking.axes.jsonl", k == 0);
        er << (k ? ", " : "") << csv << " using 1:" << col + 2 << " with lines title " << quoted(result.tracking[k].controller) << " noenhanced";
      }
      tr << "unset multiplot\n";
      er << "\n" << axes_record(dir / "errors.axes.jsonl", true);
      for (const auto& [name, script_text] : {std::pair{std::string("tracking"), tr.str()}, std::pair{std::string("errors"), er.str()}}) {
        if (const std::string err = run_gnuplot(dir, name, script_text); !err.empty()) {
          result.warnings.push_back(err);
        } else {
          result.files.push_back(name + ".png");
        }
      }
    }

    // Trajectory controllers: desired vs actual position per joint, goal start times marked.
    const std::vector<std::string>& columns = recorder.trajectory_columns();
    if (!columns.empty()) {
      const std::string csv = quoted((dir / "trajectory.csv").string());
      const std::size_t m = columns.size();
      const int cols = m > 4 ? 3 : static_cast<int>(std::min<std::size_t>(m, 2));
      const int rows = static_cast<int>((m + static_cast<std::size_t>(cols) - 1) / static_cast<std::size_t>(cols));
      std::ostringstream tj;
      tj << "set terminal pngcairo size " << 560 * cols << "," << 280 * rows + 60 << " font 'DejaVu Sans,9'\nset output "
         << quoted((dir / "trajectory.png").string()) << "\nset datafile separator ','\nset key top right opaque\nset grid\n"
         << "set xlabel 'time (s)'\nset ylabel 'position (rad, m)'\n";
      for (const TrajectoryGoalOutcome& g : result.trajectory_goals) {
        tj << "set arrow from " << g.sent_at << ", graph 0 to " << g.sent_at << ", graph 1 nohead dt 3 lc rgb '#808080'\n";
      }
      tj << "set multiplot layout " << rows << "," << cols << " title "
         << quoted(s.name + ": trajectory controllers, desired vs actual (dotted: goals sent)") << " noenhanced\n";
      for (std::size_t k = 0; k < m; ++k) {
        const std::size_t col = 2 + 2 * k;
        tj << "set title " << quoted(columns[k]) << " noenhanced\nplot " << csv << " using 1:" << col
           << " with lines lw 2 lc rgb '#0050ff' title 'desired', " << csv << " using 1:" << col + 1
           << " with lines lw 1.5 dt 2 lc rgb '#d00000' title 'actual'\n"
           << axes_record(dir / "trajectory.axes.jsonl", k == 0);
      }
      tj << "unset multiplot\n";
      if (const std::string err = run_gnuplot(dir, "trajectory", tj.str()); !err.empty()) {
        result.warnings.push_back(err);
      } else {
        result.files.push_back("trajectory.png");
      }
    }
  }

  nlohmann::ordered_json j;
  j["scenario"] = s.name;
  j["file"] = s.file;
  j["robot"] = sim.robot().name;
  j["world"] = sim.world().name;
  j["completed"] = result.completed;
  j["passed"] = result.passed;
  if (result.interrupted_by != 0) j["interrupted_by_signal"] = result.interrupted_by;
  if (!result.error.empty()) j["error"] = result.error;
  j["events"] = nlohmann::ordered_json::array();
  for (const RunEvent& e : result.events) {
    j["events"].push_back({{"t_s", e.time}, {"event", e.kind}, {"x_m", e.x}, {"y_m", e.y}, {"detail", e.detail}});
  }
  j["sim_time_s"] = result.sim_time;
  j["wall_time_s"] = result.wall_time;
  j["real_time_factor"] = result.real_time_factor;
  j["distance_m"] = result.distance;
  const description::Pose& X_WS = sim.spawn_pose();
  j["spawn_pose"] = {{"x", X_WS.position.x}, {"y", X_WS.position.y}, {"z", X_WS.position.z},
                     {"roll_rad", roll_of(X_WS.orientation)}, {"pitch_rad", pitch_of(X_WS.orientation)},
                     {"yaw_rad", yaw_of(X_WS.orientation)}};
  j["final_pose"] = {{"x", result.final_x}, {"y", result.final_y}, {"z", result.final_z}, {"yaw_rad", result.final_yaw}};
  j["max_tilt_rad"] = result.max_tilt;
  j["yaw_change_rad"] = result.yaw_change;
  if (result.has_odometry) {
    j["odometry_error_m"] = result.odometry_error;
    j["odometry_yaw_error_rad"] = result.odometry_yaw_error;
  }
  if (!result.others.empty()) {
    j["others"] = nlohmann::ordered_json::array();
    for (const RobotMotion& o : result.others) {
      nlohmann::ordered_json r = {{"name", o.name},
                                  {"distance_m", o.distance},
                                  {"final_pose", {{"x", o.final_x}, {"y", o.final_y}, {"z", o.final_z}, {"yaw_rad", o.final_yaw}}},
                                  {"yaw_change_rad", o.yaw_change}};
      if (o.has_odometry) {
        r["odometry_error_m"] = o.odometry_error;
        r["odometry_yaw_error_rad"] = o.odometry_yaw_error;
      }
      j["others"].push_back(std::move(r));
    }
  }
  if (sim.world().soil) {
    const physics::SoilParameters& soil = *sim.world().soil;
    j["soil"] = {{"name", soil.name}, {"source", soil.source}, {"model", physics::model_name(soil.model)}, {"multi_pass", soil.multi_pass}};
    j["wheels"] = nlohmann::ordered_json::array();
    for (const WheelOutcome& w : result.wheels) {
      nlohmann::ordered_json wheel = {{"link", w.link}, {"radius_m", w.radius}, {"width_m", w.width}, {"narrow", w.narrow}};
      if (w.grouser_count > 0) wheel["grousers"] = {{"height_m", w.grouser_height}, {"count", w.grouser_count}};
      wheel.update({{"why", w.origin}, {"mean_slip", w.mean_slip}, {"mean_traction_N", w.mean_traction},
                    {"max_sinkage_m", w.max_sinkage}, {"mean_sinkage_m", w.mean_sinkage},
                    {"mean_rut_depth_m", w.mean_rut_depth}, {"time_in_soil_s", w.time_in_soil}});
      j["wheels"].push_back(std::move(wheel));
    }
    j["not_wheels"] = result.not_wheels;
    if (!result.steady_state_wheel.empty()) {
      nlohmann::ordered_json rows = nlohmann::ordered_json::array();
      for (const SteadyStateRow& r : result.steady_states) {
        if (r.samples == 0) continue;
        rows.push_back({{"from_s", r.from}, {"to_s", r.to}, {"slip", r.slip}, {"drawbar_N", r.drawbar}, {"load_N", r.load},
                        {"dp_per_w", r.load > 0.0 ? r.drawbar / r.load : 0.0}, {"torque_Nm", r.torque},
                        {"sinkage_m", r.sinkage}});
      }
      j["steady_states"] = {{"wheel", result.steady_state_wheel}, {"rows", std::move(rows)}};
    }
  }
  j["tracking"] = nlohmann::ordered_json::array();
  for (const TrackingError& t : result.tracking) {
    j["tracking"].push_back({{"controller", t.controller}, {"rms_error", t.rms}, {"max_error", t.max}, {"samples", t.samples}});
  }
  j["trajectory_goals"] = nlohmann::ordered_json::array();
  for (const TrajectoryGoalOutcome& g : result.trajectory_goals) {
    nlohmann::ordered_json goal = {{"controller", g.controller}, {"goal", g.index}, {"sent_at_s", g.sent_at},
                                   {"accepted", g.accepted}, {"status", g.status}, {"finished", g.finished}};
    if (g.finished) {
      goal["finished_at_s"] = g.finished_at;
      goal["result"] = control::result_code_name(g.result.error_code);
      goal["error_string"] = g.result.error_string;
    }
    goal["samples"] = g.samples;
    double worst = 0.0;
    nlohmann::ordered_json joints = nlohmann::ordered_json::array();
    for (std::size_t k = 0; k < g.joints.size(); ++k) {
      joints.push_back({{"joint", g.joints[k]}, {"rms_error", g.rms[k]}, {"max_error", g.max[k]}});
      worst = std::max(worst, g.rms[k]);
    }
    goal["worst_rms_error"] = worst;
    goal["joints"] = joints;
    j["trajectory_goals"].push_back(goal);
  }
  j["gripper_goals"] = nlohmann::ordered_json::array();
  for (const GripperGoalOutcome& g : result.gripper_goals) {
    nlohmann::ordered_json goal = {{"controller", g.controller}, {"goal", g.index}, {"sent_at_s", g.sent_at},
                                   {"position_m", g.command.position}, {"max_effort_n", g.command.max_effort},
                                   {"accepted", g.accepted}, {"status", g.status}, {"finished", g.finished}};
    if (!g.accepted) goal["error"] = g.error;
    if (g.finished && g.accepted) {
      goal["finished_after_s"] = g.finished_after;
      goal["result"] = {{"position_m", g.result.position}, {"effort_n", g.result.effort},
                        {"reached_goal", g.result.reached_goal}, {"stalled", g.result.stalled}};
    }
    j["gripper_goals"].push_back(goal);
  }
  j["checks"] = nlohmann::ordered_json::array();
  for (const CheckOutcome& c : result.checks) j["checks"].push_back({{"check", c.name}, {"passed", c.passed}, {"detail", c.detail}});
  j["warnings"] = result.warnings;
  result.files.push_back("summary.json");
  j["files"] = result.files;
  write_summary(dir, j);
}

}  // namespace mechsim::sim
