#pragma once
// The sensors a description declares, as plain data: Gazebo <sensor> elements inside
// <gazebo reference="link"> (with their ROS <plugin>), and the model plugins that are sensors in
// all but name (gazebo_ros_imu, hector's IMU, gazebo_ros_p3d, gazebo_ros_ft_sensor). Read by
// urdf/urdf_sensors.cpp from a URDF and by urdf/sensor_reader.hpp from any <gazebo> block (a
// scenario's); errors name the file, the line and the sensor. Simulated by sensors/.
//
// Units: m, rad, s, Hz. Frames: the sensor frame S sits at `pose` (X_LS) in the frame L of the
// link it is attached to.

#include <array>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "description/pose.hpp"

namespace mechsim::description {

// One error model for SDF's <noise> (Gazebo's GaussianNoiseModel) and the plugins' noise
// parameters (gaussianNoise, hector's offset/drift/noise):
//   reading = truth + offset + bias + drift(t) + N(mean, stddev), rounded to `precision`.
// `bias` is drawn once per sensor from N(bias_mean, bias_stddev) with a random sign, as SDF
// does; `drift` is a first-order Gauss-Markov process with stationary deviation `drift_stddev`
// and correlation time `drift_time` (s), or, with drift_time = 0, a random walk whose deviation
// grows by drift_stddev per sqrt(s).
struct NoiseSpec {
  double offset = 0.0;
  double mean = 0.0, stddev = 0.0;
  double bias_mean = 0.0, bias_stddev = 0.0;
  double drift_stddev = 0.0, drift_time = 0.0;
  double precision = 0.0;  // 0: not quantised

  bool active() const {
    return offset != 0.0 || mean != 0.0 || stddev > 0.0 || bias_mean != 0.0 || bias_stddev > 0.0 ||
           drift_stddev > 0.0 || precision > 0.0;
  }
};

// One scan axis of <ray><scan>: `samples` rays from min_angle to max_angle (rad, about the
// sensor's z axis for horizontal, y for vertical). Gazebo interpolates samples * resolution
// ranges from the rays; mechsim casts that many rays instead.
struct RayAxis {
  int samples = 1;
  double resolution = 1.0;
  double min_angle = 0.0, max_angle = 0.0;  // rad
  int count() const;                        // ranges along the axis: samples * resolution, >= 1
};

// What a ray sensor's ROS plugin makes of its rays.
enum class RayOutput {
  Scan,        // the sensor's scan (gazebo_ros_laser, gazebo_ros_gpu_laser, or no plugin): LaserScan
  Range,       // gazebo_ros_range: the shortest of its rays (sensor_msgs/Range)
  PointCloud,  // gazebo_ros_block_laser: a point per interpolated ray with its intensity (sensor_msgs/PointCloud)
};

struct RaySpec {
  RayAxis horizontal, vertical;  // vertical: one sample for a planar scanner
  double range_min = 0.0, range_max = 0.0;  // m
  double range_resolution = 0.0;            // m; 0: not quantised
  NoiseSpec noise;                          // on each range (m)
  bool gpu = false;                         // gpu_ray / gpu_lidar: the same rays (see sensors/README.md)
  RayOutput output = RayOutput::Scan;
  // gazebo_ros_range and gazebo_ros_block_laser: the plugin's <gaussianNoise> (m; the block laser
  // adds it to each coordinate and to the intensity). They read the sensor's raw rays, without the
  // sensor's own <noise>.
  double plugin_noise = 0.0;
  // gazebo_ros_range: <fov> (rad, reported only) and <radiation> (ultrasound: 0, anything else
  // infrared: 1, as sensor_msgs/Range numbers them).
  double fov = 0.05;
  int radiation = 0;
};

struct ImuSpec {
  std::array<NoiseSpec, 3> rate_noise;   // per axis of the angular velocity (rad/s)
  std::array<NoiseSpec, 3> accel_noise;  // per axis of the linear acceleration (m/s^2)
  NoiseSpec yaw_noise;                   // on the reported heading (rad; hector's heading model)
  // xyzOffset / rpyOffset: q_reported = q_offset * q (the plugins apply them to the orientation
  // only); the position part is kept but moves nothing.
  Pose offset;
  // Orientation relative to the sensor's orientation at start (true) or to the world (false).
  bool initial_orientation_as_reference = false;
  std::string service_name;  // the plugin's calibrate service (std_srvs/Empty; the ROS 1 binding answers it)
};

// <contact><collision>: which of the link's collisions count. Gazebo names a URDF link's
// collisions <link>_collision, <link>_collision_1, ... (and <parent>_fixed_joint_lump__<link>_collision
// when it lumps fixed links); mechsim resolves these names to the link's collision shapes.
struct ContactSpec {
  std::vector<std::string> collisions;  // as written
  // The collision shapes each name resolves to, when the description knows them: a link's
  // collision by its own name (an SDF model's, or a URDF <collision name>), `index` its position
  // in Link::collisions; -1: every collision of `link` (a Gazebo-style URDF name). Empty: resolved
  // by the sensor against the physics from the names alone.
  struct Target {
    std::string link;
    int index = -1;
  };
  std::vector<Target> targets;
};

struct ForceTorqueSpec {
  std::string joint;
  std::string parent_link, child_link;  // the joint's
  enum class Frame { Child, Parent, Sensor } frame = Frame::Child;
  // SDF measure_direction: child_to_parent (default) reports the wrench the child applies on the
  // parent; parent_to_child the one the parent applies on the child (gazebo_ros_ft_sensor's).
  bool parent_to_child = false;
  NoiseSpec force_noise, torque_noise;  // per component (N, N m)
};

// Ground truth (gazebo_ros_p3d): pose and twist of the sensor's link in `frame` ("world" or
// "map": the world; else a link's frame).
struct GroundTruthSpec {
  std::string frame = "world";
  Pose offset;                  // xyzOffsets / rpyOffsets
  double gaussian_noise = 0.0;  // stddev on the twist (m/s, rad/s); p3d adds none to the pose
};

// Lens distortion of SDF <camera><distortion> (Brown-Conrady, as Gazebo): radial k1 k2 k3,
// tangential p1 p2, about `center` (normalised image coordinates, 0.5 0.5 the middle).
struct DistortionSpec {
  double k1 = 0.0, k2 = 0.0, k3 = 0.0, p1 = 0.0, p2 = 0.0;
  double center_x = 0.5, center_y = 0.5;
  // Gazebo scales a barrel-distorted image (k1 < 0) up until its black corners are gone; the
  // camera plugins' <borderCrop> (default true) can turn that off.
  bool crop = true;
  bool active() const { return k1 != 0.0 || k2 != 0.0 || k3 != 0.0 || p1 != 0.0 || p2 != 0.0; }
};

// One <camera> of a sensor (a multicamera has several). The camera looks along +x of its frame
// (Gazebo's convention), image up along +z; the optical frame (z forward, x right, y down) is
// that frame turned by rpy (-pi/2, 0, -pi/2).
struct CameraLens {
  std::string name;               // <camera name>
  Pose pose;                      // X_SC: <camera><pose> in the sensor frame
  double horizontal_fov = 1.047;  // rad, in (0, pi)
  int width = 320, height = 240;  // pixels
  // <image><format> as written (Gazebo's names: R8G8B8, L8, L16, R16G16B16, B8G8R8, BAYER_*8,
  // FLOAT32, ... and their *_INT* aliases); one Gazebo does not know is kept with a warning.
  std::string format = "R8G8B8";
  double near = 0.1, far = 100.0;  // m, 0 < near < far
  NoiseSpec noise;                 // on each colour channel, in [0, 1] units (Gazebo's image noise)
  DistortionSpec distortion;
};

// camera / depth / multicamera / wideanglecamera sensors with their ROS plugin's intrinsics and
// topics (gazebo_ros_camera, _multicamera, _depth_camera, _openni_kinect, _prosilica).
struct CameraSpec {
  std::vector<CameraLens> lenses;  // one; several for a multicamera
  bool depth = false;              // depth image and point cloud too (type depth)
  bool wide_angle = false;         // wideanglecamera (rendered as a pinhole, see sensors/README.md)
  // The plugin's CameraInfo: 0 means "from the image" (focal length from the FOV, principal
  // point (w+1)/2, (h+1)/2 as gazebo_ros_camera_utils does).
  double focal_length = 0.0, cx = 0.0, cy = 0.0, cx_prime = 0.0;  // pixels
  double hack_baseline = 0.0;                                       // m: P[3] = -fx * baseline
  std::array<double, 5> ros_distortion{};                           // D: k1 k2 t1 t2 k3 as the plugin says
  // m: depth at or below the cutoff, or at or beyond the maximum, is NaN (gazebo_ros_depth_camera
  // has no maximum: +inf; gazebo_ros_openni_kinect's defaults are 0.4 and 5).
  double point_cloud_cutoff = 0.4, point_cloud_cutoff_max = 5.0;
  // ROS names, resolved against <robotNamespace>/<cameraName> (absolute names kept); per lens
  // for a multicamera (image, info), one set otherwise; an empty name: that lens publishes
  // nothing (gazebo_ros_multicamera publishes only its cameras named left and right).
  std::vector<std::string> image_topics, info_topics;
  std::string depth_topic, depth_info_topic, points_topic;
  // gazebo_ros_triggered_camera: one frame per std_msgs/Empty on this topic, none otherwise.
  std::string trigger_topic;
};

// A sensor mechsim reads but cannot simulate; `reason` says why (mechsim check lists it).
struct UnsupportedSpec {
  std::string reason;
};

// The ROS plugin of a sensor: what topic and frame it publishes on, as the plugin would name
// them (its defaults filled in when the block leaves them out).
struct SensorPlugin {
  std::string name, filename;
  std::string robot_namespace;  // <robotNamespace>, "" when absent
  std::string topic;            // relative to robot_namespace unless it starts with '/'
  std::string frame;            // header.frame_id
  std::map<std::string, std::string> parameters;  // every simple child element: name -> text
  // gazebo_ros (ROS 2) plugins' <ros> block: <namespace>, and each <remapping> (and <argument>
  // of the form from:=to) as "from:=to". `ros2_block` tells whether the plugin has one; the ROS 2
  // layer names the plugin's topics the ROS 2 way when it does (src/ros2/plugin_names.hpp).
  bool ros2_block = false;
  std::string ros2_namespace;
  std::vector<std::string> ros2_remappings;
  // Set when mechsim simulates the sensor but has no ROS output for this plugin.
  std::string unsupported;
  int line = 0;

  // The topic as ROS resolves it under the plugin's namespace: "/ns/topic", or "/topic" (a
  // topic starting with '/' is absolute).
  std::string full_topic() const;
};

struct SensorSpec {
  std::string name;  // <sensor name>, or the model plugin's name
  std::string type;  // as written: ray, gpu_ray, imu, contact, force_torque, camera, ..., or "plugin"
  std::string link;  // the link it is attached to (<gazebo reference>, <bodyName>, a joint's child)
  Pose pose;         // X_LS (<pose> of the sensor)
  double update_rate = 0.0;  // Hz of simulated time; 0: every tick
  bool always_on = true;
  std::optional<SensorPlugin> plugin;
  std::variant<UnsupportedSpec, RaySpec, ImuSpec, ContactSpec, ForceTorqueSpec, GroundTruthSpec, CameraSpec> details;
  std::string source;  // the file it was declared in
  int line = 0;        // of the <sensor> (or model <plugin>) element

  bool simulated() const { return !std::holds_alternative<UnsupportedSpec>(details); }
  // "ray", "imu", "contact", "force_torque", "ground_truth", "camera" or "unsupported".
  const char* kind_name() const;
  std::string where() const;  // "SOURCE:LINE: sensor 'NAME'"
};

}  // namespace mechsim::description
