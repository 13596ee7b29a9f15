#include "controllers/drive/rover_drive_ports.hpp"

#include <cmath>

namespace mechsim::control {

bool DriveModeCommandPort::write(DriveMode mode, std::string* error) {
  switch (mode) {
    case DriveMode::Auto:
    case DriveMode::Ackermann:
    case DriveMode::Crab:
    case DriveMode::PointTurn:
      buffer_.write(mode);
      return true;
  }
  return reject("port '" + name() + "': rejected drive mode " + std::to_string(static_cast<int>(mode)) +
                    " (not auto, ackermann, crab or point_turn); the previous mode stays",
                error);
}

bool DriveModeCommandPort::write(std::string_view text, std::string* error) {
  DriveMode mode = DriveMode::Auto;
  if (!parse_drive_mode(text, mode)) {
    return reject("port '" + name() + "': rejected unknown drive mode '" + std::string(text) +
                      "' (auto, ackermann, crab or point_turn); the previous mode stays",
                  error);
  }
  return write(mode, error);
}

Quaternion OdometrySnapshot::orientation() const {
  if (has_attitude) return attitude;
  return {std::cos(yaw / 2.0), 0.0, 0.0, std::sin(yaw / 2.0)};
}

}  // namespace mechsim::control
