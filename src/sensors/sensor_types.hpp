#pragma once
// The sensor types mechsim simulates (internal to sensors/; make_sensor builds them).

#include <array>
#include <memory>
#include <vector>

#include "physics/ray_cast.hpp"
#include "physics/renderer.hpp"
#include "sensors/sensor.hpp"

namespace mechsim::sensors {

struct ChannelState;

// ray / gpu_ray: rays cast from the sensor frame against the world and the robot's shapes
// (collision shapes; visual ones for gpu_ray), the sensor's own body excluded, all at the sample
// time (Gazebo's instantaneous scan). The output follows the spec's RayOutput: a LaserScan, a
// RangeReading (gazebo_ros_range) or a PointCloudReading (gazebo_ros_block_laser).
class RaySensor final : public Sensor {
 public:
  RaySensor(const description::SensorSpec& spec, const physics::PhysicsModel& model, const std::string& prefix = "");
  std::unique_ptr<SensorState> make_state(Rng rng) const override;
  void bind(const physics::PhysicsModel& model) override;
  void sample(const physics::Physics& physics, double time, SensorState& state, SensorOutput& out) const override;

 private:
  void fill_scan(const physics::Physics& physics, double time, ChannelState& state, SensorOutput& out) const;
  void fill_range(ChannelState& state, SensorOutput& out) const;
  void fill_cloud(const physics::Physics& physics, ChannelState& state, SensorOutput& out) const;

  const description::RaySpec& ray_;
  std::size_t link_ = 0;
  physics::RayFilter filter_;
  int nh_ = 1, nv_ = 1;                          // rays cast per axis
  std::vector<description::Vec3> directions_S_;  // unit, sensor frame; vertical index outer
  LaserScan layout_;                             // angles and limits, ranges empty
};

// imu: orientation, angular velocity and specific force of the sensor frame.
class ImuSensor final : public Sensor {
 public:
  ImuSensor(const description::SensorSpec& spec, const physics::PhysicsModel& model, const std::string& prefix = "");
  std::unique_ptr<SensorState> make_state(Rng rng) const override;
  void bind(const physics::PhysicsModel& model) override;
  void sample(const physics::Physics& physics, double time, SensorState& state, SensorOutput& out) const override;

 private:
  const description::ImuSpec& imu_;
  std::size_t link_ = 0;
};

// contact (gazebo_ros_bumper): what the sensor's collisions touch.
class ContactSensor final : public Sensor {
 public:
  ContactSensor(const description::SensorSpec& spec, const physics::PhysicsModel& model, const std::string& prefix = "");
  std::unique_ptr<SensorState> make_state(Rng rng) const override;
  void bind(const physics::PhysicsModel& model) override;
  void sample(const physics::Physics& physics, double time, SensorState& state, SensorOutput& out) const override;

 private:
  std::vector<int> geoms_;               // the sensor's collision geoms (MuJoCo ids), sorted
  std::vector<std::string> geom_names_;  // their Gazebo-style names, by MuJoCo geom id (all geoms)
  std::size_t link_ = 0;                 // the sensor's link
};

// force_torque (SDF sensor, gazebo_ros_ft_sensor): the wrench a joint transmits.
class ForceTorqueSensor final : public Sensor {
 public:
  ForceTorqueSensor(const description::SensorSpec& spec, const physics::PhysicsModel& model, const std::string& prefix = "");
  std::unique_ptr<SensorState> make_state(Rng rng) const override;
  void bind(const physics::PhysicsModel& model) override;
  void sample(const physics::Physics& physics, double time, SensorState& state, SensorOutput& out) const override;

 private:
  const description::ForceTorqueSpec& ft_;
  std::size_t child_ = 0;
  std::optional<std::size_t> parent_;
};

// gazebo_ros_p3d: the true pose and twist of a link.
class GroundTruthSensor final : public Sensor {
 public:
  GroundTruthSensor(const description::SensorSpec& spec, const physics::PhysicsModel& model, const std::string& prefix = "");
  std::unique_ptr<SensorState> make_state(Rng rng) const override;
  void bind(const physics::PhysicsModel& model) override;
  void sample(const physics::Physics& physics, double time, SensorState& state, SensorOutput& out) const override;

 private:
  const description::GroundTruthSpec& gt_;
  std::size_t link_ = 0;
  std::optional<std::size_t> reference_;  // a link; none: the world
};

// camera / depth / multicamera / wideanglecamera: images rendered on the set's RenderHub.
class CameraSensor final : public Sensor {
 public:
  CameraSensor(const description::SensorSpec& spec, const physics::PhysicsModel& model, const std::string& prefix = "");
  std::unique_ptr<SensorState> make_state(Rng rng) const override;
  void bind(const physics::PhysicsModel& model) override;
  void sample(const physics::Physics& physics, double time, SensorState& state, SensorOutput& out) const override;
  bool renders() const override { return true; }
  std::pair<int, int> render_size() const override;

  struct Lens {
    physics::CameraView view;     // intrinsics and clip; X_WC filled at each sample
    description::Pose X_LC;       // optical frame in the link frame
    CameraInfo info;
    // What is rendered for this lens: its own view, or, for a lens with distortion (whose image
    // is resampled anyway), the view of an undistorted lens it shares renders with.
    physics::CameraView render;
    description::Pose render_X_LC;
    bool render_depth = false;
  };
  const std::vector<Lens>& lenses() const { return lenses_; }
  std::size_t link() const { return link_; }
  // Each lens with distortion renders through the view of an undistorted lens of `other` at the
  // same place on the same link with the same size, focal length and clip, when `other` samples at
  // the same rate: the two then share one render per instant (RenderHub::frame), the distorted
  // image resampled from it. Returns how many lenses now share.
  int share_renders_with(const CameraSensor& other);

 private:
  const description::CameraSpec& camera_;
  std::size_t link_ = 0;
  std::vector<Lens> lenses_;
};

// A state with one NoiseState per noisy channel.
struct ChannelState : SensorState {
  std::vector<NoiseState> channels;
};

}  // namespace mechsim::sensors
