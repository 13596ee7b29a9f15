// The PR2 laser tilt controller's profile port through the opaque PortRef (C++20 side of the
// bridge).
#include "controllers/pr2/laser_scanner_traj_controller.hpp"
#include "bridge/port_cast.hpp"
#include "bridge/sim_bridge.hpp"

namespace mechsim::bridge {

using detail::port_as;

bool write_periodic_command(const PortRef& port, const std::string& profile, double period, double amplitude,
                            double offset, std::string* error) {
  auto* p = port_as<control::ScanCommandPort>(port, error);
  return p && p->write(profile, period, amplitude, offset, error);
}

bool write_laser_traj_command(const PortRef& port, const std::string& profile, const std::vector<double>& positions,
                              const std::vector<double>& times_from_start, double max_velocity,
                              double max_acceleration, std::string* error) {
  auto* p = port_as<control::ScanCommandPort>(port, error);
  if (!p) return false;
  control::LaserTrajCommand c;
  if (!control::parse_periodic_profile(profile, c.profile) || c.profile == control::PeriodicProfile::Sine) {
    if (error) *error = "unknown trajectory profile '" + profile + "' (linear or blended_linear)";
    return false;
  }
  c.positions = positions;
  c.times_from_start = times_from_start;
  c.max_velocity = max_velocity;
  c.max_acceleration = max_acceleration;
  return p->write(c, error);
}

}  // namespace mechsim::bridge
