#pragma once
// Internal to the URDF reader: the Gazebo sensor blocks (urdf_sensors.cpp, urdf_sensor_types.cpp).
// They read XmlNode copies, so that a scenario's <gazebo> blocks go through the same code
// (sensor_reader.hpp).

#include <string>
#include <vector>

#include "description/robot_model.hpp"
#include "description/sensor_spec.hpp"
#include "description/urdf/urdf_reading.hpp"

namespace mechsim::description::detail {

// A <sensor> element of <gazebo reference="reference">: appends its spec to `out` (also when it
// cannot be simulated: an UnsupportedSpec says why). `robot` needs its links and joints.
void read_sensor(const XmlNode& sensor, const std::string& reference, const RobotModel& robot, Problems& p,
                 std::vector<SensorSpec>& out);

// Resolves a contact sensor's <collision> names against the robot's links and collisions
// (ContactSpec::targets); the URDF reader calls it again once the links carry their collisions.
void resolve_contact(ContactSpec& c, const std::string& link, const RobotModel& robot);

// A model <plugin> of a top-level <gazebo>: when it is a sensor plugin (gazebo_ros_imu, hector's
// IMU, p3d, f3d, ft_sensor) appends its spec and returns true; false for any other plugin.
bool read_sensor_plugin(const XmlNode& plugin, const RobotModel& robot, Problems& p, std::vector<SensorSpec>& out);

// Reads typed values of one sensor's elements, recording problems as
// "sensor 'NAME': <path> ...". Shared by the per-type readers (urdf_sensor_types.cpp).
class SensorFields {
 public:
  SensorFields(Problems& p, std::string sensor) : p_(p), sensor_(std::move(sensor)) {}
  void error(int line, const std::string& message) const;
  void warning(int line, const std::string& message) const;
  // The child's text as a number (nullopt and an error when it is not one, or not finite).
  std::optional<double> number(const XmlNode& parent, const std::string& child, const std::string& path) const;
  double number_or(const XmlNode& parent, const std::string& child, const std::string& path, double fallback) const;
  // A number that must be >= 0 (rates, deviations).
  double non_negative_or(const XmlNode& parent, const std::string& child, const std::string& path,
                         double fallback) const;
  std::optional<bool> boolean(const XmlNode& parent, const std::string& child, const std::string& path) const;
  // "x y z" or "x y z roll pitch yaw"; nullopt and an error for anything else.
  std::optional<std::vector<double>> numbers(const XmlNode& node, std::size_t count, const std::string& path) const;
  const std::string& sensor() const { return sensor_; }

 private:
  Problems& p_;
  std::string sensor_;
};

// SDF <noise> (type none | gaussian | gaussian_quantized; mean, stddev, bias_mean, bias_stddev,
// dynamic_bias_stddev, dynamic_bias_correlation_time, precision). `path` names the element.
NoiseSpec read_noise(const XmlNode& noise, const SensorFields& f, const std::string& path);

// The per-type bodies of a <sensor> (urdf_sensor_types.cpp).
RaySpec read_ray(const XmlNode& sensor, const SensorFields& f, bool gpu);
ImuSpec read_imu(const XmlNode& sensor, const SensorFields& f);
ContactSpec read_contact(const XmlNode& sensor, const SensorFields& f);
ForceTorqueSpec read_force_torque(const XmlNode& sensor, const SensorFields& f);
// sonar: <sonar><min><max><radius> checked as Gazebo checks them; not simulated (the reason says so).
UnsupportedSpec read_sonar(const XmlNode& sensor, const SensorFields& f);
// camera, depth, multicamera, wideanglecamera (urdf_camera.cpp): the <camera> elements; then the
// ROS camera plugin's intrinsics and topics (sets plugin.topic and plugin.frame).
CameraSpec read_camera(const XmlNode& sensor, const SensorFields& f, const std::string& type);
void read_camera_plugin(CameraSpec& camera, SensorPlugin& plugin, const std::string& type, const SensorFields& f,
                        const XmlNode& plugin_element);
bool is_camera_plugin(const std::string& filename);
// One of the <image><format> names Gazebo 11's camera knows.
bool is_gazebo_image_format(const std::string& format);

// Pose from "x y z roll pitch yaw" (fixed axes, URDF/SDF convention).
Pose pose_from_xyz_rpy(const std::vector<double>& v);

}  // namespace mechsim::description::detail
