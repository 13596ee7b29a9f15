#pragma once
// What sensors produce, as plain data (no ROS types): the contents of sensor_msgs/LaserScan and
// Imu, gazebo_msgs/ContactsState, geometry_msgs/WrenchStamped, nav_msgs/Odometry, and the
// images, depth and points behind sensor_msgs/Image, CameraInfo and PointCloud2. Compiles as
// C++17 too (the ROS layer reads these through its bridge).
//
// Units: m, rad, s, N, N m. Frames are named by each sensor's spec (plugin frame).

#include <array>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "description/pose.hpp"

namespace mechsim::sensors {

using description::Pose;
using description::Quat;
using description::Vec3;

using Covariance = std::array<double, 9>;  // row-major 3x3

// A scan of `horizontal_count` x `vertical_count` ranges, row by row (vertical index outer), as
// Gazebo's ray sensors give them: +inf where nothing is within range_max, -inf where the hit is
// at or below range_min (REP 117); noise is added to the others, clamped to [min, max].
struct LaserScan {
  double angle_min = 0.0, angle_max = 0.0, angle_increment = 0.0;  // rad, about the sensor's z
  double vertical_angle_min = 0.0, vertical_angle_max = 0.0, vertical_angle_increment = 0.0;
  int horizontal_count = 0, vertical_count = 1;
  double time_increment = 0.0;  // s between rays (0: every ray at the stamp, Gazebo's way)
  double scan_time = 0.0;       // s between scans
  double range_min = 0.0, range_max = 0.0;
  std::vector<float> ranges;       // m
  std::vector<float> intensities;  // laser_retro of the shape each ray hit (0: none, or nothing hit)
};

// sensor_msgs/Range's content (gazebo_ros_range): the shortest of the sensor's rays.
struct RangeReading {
  int radiation = 0;            // sensor_msgs/Range: 0 ultrasound, 1 infrared
  double field_of_view = 0.0;   // rad, as the plugin says
  double min_range = 0.0, max_range = 0.0;  // m: the ray sensor's
  double range = 0.0;           // m: max_range when nothing is within it
};

// sensor_msgs/PointCloud's content (gazebo_ros_block_laser): one point per interpolated ray in
// the sensor frame, and its intensity (one channel).
struct PointCloudReading {
  std::vector<Vec3> points;        // m
  std::vector<float> intensities;  // per point
};

struct ImuReading {
  // Orientation of the sensor frame in the reference frame (the world, or the sensor's own
  // frame at start), with the plugin's rpy offset applied.
  Quat orientation;
  Vec3 angular_velocity;     // rad/s, sensor frame
  Vec3 linear_acceleration;  // m/s^2, sensor frame: specific force, gravity included (+9.81 up at rest)
  Covariance orientation_covariance{}, angular_velocity_covariance{}, linear_acceleration_covariance{};
};

struct ContactWrench {
  Vec3 force;   // N
  Vec3 torque;  // N m
};

// One touching pair (gazebo_msgs/ContactState) as Gazebo's contact sensor gives it and
// gazebo_ros_bumper copies it: collision1 is the sensor's own.
struct ContactState {
  std::string info;  // left for the publisher (gazebo_ros_bumper writes a debug line with the time)
  std::string collision1_name, collision2_name;  // Gazebo-style scoped names (model::link::collision)
  // Per point: the force on collision1's body and its torque about that body's centre of mass, in
  // the body's frame (ODE's contact feedback, turned into the link frame by Gazebo).
  std::vector<ContactWrench> wrenches;
  ContactWrench total_wrench;           // their sum
  std::vector<Vec3> contact_positions;  // m, world frame
  std::vector<Vec3> contact_normals;    // world frame, unit, pushing collision1 away from collision2
  std::vector<double> depths;           // m, penetration
};

// Everything the sensor's collisions touch (gazebo_msgs/ContactsState). gazebo_ros_bumper
// transforms nothing: whatever its frameName, positions and normals are in the world and wrenches
// in each body's frame.
struct ContactsReading {
  std::vector<ContactState> states;
  std::size_t count = 0;  // states in use (the vector keeps its capacity between samples)
  Pose X_WL;              // the sensor's link at the sample (for consumers that want its frame)
};

struct WrenchReading {
  Vec3 force;   // N
  Vec3 torque;  // N m
};

// Pose and twist of a link (nav_msgs/Odometry of gazebo_ros_p3d): pose of the link in the
// reference frame, twist in the reference frame's orientation (as p3d publishes it).
struct GroundTruthReading {
  Pose pose;
  Vec3 linear;   // m/s
  Vec3 angular;  // rad/s
  double pose_variance = 0.0, twist_variance = 0.0;  // covariance diagonal
};

// sensor_msgs/CameraInfo's contents (plumb_bob: D = k1 k2 t1 t2 k3; K, R row-major 3x3; P 3x4).
struct CameraInfo {
  int width = 0, height = 0;
  std::string distortion_model = "plumb_bob";
  std::array<double, 5> D{};
  std::array<double, 9> K{}, R{};
  std::array<double, 12> P{};
};

// One camera's picture at the sample time, in its optical frame (z forward, x right, y down).
struct CameraImage {
  std::string name;  // the <camera>'s name
  CameraInfo info;
  std::vector<std::uint8_t> rgb;  // width * height * 3, rows from the top; distortion and noise applied
  // Depth sensors only (else empty): metres along the optical axis, NaN outside the plugin's
  // [pointCloudCutoff, pointCloudCutoffMax] (as gazebo_ros_openni_kinect), per pixel like rgb;
  // points: x y z per pixel in the optical frame (m), NaN where depth is.
  std::vector<float> depth;
  std::vector<float> points;
};

// What a camera, depth or multicamera sensor saw: one image per <camera>. `error` says why
// nothing could be rendered (no OpenGL context on this machine); the images then stay empty.
struct CameraReading {
  std::vector<CameraImage> images;
  std::string error;
};

using SensorOutput = std::variant<std::monostate, LaserScan, ImuReading, ContactsReading, WrenchReading, GroundTruthReading,
                                  CameraReading, RangeReading, PointCloudReading>;

// A sensor's latest output and when it was taken.
struct SensorReading {
  std::uint64_t count = 0;  // samples taken so far; changes with every new sample
  double stamp = 0.0;       // s of simulated time
  SensorOutput value;
};

}  // namespace mechsim::sensors
