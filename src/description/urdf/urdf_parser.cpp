// parse_urdf_string/file: tinyxml2 pre-check and extension passes, urdfdom for the kinematic
// model, conversion to RobotModel, then validation. Every problem found is collected before
// throwing, so that a user sees them all at once.
#include "description/urdf/urdf_parser.hpp"

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>

#include "description/ros2_control.hpp"
#include "description/sensor_spec.hpp"
#include "description/transmission_types.hpp"
#include "description/urdf/urdf_reading.hpp"
#include "description/urdf/urdf_sensors.hpp"
#include "description/urdf/validation.hpp"
#include "description/utf8.hpp"

namespace mechsim::description {

namespace {

namespace fs = std::filesystem;

// urdfdom logs through console_bridge's process-wide output handler. The handler installed here
// (once per process) routes messages to the capture active on the calling thread, and to the
// previous handler otherwise, so that parsing prints nothing and parses on two threads do not
// mix their messages.
thread_local std::vector<std::string>* t_console_sink = nullptr;

class CapturingHandler : public console_bridge::OutputHandler {
 public:
  explicit CapturingHandler(console_bridge::OutputHandler* previous) : previous_(previous) {}
  void log(const std::string& text, console_bridge::LogLevel level, const char* filename,
           int line) override {
    if (t_console_sink != nullptr) {
      if (level >= console_bridge::CONSOLE_BRIDGE_LOG_WARN) t_console_sink->push_back(text);
    } else if (previous_ != nullptr) {
      previous_->log(text, level, filename, line);
    }
  }

 private:
  console_bridge::OutputHandler* previous_;
};

class ConsoleCapture {
 public:
  ConsoleCapture() {
    static std::once_flag installed;
    std::call_once(installed, [] {
      static CapturingHandler handler(console_bridge::getOutputHandler());
      console_bridge::useOutputHandler(&handler);
    });
    t_console_sink = &messages_;
  }
  ~ConsoleCapture() { t_console_sink = nullptr; }
  ConsoleCapture(const ConsoleCapture&) = delete;
  ConsoleCapture& operator=(const ConsoleCapture&) = delete;
  const std::vector<std::string>& messages() const { return messages_; }

 private:
  std::vector<std::string> messages_;
};

[[noreturn]] void throw_problems(const std::string& source, const std::vector<std::string>& errors) {
  std::ostringstream msg;
  if (errors.size() == 1) {
    msg << errors.front();
  } else {
    msg << errors.size() << " problems in " << source << ":";
    for (const std::string& e : errors) msg << "\n  " << e;
  }
  throw DescriptionError(msg.str(), errors);
}

// tinyxml2's ErrorStr is "Error=XML_ERROR_... ErrorID=.. Line number=..: XMLElement name=x";
// say it in words, keeping the element's name.
std::string describe_xml_error(const tinyxml2::XMLDocument& doc) {
  std::string element;
  const std::string raw = doc.ErrorStr() != nullptr ? doc.ErrorStr() : "";
  if (const std::size_t at = raw.find("name="); at != std::string::npos) element = raw.substr(at + 5);
  const std::string in = element.empty() ? "" : " in <" + element + ">";
  switch (doc.ErrorID()) {
    case tinyxml2::XML_ERROR_EMPTY_DOCUMENT: return "the document is empty";
    case tinyxml2::XML_ERROR_MISMATCHED_ELEMENT:
      return "the end tag does not match the open element" + (element.empty() ? "" : " <" + element + ">");
    case tinyxml2::XML_ERROR_PARSING_ATTRIBUTE: return "a bad or duplicate attribute" + in;
    case tinyxml2::XML_ERROR_PARSING_ELEMENT: return "an element that cannot be parsed" + in;
    case tinyxml2::XML_ERROR_PARSING_TEXT: return "text that cannot be parsed" + in;
    case tinyxml2::XML_ERROR_PARSING_COMMENT: return "an unterminated or bad comment";
    case tinyxml2::XML_ERROR_PARSING_DECLARATION: return "a bad XML declaration";
    case tinyxml2::XML_ERROR_PARSING_CDATA: return "a bad CDATA section";
    case tinyxml2::XML_ERROR_PARSING:
      return "a syntax error (unexpected end of the document, an unclosed element or stray text)" + in;
    default: return doc.ErrorName();
  }
}

Vec3 to_vec(const urdf::Vector3& v) { return {v.x, v.y, v.z}; }

Pose to_pose(const urdf::Pose& p) {
  Pose out;
  out.position = to_vec(p.position);
  out.orientation = {p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z};
  return out;
}

// Resolves package:// URIs, looking each package up once per document (a lookup may walk
// ROS_PACKAGE_PATH).
class MeshResolver {
 public:
  MeshResolver(const PackageMap& packages, std::string base_dir)
      : packages_(packages), base_dir_(std::move(base_dir)) {}

  std::string resolve(const std::string& uri, std::vector<std::string>& unresolved) {
    static const std::string scheme = "package://";
    if (uri.starts_with(scheme)) {
      const std::string rest = uri.substr(scheme.size());
      const std::string pkg = rest.substr(0, rest.find('/'));
      if (!packages_.count(pkg)) {
        auto dir = find_package(pkg, packages_);
        if (!dir) {
          unresolved.push_back(uri);
          return {};
        }
        packages_[pkg] = *dir;
      }
    }
    auto path = resolve_uri(uri, packages_, base_dir_);
    if (!path) {
      unresolved.push_back(uri);
      return {};
    }
    return *path;
  }

 private:
  PackageMap packages_;
  std::string base_dir_;
};

Geometry to_geometry(const urdf::GeometrySharedPtr& g, MeshResolver& meshes,
                     std::vector<std::string>& unresolved) {
  Geometry out;
  if (!g) return out;
  switch (g->type) {
    case urdf::Geometry::BOX: {
      const auto& b = static_cast<const urdf::Box&>(*g);
      out.type = GeometryType::Box;
      out.size = to_vec(b.dim);
      break;
    }
    case urdf::Geometry::CYLINDER: {
      const auto& c = static_cast<const urdf::Cylinder&>(*g);
      out.type = GeometryType::Cylinder;
      out.radius = c.radius;
      out.length = c.length;
      break;
    }
    case urdf::Geometry::SPHERE: {
      out.type = GeometryType::Sphere;
      out.radius = static_cast<const urdf::Sphere&>(*g).radius;
      break;
    }
    case urdf::Geometry::MESH: {
      const auto& m = static_cast<const urdf::Mesh&>(*g);
      out.type = GeometryType::Mesh;
      out.mesh_uri = m.filename;
      out.mesh_scale = to_vec(m.scale);
      out.mesh_path = meshes.resolve(m.filename, unresolved);
      break;
    }
  }
  return out;
}

Link to_link(const urdf::Link& l, int line, MeshResolver& meshes, std::vector<std::string>& unresolved) {
  Link out;
  out.name = l.name;
  out.line = line;
  if (l.inertial) {
    const urdf::Inertial& i = *l.inertial;
    out.inertial = Inertial{to_pose(i.origin), i.mass, i.ixx, i.ixy, i.ixz, i.iyy, i.iyz, i.izz};
  }
  for (const urdf::VisualSharedPtr& v : l.visual_array) {
    if (!v) continue;
    Visual vis;
    vis.name = v->name;
    vis.origin = to_pose(v->origin);
    vis.geometry = to_geometry(v->geometry, meshes, unresolved);
    vis.material_name = v->material_name;
    if (v->material) {
      const urdf::Color& c = v->material->color;
      vis.rgba = std::array<double, 4>{c.r, c.g, c.b, c.a};
    }
    out.visuals.push_back(std::move(vis));
  }
  for (const urdf::CollisionSharedPtr& c : l.collision_array) {
    if (!c) continue;
    Collision col;
    col.name = c->name;
    col.origin = to_pose(c->origin);
    col.geometry = to_geometry(c->geometry, meshes, unresolved);
    out.collisions.push_back(std::move(col));
  }
  return out;
}

JointType to_joint_type(int t) {
  switch (t) {
    case urdf::Joint::REVOLUTE: return JointType::Revolute;
    case urdf::Joint::CONTINUOUS: return JointType::Continuous;
    case urdf::Joint::PRISMATIC: return JointType::Prismatic;
    case urdf::Joint::FLOATING: return JointType::Floating;
    case urdf::Joint::PLANAR: return JointType::Planar;
    default: return JointType::Fixed;
  }
}

Joint to_joint(const urdf::Joint& j, int line) {
  Joint out;
  out.name = j.name;
  out.line = line;
  out.type = to_joint_type(j.type);
  out.parent_link = j.parent_link_name;
  out.child_link = j.child_link_name;
  out.origin = to_pose(j.parent_to_joint_origin_transform);
  out.axis = to_vec(j.axis);
  if (j.limits) out.limits = JointLimits{j.limits->lower, j.limits->upper, j.limits->effort, j.limits->velocity};
  if (j.safety)
    out.safety = SafetyController{j.safety->soft_lower_limit, j.safety->soft_upper_limit,
                                  j.safety->k_position, j.safety->k_velocity};
  if (j.dynamics) out.dynamics = Dynamics{j.dynamics->damping, j.dynamics->friction};
  if (j.calibration) {
    Calibration c;
    if (j.calibration->rising) c.rising = *j.calibration->rising;
    if (j.calibration->falling) c.falling = *j.calibration->falling;
    out.calibration = c;
  }
  if (j.mimic) out.mimic = Mimic{j.mimic->joint_name, j.mimic->multiplier, j.mimic->offset};
  return out;
}

// A unit axis for the model (validation has already rejected a zero or non-finite one).
void normalize_axis(Vec3& a) {
  const double n = std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
  if (n > 0.0 && std::isfinite(n)) a = {a.x / n, a.y / n, a.z / n};
}

}  // namespace

RobotModel parse_urdf_string(std::string_view xml, const std::string& source_name,
                             const UrdfOptions& options, std::vector<std::string>* warnings) {
  // XML's encoding without a BOM is UTF-8, and tinyxml2 (like ROS's urdfdom) never decodes another:
  // stray 8-bit bytes would reach link names and, at the end of a run, the JSON it writes.
  if (const std::size_t at = invalid_utf8_at(xml); at != std::string_view::npos) {
    const int line = 1 + static_cast<int>(std::count(xml.begin(), xml.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
    throw_problems(source_name, {location(source_name, line) + "not UTF-8 text (" + utf8_byte_name(xml, at) +
                                 "): save the file as UTF-8"});
  }
  tinyxml2::XMLDocument doc;
  if (doc.Parse(xml.data(), xml.size()) != tinyxml2::XML_SUCCESS) {
    throw_problems(source_name,
                   {location(source_name, doc.ErrorLineNum()) + "malformed XML: " + describe_xml_error(doc)});
  }
  const tinyxml2::XMLElement* robot = doc.RootElement();
  if (robot == nullptr || std::string(robot->Name()) != "robot") {
    const int line = robot != nullptr ? robot->GetLineNum() : 1;
    throw_problems(source_name, {location(source_name, line) + "the root element is <" +
                                 (robot != nullptr ? robot->Name() : "") + ">, not <robot>"});
  }

  detail::Problems problems(source_name);
  RobotModel skeleton;
  skeleton.source = source_name;
  detail::precheck_urdf(*robot, problems, skeleton);
  detail::read_transmissions(*robot, problems, skeleton);
  detail::read_gazebo(*robot, problems, skeleton);
  detail::read_ros2_control(*robot, problems, skeleton);
  ValidationReport& report = problems.report();
  validate_structure(skeleton, report);
  if (!report.ok()) throw_problems(source_name, report.errors);

  urdf::ModelInterfaceSharedPtr parsed;
  std::vector<std::string> urdfdom_messages;
  {
    ConsoleCapture capture;
    try {
      parsed = urdf::parseURDF(std::string(xml));
    } catch (const std::exception& e) {
      urdfdom_messages.push_back(e.what());
    }
    // urdfdom repeats some messages (once per visual array and once for the first visual).
    for (const std::string& m : capture.messages())
      if (std::find(urdfdom_messages.begin(), urdfdom_messages.end(), m) == urdfdom_messages.end())
        urdfdom_messages.push_back(m);
  }
  if (!parsed) {
    std::string msg = location(source_name, 0) + "urdfdom rejected the description";
    for (const std::string& m : urdfdom_messages) msg += ": " + m;
    throw_problems(source_name, {msg});
  }

  RobotModel model;
  model.name = parsed->getName();
  model.source = source_name;
  if (parsed->getRoot()) model.root_link = parsed->getRoot()->name;
  const std::string base_dir =
      source_name.starts_with("<") ? std::string() : fs::path(source_name).parent_path().string();
  MeshResolver meshes(options.packages, base_dir);
  std::vector<std::string> unresolved;
  for (const Link& s : skeleton.links) {
    urdf::LinkConstSharedPtr l = parsed->getLink(s.name);
    if (l) model.links.push_back(to_link(*l, s.line, meshes, unresolved));
  }
  for (const Joint& s : skeleton.joints) {
    urdf::JointConstSharedPtr j = parsed->getJoint(s.name);
    if (j) model.joints.push_back(to_joint(*j, s.line));
  }
  std::map<std::string, Link*> by_name;
  for (Link& l : model.links) by_name[l.name] = &l;
  for (const Joint& j : model.joints) {
    by_name.at(j.child_link)->parent_joint = j.name;
    by_name.at(j.parent_link)->child_joints.push_back(j.name);
  }
  model.transmissions = std::move(skeleton.transmissions);
  if (options.lenient) {
    // Gazebo's gazebo_ros_control reads any transmission type (it only takes the joints' hardware
    // interfaces); mechsim builds those of kTransmissionTypes, so a lenient load leaves the
    // others out, each named.
    std::erase_if(model.transmissions, [&](const Transmission& t) {
      const bool known = t.type.empty() || std::find(kTransmissionTypes.begin(), kTransmissionTypes.end(), t.type) !=
                                               kTransmissionTypes.end();
      if (!known) {
        report.warnings.push_back(location(source_name, t.line) + "transmission '" + t.name + "' of type '" + t.type +
                                  "' left out: mechsim does not simulate that type (a vendor's hardware interface; " +
                                  "accepted: lenient)");
      }
      return !known;
    });
  }
  model.gazebo_links = std::move(skeleton.gazebo_links);
  model.gazebo_joints = std::move(skeleton.gazebo_joints);
  model.plugins = std::move(skeleton.plugins);
  model.sensors = std::move(skeleton.sensors);
  // The skeleton the sensors were read against had no collisions: contact sensors name them.
  for (SensorSpec& sensor : model.sensors)
    if (auto* contact = std::get_if<ContactSpec>(&sensor.details)) detail::resolve_contact(*contact, sensor.link, model);
  model.ros2_control = std::move(skeleton.ros2_control);

  for (const std::string& m : urdfdom_messages) report.warnings.push_back(location(source_name, 0) + "urdfdom: " + m);
  if (!unresolved.empty()) {
    report.warnings.push_back(location(source_name, 0) + std::to_string(unresolved.size()) +
                              " mesh URI(s) could not be resolved (unknown package; pass --package "
                              "NAME=DIR), first: " + unresolved.front());
  }
  validate_physics(model, ValidationOptions{options.lenient}, report);
  validate_references(model, report);
  if (report.ok()) detail::check_ros2_control(model, problems);
  if (!report.ok()) throw_problems(source_name, report.errors);
  for (Joint& j : model.joints) normalize_axis(j.axis);
  if (warnings != nullptr) warnings->insert(warnings->end(), report.warnings.begin(), report.warnings.end());
  return model;
}

RobotModel parse_urdf_file(const std::string& path, const UrdfOptions& options,
                           std::vector<std::string>* warnings) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw DescriptionError(path + ": is a directory, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw DescriptionError(path + ": cannot open the file");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return parse_urdf_string(buffer.str(), path, options, warnings);
}

}  // namespace mechsim::description
