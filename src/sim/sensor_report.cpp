#include "sim/sensor_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "description/sensor_spec.hpp"
#include "physics/transform.hpp"
#include "sim/gnuplot.hpp"
#include "sim/pose_math.hpp"

namespace mechsim::sim {

namespace fs = std::filesystem;
using sensors::SensorReading;

struct SensorReport::Channel {
  std::string file;  // file name under sensors/, without extension
  std::ofstream csv;
  std::uint64_t seen = 0;  // reading count already written
};

namespace {

constexpr double kSlack = 1e-9;

std::string file_name(std::string name) {
  for (char& c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.')) c = '_';
  return name.empty() ? std::string("sensor") : name;
}

void header(std::ostream& out, const SensorReading& r) {
  std::visit(
      [&](const auto& v) {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, sensors::LaserScan>) {
          out << "t";
          for (std::size_t i = 0; i < v.ranges.size(); ++i) out << ",r" << i;
        } else if constexpr (std::is_same_v<T, sensors::RangeReading>) {
          out << "t,range";
        } else if constexpr (std::is_same_v<T, sensors::PointCloudReading>) {
          out << "t,points,mean_range,mean_intensity";
        } else if constexpr (std::is_same_v<T, sensors::ImuReading>) {
          out << "t,qw,qx,qy,qz,roll,pitch,yaw,wx,wy,wz,ax,ay,az";
        } else if constexpr (std::is_same_v<T, sensors::ContactsReading>) {
          out << "t,pairs,points,fx,fy,fz,tx,ty,tz";
        } else if constexpr (std::is_same_v<T, sensors::WrenchReading>) {
          out << "t,fx,fy,fz,tx,ty,tz";
        } else if constexpr (std::is_same_v<T, sensors::GroundTruthReading>) {
          out << "t,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz";
        } else {
          out << "t";
        }
      },
      r.value);
  out << '\n';
}

void row(std::ostream& out, const SensorReading& r) {
  out << r.stamp;
  std::visit(
      [&](const auto& v) {
        using T = std::decay_t<decltype(v)>;
        const auto vec = [&](const description::Vec3& a) { out << ',' << a.x << ',' << a.y << ',' << a.z; };
        const auto quat = [&](const description::Quat& q) { out << ',' << q.w << ',' << q.x << ',' << q.y << ',' << q.z; };
        if constexpr (std::is_same_v<T, sensors::LaserScan>) {
          for (const float x : v.ranges) out << ',' << x;
        } else if constexpr (std::is_same_v<T, sensors::RangeReading>) {
          out << ',' << v.range;
        } else if constexpr (std::is_same_v<T, sensors::PointCloudReading>) {
          double range = 0.0, intensity = 0.0;
          for (std::size_t i = 0; i < v.points.size(); ++i) {
            range += std::sqrt(v.points[i].x * v.points[i].x + v.points[i].y * v.points[i].y + v.points[i].z * v.points[i].z);
            intensity += v.intensities[i];
          }
          const double n = v.points.empty() ? 1.0 : static_cast<double>(v.points.size());
          out << ',' << v.points.size() << ',' << range / n << ',' << intensity / n;
        } else if constexpr (std::is_same_v<T, sensors::ImuReading>) {
          quat(v.orientation);
          out << ',' << roll_of(v.orientation) << ',' << pitch_of(v.orientation) << ',' << yaw_of(v.orientation);
          vec(v.angular_velocity);
          vec(v.linear_acceleration);
        } else if constexpr (std::is_same_v<T, sensors::ContactsReading>) {
          std::size_t points = 0;
          description::Vec3 f, t;
          for (std::size_t i = 0; i < v.count; ++i) {
            const sensors::ContactState& s = v.states[i];
            points += s.contact_positions.size();
            f = {f.x + s.total_wrench.force.x, f.y + s.total_wrench.force.y, f.z + s.total_wrench.force.z};
            t = {t.x + s.total_wrench.torque.x, t.y + s.total_wrench.torque.y, t.z + s.total_wrench.torque.z};
          }
          out << ',' << v.count << ',' << points;
          vec(f);
          vec(t);
        } else if constexpr (std::is_same_v<T, sensors::WrenchReading>) {
          vec(v.force);
          vec(v.torque);
        } else if constexpr (std::is_same_v<T, sensors::GroundTruthReading>) {
          vec(v.pose.position);
          quat(v.pose.orientation);
          vec(v.linear);
          vec(v.angular);
        }
      },
      r.value);
  out << '\n';
}

// The laser's range along the ray nearest `angle` (middle row of a multi-row scan).
std::optional<double> range_at(const sensors::LaserScan& scan, double angle, std::size_t* index) {
  if (scan.horizontal_count <= 0 || scan.ranges.empty()) return std::nullopt;
  long i = scan.angle_increment > 0.0 ? std::lround((angle - scan.angle_min) / scan.angle_increment) : 0;
  i = std::clamp(i, 0L, static_cast<long>(scan.horizontal_count) - 1);
  const std::size_t k = static_cast<std::size_t>(scan.vertical_count / 2) * static_cast<std::size_t>(scan.horizontal_count) +
                        static_cast<std::size_t>(i);
  if (index != nullptr) *index = static_cast<std::size_t>(i);
  return scan.ranges[k];
}

}  // namespace

SensorReport::SensorReport(const Simulation& sim, const Scenario& scenario, const std::string& dir)
    : sim_(sim), scenario_(scenario), dir_(dir) {
  const sensors::SensorSet& set = sim.sensors();
  std::vector<std::string> used;
  for (std::size_t i = 0; i < set.size(); ++i) {
    auto c = std::make_unique<Channel>();
    c->file = file_name(set.spec(i).name);
    while (std::find(used.begin(), used.end(), c->file) != used.end()) c->file.append("_").append(std::to_string(i));
    used.push_back(c->file);
    channels_.push_back(std::move(c));
  }
  if (!dir_.empty() && !set.empty()) fs::create_directories(fs::path(dir_) / "sensors");
  picture_times_ = scenario.laser_picture_times;
  if (picture_times_.empty()) picture_times_ = {0.0, scenario.duration / 2, scenario.duration};
  std::sort(picture_times_.begin(), picture_times_.end());
  for (const Check& c : scenario.checks) {
    int index = -1;
    if (c.kind == Check::Kind::LaserRange || c.kind == Check::Kind::ImuTilt) {
      const auto i = set.find(c.sensor);
      const char* want = c.kind == Check::Kind::LaserRange ? "ray" : "imu";
      if (!i || std::string(set.spec(*i).kind_name()) != want) {
        throw ScenarioError(scenario.file + ": checks: " + c.text + ": the robot has no simulated " + want + " sensor '" +
                            c.sensor + "'");
      }
      index = static_cast<int>(*i);
    }
    check_sensor_.push_back(index);
  }
  check_reading_.resize(scenario.checks.size());
  observe(sim);  // the readings taken at construction
}

SensorReport::~SensorReport() = default;

std::string SensorReport::csv_file(std::size_t i) const { return "sensors/" + channels_[i]->file + ".csv"; }

void SensorReport::observe(const Simulation& sim) {
  const sensors::SensorSet& set = sim.sensors();
  const double t = sim.time();
  for (std::size_t i = 0; i < set.size(); ++i) {
    const SensorReading& r = set.reading(i);
    Channel& c = *channels_[i];
    if (r.count == c.seen) continue;
    c.seen = r.count;
    if (!dir_.empty()) {
      if (!c.csv.is_open()) {
        c.csv.open(fs::path(dir_) / "sensors" / (c.file + ".csv"));
        c.csv.precision(9);
        header(c.csv, r);
      }
      row(c.csv, r);
    }
    if (std::holds_alternative<sensors::LaserScan>(r.value)) {
      for (const double pt : picture_times_) {
        const bool taken = std::any_of(captures_.begin(), captures_.end(), [&](const Capture& k) {
          return k.sensor == set.spec(i).name && std::abs(k.time - pt) < kSlack;
        });
        if (!taken && r.stamp + kSlack >= pt) capture_scan(sim, i, pt);
      }
    }
  }
  for (std::size_t k = 0; k < scenario_.checks.size(); ++k) {
    const Check& c = scenario_.checks[k];
    if (check_sensor_[k] < 0) continue;
    // A check at `at` takes the reading at the first tick at or after it; without `at`, the last.
    if (c.at && check_reading_[k]) continue;
    if (!c.at || t + kSlack >= *c.at) check_reading_[k] = set.reading(static_cast<std::size_t>(check_sensor_[k]));
  }
}

void SensorReport::capture_scan(const Simulation& sim, std::size_t i, double picture_time) {
  const sensors::SensorSet& set = sim.sensors();
  const description::SensorSpec& spec = set.spec(i);
  const auto& scan = std::get<sensors::LaserScan>(set.reading(i).value);
  const auto link = sim.physics().model().link_index(spec.link);
  if (!link) return;
  const description::Pose X_WS = physics::compose(sim.physics().link_pose(*link), spec.pose);
  Capture c;
  c.time = picture_time;
  c.sensor = spec.name;
  c.x = X_WS.position.x;
  c.y = X_WS.position.y;
  for (int j = 0; j < scan.vertical_count; ++j) {
    const double pitch = scan.vertical_angle_min + j * scan.vertical_angle_increment;
    for (int h = 0; h < scan.horizontal_count; ++h) {
      const float r = scan.ranges[static_cast<std::size_t>(j * scan.horizontal_count + h)];
      if (!std::isfinite(r)) continue;
      const double yaw = scan.angle_min + h * scan.angle_increment;
      const description::Vec3 d = physics::rotate(
          X_WS.orientation, {r * std::cos(pitch) * std::cos(yaw), r * std::cos(pitch) * std::sin(yaw), r * std::sin(pitch)});
      c.points.push_back({X_WS.position.x + d.x, X_WS.position.y + d.y});
    }
  }
  captures_.push_back(std::move(c));
}

CheckOutcome SensorReport::judge(const Check& c) const {
  CheckOutcome out;
  out.name = c.text;
  char buf[400];
  const std::size_t k = static_cast<std::size_t>(&c - scenario_.checks.data());
  const std::optional<SensorReading>& r = k < check_reading_.size() ? check_reading_[k] : std::nullopt;
  const std::string when = c.at ? "t=" + std::to_string(*c.at).substr(0, 6) + " s" : std::string("the end");
  if (!r || r->count == 0) {
    std::snprintf(buf, sizeof buf, "%s at %s: no reading (the run ended first)", c.sensor.c_str(), when.c_str());
    out.detail = buf;
    return out;
  }
  if (c.kind == Check::Kind::LaserRange) {
    std::size_t ray = 0;
    const std::optional<double> range = range_at(std::get<sensors::LaserScan>(r->value), c.angle, &ray);
    const double got = range.value_or(std::nan(""));
    out.passed = std::isinf(c.range) ? (std::isinf(got) && got > 0) : std::abs(got - c.range) <= c.within;
    std::snprintf(buf, sizeof buf, "%s ray %zu (%.2f deg) at %s (sample t=%.3f s): %.4f m, wanted %.4f +- %.4f m", c.sensor.c_str(),
                  ray, c.angle * 180 / M_PI, when.c_str(), r->stamp, got, c.range, c.within);
  } else {
    const auto& imu = std::get<sensors::ImuReading>(r->value);
    const description::Vec3& f = imu.linear_acceleration;
    const double norm = std::sqrt(f.x * f.x + f.y * f.y + f.z * f.z);
    const double tilt = norm > 0.0 ? std::acos(std::clamp(f.z / norm, -1.0, 1.0)) : std::nan("");
    out.passed = std::abs(tilt - c.tilt) <= c.within_angle;
    std::snprintf(buf, sizeof buf, "%s tilt at %s (sample t=%.3f s): %.3f deg (|f| = %.4f m/s^2), wanted %.3f +- %.3f deg",
                  c.sensor.c_str(), when.c_str(), r->stamp, tilt * 180 / M_PI, norm, c.tilt * 180 / M_PI,
                  c.within_angle * 180 / M_PI);
  }
  out.detail = buf;
  return out;
}

void SensorReport::write(ScenarioResult& result, bool plots) {
  if (dir_.empty()) return;
  const sensors::SensorSet& set = sim_.sensors();
  // Lasers sampled at the end of the run that no picture time caught yet (the end time itself).
  for (std::size_t i = 0; i < set.size(); ++i) {
    if (!std::holds_alternative<sensors::LaserScan>(set.reading(i).value)) continue;
    for (const double pt : picture_times_) {
      const bool taken = std::any_of(captures_.begin(), captures_.end(), [&](const Capture& k) {
        return k.sensor == set.spec(i).name && std::abs(k.time - pt) < kSlack;
      });
      if (!taken && pt >= sim_.time() - kSlack) capture_scan(sim_, i, pt);
    }
  }
  for (std::size_t i = 0; i < channels_.size(); ++i) {
    if (!channels_[i]->csv.is_open()) continue;
    channels_[i]->csv.close();
    result.files.push_back("sensors/" + channels_[i]->file + ".csv");
  }
  if (!plots) return;
  imu_plots(result);
  if (!captures_.empty()) laser_picture(result);
}

void SensorReport::imu_plots(ScenarioResult& result) {
  const sensors::SensorSet& set = sim_.sensors();
  const fs::path dir = fs::path(dir_) / "sensors";
  for (std::size_t i = 0; i < set.size(); ++i) {
    if (std::string(set.spec(i).kind_name()) != "imu" || !channels_[i]->seen) continue;
    const std::string& name = channels_[i]->file;
    const std::string csv = quoted((dir / (name + ".csv")).string());
    std::ostringstream gp;
    gp << "set terminal pngcairo size 1100,900 font 'DejaVu Sans,10'\nset output " << quoted((dir / (name + ".png")).string())
       << "\nset datafile separator ','\nset grid\nset key top right opaque\nset xlabel 'time (s)'\n"
       << "set multiplot layout 3,1 title " << quoted(scenario_.name + ": IMU " + set.spec(i).name + " (sensor frame)")
       << " noenhanced\n"
       << "set ylabel 'angular velocity (rad/s)'\nplot " << csv << " using 1:9 with lines title 'x', " << csv
       << " using 1:10 with lines title 'y', " << csv << " using 1:11 with lines title 'z'\n"
       << "set ylabel 'linear acceleration (m/s^2)'\nplot " << csv << " using 1:12 with lines title 'x', " << csv
       << " using 1:13 with lines title 'y', " << csv << " using 1:14 with lines title 'z'\n"
       << "set ylabel 'orientation (deg)'\nplot " << csv << " using 1:($6*180/pi) with lines title 'roll', " << csv
       << " using 1:($7*180/pi) with lines title 'pitch', " << csv << " using 1:($8*180/pi) with lines title 'yaw'\n"
       << "unset multiplot\n";
    if (const std::string err = run_gnuplot(dir, name, gp.str()); !err.empty()) {
      result.warnings.push_back(err);
    } else {
      result.files.push_back("sensors/" + name + ".png");
    }
  }
}

void SensorReport::laser_picture(ScenarioResult& result) {
  const fs::path dir = dir_;
  // Frame everything seen, the robot's path and its start with a 1 m margin, square.
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  auto extend = [&](double x, double y) {
    x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  };
  std::ofstream scans(dir / "laser_scans.csv");
  scans << "x,y\n";
  std::ostringstream plots;
  for (std::size_t k = 0; k < captures_.size(); ++k) {
    const Capture& c = captures_[k];
    extend(c.x, c.y);
    for (const auto& p : c.points) {
      extend(p[0], p[1]);
      scans << p[0] << ',' << p[1] << '\n';
    }
    scans << c.x << ',' << c.y << "\n\n\n";  // the origin last; two blank lines: the next block
  }
  scans.close();
  std::ifstream base(dir / "base.csv");
  std::string line;
  std::getline(base, line);
  while (std::getline(base, line)) {
    double t = 0, x = 0, y = 0;
    if (std::sscanf(line.c_str(), "%lf,%lf,%lf", &t, &x, &y) == 3) extend(x, y);
  }
  const double cx = (x0 + x1) / 2, cy = (y0 + y1) / 2, half = std::max({x1 - x0, y1 - y0, 1.0}) / 2 + 1.0;
  std::ostringstream gp;
  gp << "set terminal pngcairo size 1200,1000 font 'DejaVu Sans,11'\nset output " << quoted((dir / "laser_scans.png").string())
     << "\nset datafile separator ','\nset size ratio -1\nset xlabel 'x (m)'\nset ylabel 'y (m)'\nset key outside bottom center horizontal\n"
     << "set xrange [" << cx - half << ":" << cx + half << "]\nset yrange [" << cy - half << ":" << cy + half << "]\n"
     << "set title " << quoted(scenario_.name + ": laser scans seen from above") << " noenhanced\n";
  std::string layers;
  if (const auto& terrain = sim_.world().spec.terrain) {
    double z0 = 0, z1 = 0;
    write_terrain(*terrain, dir / "terrain.csv", z0, z1);
    gp << "set cblabel 'height (m)'\nset palette defined (0 '#3b1a0f', 0.5 '#a0522d', 1 '#f4c28f')\n";
    layers += quoted((dir / "terrain.csv").string()) + " using 1:2:3 with image notitle, ";
  } else {
    gp << "set grid\n";
  }
  int object = 1;
  for (const physics::WorldBox& b : sim_.world().spec.boxes) {
    if (b.shape == physics::WorldBox::Shape::Cylinder || b.shape == physics::WorldBox::Shape::Sphere) {
      // an upright cylinder's or a sphere's footprint
      gp << "set object " << object++ << " circle at " << b.pose.position.x << "," << b.pose.position.y << " size "
         << b.size.x / 2 << " fillstyle solid 0.35 fillcolor rgb '#808080' front\n";
      continue;
    }
    // The box's footprint, turned by its yaw (a mesh's: its bounding box's, from its low corner).
    const double yaw = yaw_of(b.pose.orientation), c = std::cos(yaw), s = std::sin(yaw);
    const bool mesh = b.shape == physics::WorldBox::Shape::Mesh;
    const double mx = mesh ? b.mesh_min.x + b.size.x / 2 : 0.0, my = mesh ? b.mesh_min.y + b.size.y / 2 : 0.0;
    gp << "set object " << object++ << " polygon from ";
    const double corners[5][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {-1, -1}};
    for (int i = 0; i < 5; ++i) {
      const double lx = mx + corners[i][0] * b.size.x / 2, ly = my + corners[i][1] * b.size.y / 2;
      gp << (i ? " to " : "") << b.pose.position.x + c * lx - s * ly << "," << b.pose.position.y + s * lx + c * ly;
    }
    // A mesh's bounding box is larger than the mesh: drawn behind the scans, which show its shape.
    gp << (mesh ? " fillstyle transparent solid 0.2 fillcolor rgb '#808080' back\n"
                : " fillstyle solid 0.35 fillcolor rgb '#808080' front\n");
  }
  if (fs::exists(dir / "base.csv"))
    layers += quoted((dir / "base.csv").string()) + " using 2:3 with lines lw 2 lc rgb '#0050ff' title 'path of the base', ";
  const char* colours[] = {"#e00000", "#00a000", "#a000c0", "#ff8c00", "#008080", "#000000"};
  for (std::size_t k = 0; k < captures_.size(); ++k) {
    char title[160];
    std::snprintf(title, sizeof title, "%s at t=%.2f s", captures_[k].sensor.c_str(), captures_[k].time);
    const std::string colour = colours[k % 6];
    layers += quoted((dir / "laser_scans.csv").string()) + " index " + std::to_string(k) +
              " using 1:2 with points pt 7 ps 0.35 lc rgb '" + colour + "' title " + quoted(title) + " noenhanced, ";
    layers += quoted((dir / "laser_scans.csv").string()) + " index " + std::to_string(k) + " every ::" +
              std::to_string(captures_[k].points.size()) + " using 1:2 with points pt 9 ps 2 lc rgb '" + colour + "' notitle, ";
  }
  layers.resize(layers.size() - 2);
  if (const std::string err = run_gnuplot(dir, "laser_scans", gp.str() + "plot " + layers + "\n"); !err.empty()) {
    result.warnings.push_back(err);
  } else {
    result.files.push_back("laser_scans.png");
    result.files.push_back("laser_scans.csv");
  }
}

}  // namespace mechsim::sim
