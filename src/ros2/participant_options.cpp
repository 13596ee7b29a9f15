// The participant's options and names that need no DDS: distros, GUIDs as text, and the ROS 2
// environment variables (ROS_DOMAIN_ID, ROS_LOCALHOST_ONLY, ROS_AUTOMATIC_DISCOVERY_RANGE).
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "ros2/dds_participant.hpp"

namespace mechsim::ros2 {

const char* distro_name(Distro distro) { return distro == Distro::Humble ? "humble" : "jazzy"; }

std::optional<Distro> parse_distro(const std::string& name) {
  if (name == "humble") return Distro::Humble;
  if (name == "jazzy") return Distro::Jazzy;
  return std::nullopt;
}

std::string guid_string(const Guid& g) {
  char text[48];
  std::snprintf(text, sizeof text, "%02x%02x%02x%02x.%02x%02x%02x%02x.%02x%02x%02x%02x:%02x%02x%02x%02x", g[0], g[1],
                g[2], g[3], g[4], g[5], g[6], g[7], g[8], g[9], g[10], g[11], g[12], g[13], g[14], g[15]);
  return text;
}

ParticipantOptions options_from_environment(Distro distro) {
  ParticipantOptions o;
  o.distro = distro;
  if (const char* id = std::getenv("ROS_DOMAIN_ID"); id != nullptr && *id != '\0') {
    char* end = nullptr;
    errno = 0;
    const long value = std::strtol(id, &end, 10);
    if (end == id || *end != '\0' || errno != 0 || value < 0 || value > 232) {
      throw std::runtime_error(std::string("ROS_DOMAIN_ID '") + id +
                               "' is not a domain id (an integer 0..232; 0..101 and 215..232 are safe for UDP ports)");
    }
    o.domain_id = static_cast<int>(value);
  }
  if (const char* only = std::getenv("ROS_LOCALHOST_ONLY"); only != nullptr && std::strcmp(only, "1") == 0) {
    o.localhost_only = true;
  }
  if (const char* range = std::getenv("ROS_AUTOMATIC_DISCOVERY_RANGE"); range != nullptr && *range != '\0') {
    const std::string r = range;
    if (r == "LOCALHOST") {
      o.localhost_only = true;
    } else if (r != "SUBNET" && r != "SYSTEM_DEFAULT") {
      throw std::runtime_error("ROS_AUTOMATIC_DISCOVERY_RANGE '" + r +
                               "' is not supported by mechsim (LOCALHOST, SUBNET or SYSTEM_DEFAULT)");
    }
  }
  return o;
}

}  // namespace mechsim::ros2
