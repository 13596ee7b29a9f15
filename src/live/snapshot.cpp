#include "live/snapshot.hpp"

#include <algorithm>
#include <limits>
#include <utility>
#include <variant>

#include "control/ports.hpp"
#include "controllers/drive/rover_drive_ports.hpp"
#include "sensors/sensor_output.hpp"
#include "sim/simulation.hpp"

namespace mechsim::live {

namespace {

constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

const control::StatePort<control::OdometrySnapshot>* find_odometry(sim::Simulation& sim) {
  for (const control::ControllerInfo& info : sim.controllers().list_controllers()) {
    control::Controller* c = sim.controllers().controller(info.name);
    if (c == nullptr) continue;
    for (control::Port* p : c->ports()) {
      if (p->kind() != control::PortKind::Odometry) continue;
      if (auto* odometry = dynamic_cast<const control::StatePort<control::OdometrySnapshot>*>(p)) return odometry;
    }
  }
  return nullptr;
}

}  // namespace

StreamLayout make_stream_layout(sim::Simulation& sim, std::string urdf, std::vector<std::array<double, 2>> waypoints) {
  StreamLayout layout;
  const description::RobotModel& robot = sim.robot();
  const physics::PhysicsModel& model = sim.physics().model();
  // Links in tree order from the root, so that every parent comes before its children.
  std::vector<std::string> order{robot.root_link};
  for (std::size_t k = 0; k < order.size(); ++k) {
    const description::Link* link = robot.link(order[k]);
    if (link == nullptr) continue;
    for (const std::string& joint_name : link->child_joints) {
      if (const description::Joint* j = robot.joint(joint_name)) order.push_back(j->child_link);
    }
  }
  for (const std::string& name : order) {
    const std::optional<std::size_t> index = model.link_index(name);
    if (!index) continue;
    std::size_t parent = kNone;
    // The nearest ancestor that is streamed.
    for (const description::Link* link = robot.link(name); link != nullptr && !link->parent_joint.empty();) {
      const description::Joint* j = robot.joint(link->parent_joint);
      if (j == nullptr) break;
      const auto found = std::find(layout.links.begin(), layout.links.end(), j->parent_link);
      if (found != layout.links.end()) {
        parent = static_cast<std::size_t>(found - layout.links.begin());
        break;
      }
      link = robot.link(j->parent_link);
    }
    layout.links.push_back(name);
    layout.physics_link.push_back(*index);
    layout.parent.push_back(parent);
  }
  for (const mechanism::JointInfo& j : sim.mechanism().joints) layout.joints.push_back(j.name);
  layout.mechanism_joints = layout.joints.size();
  const std::vector<physics::JointInfo>& physics_joints = model.joints();
  for (std::size_t p = 0; p < physics_joints.size(); ++p) {
    if (sim.mechanism().joint_index(physics_joints[p].name) >= 0) continue;
    layout.joints.push_back(physics_joints[p].name);
    layout.physics_joint.push_back(p);
  }
  layout.odometry = find_odometry(sim);
  if (layout.odometry != nullptr) {
    const control::OdometrySnapshot odom = layout.odometry->read();
    layout.odom_frame = odom.in_world ? layout.world_frame : odom.frame_id;
    layout.odom_child_frame = odom.child_frame_id;
  }
  const sensors::SensorSet& sensor_set = sim.sensors();
  for (std::size_t i = 0; i < sensor_set.size(); ++i) {
    const auto* scan = std::get_if<sensors::LaserScan>(&sensor_set.reading(i).value);
    if (scan == nullptr || scan->horizontal_count <= 0) continue;
    LaserLayout laser;
    laser.name = sensor_set.spec(i).name;
    laser.topic = "/scan/" + laser.name;
    laser.link = sensor_set.spec(i).link;
    laser.X_LS = sensor_set.spec(i).pose;
    laser.sensor = i;
    laser.angle_min = scan->angle_min;
    laser.angle_max = scan->angle_max;
    laser.rays = static_cast<std::size_t>(scan->horizontal_count);
    layout.lasers.push_back(std::move(laser));
  }
  layout.robot_description = std::move(urdf);
  layout.waypoints = std::move(waypoints);
  return layout;
}

Snapshot make_snapshot(const StreamLayout& layout) {
  Snapshot s;
  s.X_WL.resize(layout.links.size());
  s.position.resize(layout.joints.size());
  s.velocity.resize(layout.joints.size());
  s.effort.resize(layout.joints.size());
  s.lasers.resize(layout.lasers.size());
  for (std::size_t k = 0; k < layout.lasers.size(); ++k) s.lasers[k].ranges.resize(layout.lasers[k].rays);
  return s;
}

void capture_snapshot(const StreamLayout& layout, const sim::Simulation& sim, Snapshot& out) noexcept {
  out.time = sim.time();
  out.tick = sim.ticks();
  const physics::Physics& physics = sim.physics();
  for (std::size_t k = 0; k < layout.links.size(); ++k) out.X_WL[k] = physics.link_pose(layout.physics_link[k]);
  const std::vector<mechanism::JointState>& joints = sim.mechanism_state().joints;
  for (std::size_t k = 0; k < layout.mechanism_joints; ++k) {
    out.position[k] = joints[k].position;
    out.velocity[k] = joints[k].velocity;
    out.effort[k] = joints[k].measured_effort;
  }
  for (std::size_t k = 0; k < layout.physics_joint.size(); ++k) {
    const std::size_t j = layout.mechanism_joints + k;
    out.position[j] = physics.position(layout.physics_joint[k]);
    out.velocity[j] = physics.velocity(layout.physics_joint[k]);
    out.effort[j] = 0.0;
  }
  out.has_odometry = false;
  if (layout.odometry != nullptr && layout.odometry->sequence() > 0) {
    // The port's snapshot holds two short frame names (within the small-string buffer).
    const control::OdometrySnapshot odom = layout.odometry->read();
    out.has_odometry = true;
    out.odom_x = odom.x;
    out.odom_y = odom.y;
    out.odom_z = odom.z;
    const control::Quaternion q = odom.orientation();
    out.odom_orientation = {q.w, q.x, q.y, q.z};
  }
  for (std::size_t k = 0; k < layout.lasers.size(); ++k) {
    const sensors::SensorReading& reading = sim.sensors().reading(layout.lasers[k].sensor);
    LaserFrame& frame = out.lasers[k];
    if (reading.count == frame.count) continue;
    const auto* scan = std::get_if<sensors::LaserScan>(&reading.value);
    if (scan == nullptr) continue;
    frame.count = reading.count;
    frame.stamp = reading.stamp;
    const std::size_t n = std::min(frame.ranges.size(), scan->ranges.size());
    std::copy_n(scan->ranges.begin(), n, frame.ranges.begin());
  }
}

}  // namespace mechsim::live
