#pragma once
// Per-camera overrides for fast runs (issue 13, "render only what is needed"): a lower rate or a
// lower resolution than the description's, for one camera sensor by name or for every camera
// ("all"). A resolution change keeps the field of view, so the plugin's CameraInfo stays true to
// the image: an explicit focal length and principal point are scaled with it.

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "description/robot_model.hpp"

namespace mechsim::description {

struct CameraOverride {
  std::optional<double> rate;   // Hz of simulated time (> 0)
  std::optional<int> width;     // pixels (> 0); the height follows the aspect ratio when absent
  std::optional<int> height;    // pixels (> 0); the width follows when absent
  std::string origin;           // where it was written ("file:line"), for messages
};

// Applies `overrides` (sensor name or "all" -> override; a named one wins over "all") to the
// camera sensors of `robot`. Throws DescriptionError naming the override's origin for a name that
// is no camera sensor of the robot, or a rate/size that is not positive (sizes up to 8192).
// Returns one line per camera changed ("sensor 'NAME': 15 Hz 1280x720 -> 5 Hz 640x360").
std::vector<std::string> apply_camera_overrides(RobotModel& robot, const std::map<std::string, CameraOverride>& overrides);

}  // namespace mechsim::description
