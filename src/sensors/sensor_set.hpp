#pragma once
// The sensors of one simulation, sampled at their rates in simulated time: the `sensors/` side of
// DESIGN.md's tick step 5. sim::Simulation owns one and calls sample_due() after each physics
// step; publishers and recorders then read the readings (count changes with each new sample).
//
// Rates: a sensor of rate r is due at t = k / r (k = 0, 1, ...) and sampled at the first tick at
// or after that time, so the samples keep the rate's schedule without drift; rate 0 means every
// tick. Every sensor is sampled once at construction (t = the simulation's start), so a reading
// exists from the start.
//
// Noise: one generator per sensor, seeded from (seed, the sensor's name), so adding a sensor does
// not change another's noise, and the same seed gives bit-identical readings.
//
// Threads: everything here belongs to the simulation's loop thread.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "description/sensor_spec.hpp"
#include "physics/physics.hpp"
#include "sensors/render_hub.hpp"
#include "sensors/sensor.hpp"
#include "sensors/sensor_output.hpp"

namespace mechsim::sensors {

// A declared sensor mechsim does not simulate, and why.
struct SkippedSensor {
  description::SensorSpec spec;
  std::string reason;
  bool left_out = false;  // simulated type, but not with this physics model (SensorLeftOut): a warning
};

class SensorSet {
 public:
  SensorSet() = default;
  // Builds every simulated spec against `model` (make_sensor); specs that cannot be simulated go
  // to skipped(). Throws SensorError for a spec that claims to be simulated but cannot be built.
  // Cameras draw `render_model()` when given (built on their first render), else `model`.
  // `physics_prefix`: what the physics puts before the robot's names ("<name>::" for another robot
  // of the world, sim::OtherRobot).
  SensorSet(const std::vector<description::SensorSpec>& specs, std::shared_ptr<const physics::PhysicsModel> model,
            std::uint64_t seed, RenderModelFactory render_model = {}, std::string physics_prefix = "");

  std::size_t size() const { return sensors_.size(); }
  bool empty() const { return sensors_.empty(); }
  const Sensor& sensor(std::size_t i) const { return *sensors_[i]; }
  const description::SensorSpec& spec(std::size_t i) const { return sensors_[i]->spec(); }
  const SensorReading& reading(std::size_t i) const { return readings_[i]; }
  std::optional<std::size_t> find(std::string_view name) const;
  const std::vector<SkippedSensor>& skipped() const { return skipped_; }
  // The cameras' shared renderer (null without cameras): its error, scene updates, renders.
  const RenderHub* render_hub() const { return hub_.get(); }

  // The physics was rebuilt with more or fewer robots or objects: the cameras render the new model
  // from their next frame; another robot's sensors (a physics prefix), whose links and geoms move
  // in it, look them up again (Sensor::bind). Readings, schedules, noise and enabled flags go on.
  void set_model(std::shared_ptr<const physics::PhysicsModel> model, RenderModelFactory render_model = {});

  // Samples every enabled sensor that is due at `time` (s). Returns how many were sampled.
  std::size_t sample_due(const physics::Physics& physics, double time);
  // Samples every enabled sensor now, and restarts the schedules from `time` (after a reset: the
  // generators and drifts go on).
  void sample_all(const physics::Physics& physics, double time);

  // A disabled sensor is not sampled (its reading stays as it was): for sensors nobody consumes.
  // Cameras start disabled (they render only for a consumer); the others enabled.
  void set_enabled(std::size_t i, bool enabled) { enabled_[i] = enabled; }
  bool enabled(std::size_t i) const { return enabled_[i]; }
  // A held sensor is sampled at its rate whether enabled or not: a controller reads it (the IMU
  // and force-torque handles of control/sensor_hardware.hpp), whoever else consumes it.
  void set_held(std::size_t i, bool held) { held_[i] = held; }
  bool held(std::size_t i) const { return held_[i] != 0; }
  // Samples sensor i at the next sample_due(), enabled or not, due or not (a report's picture).
  void request(std::size_t i) { requested_[i] = 1; }

 private:
  void take(std::size_t i, const physics::Physics& physics, double time);
  // Raw and rectified cameras at one place share renders (CameraSensor::share_renders_with).
  void share_camera_renders();

  std::shared_ptr<const physics::PhysicsModel> model_;
  std::string prefix_;  // the robot's names in the physics (Sensor's physics_prefix)
  std::vector<std::unique_ptr<Sensor>> sensors_;
  std::vector<std::unique_ptr<SensorState>> states_;
  std::vector<SensorReading> readings_;
  std::vector<double> next_due_;  // s
  std::vector<char> enabled_;
  std::vector<char> requested_;
  std::vector<char> held_;
  std::vector<SkippedSensor> skipped_;
  std::unique_ptr<RenderHub> hub_;
};

}  // namespace mechsim::sensors
