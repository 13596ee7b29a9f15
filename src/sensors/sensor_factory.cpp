// make_sensor: one line per sensor type (sensors/README.md, "Adding a sensor type").
#include <variant>

#include "sensors/sensor_types.hpp"

namespace mechsim::sensors {

std::size_t Sensor::resolve_link(const physics::PhysicsModel& model) const {
  const auto link = model.link_index(physics_name(spec_.link));
  if (!link) throw SensorError(spec_.where() + ": the physics has no link '" + spec_.link + "'");
  return *link;
}

std::unique_ptr<Sensor> make_sensor(const description::SensorSpec& spec, const physics::PhysicsModel& model,
                                    const std::string& prefix) {
  using namespace description;
  if (std::holds_alternative<RaySpec>(spec.details)) return std::make_unique<RaySensor>(spec, model, prefix);
  if (std::holds_alternative<ImuSpec>(spec.details)) return std::make_unique<ImuSensor>(spec, model, prefix);
  if (std::holds_alternative<ContactSpec>(spec.details)) return std::make_unique<ContactSensor>(spec, model, prefix);
  if (std::holds_alternative<ForceTorqueSpec>(spec.details)) return std::make_unique<ForceTorqueSensor>(spec, model, prefix);
  if (std::holds_alternative<GroundTruthSpec>(spec.details)) return std::make_unique<GroundTruthSensor>(spec, model, prefix);
  if (std::holds_alternative<CameraSpec>(spec.details)) return std::make_unique<CameraSensor>(spec, model, prefix);
  throw SensorError(spec.where() + ": not simulated (" + std::get<UnsupportedSpec>(spec.details).reason + ")");
}

}  // namespace mechsim::sensors
