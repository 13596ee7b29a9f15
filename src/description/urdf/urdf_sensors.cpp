// Gazebo sensors in a description: <sensor> elements (common elements, the type's body, the ROS
// plugin and the names it would publish under) and the model plugins that are sensors.
#include "description/urdf/urdf_sensors.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <set>
#include <sstream>
#include <string_view>

namespace mechsim::description::detail {

namespace {

// SDF sensor types mechsim knows but does not simulate, with the reason `mechsim check` gives.
std::string unsupported_type_reason(const std::string& type) {
  static const std::set<std::string> cameras = {"thermal", "logical_camera", "rgbd_camera", "depth_camera",
                                                "boundingbox_camera", "segmentation_camera"};
  static const std::set<std::string> others = {"gps",  "navsat",           "altimeter",           "magnetometer",
                                               "rfid",            "rfidtag",             "wireless_receiver",
                                               "wireless_transmitter", "wireless_transceiver", "air_pressure", "custom"};
  if (cameras.count(type)) return "mechsim simulates camera, depth, multicamera and wideanglecamera, not " + type;
  if (others.count(type)) return "mechsim does not simulate " + type + " sensors";
  return "";
}

// Plugins whose output mechsim publishes, by sensor kind.
bool plugin_published(std::string_view kind, std::string_view filename) {
  if (kind == "ray")
    return filename == "libgazebo_ros_laser.so" || filename == "libgazebo_ros_gpu_laser.so" ||
           filename == "libgazebo_ros_range.so" || filename == "libgazebo_ros_block_laser.so";
  if (kind == "imu") return filename == "libgazebo_ros_imu_sensor.so";
  if (kind == "contact") return filename == "libgazebo_ros_bumper.so";
  if (kind == "camera") return is_camera_plugin(std::string(filename));  // ros/sensor_publishers
  return false;
}

std::string param(const std::map<std::string, std::string>& p, const std::string& key, const std::string& fallback) {
  const auto it = p.find(key);
  return it != p.end() ? it->second : fallback;
}

// gazebo_ros' <ros> block (gazebo_ros/node.cpp reads <namespace>, <remapping> and, in Dashing's
// style, <argument>s such as "__ns:=/x" or "~/out:=scan").
void read_ros2_block(const XmlNode& e, SensorPlugin& plugin) {
  const XmlNode* ros = e.child("ros");
  if (ros == nullptr) return;
  plugin.ros2_block = true;
  for (const XmlNode& c : ros->children) {
    if (c.name == "namespace") {
      plugin.ros2_namespace = c.text;
    } else if (c.name == "remapping" || c.name == "argument") {
      // An <argument> may hold "--ros-args -r a:=b": every token with ":=" is a rule.
      std::string token;
      std::istringstream words(c.text);
      while (words >> token) {
        if (token.rfind("__ns:=", 0) == 0) plugin.ros2_namespace = token.substr(6);
        else if (token.find(":=") != std::string::npos) plugin.ros2_remappings.push_back(token);
      }
    }
  }
}

SensorPlugin read_plugin_element(const XmlNode& e, const SensorFields& f) {
  SensorPlugin plugin;
  plugin.name = e.attribute("name").value_or("");
  plugin.filename = e.attribute("filename").value_or("");
  plugin.line = e.line;
  if (plugin.filename.empty()) f.error(e.line, "<plugin> has no 'filename' attribute");
  for (const XmlNode& c : e.children)
    if (c.children.empty()) plugin.parameters[c.name] = c.text;
  plugin.robot_namespace = param(plugin.parameters, "robotNamespace", "");
  read_ros2_block(e, plugin);
  return plugin;
}

// The plugin's ROS names, with the defaults each plugin uses when the block leaves them out.
void name_outputs(SensorPlugin& plugin, const std::string& kind, const std::string& link) {
  const auto& p = plugin.parameters;
  const std::string& file = plugin.filename;
  if (file == "libgazebo_ros_laser.so" || file == "libgazebo_ros_gpu_laser.so") {
    plugin.topic = param(p, "topicName", "/world");
    plugin.frame = param(p, "frameName", "/world");
  } else if (file == "libgazebo_ros_range.so") {
    plugin.topic = param(p, "topicName", "/range");
    plugin.frame = param(p, "frameName", "/world");
  } else if (file == "libgazebo_ros_block_laser.so") {
    plugin.topic = param(p, "topicName", "/world");
    plugin.frame = param(p, "frameName", "/world");
  } else if (file == "libgazebo_ros_imu_sensor.so") {
    plugin.topic = param(p, "topicName", "imu_data");
    plugin.frame = param(p, "frameName", link);
  } else if (file == "libgazebo_ros_bumper.so") {
    plugin.topic = param(p, "bumperTopicName", "bumper_states");
    plugin.frame = param(p, "frameName", "world");
  } else if (file == "libgazebo_ros_imu.so") {
    plugin.topic = param(p, "topicName", "/default_imu");  // gazebo_ros_imu's default
    plugin.frame = param(p, "frameName", link);
  } else if (file == "libhector_gazebo_ros_imu.so") {
    plugin.topic = param(p, "topicName", "imu");
    plugin.frame = param(p, "frameId", param(p, "frameName", link));
  } else if (file == "libgazebo_ros_p3d.so") {
    plugin.topic = param(p, "topicName", "");
    plugin.frame = param(p, "frameName", "world");
  } else if (file == "libgazebo_ros_ft_sensor.so") {
    plugin.topic = param(p, "topicName", "");
    plugin.frame = link;
  } else {
    plugin.topic = param(p, "topicName", "");
    plugin.frame = param(p, "frameName", link);
  }
  if (!plugin_published(kind, file) && file != "libgazebo_ros_imu.so" && file != "libhector_gazebo_ros_imu.so" &&
      file != "libgazebo_ros_p3d.so" && file != "libgazebo_ros_ft_sensor.so") {
    plugin.unsupported = "mechsim has no ROS output for " + (file.empty() ? std::string("this plugin") : file) +
                         " on a " + kind + " sensor (simulated and recorded, not published)";
  }
}

std::optional<double> plugin_number(const SensorPlugin& plugin, const std::string& key, const SensorFields& f,
                                    const XmlNode& e) {
  const auto it = plugin.parameters.find(key);
  if (it == plugin.parameters.end()) return std::nullopt;
  const XmlNode* c = e.child(key);
  const int line = c != nullptr ? c->line : e.line;
  const auto v = parse_number(it->second);
  if (!v || !std::isfinite(*v)) {
    f.error(line, "<plugin><" + key + "> is not a number: \"" + it->second + "\"");
    return std::nullopt;
  }
  return v;
}

std::optional<std::vector<double>> plugin_vector(const std::string& key, const SensorFields& f, const XmlNode& e) {
  const XmlNode* c = e.child(key);
  if (c == nullptr) return std::nullopt;
  return f.numbers(*c, 3, "plugin><" + key);
}

Pose offset_pose(const char* xyz_key, const char* rpy_key, const SensorFields& f,
                 const XmlNode& e) {
  std::vector<double> v(6, 0.0);
  if (auto xyz = plugin_vector(xyz_key, f, e)) std::copy(xyz->begin(), xyz->end(), v.begin());
  if (auto rpy = plugin_vector(rpy_key, f, e)) std::copy(rpy->begin(), rpy->end(), v.begin() + 3);
  return pose_from_xyz_rpy(v);
}

double plugin_rate(const SensorPlugin& plugin, const std::string& key, const SensorFields& f, const XmlNode& e,
                   double fallback) {
  const auto v = plugin_number(plugin, key, f, e);
  if (v && *v < 0.0) {
    f.error(e.child(key)->line, "<plugin><" + key + "> must be >= 0 Hz, got " + plugin.parameters.at(key));
    return fallback;
  }
  return v.value_or(fallback);
}

double plugin_deviation(const SensorPlugin& plugin, const std::string& key, const SensorFields& f, const XmlNode& e) {
  const auto v = plugin_number(plugin, key, f, e);
  if (v && *v < 0.0) {
    f.error(e.child(key)->line, "<plugin><" + key + "> must be >= 0, got " + plugin.parameters.at(key));
    return 0.0;
  }
  return v.value_or(0.0);
}

// Hector's error model for one quantity: <prefix>Offset, <prefix>Drift, <prefix>DriftFrequency,
// <prefix>GaussianNoise (scalars or "x y z").
std::array<NoiseSpec, 3> hector_noise(const std::string& prefix, const SensorFields& f,
                                      const XmlNode& e) {
  std::array<NoiseSpec, 3> n{};
  auto read3 = [&](const std::string& key, auto&& set) {
    const XmlNode* c = e.child(key);
    if (c == nullptr) return;
    const auto v = parse_numbers(c->text);
    if (!v || (v->size() != 1 && v->size() != 3)) {
      f.error(c->line, "<plugin><" + key + "> must hold 1 or 3 numbers, not \"" + c->text + "\"");
      return;
    }
    for (int i = 0; i < 3; ++i) set(n[static_cast<std::size_t>(i)], (*v)[v->size() == 1 ? 0 : static_cast<std::size_t>(i)]);
  };
  read3(prefix + "Offset", [](NoiseSpec& s, double x) { s.offset = x; });
  read3(prefix + "Drift", [](NoiseSpec& s, double x) { s.drift_stddev = std::abs(x); });
  read3(prefix + "DriftFrequency", [](NoiseSpec& s, double x) { s.drift_time = x > 0.0 ? 1.0 / x : 0.0; });
  read3(prefix + "GaussianNoise", [](NoiseSpec& s, double x) { s.stddev = std::abs(x); });
  return n;
}

// The link a model plugin's <bodyName> names; an error (and "") when there is none.
std::string body_link(const SensorPlugin& plugin, const RobotModel& robot, const SensorFields& f, const XmlNode& e) {
  const std::string body = param(plugin.parameters, "bodyName", "");
  if (body.empty()) {
    f.error(e.line, "<plugin> " + plugin.filename + " needs a <bodyName> (the link it measures)");
    return "";
  }
  if (robot.link(body) == nullptr) {
    f.error(e.child("bodyName")->line, "<bodyName> names no link of the robot: '" + body + "'");
    return "";
  }
  return body;
}

// gazebo_ros_range's parameters (defaults: fov 0.05 rad, ultrasound, no noise, the sensor's
// rate) on a ray sensor.
void read_range_plugin(RaySpec& ray, SensorSpec& s, const SensorPlugin& plugin, const SensorFields& f,
                       const XmlNode& e) {
  ray.output = RayOutput::Range;
  ray.plugin_noise = plugin_deviation(plugin, "gaussianNoise", f, e);
  ray.fov = plugin_number(plugin, "fov", f, e).value_or(0.05);
  const std::string radiation = param(plugin.parameters, "radiation", "ultrasound");
  ray.radiation = radiation == "ultrasound" ? 0 : 1;
  // The plugin publishes at most at its <updateRate> (0: every sensor update).
  const double rate = plugin_rate(plugin, "updateRate", f, e, 0.0);
  if (rate > 0.0 && (s.update_rate <= 0.0 || rate < s.update_rate)) s.update_rate = rate;
}

}  // namespace

// The collision shapes a contact sensor's <collision> names refer to: a collision of the sensor's
// link (then of any link) with that name (SDF models name theirs; URDF may), else Gazebo's names for
// a URDF link's shapes (<link>_collision[_N], lumped <parent>_fixed_joint_lump__<link>_collision):
// every shape of that link. Names that fit neither are left to the sensor (it names the problem).
void resolve_contact(ContactSpec& c, const std::string& link, const RobotModel& robot) {
  c.targets.clear();
  for (const std::string& name : c.collisions) {
    std::optional<ContactSpec::Target> found;
    const auto by_name = [&](const Link& l) {
      for (std::size_t i = 0; i < l.collisions.size(); ++i)
        if (!l.collisions[i].name.empty() && l.collisions[i].name == name) return std::optional<ContactSpec::Target>(ContactSpec::Target{l.name, static_cast<int>(i)});
      return std::optional<ContactSpec::Target>();
    };
    if (const Link* own = robot.link(link)) found = by_name(*own);
    for (std::size_t i = 0; !found && i < robot.links.size(); ++i) found = by_name(robot.links[i]);
    if (!found) {
      std::string base = name;
      const std::string lump = "_fixed_joint_lump__";
      if (const auto at = base.find(lump); at != std::string::npos) base = base.substr(at + lump.size());
      const auto at = base.rfind("_collision");
      if (at != std::string::npos && robot.link(base.substr(0, at)) != nullptr) found = ContactSpec::Target{base.substr(0, at), -1};
    }
    if (!found) {
      c.targets.clear();  // one the description cannot place: the sensor resolves them all by name
      return;
    }
    c.targets.push_back(*found);
  }
}

void read_sensor(const XmlNode& sensor, const std::string& reference, const RobotModel& robot, Problems& p,
                 std::vector<SensorSpec>& out) {
  SensorSpec s;
  s.name = sensor.attribute("name").value_or("");
  s.type = sensor.attribute("type").value_or("");
  s.line = sensor.line;
  s.source = p.source();
  const SensorFields f(p, s.name.empty() ? "<unnamed>" : s.name);
  if (s.name.empty()) f.error(sensor.line, "<sensor> has no 'name' attribute");
  if (s.type.empty()) f.error(sensor.line, "<sensor> has no 'type' attribute");

  // The sensor's link: <gazebo reference="link">, or for a force_torque sensor the joint's child.
  const Joint* joint = robot.joint(reference);
  if (reference.empty()) {
    f.error(sensor.line, "a <sensor> must sit in a <gazebo reference=\"LINK\"> element");
  } else if (robot.link(reference) != nullptr) {
    s.link = reference;
  } else if (joint != nullptr) {
    s.link = joint->child_link;
  } else {
    f.error(sensor.line, "<gazebo reference=\"" + reference + "\"> names no link or joint of the robot");
  }

  s.update_rate = f.number_or(sensor, "update_rate", "update_rate", 0.0);
  if (s.update_rate < 0.0) {
    f.error(sensor.child("update_rate")->line, "<update_rate> must be >= 0 Hz (0: every step), got " +
                                                   sensor.child("update_rate")->text);
    s.update_rate = 0.0;
  }
  s.always_on = f.boolean(sensor, "always_on", "always_on").value_or(true);
  if (const XmlNode* pose = sensor.child("pose")) {
    if (auto v = f.numbers(*pose, 6, "pose")) s.pose = pose_from_xyz_rpy(*v);
  }

  std::string kind;
  if (s.type == "ray" || s.type == "gpu_ray" || s.type == "lidar" || s.type == "gpu_lidar") {
    s.details = read_ray(sensor, f, s.type == "gpu_ray" || s.type == "gpu_lidar");
    kind = "ray";
  } else if (s.type == "imu") {
    s.details = read_imu(sensor, f);
    kind = "imu";
  } else if (s.type == "contact") {
    ContactSpec contact = read_contact(sensor, f);
    resolve_contact(contact, s.link, robot);
    s.details = std::move(contact);
    kind = "contact";
  } else if (s.type == "sonar") {
    s.details = read_sonar(sensor, f);
    kind = "sonar";
  } else if (s.type == "force_torque") {
    ForceTorqueSpec ft = read_force_torque(sensor, f);
    if (joint == nullptr) {
      if (!reference.empty())
        f.error(sensor.line, "a force_torque sensor must sit in a <gazebo reference=\"JOINT\">, not a link");
    } else {
      ft.joint = joint->name;
      ft.parent_link = joint->parent_link;
      ft.child_link = joint->child_link;
    }
    s.details = ft;
    kind = "force_torque";
  } else if (s.type == "camera" || s.type == "depth" || s.type == "multicamera" || s.type == "wideanglecamera") {
    s.details = read_camera(sensor, f, s.type);
    kind = "camera";
  } else if (!s.type.empty()) {
    const std::string reason = unsupported_type_reason(s.type);
    if (reason.empty()) {
      f.error(sensor.line, "unknown sensor type \"" + s.type +
                               "\" (Gazebo's are ray, gpu_ray, imu, contact, force_torque, camera, depth, ...)");
    }
    s.details = UnsupportedSpec{reason};
    kind = s.type;
  }

  const std::vector<const XmlNode*> plugins = sensor.children_named("plugin");
  if (plugins.size() > 1) f.warning(plugins[1]->line, "only the first <plugin> of a sensor is used");
  if (!plugins.empty()) {
    SensorPlugin plugin = read_plugin_element(*plugins.front(), f);
    name_outputs(plugin, kind, s.link);
    const XmlNode& e = *plugins.front();
    if (auto* imu = std::get_if<ImuSpec>(&s.details)) {
      // gazebo_ros_imu_sensor: <gaussianNoise> on rates and accelerations, <rpyOffset> on the
      // orientation, <updateRateHZ> as a second rate limit.
      const double gn = plugin_deviation(plugin, "gaussianNoise", f, e);
      for (auto* axes : {&imu->rate_noise, &imu->accel_noise})
        for (NoiseSpec& n : *axes)
          if (gn > 0.0) n.stddev = std::sqrt(n.stddev * n.stddev + gn * gn);
      imu->offset = offset_pose("xyzOffset", "rpyOffset", f, e);
      // The plugin's default is true (deprecated: REP 145 wants the world as reference).
      imu->initial_orientation_as_reference = true;
      const auto ref = plugin.parameters.find("initialOrientationAsReference");
      if (ref != plugin.parameters.end()) {
        const auto b = parse_bool(ref->second);
        if (!b) f.error(e.child("initialOrientationAsReference")->line, "<initialOrientationAsReference> is not a boolean");
        imu->initial_orientation_as_reference = b.value_or(false);
      }
      const double plugin_rate_hz = plugin_rate(plugin, "updateRateHZ", f, e, 0.0);
      if (plugin_rate_hz > 0.0 && (s.update_rate <= 0.0 || plugin_rate_hz < s.update_rate)) s.update_rate = plugin_rate_hz;
    } else if (auto* ray = std::get_if<RaySpec>(&s.details)) {
      const double gn = plugin_deviation(plugin, "gaussianNoise", f, e);
      if (plugin.filename == "libgazebo_ros_range.so") {
        read_range_plugin(*ray, s, plugin, f, e);
      } else if (plugin.filename == "libgazebo_ros_block_laser.so") {
        // The block laser reads <updateRate> and <hokuyoMinIntensity> but uses neither: the
        // sensor's own rate paces it.
        ray->output = RayOutput::PointCloud;
        ray->plugin_noise = gn;
      } else if (gn > 0.0 && !ray->noise.active()) {
        // gazebo_ros_laser ignores the old block laser's <gaussianNoise>; mechsim takes it as the
        // ranges' deviation when the sensor has no <noise> of its own (the PR2's Hokuyos).
        ray->noise.stddev = gn;
      }
    } else if (auto* camera = std::get_if<CameraSpec>(&s.details)) {
      if (is_camera_plugin(plugin.filename)) read_camera_plugin(*camera, plugin, s.type, f, e);
    } else if (s.type == "sonar" && plugin.filename == "libgazebo_ros_range.so") {
      // Gazebo's gazebo_ros_range refuses a sonar sensor at load ("GazeboRosRange controller
      // requires a Ray Sensor as its parent"), so nothing publishes it.
      plugin.unsupported = "libgazebo_ros_range.so needs a ray sensor (Gazebo's plugin refuses a sonar sensor); use "
                           "<sensor type=\"ray\"> for a sensor_msgs/Range";
    }
    s.plugin = std::move(plugin);
  }
  out.push_back(std::move(s));
}

bool read_sensor_plugin(const XmlNode& e, const RobotModel& robot, Problems& p, std::vector<SensorSpec>& out) {
  const std::string file = e.attribute("filename").value_or("");
  static const std::set<std::string> sensor_plugins = {"libgazebo_ros_imu.so", "libhector_gazebo_ros_imu.so",
                                                       "libgazebo_ros_p3d.so", "libgazebo_ros_ft_sensor.so",
                                                       "libgazebo_ros_f3d.so"};
  if (!sensor_plugins.count(file)) return false;
  SensorSpec s;
  s.name = e.attribute("name").value_or(file);
  s.type = "plugin";
  s.line = e.line;
  s.source = p.source();
  const SensorFields f(p, s.name);
  SensorPlugin plugin = read_plugin_element(e, f);

  if (file == "libgazebo_ros_ft_sensor.so") {
    ForceTorqueSpec ft;
    ft.parent_to_child = true;  // the joint's wrench on its child, in the child's frame
    ft.joint = param(plugin.parameters, "jointName", "");
    const Joint* joint = robot.joint(ft.joint);
    if (ft.joint.empty()) f.error(e.line, "<plugin> libgazebo_ros_ft_sensor.so needs a <jointName>");
    else if (joint == nullptr) f.error(e.child("jointName")->line, "<jointName> names no joint of the robot: '" + ft.joint + "'");
    else {
      s.link = ft.child_link = joint->child_link;
      ft.parent_link = joint->parent_link;
    }
    const double gn = plugin_deviation(plugin, "gaussianNoise", f, e);
    ft.force_noise.stddev = ft.torque_noise.stddev = gn;
    s.details = ft;
    s.update_rate = plugin_rate(plugin, "updateRate", f, e, 0.0);
  } else {
    s.link = body_link(plugin, robot, f, e);
    if (file == "libgazebo_ros_p3d.so") {
      GroundTruthSpec gt;
      gt.frame = param(plugin.parameters, "frameName", "world");
      if (!gt.frame.empty() && gt.frame.front() == '/') gt.frame.erase(0, 1);
      if (gt.frame != "world" && gt.frame != "map" && robot.link(gt.frame) == nullptr)
        f.error(e.child("frameName")->line, "<frameName> is neither world, map nor a link of the robot: '" + gt.frame + "'");
      gt.offset = offset_pose("xyzOffsets", "rpyOffsets", f, e);
      gt.gaussian_noise = plugin_deviation(plugin, "gaussianNoise", f, e);
      s.details = gt;
      s.update_rate = plugin_rate(plugin, "updateRate", f, e, 0.0);
    } else if (file == "libgazebo_ros_f3d.so") {
      s.details = UnsupportedSpec{"libgazebo_ros_f3d.so (the forces applied to a body) is not simulated"};
      s.update_rate = plugin_rate(plugin, "updateRate", f, e, 0.0);
    } else {
      ImuSpec imu;
      if (file == "libgazebo_ros_imu.so") {
        const double gn = plugin_deviation(plugin, "gaussianNoise", f, e);
        for (auto* axes : {&imu.rate_noise, &imu.accel_noise})
          for (NoiseSpec& n : *axes) n.stddev = gn;
        imu.offset = offset_pose("xyzOffset", "rpyOffset", f, e);
        imu.service_name = param(plugin.parameters, "serviceName", "/default_imu");  // as its topic
      } else {
        imu.rate_noise = hector_noise("rate", f, e);
        imu.accel_noise = hector_noise("accel", f, e);
        imu.yaw_noise = hector_noise("heading", f, e)[0];
        imu.offset = offset_pose("xyzOffset", "rpyOffset", f, e);
        // hector's default: <topicName>/calibrate
        imu.service_name = param(plugin.parameters, "serviceName", param(plugin.parameters, "topicName", "imu") + "/calibrate");
      }
      s.details = imu;
      s.update_rate = plugin_rate(plugin, "updateRate", f, e, 0.0);
    }
  }
  name_outputs(plugin, "plugin", s.link);
  if (file == "libgazebo_ros_f3d.so") plugin.unsupported = "not simulated";
  if (plugin.topic.empty() && (file == "libgazebo_ros_p3d.so" || file == "libgazebo_ros_ft_sensor.so"))
    f.error(e.line, "<plugin> " + file + " needs a <topicName>");
  s.plugin = std::move(plugin);
  out.push_back(std::move(s));
  return true;
}

}  // namespace mechsim::description::detail
