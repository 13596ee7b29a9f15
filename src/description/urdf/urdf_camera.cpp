// Camera sensors (SDF <camera> as Gazebo classic reads it) and their ROS camera plugins'
// intrinsics and topics (gazebo_ros_camera_utils' parameters and defaults).
#include <cmath>
#include <limits>
#include <set>

#include "description/urdf/urdf_sensors.hpp"

namespace mechsim::description::detail {

namespace {

constexpr double kPi = 3.14159265358979323846;

int read_pixels(const XmlNode& image, const char* key, int fallback, const SensorFields& f) {
  const auto v = f.number(image, key, std::string("camera><image><") + key);
  if (!v) return fallback;
  if (*v < 1.0 || *v != std::floor(*v) || *v > 16384.0) {
    f.error(image.child(key)->line, std::string("<camera><image><") + key + "> must be a whole number of pixels in 1..16384, got " +
                                        image.child(key)->text);
    return fallback;
  }
  return static_cast<int>(*v);
}

CameraLens read_lens(const XmlNode& camera, const SensorFields& f, bool wide_angle) {
  CameraLens lens;
  lens.name = camera.attribute("name").value_or("");
  if (const XmlNode* pose = camera.child("pose")) {
    if (auto v = f.numbers(*pose, 6, "camera><pose")) lens.pose = pose_from_xyz_rpy(*v);
  }
  lens.horizontal_fov = f.number_or(camera, "horizontal_fov", "camera><horizontal_fov", lens.horizontal_fov);
  if (!(lens.horizontal_fov > 0.0 && lens.horizontal_fov < kPi)) {
    const XmlNode* h = camera.child("horizontal_fov");
    f.error(h != nullptr ? h->line : camera.line,
            "<camera><horizontal_fov> must be in (0, pi) rad for a pinhole camera" +
                std::string(wide_angle ? " (mechsim renders a wideanglecamera as one)" : "") + ", got " +
                std::to_string(lens.horizontal_fov));
  }
  if (const XmlNode* image = camera.child("image")) {
    lens.width = read_pixels(*image, "width", lens.width, f);
    lens.height = read_pixels(*image, "height", lens.height, f);
    if (const XmlNode* format = image->child("format")) {
      lens.format = format->text;
      // Gazebo's camera renders an unknown format as 8-bit colour (with an error) and runs on.
      if (!is_gazebo_image_format(format->text))
        f.warning(format->line, "<camera><image><format> \"" + format->text +
                                    "\" is not one of Gazebo's (L8, L16, R8G8B8, B8G8R8, R16G16B16, BAYER_*8, FLOAT16, "
                                    "FLOAT32 and their *_INT* names); Gazebo renders it as 8-bit colour, and so does mechsim");
    }
  }
  if (const XmlNode* clip = camera.child("clip")) {
    lens.near = f.number_or(*clip, "near", "camera><clip><near", lens.near);
    lens.far = f.number_or(*clip, "far", "camera><clip><far", lens.far);
    if (!(lens.near > 0.0) || !(lens.near < lens.far)) {
      f.error(clip->line, "<camera><clip> needs 0 < near < far, got near " + std::to_string(lens.near) + ", far " +
                              std::to_string(lens.far));
    }
  }
  if (const XmlNode* noise = camera.child("noise")) lens.noise = read_noise(*noise, f, "camera><noise");
  if (const XmlNode* d = camera.child("distortion")) {
    DistortionSpec& ds = lens.distortion;
    ds.k1 = f.number_or(*d, "k1", "camera><distortion><k1", 0.0);
    ds.k2 = f.number_or(*d, "k2", "camera><distortion><k2", 0.0);
    ds.k3 = f.number_or(*d, "k3", "camera><distortion><k3", 0.0);
    ds.p1 = f.number_or(*d, "p1", "camera><distortion><p1", 0.0);
    ds.p2 = f.number_or(*d, "p2", "camera><distortion><p2", 0.0);
    // Gazebo crops a barrel-distorted image unless a camera plugin's <borderCrop> says not to.
    ds.crop = ds.k1 < 0.0;
    if (const XmlNode* c = d->child("center")) {
      if (auto v = f.numbers(*c, 2, "camera><distortion><center")) {
        ds.center_x = (*v)[0];
        ds.center_y = (*v)[1];
      }
    }
  }
  return lens;
}

// ROS's resolution of `name` under the node handle "<robotNamespace>/<cameraName>": absolute
// names are kept; duplicate and trailing slashes go.
std::string resolve(const std::string& ns, const std::string& camera, const std::string& name) {
  std::string joined = !name.empty() && name.front() == '/' ? name : ns + "/" + camera + "/" + name;
  std::string out = "/";
  for (const char c : joined) {
    if (c == '/' && out.back() == '/') continue;
    out.push_back(c);
  }
  while (out.size() > 1 && out.back() == '/') out.pop_back();
  return out;
}

std::string param(const SensorPlugin& p, const std::string& key, const std::string& fallback) {
  const auto it = p.parameters.find(key);
  return it != p.parameters.end() ? it->second : fallback;
}

double plugin_double(const SensorPlugin& p, const std::string& key, double fallback, const SensorFields& f,
                     const XmlNode& e) {
  const auto it = p.parameters.find(key);
  if (it == p.parameters.end()) return fallback;
  const auto v = parse_number(it->second);
  if (!v || !std::isfinite(*v)) {
    const XmlNode* c = e.child(key);
    f.error(c != nullptr ? c->line : e.line, "<plugin><" + key + "> is not a number: \"" + it->second + "\"");
    return fallback;
  }
  return *v;
}

}  // namespace

bool is_camera_plugin(const std::string& filename) {
  static const std::set<std::string> plugins = {"libgazebo_ros_camera.so", "libgazebo_ros_multicamera.so",
                                                "libgazebo_ros_depth_camera.so", "libgazebo_ros_openni_kinect.so",
                                                "libgazebo_ros_prosilica.so", "libgazebo_ros_triggered_camera.so"};
  return plugins.count(filename) > 0;
}

bool is_gazebo_image_format(const std::string& format) {
  // rendering::Camera's formats in Gazebo 11 (its OgrePixelFormat).
  static const std::set<std::string> formats = {
      "L8",          "L_INT8",      "L16",         "L_INT16",     "L_UINT16",  "R8G8B8",   "RGB_INT8",
      "B8G8R8",      "BGR_INT8",    "R16G16B16",   "RGB_INT16",   "RGB_UINT16", "FLOAT32", "R_FLOAT32",
      "FLOAT16",     "R_FLOAT16",   "BAYER_RGGB8", "BAYER_BGGR8", "BAYER_GBRG8", "BAYER_GRBG8"};
  return formats.count(format) > 0;
}

CameraSpec read_camera(const XmlNode& sensor, const SensorFields& f, const std::string& type) {
  CameraSpec c;
  c.depth = type == "depth";
  c.wide_angle = type == "wideanglecamera";
  const std::vector<const XmlNode*> cameras = sensor.children_named("camera");
  if (cameras.empty()) {
    f.error(sensor.line, "a " + type + " sensor needs a <camera> element");
    return c;
  }
  if (type != "multicamera" && cameras.size() > 1) f.warning(cameras[1]->line, "only the first <camera> of a " + type + " sensor is used");
  for (const XmlNode* cam : cameras) {
    c.lenses.push_back(read_lens(*cam, f, c.wide_angle));
    if (type != "multicamera") break;
  }
  // Without a depth plugin, depth is kept over the clip range.
  c.point_cloud_cutoff = c.lenses.front().near;
  c.point_cloud_cutoff_max = c.lenses.front().far;
  return c;
}

void read_camera_plugin(CameraSpec& c, SensorPlugin& plugin, const std::string& type, const SensorFields& f,
                        const XmlNode& e) {
  const std::string& file = plugin.filename;
  const bool depth_plugin = file == "libgazebo_ros_openni_kinect.so" || file == "libgazebo_ros_depth_camera.so";
  if (depth_plugin && type != "depth") {
    f.error(e.line, file + " needs a sensor of type depth, not " + type);
    return;
  }
  if (file == "libgazebo_ros_multicamera.so" && type != "multicamera") {
    f.error(e.line, file + " needs a sensor of type multicamera, not " + type);
    return;
  }
  const std::string camera_name = param(plugin, "cameraName", "");
  // The depth plugins publish their colour image as an infrared one unless told otherwise.
  const std::string image = param(plugin, "imageTopicName", depth_plugin ? "ir/image_raw" : "image_raw");
  const std::string info = param(plugin, "cameraInfoTopicName", depth_plugin ? "ir/camera_info" : "camera_info");
  plugin.frame = param(plugin, "frameName", "/world");
  c.focal_length = plugin_double(plugin, "focalLength", 0.0, f, e);
  c.cx = plugin_double(plugin, "Cx", 0.0, f, e);
  c.cy = plugin_double(plugin, "Cy", 0.0, f, e);
  c.cx_prime = plugin_double(plugin, "CxPrime", 0.0, f, e);
  c.hack_baseline = plugin_double(plugin, "hackBaseline", 0.0, f, e);
  const char* keys[5] = {"distortionK1", "distortionK2", "distortionT1", "distortionT2", "distortionK3"};
  for (int i = 0; i < 5; ++i) c.ros_distortion[static_cast<std::size_t>(i)] = plugin_double(plugin, keys[i], 0.0, f, e);
  if (c.focal_length < 0.0) f.error(e.line, "<plugin><focalLength> must be >= 0 (0: from the FOV)");
  if (const auto crop = plugin.parameters.find("borderCrop"); crop != plugin.parameters.end()) {
    const auto b = parse_bool(crop->second);
    const XmlNode* at = e.child("borderCrop");
    if (!b) f.error(at != nullptr ? at->line : e.line, "<plugin><borderCrop> is not a boolean: \"" + crop->second + "\"");
    // Gazebo crops only a barrel distortion (k1 < 0), whatever the plugin says.
    for (CameraLens& lens : c.lenses) lens.distortion.crop = b.value_or(true) && lens.distortion.k1 < 0.0;
  }
  const std::string& ns = plugin.robot_namespace;
  if (file == "libgazebo_ros_multicamera.so") {
    // gazebo_ros_multicamera gives a camera whose name holds "left" the node handle
    // <cameraName>/left, one holding "right" <cameraName>/right, and publishes no other.
    for (const CameraLens& lens : c.lenses) {
      const char* side = lens.name.find("left") != std::string::npos    ? "left"
                         : lens.name.find("right") != std::string::npos ? "right"
                                                                         : nullptr;
      if (side == nullptr) {
        f.warning(e.line, file + " publishes only cameras whose name holds left or right, not camera '" + lens.name + "'");
        c.image_topics.emplace_back();
        c.info_topics.emplace_back();
        continue;
      }
      c.image_topics.push_back(resolve(ns, camera_name + "/" + side, image));
      c.info_topics.push_back(resolve(ns, camera_name + "/" + side, info));
    }
  } else {
    c.image_topics.push_back(resolve(ns, camera_name, image));
    c.info_topics.push_back(resolve(ns, camera_name, info));
  }
  if (depth_plugin) {
    c.depth_topic = resolve(ns, camera_name, param(plugin, "depthImageTopicName", "depth/image_raw"));
    c.depth_info_topic = resolve(ns, camera_name, param(plugin, "depthImageCameraInfoTopicName", "depth/camera_info"));
    c.points_topic = resolve(ns, camera_name, param(plugin, "pointCloudTopicName", "points"));
    c.point_cloud_cutoff = plugin_double(plugin, "pointCloudCutoff", 0.4, f, e);
    // gazebo_ros_depth_camera keeps every depth beyond its cutoff; openni_kinect cuts at 5 m.
    c.point_cloud_cutoff_max = file == "libgazebo_ros_openni_kinect.so"
                                   ? plugin_double(plugin, "pointCloudCutoffMax", 5.0, f, e)
                                   : std::numeric_limits<double>::infinity();
    if (!(c.point_cloud_cutoff >= 0.0 && c.point_cloud_cutoff < c.point_cloud_cutoff_max))
      f.error(e.line, "<plugin> needs 0 <= pointCloudCutoff < pointCloudCutoffMax, got " +
                          std::to_string(c.point_cloud_cutoff) + " and " + std::to_string(c.point_cloud_cutoff_max));
  }
  if (file == "libgazebo_ros_triggered_camera.so")
    c.trigger_topic = resolve(ns, camera_name, param(plugin, "triggerTopicName", "image_trigger"));
  plugin.topic = c.image_topics.front();
  for (const std::string& t : c.image_topics)
    if (!t.empty()) {
      plugin.topic = t;
      break;
    }
}

}  // namespace mechsim::description::detail
