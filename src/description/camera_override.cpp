#include "description/camera_override.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <variant>
#include <vector>

#include "description/sensor_spec.hpp"
#include "description/urdf/urdf_parser.hpp"

namespace mechsim::description {

namespace {

std::string size_text(double rate, const CameraLens& lens) {
  char text[96];
  std::snprintf(text, sizeof text, "%g Hz %dx%d", rate, lens.width, lens.height);
  return text;
}

void check(const CameraOverride& o, const std::string& name) {
  const std::string where = (o.origin.empty() ? std::string() : o.origin + ": ") + "camera override '" + name + "'";
  if (o.rate && !(*o.rate > 0.0 && std::isfinite(*o.rate))) throw DescriptionError(where + ": rate must be > 0 Hz");
  for (const auto& [key, v] : {std::pair{"width", o.width}, std::pair{"height", o.height}}) {
    if (v && (*v <= 0 || *v > 8192)) throw DescriptionError(where + ": " + key + " must be 1 to 8192 pixels");
  }
}

// Scales a principal point given in the plugin (0: from the image) from `from` to `to` pixels,
// keeping its place in the image (pixel centres: c' = (c - 0.5) s + 0.5).
double scale_centre(double c, int from, int to) {
  if (c == 0.0) return 0.0;
  const double s = static_cast<double>(to) / static_cast<double>(from);
  return (c - 0.5) * s + 0.5;
}

}  // namespace

std::vector<std::string> apply_camera_overrides(RobotModel& robot, const std::map<std::string, CameraOverride>& overrides) {
  std::vector<std::string> notes;
  for (const auto& [name, o] : overrides) {
    check(o, name);
    if (name == "all") continue;
    bool found = false;
    for (const SensorSpec& s : robot.sensors) found = found || (s.name == name && std::holds_alternative<CameraSpec>(s.details));
    if (!found) {
      std::string cameras;
      for (const SensorSpec& s : robot.sensors) {
        if (std::holds_alternative<CameraSpec>(s.details)) cameras += (cameras.empty() ? "" : ", ") + s.name;
      }
      throw DescriptionError((o.origin.empty() ? std::string() : o.origin + ": ") + "camera override '" + name +
                             "': the robot has no camera sensor of that name (its cameras: " +
                             (cameras.empty() ? std::string("none") : cameras) + ")");
    }
  }
  const auto all = overrides.find("all");
  for (SensorSpec& s : robot.sensors) {
    auto* camera = std::get_if<CameraSpec>(&s.details);
    if (camera == nullptr || camera->lenses.empty()) continue;
    auto it = overrides.find(s.name);
    if (it == overrides.end()) it = all;
    if (it == overrides.end()) continue;
    const CameraOverride& o = it->second;
    const std::string before = size_text(s.update_rate, camera->lenses.front());
    if (o.rate) s.update_rate = *o.rate;
    if (o.width || o.height) {
      const CameraLens& first = camera->lenses.front();
      const int from_w = first.width, from_h = first.height;
      const int w = o.width ? *o.width
                            : std::max(1, static_cast<int>(std::lround(static_cast<double>(*o.height) * from_w / from_h)));
      const int h = o.height ? *o.height
                             : std::max(1, static_cast<int>(std::lround(static_cast<double>(*o.width) * from_h / from_w)));
      for (CameraLens& lens : camera->lenses) {
        lens.width = w;
        lens.height = h;
      }
      camera->focal_length *= static_cast<double>(w) / static_cast<double>(from_w);
      camera->cx = scale_centre(camera->cx, from_w, w);
      camera->cx_prime = scale_centre(camera->cx_prime, from_w, w);
      camera->cy = scale_centre(camera->cy, from_h, h);
    }
    const std::string after = size_text(s.update_rate, camera->lenses.front());
    notes.push_back("sensor '" + s.name + "': " + before + " -> " + after + " (camera override '" + it->first + "')");
  }
  return notes;
}

}  // namespace mechsim::description
