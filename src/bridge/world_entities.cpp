// World: Gazebo's model API over the world's entities: states in reference frames, properties,
// forces, physics properties (world.hpp).
#include <algorithm>
#include <cmath>

#include "bridge/world.hpp"
#include "physics/transform.hpp"

namespace mechsim::bridge {

namespace {

using description::Pose;
using description::Vec3;

constexpr double kMaxStateValue = 1e10;  // MuJoCo's mjMAXVAL

Vec3 sub(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }

// E's state relative to R (both in the world frame).
EntityState relative(const EntityState& R, const EntityState& E) {
  const description::Quat R_inv = physics::quat_conjugate(R.pose.orientation);
  EntityState out;
  out.pose = physics::compose(physics::inverse(R.pose), E.pose);
  out.linear = physics::rotate(R_inv, sub(E.linear, R.linear));
  out.angular = physics::rotate(R_inv, sub(E.angular, R.angular));
  return out;
}

// E given relative to R, in the world frame (the twist rotated into the world; R's motion is not
// added, as gazebo_ros sets it).
EntityState absolute(const EntityState& R, const EntityState& E) {
  EntityState out;
  out.pose = physics::compose(R.pose, E.pose);
  out.linear = physics::rotate(R.pose.orientation, E.linear);
  out.angular = physics::rotate(R.pose.orientation, E.angular);
  return out;
}

// Why a requested pose and twist cannot be set ("" when they can): a non-finite number, a value
// at or beyond MuJoCo's mjMAXVAL (1e10: what its step takes for a diverged state), or a zero
// quaternion (no orientation; spawn refuses it too). Checked before composing with a frame, which
// would normalise a zero quaternion into the identity.
std::string unusable_state(const EntityState& s) {
  const Pose& p = s.pose;
  const double values[] = {p.position.x,    p.position.y,    p.position.z, p.orientation.w, p.orientation.x,
                           p.orientation.y, p.orientation.z, s.linear.x,   s.linear.y,      s.linear.z,
                           s.angular.x,     s.angular.y,     s.angular.z};
  for (const double v : values) {
    if (!std::isfinite(v)) return "the pose and twist must be finite";
    if (std::abs(v) >= kMaxStateValue) return "the pose and twist must be below 1e10 (m, m/s, rad/s) in magnitude";
  }
  const auto& q = p.orientation;
  if (std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z) < 1e-9) return "the orientation quaternion is zero";
  return "";
}

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// "model::name" -> {model, name}; a name without a scope -> {"", name}.
std::pair<std::string, std::string> split_scope(const std::string& scoped) {
  const auto cut = scoped.rfind("::");
  if (cut == std::string::npos) return {"", scoped};
  return {scoped.substr(0, cut), scoped.substr(cut + 2)};
}

BridgeResult refused(std::string why) { return {false, std::move(why)}; }

}  // namespace

bool World::resolve(const std::string& name, Entity& out, std::string* status) const {
  out = Entity{};
  if (name.empty() || name == "world" || name == "map") return true;
  for (std::size_t i = 0; i < world_models_.size(); ++i) {
    const std::string& m = world_models_[i];
    if (name == m || name.rfind(m + "::", 0) == 0) {
      out.kind = Entity::Kind::WorldModel;
      out.model = i;
      return true;
    }
  }
  for (const Model& m : models_) {
    if (name == m.info.name) {
      out.kind = Entity::Kind::Model;
      out.bridge = m.bridge.get();
      return true;
    }
  }
  // "model::link", or a link alone: the first model (in spawn order) that has it.
  const auto [model, link] = split_scope(name);
  for (const Model& m : models_) {
    if (!model.empty() && model != m.info.name) continue;
    for (const std::string& l : m.bridge->link_names()) {
      if (l == link) {
        out.kind = Entity::Kind::ModelLink;
        out.link = link;
        out.bridge = m.bridge.get();
        return true;
      }
    }
  }
  std::string all;
  for (const std::string& m : world_models_) all += (all.empty() ? "" : ", ") + m;
  for (const Model& m : models_) all += (all.empty() ? "" : ", ") + m.info.name;
  *status = "no entity '" + name + "' in the world (models: " + all + ")";
  return false;
}

bool World::entity_state(const Entity& e, EntityState& out, std::string* status) const {
  out = EntityState{};
  if (e.kind == Entity::Kind::World) return true;
  if (e.kind == Entity::Kind::WorldModel) {
    // The SDF world's moving models move in the world's physics; static ones (and the ground
    // plane of mechsim's worlds) are where the world puts them.
    if (e.model >= sdf_model_count_) {
      out.pose = world_model_poses_[e.model];
      return true;
    }
    const BridgeResult r = world_->world_model_state(e.model, out);
    if (!r.ok) *status = r.error;
    return r.ok;
  }
  const BridgeResult r = e.bridge->link_state(e.kind == Entity::Kind::Model ? std::string() : e.link, out);
  if (!r.ok) *status = r.error;
  return r.ok;
}

BridgeResult World::model_state(const std::string& model, const std::string& relative_to, EntityState& out) const {
  std::lock_guard<std::mutex> lock(mutex_);
  Entity m, frame;
  EntityState X_WM, X_WR;
  std::string why;
  if (!resolve(model, m, &why) || !resolve(relative_to, frame, &why) || !entity_state(m, X_WM, &why) ||
      !entity_state(frame, X_WR, &why))
    return refused(why);
  if (m.kind == Entity::Kind::World) return refused("model_name is empty");
  out = relative(X_WR, X_WM);
  return {};
}

BridgeResult World::link_state(const std::string& link, const std::string& reference_frame, EntityState& out) const {
  std::lock_guard<std::mutex> lock(mutex_);
  Entity l, frame;
  EntityState X_WL, X_WR;
  std::string why;
  if (!resolve(link, l, &why) || !resolve(reference_frame, frame, &why) || !entity_state(l, X_WL, &why) ||
      !entity_state(frame, X_WR, &why))
    return refused(why);
  out = relative(X_WR, X_WL);
  return {};
}

BridgeResult World::set_root(const Entity& target, const std::string& frame_name, const EntityState& given) {
  if (target.kind == Entity::Kind::World) return refused("the world itself does not move");
  if (target.kind == Entity::Kind::WorldModel && target.model >= sdf_model_count_)
    return refused("model '" + world_models_[target.model] + "' is static, part of the world");
  if (target.kind == Entity::Kind::ModelLink && target.link != target.bridge->robot().root_link) {
    return refused("link '" + target.link + "' is moved by its joints: mechsim sets a robot's root link (" +
                   target.bridge->robot().root_link + ", the model's pose) only");
  }
  // The request's own numbers first: 1e300 m went through to MuJoCo, which took it for a diverged
  // simulation and stopped it.
  if (const std::string why = unusable_state(given); !why.empty()) return refused(why);
  Entity frame;
  EntityState X_WR;
  std::string why;
  if (!resolve(frame_name, frame, &why) || !entity_state(frame, X_WR, &why)) return refused(why);
  return target.kind == Entity::Kind::WorldModel ? world_->set_world_model_state(target.model, absolute(X_WR, given))
                                                 : target.bridge->set_root_state(absolute(X_WR, given));
}

BridgeResult World::set_model_state(const std::string& model, const std::string& reference_frame,
                                    const EntityState& state) {
  std::lock_guard<std::mutex> lock(mutex_);
  Entity m;
  std::string why;
  if (!resolve(model, m, &why)) return refused(why);
  return set_root(m, reference_frame, state);
}

BridgeResult World::set_link_state(const std::string& link, const std::string& reference_frame,
                                   const EntityState& state) {
  std::lock_guard<std::mutex> lock(mutex_);
  Entity l;
  std::string why;
  if (!resolve(link, l, &why)) return refused(why);
  return set_root(l, reference_frame, state);
}

BridgeResult World::model_properties(const std::string& model, ModelProperties& out) const {
  std::lock_guard<std::mutex> lock(mutex_);
  out = ModelProperties{};
  Entity m;
  std::string why;
  if (!resolve(model, m, &why)) return refused(why);
  if (m.kind == Entity::Kind::World || m.kind == Entity::Kind::ModelLink) return refused("'" + model + "' is no model");
  if (m.kind == Entity::Kind::WorldModel) {
    out.is_static = true;
    return {};
  }
  const description::RobotModel& robot = m.bridge->robot();
  out.canonical_body_name = robot.root_link;
  out.body_names = m.bridge->link_names();
  for (const description::Link& link : robot.links)
    for (std::size_t i = 0; i < link.collisions.size(); ++i)
      out.geom_names.push_back(link.collisions[i].name.empty() ? link.name + "_collision_" + std::to_string(i)
                                                                : link.collisions[i].name);
  for (const description::Joint& joint : robot.joints)
    if (joint.type != description::JointType::Fixed) out.joint_names.push_back(joint.name);
  return {};
}

SimBridge* World::joint_owner(const std::string& scoped, std::string& joint, std::string* status) const {
  const auto [model, name] = split_scope(scoped);
  for (const Model& m : models_) {
    if ((model.empty() || model == m.info.name) && m.bridge->robot().joint(name) != nullptr) {
      joint = name;
      return m.bridge.get();
    }
  }
  *status = "no joint '" + scoped + "' in the world";
  return nullptr;
}

BridgeResult World::joint_properties(const std::string& joint, JointPropertiesData& out) const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::string name, why;
  SimBridge* owner = joint_owner(joint, name, &why);
  if (owner == nullptr) return refused(why);
  return owner->joint_properties(name, out);
}

BridgeResult World::link_properties(const std::string& link, LinkPropertiesData& out) const {
  std::lock_guard<std::mutex> lock(mutex_);
  Entity l;
  std::string why;
  if (!resolve(link, l, &why)) return refused(why);
  if (l.kind != Entity::Kind::ModelLink) return refused("'" + link + "' is no link of a robot");
  return l.bridge->link_properties(l.link, out);
}

PhysicsProperties World::physics_properties() const {
  std::lock_guard<std::mutex> lock(mutex_);
  PhysicsProperties p;
  p.time_step = options_.period;
  p.paused = world_ ? world_->paused() : options_.paused;
  // gazebo's real_time_update_rate: steps per wall second (0: as fast as possible).
  p.max_update_rate = (world_ ? world_->real_time_factor() : options_.real_time_factor) / options_.period;
  p.gravity = world_ ? world_->gravity() : gravity_;
  return p;
}

BridgeResult World::set_physics_properties(const PhysicsProperties& p) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!std::isfinite(p.time_step) || std::abs(p.time_step - options_.period) > 1e-12) {
    return refused("time_step " + std::to_string(p.time_step) + " s: mechsim steps at " +
                   std::to_string(options_.period) + " s (its controllers' tick), unchanged");
  }
  if (!std::isfinite(p.max_update_rate) || p.max_update_rate < 0.0)
    return refused("max_update_rate must be finite and >= 0 (0: as fast as possible)");
  if (!finite(p.gravity)) return refused("gravity must be finite");
  // The world's: every model's.
  world_->set_real_time_factor(p.max_update_rate * options_.period);
  const BridgeResult r = world_->set_gravity(p.gravity);
  if (r.ok) gravity_ = p.gravity;
  return r;
}

BridgeResult World::set_model_configuration(const std::string& model, const std::vector<std::string>& joints,
                                            const std::vector<double>& positions) {
  std::lock_guard<std::mutex> lock(mutex_);
  const Model* m = find(model);
  if (m == nullptr) {
    const bool world_model = std::find(world_models_.begin(), world_models_.end(), model) != world_models_.end();
    return refused(world_model ? "model '" + model + "' is static, part of the world" : "no model '" + model + "' in the world");
  }
  return m->bridge->set_joint_positions(joints, positions);
}

BridgeResult World::apply_body_wrench(const std::string& body, const std::string& reference_frame, const Vec3& force,
                                      const Vec3& torque, const Vec3& reference_point, double start, double duration) {
  std::lock_guard<std::mutex> lock(mutex_);
  Entity b, frame;
  EntityState X_WF;
  std::string why;
  if (!resolve(body, b, &why) || !resolve(reference_frame, frame, &why) || !entity_state(frame, X_WF, &why))
    return refused(why);
  if (b.kind != Entity::Kind::ModelLink && b.kind != Entity::Kind::Model) return refused("'" + body + "' is no body of a robot");
  const std::string link = b.kind == Entity::Kind::Model ? b.bridge->robot().root_link : b.link;
  const auto& q = X_WF.pose.orientation;
  // reference_point: where the force acts, from the body's centre of mass, along the reference
  // frame's axes (gazebo_ros adds reference_point x force to the torque).
  return b.bridge->apply_link_wrench(link, physics::rotate(q, force), physics::rotate(q, torque),
                                     physics::rotate(q, reference_point), start, duration);
}

BridgeResult World::apply_joint_effort(const std::string& joint, double effort, double start, double duration) {
  std::lock_guard<std::mutex> lock(mutex_);
  std::string name, why;
  SimBridge* owner = joint_owner(joint, name, &why);
  if (owner == nullptr) return refused(why);
  return owner->apply_joint_effort(name, effort, start, duration);
}

BridgeResult World::clear_body_wrenches(const std::string& body) {
  std::lock_guard<std::mutex> lock(mutex_);
  Entity b;
  std::string why;
  if (!resolve(body, b, &why)) return refused(why);
  if (b.kind != Entity::Kind::ModelLink && b.kind != Entity::Kind::Model) return refused("no body '" + body + "'");
  return b.bridge->clear_link_wrenches(b.kind == Entity::Kind::Model ? b.bridge->robot().root_link : b.link);
}

BridgeResult World::clear_joint_forces(const std::string& joint) {
  std::lock_guard<std::mutex> lock(mutex_);
  std::string name, why;
  SimBridge* owner = joint_owner(joint, name, &why);
  if (owner == nullptr) return refused(why);
  return owner->clear_joint_efforts(name);
}

BridgeResult World::set_joint_properties(const std::string& joint, const JointPropertyChange& change) {
  std::lock_guard<std::mutex> lock(mutex_);
  std::string name, why;
  SimBridge* owner = joint_owner(joint, name, &why);
  if (owner == nullptr) return refused(why);
  return owner->set_joint_properties(name, change);
}

BridgeResult World::set_link_properties(const std::string& link, const LinkPropertiesData& properties) {
  std::lock_guard<std::mutex> lock(mutex_);
  Entity l;
  std::string why;
  if (!resolve(link, l, &why)) return refused(why);
  if (l.kind != Entity::Kind::ModelLink && l.kind != Entity::Kind::Model) return refused("'" + link + "' is no link of a robot");
  return l.bridge->set_link_properties(l.kind == Entity::Kind::Model ? l.bridge->robot().root_link : l.link, properties);
}

std::vector<std::string> World::light_names() const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<std::string> names;
  for (const LightProperties& l : lights_) names.push_back(l.name);
  return names;
}

BridgeResult World::light_properties(const std::string& light, LightProperties& out) const {
  std::lock_guard<std::mutex> lock(mutex_);
  for (const LightProperties& l : lights_) {
    if (l.name == light) {
      out = l;
      return {};
    }
  }
  return refused("light '" + light + "' not found");
}

BridgeResult World::set_light_properties(const LightProperties& properties) {
  std::lock_guard<std::mutex> lock(mutex_);
  for (double v : properties.diffuse)
    if (!std::isfinite(v)) return refused("diffuse must be finite");
  for (double v : properties.specular)
    if (!std::isfinite(v)) return refused("specular must be finite");
  if (!std::isfinite(properties.attenuation_constant) || !std::isfinite(properties.attenuation_linear) ||
      !std::isfinite(properties.attenuation_quadratic) || !finite(properties.direction) ||
      !finite(properties.pose.position))
    return refused("attenuation, direction and pose must be finite");
  for (LightProperties& l : lights_) {
    if (l.name == properties.name) {
      const std::string type = l.type;
      l = properties;
      l.type = type;
      return {};
    }
  }
  return refused("light '" + properties.name + "' not found");
}

BridgeResult World::delete_light(const std::string& light) {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = std::find_if(lights_.begin(), lights_.end(), [&](const LightProperties& l) { return l.name == light; });
  if (it == lights_.end()) return refused("Requested light " + light + " not found!");
  lights_.erase(it);
  return {};
}

void World::model_states_now(std::vector<NamedState>& out) {
  // The loop thread: models_ changes only under models_mutex_ (spawn, delete).
  std::lock_guard<std::mutex> lock(models_mutex_);
  world_->world_model_states_now(world_scratch_);
  out.resize(world_models_.size() + models_.size());
  for (std::size_t i = 0; i < world_models_.size(); ++i) {
    out[i].name = world_models_[i];
    // An SDF world's models where the physics has them; the ground plane of mechsim's worlds at
    // the origin.
    out[i].state = i < world_scratch_.size() ? world_scratch_[i] : EntityState{};
  }
  for (std::size_t r = 0; r < models_.size(); ++r) {
    NamedState& s = out[world_models_.size() + r];
    s.name = models_[r].info.name;
    models_[r].bridge->model_state_now(s.state);
  }
}

void World::link_states_now(std::vector<NamedState>& out) {
  std::lock_guard<std::mutex> lock(models_mutex_);
  link_scratch_.resize(models_.size());
  std::size_t count = 0;
  for (std::size_t r = 0; r < models_.size(); ++r) {
    models_[r].bridge->link_states_now(link_scratch_[r]);
    count += link_scratch_[r].size();
  }
  out.resize(count);
  std::size_t k = 0;
  for (std::size_t r = 0; r < models_.size(); ++r) {
    const std::vector<std::string>& names = models_[r].bridge->link_names();
    for (std::size_t i = 0; i < names.size(); ++i, ++k) {
      out[k].name = models_[r].info.name + "::" + names[i];
      out[k].state = link_scratch_[r][i];
    }
  }
}

}  // namespace mechsim::bridge
