#include "description/urdf/validation.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include <Eigen/Eigenvalues>

namespace mechsim::description {

std::string location(const std::string& source, int line) {
  if (line > 0) return source + ":" + std::to_string(line) + ": ";
  return source + ": ";
}

namespace {

std::string num(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

class Reporter {
 public:
  Reporter(const RobotModel& model, ValidationReport& report, bool lenient = false)
      : source_(model.source.empty() ? "<robot>" : model.source), report_(report), lenient_(lenient) {}
  void error(int line, const std::string& message) { report_.errors.push_back(location(source_, line) + message); }
  void warning(int line, const std::string& message) {
    report_.warnings.push_back(location(source_, line) + message);
  }
  // A physical-plausibility problem: an error unless lenient.
  void physical(int line, const std::string& message) {
    if (lenient_) {
      warning(line, message + " (accepted: lenient)");
    } else {
      error(line, message);
    }
  }

 private:
  std::string source_;
  ValidationReport& report_;
  bool lenient_;
};

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool finite(const Pose& p) {
  const Quat& q = p.orientation;
  return finite(p.position) && std::isfinite(q.w) && std::isfinite(q.x) && std::isfinite(q.y) &&
         std::isfinite(q.z);
}

template <typename T>
void check_unique(const std::vector<T>& items, const char* kind, Reporter& r) {
  std::map<std::string, int> first_line;
  for (const T& item : items) {
    auto [it, inserted] = first_line.emplace(item.name, item.line);
    if (!inserted)
      r.error(item.line, std::string(kind) + " '" + item.name + "' is defined twice (first at line " +
                             std::to_string(it->second) + ")");
  }
}

void check_inertial(const Link& link, Reporter& r) {
  const Inertial& in = *link.inertial;
  const std::string what = "link '" + link.name + "': ";
  const double values[] = {in.mass, in.ixx, in.ixy, in.ixz, in.iyy, in.iyz, in.izz};
  for (double v : values) {
    if (!std::isfinite(v)) {
      r.error(link.line, what + "inertial holds a value that is not finite");
      return;
    }
  }
  if (!finite(in.origin)) r.error(link.line, what + "inertial origin is not finite");
  if (in.mass < 0.0) r.physical(link.line, what + "negative mass " + num(in.mass) + " kg");
  const bool any_inertia = in.ixx != 0.0 || in.iyy != 0.0 || in.izz != 0.0 || in.ixy != 0.0 ||
                           in.ixz != 0.0 || in.iyz != 0.0;
  if (in.mass <= 0.0 && !any_inertia) return;  // a massless frame holder
  Eigen::Matrix3d inertia;
  inertia << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
  const Eigen::Vector3d moments =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(inertia, Eigen::EigenvaluesOnly).eigenvalues();
  const std::string listed = num(moments[0]) + ", " + num(moments[1]) + ", " + num(moments[2]);
  if (moments[0] <= 0.0) {
    r.physical(link.line, what + "inertia is not positive definite (principal moments " + listed +
                              " kg m^2)");
    return;
  }
  // Eigenvalues come sorted ascending; a rigid body has I1 + I2 >= I3. The tolerance absorbs
  // rounding of CAD-exported values.
  if (moments[0] + moments[1] < moments[2] * (1.0 - 1e-6)) {
    r.physical(link.line, what + "inertia breaks the triangle inequality (principal moments " +
                              listed + " kg m^2: " + num(moments[0]) + " + " + num(moments[1]) +
                              " < " + num(moments[2]) + ")");
  }
}

void check_geometry(const Geometry& g, const std::string& what, int line, Reporter& r) {
  const double values[] = {g.size.x, g.size.y, g.size.z, g.radius, g.length,
                           g.mesh_scale.x, g.mesh_scale.y, g.mesh_scale.z};
  for (double v : values) {
    if (!std::isfinite(v)) {
      r.error(line, what + "geometry holds a value that is not finite");
      return;
    }
  }
  if (g.size.x < 0.0 || g.size.y < 0.0 || g.size.z < 0.0 || g.radius < 0.0 || g.length < 0.0)
    r.physical(line, what + "geometry has a negative size");
}

bool moves(JointType t) { return t != JointType::Fixed && t != JointType::Floating; }

void check_joint(const Joint& j, Reporter& r) {
  const std::string what = "joint '" + j.name + "': ";
  if (!finite(j.origin)) r.error(j.line, what + "origin is not finite");
  if (!finite(j.axis)) {
    r.error(j.line, what + "axis is not finite");
  } else if (moves(j.type) && j.axis.x == 0.0 && j.axis.y == 0.0 && j.axis.z == 0.0) {
    r.error(j.line, what + "zero axis (0 0 0)");
  }
  if (j.limits) {
    const JointLimits& l = *j.limits;
    if (!std::isfinite(l.lower) || !std::isfinite(l.upper) || !std::isfinite(l.effort) ||
        !std::isfinite(l.velocity)) {
      r.error(j.line, what + "limit holds a value that is not finite");
    } else {
      const bool bounded = j.type == JointType::Revolute || j.type == JointType::Prismatic;
      if (bounded && l.lower > l.upper)
        r.physical(j.line, what + "lower limit " + num(l.lower) + " > upper limit " + num(l.upper));
      if (l.effort < 0.0) r.physical(j.line, what + "negative effort limit " + num(l.effort));
      if (l.velocity < 0.0) r.physical(j.line, what + "negative velocity limit " + num(l.velocity));
    }
  }
  if (j.safety) {
    const SafetyController& s = *j.safety;
    if (!std::isfinite(s.soft_lower_limit) || !std::isfinite(s.soft_upper_limit) ||
        !std::isfinite(s.k_position) || !std::isfinite(s.k_velocity)) {
      r.error(j.line, what + "safety_controller holds a value that is not finite");
    } else if (s.soft_lower_limit > s.soft_upper_limit && j.type != JointType::Continuous) {
      r.physical(j.line, what + "soft lower limit " + num(s.soft_lower_limit) + " > soft upper limit " +
                             num(s.soft_upper_limit));
    }
  }
  if (j.dynamics) {
    if (!std::isfinite(j.dynamics->damping) || !std::isfinite(j.dynamics->friction)) {
      r.error(j.line, what + "dynamics holds a value that is not finite");
    } else {
      if (j.dynamics->damping < 0.0) r.physical(j.line, what + "negative damping " + num(j.dynamics->damping));
      if (j.dynamics->friction < 0.0) r.physical(j.line, what + "negative friction " + num(j.dynamics->friction));
    }
  }
  if (j.mimic && (!std::isfinite(j.mimic->multiplier) || !std::isfinite(j.mimic->offset)))
    r.error(j.line, what + "mimic multiplier or offset is not finite");
  if (j.calibration && ((j.calibration->rising && !std::isfinite(*j.calibration->rising)) ||
                        (j.calibration->falling && !std::isfinite(*j.calibration->falling))))
    r.error(j.line, what + "calibration holds a value that is not finite");
}

// The line of the transmission child naming `name`, for a precise message.
int entry_line(const Transmission& t, const std::string& name) {
  for (const XmlNode& c : t.xml.children)
    if (c.attribute("name") == name) return c.line;
  return t.line;
}

// What ros_control and gazebo_ros_control accept with at most a warning: a repeated transmission
// name (both load), the <hardwareInterface> in the <actuator> only (gazebo_ros_control reads it
// there), a joint several transmissions name (each adds an interface) with different actuators.
void check_transmissions(const RobotModel& model, Reporter& r) {
  std::map<std::string, const Transmission*> by_name;
  std::map<std::string, const Transmission*> by_joint;
  for (const Transmission& t : model.transmissions) {
    if (auto [it, inserted] = by_name.emplace(t.name, &t); !inserted) {
      r.warning(t.line, "transmission '" + t.name + "' is defined twice (first at line " + std::to_string(it->second->line) +
                            "); both are loaded, as ros_control does");
    }
    const bool ros_control = t.type.rfind("transmission_interface/", 0) == 0;
    for (const TransmissionJoint& j : t.joints) {
      if (ros_control && j.hardware_interfaces.empty() && t.actuators.size() == 1 &&
          !t.actuators[0].hardware_interfaces.empty()) {
        r.warning(entry_line(t, j.name), "transmission '" + t.name + "': joint '" + j.name +
                                             "' names its <hardwareInterface> in <actuator> '" + t.actuators[0].name +
                                             "'; used for the joint, as gazebo_ros_control does (which asks for it "
                                             "inside <joint>)");
      }
      if (!j.role.empty()) continue;
      auto [it, inserted] = by_joint.emplace(j.name, &t);
      if (inserted || t.actuators.size() != 1 || it->second->actuators.size() != 1) continue;
      const std::string& first = it->second->actuators[0].name;
      if (t.actuators[0].name != first) {
        r.warning(entry_line(t, t.actuators[0].name),
                  "transmission '" + t.name + "': joint '" + j.name + "' is also driven by transmission '" +
                      it->second->name + "' (line " + std::to_string(it->second->line) + ") through actuator '" + first +
                      "'; actuator '" + t.actuators[0].name + "' is no second motor (the joint gets this one's interfaces)");
      }
    }
  }
}

}  // namespace

void validate_structure(const RobotModel& model, ValidationReport& report) {
  Reporter r(model, report);
  check_unique(model.links, "link", r);
  check_unique(model.joints, "joint", r);
  check_transmissions(model, r);

  std::map<std::string, const Link*> links;
  for (const Link& l : model.links) links.emplace(l.name, &l);
  std::map<std::string, const Joint*> parent_joint;  // child link -> the joint above it
  for (const Joint& j : model.joints) {
    const std::string what = "joint '" + j.name + "': ";
    bool ok = true;
    if (!links.count(j.parent_link)) {
      r.error(j.line, what + "parent link '" + j.parent_link + "' does not exist");
      ok = false;
    }
    if (!links.count(j.child_link)) {
      r.error(j.line, what + "child link '" + j.child_link + "' does not exist");
      ok = false;
    }
    if (!ok) continue;
    if (j.parent_link == j.child_link) {
      r.error(j.line, what + "parent and child are the same link '" + j.child_link + "'");
      continue;
    }
    auto [it, inserted] = parent_joint.emplace(j.child_link, &j);
    if (!inserted)
      r.error(j.line, what + "link '" + j.child_link + "' already has parent joint '" + it->second->name +
                          "' (line " + std::to_string(it->second->line) + "); a link has one parent");
  }

  std::vector<const Link*> roots;
  for (const Link& l : model.links)
    if (!parent_joint.count(l.name) && std::find_if(roots.begin(), roots.end(), [&](const Link* x) {
                                         return x->name == l.name;
                                       }) == roots.end())
      roots.push_back(&l);
  if (roots.size() > 1) {
    std::string names;
    for (const Link* l : roots) names += (names.empty() ? "'" : ", '") + l->name + "'";
    r.error(roots[1]->line, "several root links (" + names + "); a URDF tree has one root");
  }

  // Cycles: walk up from every link; a walk that meets its own path found a cycle.
  std::set<std::string> done;
  for (const Link& start : model.links) {
    std::vector<std::string> path;
    std::map<std::string, std::size_t> on_path;  // link -> index in path, for long chains
    std::string current = start.name;
    while (!done.count(current)) {
      if (auto seen_at = on_path.find(current); seen_at != on_path.end()) {
        const auto seen = path.begin() + static_cast<std::ptrdiff_t>(seen_at->second);
        std::string chain;
        int line = 0;
        for (auto it = seen; it != path.end(); ++it) {
          const Joint* j = parent_joint.at(*it);
          chain += (chain.empty() ? "'" : " <- '") + j->name + "'";
          if (line == 0 || j->line < line) line = j->line;
        }
        r.error(line, "kinematic cycle through joints " + chain + " (link '" + current + "')");
        break;
      }
      on_path.emplace(current, path.size());
      path.push_back(current);
      auto up = parent_joint.find(current);
      if (up == parent_joint.end()) break;
      current = up->second->parent_link;
    }
    done.insert(path.begin(), path.end());
  }
  if (roots.empty() && !model.links.empty())
    r.error(model.links.front().line, "no root link: every link is the child of a joint");
}

void validate_physics(const RobotModel& model, const ValidationOptions& options, ValidationReport& report) {
  Reporter r(model, report, options.lenient);
  for (const Link& l : model.links) {
    if (l.inertial) check_inertial(l, r);
    const std::string what = "link '" + l.name + "': ";
    for (const Visual& v : l.visuals) {
      if (!finite(v.origin)) r.error(l.line, what + "visual origin is not finite");
      check_geometry(v.geometry, what + "visual ", l.line, r);
    }
    for (const Collision& c : l.collisions) {
      if (!finite(c.origin)) r.error(l.line, what + "collision origin is not finite");
      check_geometry(c.geometry, what + "collision ", l.line, r);
    }
  }
  for (const Joint& j : model.joints) check_joint(j, r);
  for (const Transmission& t : model.transmissions) {
    const std::string what = "transmission '" + t.name + "': ";
    auto check = [&](std::optional<double> reduction, int line) {
      if (!reduction) return;
      if (!std::isfinite(*reduction)) r.error(line, what + "mechanical reduction is not finite");
      else if (*reduction == 0.0) r.error(line, what + "mechanical reduction is zero");
    };
    check(t.mechanical_reduction, t.line);
    for (const TransmissionJoint& j : t.joints) check(j.mechanical_reduction, entry_line(t, j.name));
    for (const TransmissionActuator& a : t.actuators) check(a.mechanical_reduction, entry_line(t, a.name));
  }
}

void validate_references(const RobotModel& model, ValidationReport& report) {
  Reporter r(model, report);
  std::set<std::string> joints;
  for (const Joint& j : model.joints) joints.insert(j.name);
  for (const Joint& j : model.joints) {
    if (!j.mimic) continue;
    if (j.mimic->joint == j.name) {
      r.error(j.line, "joint '" + j.name + "': mimics itself");
    } else if (!joints.count(j.mimic->joint)) {
      r.error(j.line, "joint '" + j.name + "': mimics joint '" + j.mimic->joint + "', which does not exist");
    }
  }
  for (const Transmission& t : model.transmissions) {
    for (const TransmissionJoint& j : t.joints) {
      if (joints.count(j.name)) continue;
      const std::string role = j.role.empty() ? "" : " (" + j.role + ")";
      r.error(entry_line(t, j.name),
              "transmission '" + t.name + "': joint '" + j.name + "'" + role + " does not exist");
    }
  }
}

ValidationReport validate_robot(const RobotModel& model, const ValidationOptions& options) {
  ValidationReport report;
  validate_structure(model, report);
  validate_physics(model, options, report);
  validate_references(model, report);
  return report;
}

}  // namespace mechsim::description
