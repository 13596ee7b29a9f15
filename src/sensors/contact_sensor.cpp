// contact sensors (gazebo_ros_bumper): the contacts of the sensor's collision shapes, grouped by
// touching pair as gazebo_msgs/ContactsState has them.
#include <algorithm>
#include <string_view>

#include "physics/transform.hpp"
#include "sensors/sensor_types.hpp"

namespace mechsim::sensors {

namespace {

struct ContactSensorState : SensorState {
  std::vector<physics::Contact> contacts;  // scratch
  std::vector<std::pair<int, int>> pairs;  // (own geom, other geom) of each state in use
};

// The link a Gazebo collision name refers to: "<link>_collision", "<link>_collision_<n>", and
// the lumped "<parent>_fixed_joint_lump__<link>_collision[_<n>]"; "" when the name has neither form.
std::string collision_link(std::string name) {
  const std::string lump = "_fixed_joint_lump__";
  if (const auto at = name.find(lump); at != std::string::npos) name = name.substr(at + lump.size());
  const auto at = name.rfind("_collision");
  if (at == std::string::npos) return "";
  const std::string tail = name.substr(at + 10);
  if (!tail.empty() && (tail[0] != '_' || tail.size() < 2 ||
                        !std::all_of(tail.begin() + 1, tail.end(), [](char c) { return c >= '0' && c <= '9'; })))
    return "";
  return name.substr(0, at);
}

// Gazebo's scoped name of a compiled geom: model::link::collision.
std::string gazebo_name(const physics::PhysicsModel& model, int geom) {
  const std::string_view n = model.geom_name(geom);
  const auto cut = n.rfind("/collision/");
  if (cut != std::string_view::npos) {
    const std::string link(n.substr(0, cut));
    const std::string index(n.substr(cut + 11));
    return model.robot_name() + "::" + link + "::" + link + "_collision" + (index == "0" ? "" : "_" + index);
  }
  if (n == "ground") return "ground_plane::link::collision";
  // A world object: an SDF world's shapes are named model::link::collision already; a scenario's
  // box by its name alone.
  if (n.rfind("box:", 0) == 0)
    return n.find("::") != std::string_view::npos ? std::string(n.substr(4)) : std::string(n.substr(4)) + "::link::collision";
  if (n.empty()) return "world::link::collision";
  return std::string(n) + "::link::collision";
}

}  // namespace

ContactSensor::ContactSensor(const description::SensorSpec& spec, const physics::PhysicsModel& model,
                             const std::string& prefix)
    : Sensor(spec, prefix) {
  ContactSensor::bind(model);
}

void ContactSensor::bind(const physics::PhysicsModel& model) {
  const description::SensorSpec& spec = this->spec();
  link_ = resolve_link(model);
  geom_names_.clear();
  geoms_.clear();
  const auto& contact = std::get<description::ContactSpec>(spec.details);
  for (int g = 0; g < model.geom_count(); ++g) geom_names_.push_back(gazebo_name(model, g));
  // The shapes the description placed (an SDF collision by its name, or a link's), else those
  // Gazebo's URDF names refer to.
  std::vector<std::pair<std::string, std::string>> wanted;  // (link, geom name or prefix)
  if (contact.targets.size() == contact.collisions.size() && !contact.targets.empty()) {
    for (std::size_t k = 0; k < contact.targets.size(); ++k) {
      const description::ContactSpec::Target& t = contact.targets[k];
      std::string name = physics_name(t.link) + "/collision/" + (t.index >= 0 ? std::to_string(t.index) : "");
      // An SDF model the world holds as an object (one shape): its geom is "box:<model>::<link>::<collision>".
      const std::string object = "box:" + physics_name(t.link) + "::" + contact.collisions[k];
      for (int g = 0; g < model.geom_count() && t.index >= 0; ++g)
        if (model.geom_name(g) == object) name = object;
      wanted.emplace_back(t.link, name);
    }
  } else {
    for (const std::string& collision : contact.collisions) {
      const std::string link = collision_link(collision);
      const std::string owner = link.empty() ? spec.link : link;
      wanted.emplace_back(owner, physics_name(owner) + "/collision/");
    }
  }
  for (std::size_t k = 0; k < wanted.size(); ++k) {
    const auto& [owner, name] = wanted[k];
    const bool prefix = name.back() == '/';
    bool found = false;
    for (int g = 0; g < model.geom_count(); ++g) {
      const std::string_view n = model.geom_name(g);
      if (prefix ? n.rfind(name, 0) != 0 : n != name) continue;
      geoms_.push_back(g);
      found = true;
    }
    if (!found) {
      const std::string what = spec.where() + ": <contact><collision>" + contact.collisions[k] +
                               "</collision> matches no collision shape of the physics (link '" + owner + "' has none)";
      // A link without shapes: its collision was a mesh the physics left out (said at start-up),
      // or it never had one; either way the sensor can report nothing, and Gazebo too runs on
      // without it. A link that does not exist is a mistake in the description.
      if (model.link_index(physics_name(owner)) >= 0) throw SensorLeftOut(what + "; the sensor is left out");
      throw SensorError(what);
    }
  }
  std::sort(geoms_.begin(), geoms_.end());
  geoms_.erase(std::unique(geoms_.begin(), geoms_.end()), geoms_.end());
}

std::unique_ptr<SensorState> ContactSensor::make_state(Rng rng) const {
  auto state = std::make_unique<ContactSensorState>();
  state->rng = std::move(rng);
  return state;
}

void ContactSensor::sample(const physics::Physics& physics, double, SensorState& base, SensorOutput& out) const {
  auto& state = static_cast<ContactSensorState&>(base);
  if (!std::holds_alternative<ContactsReading>(out)) out = ContactsReading{};
  ContactsReading& r = std::get<ContactsReading>(out);
  for (std::size_t i = 0; i < r.count; ++i) {
    ContactState& s = r.states[i];
    s.wrenches.clear();
    s.contact_positions.clear();
    s.contact_normals.clear();
    s.depths.clear();
    s.total_wrench = {};
  }
  r.count = 0;
  r.X_WL = physics.link_pose(link_);
  state.pairs.clear();
  physics.contacts(state.contacts);
  const physics::PhysicsModel& model = physics.model();
  const auto own = [&](int g) { return std::binary_search(geoms_.begin(), geoms_.end(), g); };
  for (const physics::Contact& c : state.contacts) {
    const bool a = own(c.geom_a), b = own(c.geom_b);
    if (!a && !b) continue;
    const int mine = b ? c.geom_b : c.geom_a, other = b ? c.geom_a : c.geom_b;
    // The force on our shape: MuJoCo's contact force is what a exerts on b.
    const double sign = b ? 1.0 : -1.0;
    const Vec3 F_W{sign * c.force.x, sign * c.force.y, sign * c.force.z};
    const Vec3 n_W{sign * c.normal.x, sign * c.normal.y, sign * c.normal.z};
    // As ODE's contact feedback through Gazebo: the torque about the body's centre of mass, both
    // turned into the body's frame.
    const int body = model.geom_body(mine);
    const description::Pose X_WB = physics.body_pose(body);
    const Vec3 com = physics.body_com(body);
    const Vec3 arm{c.position.x - com.x, c.position.y - com.y, c.position.z - com.z};
    const Vec3 T_W{arm.y * F_W.z - arm.z * F_W.y, arm.z * F_W.x - arm.x * F_W.z, arm.x * F_W.y - arm.y * F_W.x};
    const description::Quat q_BW = physics::inverse(X_WB).orientation;
    std::size_t k = 0;
    while (k < r.count && state.pairs[k] != std::make_pair(mine, other)) ++k;
    if (k == r.count) {
      if (r.states.size() <= k) r.states.emplace_back();
      ContactState& s = r.states[k];
      s.collision1_name = geom_names_[static_cast<std::size_t>(mine)];
      s.collision2_name = geom_names_[static_cast<std::size_t>(other)];
      state.pairs.emplace_back(mine, other);
      ++r.count;
    }
    ContactState& s = r.states[k];
    const Vec3 F = physics::rotate(q_BW, F_W), T = physics::rotate(q_BW, T_W);
    s.wrenches.push_back({F, T});
    s.total_wrench.force = {s.total_wrench.force.x + F.x, s.total_wrench.force.y + F.y, s.total_wrench.force.z + F.z};
    s.total_wrench.torque = {s.total_wrench.torque.x + T.x, s.total_wrench.torque.y + T.y,
                             s.total_wrench.torque.z + T.z};
    s.contact_positions.push_back(c.position);
    s.contact_normals.push_back(n_W);
    s.depths.push_back(c.depth);
  }
}

}  // namespace mechsim::sensors
