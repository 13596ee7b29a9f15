#pragma once
// One simulated sensor. Model/data split as everywhere in mechsim: a Sensor is its spec resolved
// against a compiled PhysicsModel (link indices, MuJoCo bodies, ray directions and filters),
// immutable and shareable; its SensorState (random generator, noise biases and drifts, scratch
// buffers) belongs to one simulation. sensors/README.md says how a new type plugs in.

#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include "description/sensor_spec.hpp"
#include "physics/physics.hpp"
#include "physics/physics_model.hpp"
#include "sensors/noise.hpp"
#include "sensors/sensor_output.hpp"

namespace mechsim::sensors {

// A sensor that cannot be built against the physics model; what() names the sensor and where it
// was declared (SensorSpec::where()).
struct SensorError : std::runtime_error {
  using std::runtime_error::runtime_error;
};
// A sensor that cannot work with this physics model although its description is right, e.g. a
// contact sensor on a link whose collision mesh the physics left out: the set skips it with the
// reason (a warning), the run goes on.
struct SensorLeftOut : SensorError {
  using SensorError::SensorError;
};

class RenderHub;

// The mutable part of one sensor in one simulation. Sensor types derive their own state.
struct SensorState {
  virtual ~SensorState() = default;
  Rng rng;
  double last_sample = -1.0;  // s: time of the previous sample, -1 before the first
  RenderHub* render = nullptr;  // the set's shared renderer, for sensors that render()
};

class Sensor {
 public:
  // `physics_prefix`: what the physics puts before the robot's link names ("<name>::" for another
  // robot of the world, sim::OtherRobot; "" for the first).
  explicit Sensor(description::SensorSpec spec, std::string physics_prefix = "")
      : spec_(std::move(spec)), prefix_(std::move(physics_prefix)) {}
  virtual ~Sensor() = default;
  Sensor(const Sensor&) = delete;
  Sensor& operator=(const Sensor&) = delete;

  const description::SensorSpec& spec() const { return spec_; }

  // Cameras: sampled through the set's RenderHub (state.render), and only while someone consumes
  // them (the set starts them disabled).
  virtual bool renders() const { return false; }
  // The largest image the sensor renders (pixels), for the shared offscreen buffer.
  virtual std::pair<int, int> render_size() const { return {0, 0}; }

  // A fresh state owning `rng`; constant biases are drawn from it here.
  virtual std::unique_ptr<SensorState> make_state(Rng rng) const = 0;

  // Samples the physics as it is now (simulated time `time`, s) into `out` (which holds this
  // sensor's output type after the first call). Allocates only while the output grows (the first
  // sample; more contacts than ever before); throws nothing. `state.last_sample` is the previous
  // sample's time (the caller updates it afterwards).
  virtual void sample(const physics::Physics& physics, double time, SensorState& state, SensorOutput& out) const = 0;

  // Looks the sensor's links, bodies and geoms up in `model` (the constructor does it first): for
  // another robot's sensors once the world's physics was rebuilt with more or fewer robots, which
  // moves their indices. Throws SensorError as the constructor does. Loop thread, between samples.
  virtual void bind(const physics::PhysicsModel& model) = 0;

 protected:
  // The physics link of spec().link (throws SensorError when the physics has none).
  std::size_t resolve_link(const physics::PhysicsModel& model) const;
  // The physics' name of the robot's link (or geom prefix) `name`.
  std::string physics_name(const std::string& name) const { return prefix_ + name; }
  const std::string& physics_prefix() const { return prefix_; }

 private:
  description::SensorSpec spec_;
  std::string prefix_;
};

// The Sensor of a simulated spec (sensor_factory.cpp: one line per type). Throws SensorError
// when the spec cannot be simulated on this model (UnsupportedSpec; a link the physics merged
// away where a body is needed).
std::unique_ptr<Sensor> make_sensor(const description::SensorSpec& spec, const physics::PhysicsModel& model,
                                    const std::string& physics_prefix = "");

}  // namespace mechsim::sensors
