#pragma once
// The simulated sensors on ROS, as their Gazebo plugins publish them: sensor_msgs/LaserScan
// (gazebo_ros_laser, gazebo_ros_gpu_laser), sensor_msgs/Range (gazebo_ros_range),
// sensor_msgs/PointCloud (gazebo_ros_block_laser), sensor_msgs/Imu (gazebo_ros_imu_sensor,
// gazebo_ros_imu, hector's IMU), gazebo_msgs/ContactsState (gazebo_ros_bumper),
// geometry_msgs/WrenchStamped (gazebo_ros_ft_sensor), nav_msgs/Odometry (gazebo_ros_p3d), and
// sensor_msgs/Image + CameraInfo (+ a 32FC1 depth Image, its CameraInfo and a PointCloud2 for
// depth cameras) of gazebo_ros_camera, _multicamera, _depth_camera, _openni_kinect, _prosilica
// and _triggered_camera (a frame per std_msgs/Empty on its trigger topic); on the topic and with
// the frame the plugin would use, stamped in simulated time.
// The PR2's fingertip pressure (pr2_msgs/PressureState on /pressure/<side>_gripper_motor, 25 Hz
// of sim time, as the real grippers publish it) is made from the fingertip contact sensors, as
// pr2_gazebo's contact-to-pressure translator did (sensors/pr2_fingertip_pressure.hpp).
// Plain publishers on image_transport's raw topic names: Debian packages image_transport but no
// transport plugin (compressed, theora), so it would add the same raw topic only.
//
// Cost: a sensor is sampled only while one of its topics has a subscriber (gazebo_ros_laser and
// the camera plugins activate their sensor on the first connection; mechsim does it for every
// sensor, as nothing else in the node reads them), so with nobody listening a tick pays one
// relaxed atomic load per sensor. Subscriber counts are kept by roscpp's connect/disconnect
// callbacks (spinner threads), not asked for in the tick. Publishing never waits on a subscriber:
// the tick fills a message and queues it for the sender thread, which hands it to roscpp (queue
// size 1 for cameras: a slow subscriber loses frames, the tick goes on).
//
// Threads: publish() runs in the loop thread after each tick (an observer), as the node's other
// publishers do; a sender thread of its own calls roscpp's publish (sensor_publishers.cpp says why).

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <ros/ros.h>

#include "ros/bridge_names.hpp"

namespace mechsim::ros {

// What publishing cost so far: the loop thread's wall time in publish() (what an unsubscribed
// tick pays), and its CPU time filling and publishing messages (what a subscriber costs; CPU
// time, as on a loaded machine wall time counts the other processes' turns).
struct SensorPublishStats {
  std::uint64_t calls = 0;            // publish() calls (ticks)
  double wall_seconds = 0.0;          // in publish() in all
  double publish_cpu_seconds = 0.0;   // filling and publishing messages, cameras included
  std::uint64_t messages = 0;         // messages published, cameras included
  std::uint64_t dropped = 0;          // not published: the sender's queue was full
  double sender_cpu_seconds = 0.0;    // the sender thread's CPU time (roscpp's serialisation and writes)
  std::uint64_t camera_frames = 0;    // camera readings published (all of a sensor's topics)
  double camera_seconds = 0.0;        // CPU filling and publishing them (rendering is in the tick)
};

class SensorPublishers {
 public:
  // Advertises the topics of every published sensor (absolute names, robotNamespace + topicName
  // as the plugins resolve them) and disables the sensors nobody consumes. Logs what it leaves
  // out (not simulated; no ROS plugin; a plugin mechsim does not publish for).
  SensorPublishers(::ros::NodeHandle root, SimBridge& bridge);
  ~SensorPublishers();
  SensorPublishers(const SensorPublishers&) = delete;
  SensorPublishers& operator=(const SensorPublishers&) = delete;

  // Enables the sensors that gained a subscriber, disables the others, and publishes every
  // reading newer than the last one published. Loop thread.
  void publish();

  // "sensor -> topic (type, frame F)" per advertised topic, for the log.
  const std::vector<std::string>& topics() const { return topics_; }
  SensorPublishStats stats() const;

  struct Output;    // sensor_publishers.cpp, camera_publishers.cpp
  struct Pressure;  // sensor_publishers.cpp

 private:
  void add_camera(std::size_t sensor, const description::SensorSpec& spec, const std::string& frame);
  void publish_camera(Output& o, const sensors::SensorReading& r);
  void publish_camera_info_only(Output& o);
  void publish_triggered(Output& o);
  void add_pressure(const std::string& side);
  void publish_pressure(Pressure& p, double time);
  // A new message of type M stamped and framed, filled by fill(M&), queued for the sender.
  template <class M, class Fill>
  void send(const ::ros::Publisher& publisher, const ::ros::Time& stamp, const std::string& frame, Fill&& fill);
  class Sender;  // the thread that calls roscpp's publish

  ::ros::NodeHandle root_;
  SimBridge& bridge_;
  std::vector<std::unique_ptr<Output>> outputs_;
  std::vector<std::unique_ptr<Pressure>> pressures_;
  std::vector<std::string> topics_;
  std::vector<::ros::ServiceServer> services_;  // IMU calibration services
  SensorPublishStats stats_;
  bool pushed_ = false;  // this tick queued messages: wake the sender
  std::unique_ptr<Sender> sender_;  // last: joined first, while the publishers exist
};

}  // namespace mechsim::ros
