#include "description/sdf/sdf_paths.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

namespace mechsim::description::sdf_detail {
namespace fs = std::filesystem;

namespace {

void split_into(const char* env, std::vector<std::string>& out) {
  if (env == nullptr) return;
  std::stringstream list(env);
  std::string entry;
  while (std::getline(list, entry, ':'))
    if (!entry.empty()) out.push_back(entry);
}

bool is_file(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec);
}

// mechsim's own minimal equivalents of the two models nearly every Gazebo world includes, written
// from the SDF specification and the values Gazebo's models are known to carry: a static plane
// with normal +z (friction mu 100, mu2 50, as Gazebo's ground plane), and a directional light.
constexpr const char* kGroundPlaneSdf = R"(<?xml version="1.0"?>
<sdf version="1.6">
  <model name="ground_plane">
    <static>true</static>
    <link name="link">
      <collision name="collision">
        <geometry><plane><normal>0 0 1</normal><size>100 100</size></plane></geometry>
        <surface><friction><ode><mu>100</mu><mu2>50</mu2></ode></friction></surface>
      </collision>
      <visual name="visual">
        <geometry><plane><normal>0 0 1</normal><size>100 100</size></plane></geometry>
      </visual>
    </link>
  </model>
</sdf>
)";

constexpr const char* kSunSdf = R"(<?xml version="1.0"?>
<sdf version="1.6">
  <light type="directional" name="sun">
    <cast_shadows>true</cast_shadows>
    <pose>0 0 10 0 0 0</pose>
    <diffuse>0.8 0.8 0.8 1</diffuse>
    <specular>0.2 0.2 0.2 1</specular>
    <attenuation><range>1000</range><constant>0.9</constant><linear>0.01</linear><quadratic>0.001</quadratic></attenuation>
    <direction>-0.5 0.1 -0.9</direction>
  </light>
</sdf>
)";

// A calibration target as worlds with cameras include it (model://checkerboard_plane): a static
// board of 8 x 8 squares of 0.1 m, black and white, standing upright (facing +x) with its lower
// edge 0.05 m above the ground. mechsim's own: the squares are visuals (the renderer draws them),
// the board one thin collision box.
std::string checkerboard_sdf() {
  constexpr int kSquares = 8;
  constexpr double kSquare = 0.1, kThick = 0.005, kBottom = 0.05;
  std::string visuals;
  for (int r = 0; r < kSquares; ++r) {
    for (int c = 0; c < kSquares; ++c) {
      const double y = (c - kSquares / 2 + 0.5) * kSquare;
      const double z = kBottom + (r + 0.5) * kSquare;
      const char* colour = (r + c) % 2 == 0 ? "0 0 0 1" : "1 1 1 1";
      visuals += "      <visual name=\"square_" + std::to_string(r) + "_" + std::to_string(c) + "\"><pose>0 " +
                 std::to_string(y) + " " + std::to_string(z) + " 0 0 0</pose><geometry><box><size>" +
                 std::to_string(kThick) + " " + std::to_string(kSquare) + " " + std::to_string(kSquare) +
                 "</size></box></geometry><material><ambient>" + colour + "</ambient><diffuse>" + colour +
                 "</diffuse></material></visual>\n";
    }
  }
  const double side = kSquares * kSquare;
  return "<?xml version=\"1.0\"?>\n<sdf version=\"1.6\">\n  <model name=\"checkerboard_plane\">\n    <static>true</static>\n"
         "    <link name=\"link\">\n      <collision name=\"collision\"><pose>-0.001 0 " + std::to_string(kBottom + side / 2) +
         " 0 0 0</pose><geometry><box><size>" + std::to_string(kThick) + " " + std::to_string(side) + " " +
         std::to_string(side) + "</size></box></geometry></collision>\n" + visuals + "    </link>\n  </model>\n</sdf>\n";
}

// A 20 m x 20 m asphalt ground (model://asphalt_plane): a static plane as the ground plane's,
// dark grey.
constexpr const char* kAsphaltPlaneSdf = R"(<?xml version="1.0"?>
<sdf version="1.6">
  <model name="asphalt_plane">
    <static>true</static>
    <link name="link">
      <collision name="collision">
        <geometry><box><size>20 20 0.1</size></box></geometry>
        <pose>0 0 -0.05 0 0 0</pose>
      </collision>
      <visual name="visual">
        <pose>0 0 -0.05 0 0 0</pose>
        <geometry><box><size>20 20 0.1</size></box></geometry>
        <material><ambient>0.2 0.2 0.2 1</ambient><diffuse>0.2 0.2 0.2 1</diffuse></material>
      </visual>
    </link>
  </model>
</sdf>
)";

void write_model(const fs::path& root, const std::string& name, const char* sdf) {
  fs::create_directories(root / name);
  std::ofstream(root / name / "model.config")
      << "<?xml version=\"1.0\"?>\n<model><name>" << name
      << "</name><version>1.0</version><sdf version=\"1.6\">model.sdf</sdf>"
      << "<description>mechsim's own minimal " << name << "</description></model>\n";
  std::ofstream(root / name / "model.sdf") << sdf;
}

}  // namespace

SdfSearch make_search(const SdfOptions& options) {
  SdfSearch s;
  s.model_dirs = options.model_paths;
  s.packages = options.packages;
  if (options.use_environment) {
    split_into(std::getenv("GAZEBO_MODEL_PATH"), s.model_dirs);
    // What packages export to gazebo_ros (package.xml <export><gazebo_ros gazebo_model_path=...>),
    // which gazebo_ros' launch scripts add to Gazebo's paths.
    for (std::string& dir : gazebo_ros_exports("gazebo_model_path")) s.model_dirs.push_back(std::move(dir));
    if (const char* home = std::getenv("HOME")) s.model_dirs.push_back(std::string(home) + "/.gazebo/models");
    split_into(std::getenv("GAZEBO_RESOURCE_PATH"), s.resource_dirs);
    for (std::string& dir : gazebo_ros_exports("gazebo_media_path")) s.resource_dirs.push_back(std::move(dir));
  }
  return s;
}

std::string resolve_uri(const std::string& uri, const std::string& from_file, const SdfSearch& search) {
  static const std::string model_scheme = "model://", file_scheme = "file://", package_scheme = "package://";
  if (uri.starts_with(model_scheme)) {
    const std::string rest = uri.substr(model_scheme.size());
    for (const std::string& dir : search.model_dirs)
      if (is_file(fs::path(dir) / rest)) return (fs::path(dir) / rest).string();
    return {};
  }
  if (uri.starts_with(package_scheme)) {
    const auto p = description::resolve_uri(uri, search.packages, "");
    return p && is_file(*p) ? *p : std::string();
  }
  std::string path = uri.starts_with(file_scheme) ? uri.substr(file_scheme.size()) : uri;
  if (fs::path(path).is_absolute()) return is_file(path) ? path : std::string();
  // Relative: beside the SDF file, then Gazebo's resource folders (file://media/... in worlds).
  const fs::path here = fs::path(from_file).parent_path();
  if (!from_file.empty() && is_file(here / path)) return (here / path).string();
  for (const std::string& dir : search.resource_dirs)
    if (is_file(fs::path(dir) / path)) return (fs::path(dir) / path).string();
  return {};
}

BuiltinModels::BuiltinModels() {
  std::string pattern = (fs::temp_directory_path() / "mechsim-sdf-models-XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr) throw SdfError("cannot create a temporary folder for mechsim's own library models");
  dir_ = pattern;
  write_model(dir_, "ground_plane", kGroundPlaneSdf);
  write_model(dir_, "sun", kSunSdf);
  write_model(dir_, "checkerboard_plane", checkerboard_sdf().c_str());
  write_model(dir_, "asphalt_plane", kAsphaltPlaneSdf);
}

BuiltinModels::~BuiltinModels() {
  std::error_code ec;
  fs::remove_all(dir_, ec);
}

}  // namespace mechsim::description::sdf_detail
