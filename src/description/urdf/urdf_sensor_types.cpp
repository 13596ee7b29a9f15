// The bodies of Gazebo <sensor> elements by type (SDF 1.4-1.6 as Gazebo classic reads them):
// <ray>/<lidar>, <imu>, <contact>, <force_torque>, and SDF <noise>.
#include <algorithm>
#include <cmath>

#include "description/urdf/urdf_sensors.hpp"

namespace mechsim::description::detail {

void SensorFields::error(int line, const std::string& message) const {
  p_.error(line, "sensor '" + sensor_ + "': " + message);
}

void SensorFields::warning(int line, const std::string& message) const {
  p_.warning(line, "sensor '" + sensor_ + "': " + message);
}

std::optional<double> SensorFields::number(const XmlNode& parent, const std::string& child,
                                           const std::string& path) const {
  const XmlNode* c = parent.child(child);
  if (c == nullptr) return std::nullopt;
  const std::string text = c->attribute("value").value_or(c->text);
  const auto v = parse_number(text);
  if (!v) {
    error(c->line, "<" + path + "> is not a number: \"" + text + "\"");
    return std::nullopt;
  }
  if (!std::isfinite(*v)) {
    error(c->line, "<" + path + "> is not finite: \"" + text + "\"");
    return std::nullopt;
  }
  return v;
}

double SensorFields::number_or(const XmlNode& parent, const std::string& child, const std::string& path,
                               double fallback) const {
  return number(parent, child, path).value_or(fallback);
}

double SensorFields::non_negative_or(const XmlNode& parent, const std::string& child, const std::string& path,
                                     double fallback) const {
  const auto v = number(parent, child, path);
  if (v && *v < 0.0) {
    error(parent.child(child)->line, "<" + path + "> must be >= 0, got " + parent.child(child)->text);
    return fallback;
  }
  return v.value_or(fallback);
}

std::optional<bool> SensorFields::boolean(const XmlNode& parent, const std::string& child,
                                          const std::string& path) const {
  const XmlNode* c = parent.child(child);
  if (c == nullptr) return std::nullopt;
  const auto v = parse_bool(c->attribute("value").value_or(c->text));
  if (!v) error(c->line, "<" + path + "> is not a boolean: \"" + c->text + "\"");
  return v;
}

std::optional<std::vector<double>> SensorFields::numbers(const XmlNode& node, std::size_t count,
                                                         const std::string& path) const {
  const auto v = parse_numbers(node.text);
  if (!v || v->size() != count) {
    error(node.line, "<" + path + "> must hold " + std::to_string(count) + " numbers, not \"" + node.text + "\"");
    return std::nullopt;
  }
  for (const double x : *v) {
    if (!std::isfinite(x)) {
      error(node.line, "<" + path + "> is not finite: \"" + node.text + "\"");
      return std::nullopt;
    }
  }
  return v;
}

Pose pose_from_xyz_rpy(const std::vector<double>& v) {
  Pose pose;
  pose.position = {v[0], v[1], v[2]};
  const double cr = std::cos(v[3] / 2), sr = std::sin(v[3] / 2);
  const double cp = std::cos(v[4] / 2), sp = std::sin(v[4] / 2);
  const double cy = std::cos(v[5] / 2), sy = std::sin(v[5] / 2);
  // Fixed axes x (roll), y (pitch), z (yaw): q = qz * qy * qx.
  pose.orientation = {cr * cp * cy + sr * sp * sy, sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy,
                      cr * cp * sy - sr * sp * cy};
  return pose;
}

NoiseSpec read_noise(const XmlNode& noise, const SensorFields& f, const std::string& path) {
  NoiseSpec n;
  // SDF 1.5+: <noise type="gaussian">; SDF 1.4: <noise><type>gaussian</type>.
  std::string type = noise.attribute("type").value_or("");
  if (const XmlNode* t = noise.child("type")) type = t->text;
  if (type.empty() && noise.children.empty()) return n;
  if (type == "none") return n;
  if (type != "gaussian" && type != "gaussian_quantized") {
    f.error(noise.line, "<" + path + "> type \"" + type + "\" is not none, gaussian or gaussian_quantized");
    return n;
  }
  n.mean = f.number_or(noise, "mean", path + "><mean", 0.0);
  n.stddev = f.non_negative_or(noise, "stddev", path + "><stddev", 0.0);
  n.bias_mean = f.number_or(noise, "bias_mean", path + "><bias_mean", 0.0);
  n.bias_stddev = f.non_negative_or(noise, "bias_stddev", path + "><bias_stddev", 0.0);
  n.drift_stddev = f.non_negative_or(noise, "dynamic_bias_stddev", path + "><dynamic_bias_stddev", 0.0);
  n.drift_time = f.non_negative_or(noise, "dynamic_bias_correlation_time", path + "><dynamic_bias_correlation_time", 0.0);
  if (type == "gaussian_quantized") n.precision = f.non_negative_or(noise, "precision", path + "><precision", 0.0);
  return n;
}

namespace {

RayAxis read_axis(const XmlNode& axis, const SensorFields& f, const std::string& path) {
  RayAxis a;
  const auto samples = f.number(axis, "samples", path + "><samples");
  if (!samples && axis.child("samples") == nullptr) f.error(axis.line, "<" + path + "> has no <samples>");
  if (samples) {
    if (*samples < 1.0 || *samples != std::floor(*samples) || *samples > 1e6) {
      f.error(axis.child("samples")->line, "<" + path + "><samples> must be a whole number >= 1, got " +
                                                axis.child("samples")->text);
    } else {
      a.samples = static_cast<int>(*samples);
    }
  }
  a.resolution = f.number_or(axis, "resolution", path + "><resolution", 1.0);
  if (!(a.resolution > 0.0)) {
    f.error(axis.child("resolution")->line, "<" + path + "><resolution> must be > 0");
    a.resolution = 1.0;
  }
  a.min_angle = f.number_or(axis, "min_angle", path + "><min_angle", 0.0);
  a.max_angle = f.number_or(axis, "max_angle", path + "><max_angle", 0.0);
  if (a.min_angle > a.max_angle) {
    f.error(axis.line, "<" + path + "> min_angle " + std::to_string(a.min_angle) + " > max_angle " +
                           std::to_string(a.max_angle));
  }
  return a;
}

}  // namespace

RaySpec read_ray(const XmlNode& sensor, const SensorFields& f, bool gpu) {
  RaySpec r;
  r.gpu = gpu;
  const XmlNode* ray = sensor.child("ray");
  std::string tag = "ray";
  if (ray == nullptr) {
    ray = sensor.child("lidar");  // SDF 1.6+ spelling
    tag = "lidar";
  }
  if (ray == nullptr) {
    f.error(sensor.line, "a " + sensor.attribute("type").value_or("ray") + " sensor needs a <ray> element");
    return r;
  }
  const XmlNode* scan = ray->child("scan");
  const XmlNode* horizontal = scan != nullptr ? scan->child("horizontal") : nullptr;
  if (horizontal == nullptr) {
    f.error(ray->line, "<" + tag + "> has no <scan><horizontal>");
  } else {
    r.horizontal = read_axis(*horizontal, f, tag + "><scan><horizontal");
  }
  if (const XmlNode* vertical = scan != nullptr ? scan->child("vertical") : nullptr)
    r.vertical = read_axis(*vertical, f, tag + "><scan><vertical");
  const XmlNode* range = ray->child("range");
  if (range == nullptr) {
    f.error(ray->line, "<" + tag + "> has no <range> (min and max in m)");
    return r;
  }
  const auto lo = f.number(*range, "min", tag + "><range><min");
  const auto hi = f.number(*range, "max", tag + "><range><max");
  if (range->child("max") == nullptr) f.error(range->line, "<" + tag + "><range> has no <max>");
  r.range_min = lo.value_or(0.0);
  r.range_max = hi.value_or(0.0);
  if (r.range_min < 0.0) f.error(range->line, "<" + tag + "><range><min> must be >= 0, got " + std::to_string(r.range_min));
  if (hi && !(r.range_max > r.range_min)) {
    f.error(range->line, "<" + tag + "><range> min " + std::to_string(r.range_min) + " must be below max " +
                             std::to_string(r.range_max));
  }
  r.range_resolution = f.non_negative_or(*range, "resolution", tag + "><range><resolution", 0.0);
  if (const XmlNode* noise = ray->child("noise")) r.noise = read_noise(*noise, f, tag + "><noise");
  return r;
}

ImuSpec read_imu(const XmlNode& sensor, const SensorFields& f) {
  ImuSpec imu;
  const XmlNode* block = sensor.child("imu");
  if (block == nullptr) return imu;
  // SDF 1.5+: <angular_velocity><x><noise>..., <linear_acceleration><x><noise>...
  static constexpr const char* kAxes[3] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    if (const XmlNode* av = block->child("angular_velocity"))
      if (const XmlNode* ax = av->child(kAxes[i]))
        if (const XmlNode* n = ax->child("noise"))
          imu.rate_noise[i] = read_noise(*n, f, std::string("imu><angular_velocity><") + kAxes[i] + "><noise");
    if (const XmlNode* la = block->child("linear_acceleration"))
      if (const XmlNode* ax = la->child(kAxes[i]))
        if (const XmlNode* n = ax->child("noise"))
          imu.accel_noise[i] = read_noise(*n, f, std::string("imu><linear_acceleration><") + kAxes[i] + "><noise");
  }
  // SDF 1.4: <noise><type>gaussian</type><rate>...</rate><accel>...</accel></noise>, one model
  // for the three axes.
  if (const XmlNode* noise = block->child("noise")) {
    const XmlNode* type = noise->child("type");
    const std::string t = type != nullptr ? type->text : noise->attribute("type").value_or("");
    for (const char* part : {"rate", "accel"}) {
      const XmlNode* m = noise->child(part);
      if (m == nullptr) continue;
      XmlNode typed = *m;
      typed.attributes["type"] = t;
      const NoiseSpec n = read_noise(typed, f, std::string("imu><noise><") + part);
      auto& target = std::string(part) == "rate" ? imu.rate_noise : imu.accel_noise;
      target.fill(n);
    }
  }
  return imu;
}

ContactSpec read_contact(const XmlNode& sensor, const SensorFields& f) {
  ContactSpec c;
  const XmlNode* block = sensor.child("contact");
  if (block == nullptr) {
    f.error(sensor.line, "a contact sensor needs <contact><collision>NAME</collision></contact>");
    return c;
  }
  for (const XmlNode* col : block->children_named("collision")) {
    const auto name = col->attribute("name");
    if (!col->text.empty()) {
      c.collisions.push_back(col->text);
    } else if (name && !name->empty()) {
      // Old worlds (gazebo_plugins' bumper test) write <collision name="NAME"/>.
      f.warning(col->line, "<contact><collision name=\"" + *name + "\"/> taken as <collision>" + *name + "</collision>");
      c.collisions.push_back(*name);
    } else {
      f.error(col->line, "<contact><collision> is empty");
    }
  }
  if (c.collisions.empty() && block->child("collision") == nullptr)
    f.error(block->line, "<contact> names no <collision>");
  return c;
}

UnsupportedSpec read_sonar(const XmlNode& sensor, const SensorFields& f) {
  const XmlNode* sonar = sensor.child("sonar");
  if (sonar == nullptr) {
    f.error(sensor.line, "a sonar sensor needs a <sonar> element (min, max, radius)");
  } else {
    const double lo = f.number_or(*sonar, "min", "sonar><min", 0.0);
    const double hi = f.number_or(*sonar, "max", "sonar><max", 1.0);
    const double radius = f.number_or(*sonar, "radius", "sonar><radius", 0.5);
    if (radius < 0.0) f.error(sonar->line, "<sonar><radius> must be >= 0, got " + std::to_string(radius));
    if (lo < 0.0) f.error(sonar->line, "<sonar><min> must be >= 0, got " + std::to_string(lo));
    if (lo > hi) f.error(sonar->line, "<sonar> min " + std::to_string(lo) + " must not exceed max " + std::to_string(hi));
  }
  return UnsupportedSpec{"mechsim does not simulate sonar sensors (Gazebo's cone of contacts, published on Gazebo's own "
                         "transport only); a ray sensor with libgazebo_ros_range.so gives sensor_msgs/Range"};
}

ForceTorqueSpec read_force_torque(const XmlNode& sensor, const SensorFields& f) {
  ForceTorqueSpec ft;
  const XmlNode* block = sensor.child("force_torque");
  if (block == nullptr) return ft;
  if (const XmlNode* frame = block->child("frame")) {
    if (frame->text == "child") ft.frame = ForceTorqueSpec::Frame::Child;
    else if (frame->text == "parent") ft.frame = ForceTorqueSpec::Frame::Parent;
    else if (frame->text == "sensor") ft.frame = ForceTorqueSpec::Frame::Sensor;
    else f.error(frame->line, "<force_torque><frame> \"" + frame->text + "\" is not child, parent or sensor");
  }
  if (const XmlNode* dir = block->child("measure_direction")) {
    if (dir->text == "parent_to_child") ft.parent_to_child = true;
    else if (dir->text != "child_to_parent")
      f.error(dir->line, "<force_torque><measure_direction> \"" + dir->text +
                             "\" is not child_to_parent or parent_to_child");
  }
  for (const char* part : {"force", "torque"}) {
    const XmlNode* p = block->child(part);
    const XmlNode* x = p != nullptr ? p->child("x") : nullptr;
    const XmlNode* n = x != nullptr ? x->child("noise") : nullptr;
    if (n == nullptr) continue;
    const NoiseSpec noise = read_noise(*n, f, std::string("force_torque><") + part + "><x><noise");
    (std::string(part) == "force" ? ft.force_noise : ft.torque_noise) = noise;
  }
  return ft;
}

}  // namespace mechsim::description::detail
