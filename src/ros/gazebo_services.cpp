// GazeboWorld: gazebo_ros' model state, property and force services (gazebo_world.hpp).
//
// Names as gazebo_ros takes them: a model by its name, a link as "model::link" (a link name
// alone is taken when the robot has it), a joint as "joint" or "model::joint". A reference frame
// "" or "world" is the world; a model's frame is its root link's. States relative to a frame R:
// pose X_RE, twist (v_E - v_R, w_E - w_R) expressed in R, as gazebo_ros computes them.
// Every refusal answers success = false with why, and leaves the simulation as it was.
#include <gazebo_msgs/ApplyBodyWrench.h>
#include <gazebo_msgs/ApplyJointEffort.h>
#include <gazebo_msgs/BodyRequest.h>
#include <gazebo_msgs/GetJointProperties.h>
#include <gazebo_msgs/GetLinkProperties.h>
#include <gazebo_msgs/GetLinkState.h>
#include <gazebo_msgs/GetModelProperties.h>
#include <gazebo_msgs/GetModelState.h>
#include <gazebo_msgs/GetPhysicsProperties.h>
#include <gazebo_msgs/GetWorldProperties.h>
#include <gazebo_msgs/JointRequest.h>
#include <gazebo_msgs/SetLinkState.h>
#include <gazebo_msgs/SetModelConfiguration.h>
#include <gazebo_msgs/SetModelState.h>
#include <gazebo_msgs/SetPhysicsProperties.h>

#include <cmath>

#include "physics/transform.hpp"
#include "ros/gazebo_world.hpp"

namespace mechsim::ros {

namespace {

using description::Pose;
using description::Vec3;

constexpr double kMaxStateValue = 1e10;  // MuJoCo's mjMAXVAL

Pose pose_from(const geometry_msgs::Pose& p) {
  return {{p.position.x, p.position.y, p.position.z}, {p.orientation.w, p.orientation.x, p.orientation.y, p.orientation.z}};
}

geometry_msgs::Pose to_msg(const Pose& p) {
  geometry_msgs::Pose m;
  m.position.x = p.position.x;
  m.position.y = p.position.y;
  m.position.z = p.position.z;
  m.orientation.w = p.orientation.w;
  m.orientation.x = p.orientation.x;
  m.orientation.y = p.orientation.y;
  m.orientation.z = p.orientation.z;
  return m;
}

Vec3 vec_from(const geometry_msgs::Vector3& v) { return {v.x, v.y, v.z}; }

geometry_msgs::Vector3 to_msg(const Vec3& v) {
  geometry_msgs::Vector3 m;
  m.x = v.x;
  m.y = v.y;
  m.z = v.z;
  return m;
}

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
// quaternion (no orientation; spawn refuses it too).
std::string unusable_state(const geometry_msgs::Pose& p, const geometry_msgs::Twist& t) {
  const double values[] = {p.position.x,    p.position.y,    p.position.z,  p.orientation.w, p.orientation.x,
                           p.orientation.y, p.orientation.z, t.linear.x,    t.linear.y,      t.linear.z,
                           t.angular.x,     t.angular.y,     t.angular.z};
  for (const double v : values) {
    if (!std::isfinite(v)) return "the pose and twist must be finite";
    if (std::abs(v) >= kMaxStateValue) return "the pose and twist must be below 1e10 (m, m/s, rad/s) in magnitude";
  }
  const auto& q = p.orientation;
  if (std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z) < 1e-9) return "the orientation quaternion is zero";
  return "";
}

// "model::name" -> {model, name}; a name without a scope -> {"", name}.
std::pair<std::string, std::string> split_scope(const std::string& scoped) {
  const auto cut = scoped.rfind("::");
  if (cut == std::string::npos) return {"", scoped};
  return {scoped.substr(0, cut), scoped.substr(cut + 2)};
}

}  // namespace

struct GazeboWorld::Entity {
  enum class Kind { World, WorldModel, Robot, RobotLink };
  Kind kind = Kind::World;
  std::string link;  // RobotLink: the URDF link
  std::size_t model = 0;  // WorldModel: index into world_models_
  SimNode* robot = nullptr;  // Robot, RobotLink: the robot's node
  // The entity's state in the world frame (the robot's, and the world's moving models while a
  // robot's physics holds them, through the robot's loop thread).
  bool state(const GazeboWorld& w, EntityState& out, std::string* status) const {
    out = EntityState{};
    if (kind == Kind::World) return true;
    if (kind == Kind::WorldModel) {
      // Moving models move only in a robot's physics; without one they are where the SDF put them.
      if (w.host() == nullptr || model >= w.sdf_model_count_) {
        out.pose = w.world_model_poses_[model];
        return true;
      }
      const BridgeResult r = w.host()->bridge().world_model_state(model, out);
      if (!r.ok) *status = r.error;
      return r.ok;
    }
    const BridgeResult r = robot->bridge().link_state(kind == Kind::Robot ? std::string() : link, out);
    if (!r.ok) *status = r.error;
    return r.ok;
  }
};

bool GazeboWorld::resolve(const std::string& name, Entity& out, std::string* status) const {
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
  for (const Robot& r : robots_) {
    if (name == r.name) {
      out.kind = Entity::Kind::Robot;
      out.robot = r.node.get();
      return true;
    }
  }
  // "model::link", or a link alone: the first robot (in spawn order) that has it.
  const auto [model, link] = split_scope(name);
  for (const Robot& r : robots_) {
    if (!model.empty() && model != r.name) continue;
    for (const std::string& l : r.node->bridge().link_names()) {
      if (l == link) {
        out.kind = Entity::Kind::RobotLink;
        out.link = link;
        out.robot = r.node.get();
        return true;
      }
    }
  }
  *status = "no entity '" + name + "' in the world (models: " + [&] {
    std::string all;
    for (const std::string& m : model_names()) all += (all.empty() ? "" : ", ") + m;
    return all;
  }() + ")";
  return false;
}

std::vector<std::string> GazeboWorld::model_names() const {
  std::vector<std::string> names = world_models_;
  for (const Robot& r : robots_) names.push_back(r.name);
  return names;
}

void GazeboWorld::advertise_model_services() {
  // A joint of a robot ("model::joint", or "joint": the first robot that has it) and the robot's
  // node; {nullptr, ""} when none has it.
  auto joint_of = [this](const std::string& scoped, std::string* status) -> std::pair<SimNode*, std::string> {
    const auto [model, joint] = split_scope(scoped);
    for (const Robot& r : robots_) {
      if ((model.empty() || model == r.name) && r.node->bridge().robot().joint(joint) != nullptr) return {r.node.get(), joint};
    }
    *status = "no joint '" + scoped + "' in the world";
    return {nullptr, ""};
  };
  auto robot_named = [this](const std::string& model, std::string* status) -> SimNode* {
    if (const Robot* r = find_robot(model)) return r->node.get();
    bool world_model = false;
    for (const std::string& m : world_models_) world_model = world_model || m == model;
    *status = world_model ? "model '" + model + "' is static, part of the world" : "no model '" + model + "' in the world";
    return nullptr;
  };

  using GetModelState = gazebo_msgs::GetModelState;
  services_.push_back(root_nh_.advertiseService<GetModelState::Request, GetModelState::Response>(
      "/gazebo/get_model_state", [this](GetModelState::Request& req, GetModelState::Response& res) {
        std::lock_guard<std::mutex> lock(mutex_);
        Entity model, frame;
        EntityState X_WM, X_WR;
        res.success = resolve(req.model_name, model, &res.status_message) &&
                      resolve(req.relative_entity_name, frame, &res.status_message) &&
                      model.state(*this, X_WM, &res.status_message) && frame.state(*this, X_WR, &res.status_message);
        if (res.success && model.kind == Entity::Kind::World) {
          res.success = false;
          res.status_message = "model_name is empty";
        }
        if (!res.success) return true;
        const EntityState s = relative(X_WR, X_WM);
        res.header.stamp = ::ros::Time(time());
        res.header.frame_id = req.relative_entity_name;
        res.pose = to_msg(s.pose);
        res.twist.linear = to_msg(s.linear);
        res.twist.angular = to_msg(s.angular);
        res.status_message = "GetModelState: got properties";
        return true;
      }));

  using GetLinkState = gazebo_msgs::GetLinkState;
  services_.push_back(root_nh_.advertiseService<GetLinkState::Request, GetLinkState::Response>(
      "/gazebo/get_link_state", [this](GetLinkState::Request& req, GetLinkState::Response& res) {
        std::lock_guard<std::mutex> lock(mutex_);
        Entity link, frame;
        EntityState X_WL, X_WR;
        res.success = resolve(req.link_name, link, &res.status_message) &&
                      resolve(req.reference_frame, frame, &res.status_message) &&
                      link.state(*this, X_WL, &res.status_message) && frame.state(*this, X_WR, &res.status_message);
        if (!res.success) return true;
        const EntityState s = relative(X_WR, X_WL);
        res.link_state.link_name = req.link_name;
        res.link_state.reference_frame = req.reference_frame;
        res.link_state.pose = to_msg(s.pose);
        res.link_state.twist.linear = to_msg(s.linear);
        res.link_state.twist.angular = to_msg(s.angular);
        res.status_message = "GetLinkState: got state";
        return true;
      }));

  // Sets the robot's root from a state given in `frame` (model or its root link).
  auto set_root = [this](const Entity& target, const std::string& frame_name, const geometry_msgs::Pose& pose,
                         const geometry_msgs::Twist& twist, std::string* status) {
    if (target.kind == Entity::Kind::World) {
      *status = "the world itself does not move";
      return false;
    }
    if (target.kind == Entity::Kind::WorldModel && (host() == nullptr || target.model >= sdf_model_count_)) {
      *status = host() != nullptr ? "model '" + world_models_[target.model] + "' is static, part of the world"
                                  : "the world's models move in a robot's physics: spawn a robot first";
      return false;
    }
    if (target.kind == Entity::Kind::RobotLink && target.link != target.robot->bridge().robot().root_link) {
      *status = "link '" + target.link + "' is moved by its joints: mechsim sets a robot's root link (" +
                target.robot->bridge().robot().root_link + ", the model's pose) only";
      return false;
    }
    // The request's own numbers first: composing with the frame normalises the orientation, which
    // turned a zero quaternion into the identity, and 1e300 m went through to MuJoCo, which took it
    // for a diverged simulation and stopped it.
    if (const std::string why = unusable_state(pose, twist); !why.empty()) {
      *status = why;
      return false;
    }
    Entity frame;
    EntityState X_WR;
    if (!resolve(frame_name, frame, status) || !frame.state(*this, X_WR, status)) return false;
    EntityState given;
    given.pose = pose_from(pose);
    given.linear = vec_from(twist.linear);
    given.angular = vec_from(twist.angular);
    const BridgeResult r = target.kind == Entity::Kind::WorldModel
                               ? host()->bridge().set_world_model_state(target.model, absolute(X_WR, given))
                               : target.robot->bridge().set_root_state(absolute(X_WR, given));
    if (!r.ok) *status = r.error;
    return r.ok;
  };

  using SetModelState = gazebo_msgs::SetModelState;
  services_.push_back(root_nh_.advertiseService<SetModelState::Request, SetModelState::Response>(
      "/gazebo/set_model_state", [this, set_root](SetModelState::Request& req, SetModelState::Response& res) {
        std::lock_guard<std::mutex> lock(mutex_);
        const gazebo_msgs::ModelState& s = req.model_state;
        Entity model;
        res.success = resolve(s.model_name, model, &res.status_message) &&
                      set_root(model, s.reference_frame, s.pose, s.twist, &res.status_message);
        if (res.success) res.status_message = "SetModelState: set model state done";
        return true;
      }));
  model_state_sub_ = root_nh_.subscribe<gazebo_msgs::ModelState>(
      "/gazebo/set_model_state", 10, [this, set_root](const gazebo_msgs::ModelState::ConstPtr& s) {
        std::lock_guard<std::mutex> lock(mutex_);
        Entity model;
        std::string status;
        if (!resolve(s->model_name, model, &status) || !set_root(model, s->reference_frame, s->pose, s->twist, &status)) {
          ROS_WARN_STREAM("mechsim: /gazebo/set_model_state: " << status);
        }
      });

  using SetLinkState = gazebo_msgs::SetLinkState;
  services_.push_back(root_nh_.advertiseService<SetLinkState::Request, SetLinkState::Response>(
      "/gazebo/set_link_state", [this, set_root](SetLinkState::Request& req, SetLinkState::Response& res) {
        std::lock_guard<std::mutex> lock(mutex_);
        const gazebo_msgs::LinkState& s = req.link_state;
        Entity link;
        res.success = resolve(s.link_name, link, &res.status_message) &&
                      set_root(link, s.reference_frame, s.pose, s.twist, &res.status_message);
        if (res.success) res.status_message = "SetLinkState: set link state done";
        return true;
      }));

  using GetWorld = gazebo_msgs::GetWorldProperties;
  services_.push_back(root_nh_.advertiseService<GetWorld::Request, GetWorld::Response>(
      "/gazebo/get_world_properties", [this](GetWorld::Request&, GetWorld::Response& res) {
        std::lock_guard<std::mutex> lock(mutex_);
        res.sim_time = time();
        res.model_names = model_names();
        res.rendering_enabled = false;
        res.success = true;
        res.status_message = "GetWorldProperties: got properties";
        return true;
      }));

  using GetModel = gazebo_msgs::GetModelProperties;
  services_.push_back(root_nh_.advertiseService<GetModel::Request, GetModel::Response>(
      "/gazebo/get_model_properties", [this](GetModel::Request& req, GetModel::Response& res) {
        std::lock_guard<std::mutex> lock(mutex_);
        Entity model;
        res.success = resolve(req.model_name, model, &res.status_message);
        if (res.success && (model.kind == Entity::Kind::World || model.kind == Entity::Kind::RobotLink)) {
          res.success = false;
          res.status_message = "'" + req.model_name + "' is no model";
        }
        if (!res.success) return true;
        if (model.kind == Entity::Kind::WorldModel) {
          res.is_static = true;
        } else {
          const description::RobotModel& robot = model.robot->bridge().robot();
          res.canonical_body_name = robot.root_link;
          res.body_names = model.robot->bridge().link_names();
          for (const description::Link& link : robot.links)
            for (std::size_t i = 0; i < link.collisions.size(); ++i)
              res.geom_names.push_back(link.collisions[i].name.empty() ? link.name + "_collision_" + std::to_string(i)
                                                                        : link.collisions[i].name);
          for (const description::Joint& joint : robot.joints)
            if (joint.type != description::JointType::Fixed) res.joint_names.push_back(joint.name);
          res.is_static = false;
        }
        res.status_message = "GetModelProperties: got properties";
        return true;
      }));

  using GetJoint = gazebo_msgs::GetJointProperties;
  services_.push_back(root_nh_.advertiseService<GetJoint::Request, GetJoint::Response>(
      "/gazebo/get_joint_properties", [this, joint_of](GetJoint::Request& req, GetJoint::Response& res) {
        std::lock_guard<std::mutex> lock(mutex_);
        const auto [robot, joint] = joint_of(req.joint_name, &res.status_message);
        res.success = robot != nullptr;
        if (!res.success) return true;
        JointPropertiesData p;
        const BridgeResult r = robot->bridge().joint_properties(joint, p);
        res.success = r.ok;
        if (!r.ok) {
          res.status_message = r.error;
          return true;
        }
        res.type = static_cast<std::uint8_t>(p.type);
        res.damping = {p.damping};
        res.position = {p.position};
        res.rate = {p.rate};
        res.status_message = "GetJointProperties: got properties";
        return true;
      }));

  using GetLink = gazebo_msgs::GetLinkProperties;
  services_.push_back(root_nh_.advertiseService<GetLink::Request, GetLink::Response>(
      "/gazebo/get_link_properties", [this](GetLink::Request& req, GetLink::Response& res) {
        std::lock_guard<std::mutex> lock(mutex_);
        Entity link;
        res.success = resolve(req.link_name, link, &res.status_message);
        if (res.success && link.kind != Entity::Kind::RobotLink) {
          res.success = false;
          res.status_message = "'" + req.link_name + "' is no link of a robot";
        }
        if (!res.success) return true;
        LinkPropertiesData p;
        const BridgeResult r = link.robot->bridge().link_properties(link.link, p);
        res.success = r.ok;
        res.status_message = r.ok ? "GetLinkProperties: got properties" : r.error;
        res.com = to_msg(p.com);
        res.gravity_mode = p.gravity_mode;
        res.mass = p.mass;
        res.ixx = p.ixx, res.ixy = p.ixy, res.ixz = p.ixz, res.iyy = p.iyy, res.iyz = p.iyz, res.izz = p.izz;
        return true;
      }));

  using GetPhysics = gazebo_msgs::GetPhysicsProperties;
  services_.push_back(root_nh_.advertiseService<GetPhysics::Request, GetPhysics::Response>(
      "/gazebo/get_physics_properties", [this](GetPhysics::Request&, GetPhysics::Response& res) {
        std::lock_guard<std::mutex> lock(mutex_);
        res.time_step = options_.period;
        res.pause = paused();
        // gazebo's real_time_update_rate: steps per wall second (0: as fast as possible).
        res.max_update_rate = real_time_factor_.load() / options_.period;
        res.gravity = to_msg(host() != nullptr ? host()->bridge().gravity() : gravity_);
        res.success = true;
        res.status_message = "GetPhysicsProperties: mechsim steps MuJoCo; ode_config is not used";
        return true;
      }));

  using SetPhysics = gazebo_msgs::SetPhysicsProperties;
  services_.push_back(root_nh_.advertiseService<SetPhysics::Request, SetPhysics::Response>(
      "/gazebo/set_physics_properties", [this](SetPhysics::Request& req, SetPhysics::Response& res) {
        std::lock_guard<std::mutex> lock(mutex_);
        const Vec3 g = vec_from(req.gravity);
        res.success = false;
        if (!std::isfinite(req.time_step) || std::abs(req.time_step - options_.period) > 1e-12) {
          res.status_message = "time_step " + std::to_string(req.time_step) + " s: mechsim steps at " +
                               std::to_string(options_.period) + " s (its controllers' tick), unchanged";
        } else if (!std::isfinite(req.max_update_rate) || req.max_update_rate < 0.0) {
          res.status_message = "max_update_rate must be finite and >= 0 (0: as fast as possible)";
        } else if (!std::isfinite(g.x) || !std::isfinite(g.y) || !std::isfinite(g.z)) {
          res.status_message = "gravity must be finite";
        } else {
          const double factor = req.max_update_rate * options_.period;
          real_time_factor_.store(factor);
          gravity_ = g;
          if (host() != nullptr) {  // the world's: every robot's
            host()->bridge().set_real_time_factor(factor);
            const BridgeResult r = host()->bridge().set_gravity(g);
            res.status_message = r.error;
            res.success = r.ok;
          } else {
            res.success = true;
          }
          if (res.success) res.status_message = "SetPhysicsProperties: physics properties set (ode_config not used)";
        }
        return true;
      }));

  using SetConfig = gazebo_msgs::SetModelConfiguration;
  services_.push_back(root_nh_.advertiseService<SetConfig::Request, SetConfig::Response>(
      "/gazebo/set_model_configuration",
      [this, robot_named](SetConfig::Request& req, SetConfig::Response& res) {
        std::lock_guard<std::mutex> lock(mutex_);
        SimNode* robot = robot_named(req.model_name, &res.status_message);
        res.success = robot != nullptr;
        if (!res.success) return true;
        const BridgeResult r = robot->bridge().set_joint_positions(req.joint_names, req.joint_positions);
        res.success = r.ok;
        res.status_message = r.ok ? "SetModelConfiguration: success" : r.error;
        return true;
      }));

  using Wrench = gazebo_msgs::ApplyBodyWrench;
  services_.push_back(root_nh_.advertiseService<Wrench::Request, Wrench::Response>(
      "/gazebo/apply_body_wrench", [this](Wrench::Request& req, Wrench::Response& res) {
        std::lock_guard<std::mutex> lock(mutex_);
        Entity body, frame;
        EntityState X_WF;
        res.success = resolve(req.body_name, body, &res.status_message) &&
                      resolve(req.reference_frame, frame, &res.status_message) &&
                      frame.state(*this, X_WF, &res.status_message);
        if (res.success && body.kind != Entity::Kind::RobotLink && body.kind != Entity::Kind::Robot) {
          res.success = false;
          res.status_message = "'" + req.body_name + "' is no body of a robot";
        }
        if (!res.success) return true;
        const std::string link = body.kind == Entity::Kind::Robot ? body.robot->bridge().robot().root_link : body.link;
        const auto& q = X_WF.pose.orientation;
        const Vec3 f = physics::rotate(q, vec_from(req.wrench.force));
        const Vec3 t = physics::rotate(q, vec_from(req.wrench.torque));
        // reference_point: where the force acts, from the body's centre of mass, along the
        // reference frame's axes (gazebo_ros adds reference_point x force to the torque).
        const Vec3 offset = physics::rotate(q, Vec3{req.reference_point.x, req.reference_point.y, req.reference_point.z});
        const BridgeResult r = body.robot->bridge().apply_link_wrench(link, f, t, offset, req.start_time.toSec(),
                                                                      req.duration.toSec());
        res.success = r.ok;
        res.status_message = r.ok ? "ApplyBodyWrench: success" : r.error;
        return true;
      }));

  using Effort = gazebo_msgs::ApplyJointEffort;
  services_.push_back(root_nh_.advertiseService<Effort::Request, Effort::Response>(
      "/gazebo/apply_joint_effort", [this, joint_of](Effort::Request& req, Effort::Response& res) {
        std::lock_guard<std::mutex> lock(mutex_);
        const auto [robot, joint] = joint_of(req.joint_name, &res.status_message);
        res.success = robot != nullptr;
        if (!res.success) return true;
        const BridgeResult r = robot->bridge().apply_joint_effort(joint, req.effort, req.start_time.toSec(),
                                                                  req.duration.toSec());
        res.success = r.ok;
        res.status_message = r.ok ? "ApplyJointEffort: effort set" : r.error;
        return true;
      }));

  using Body = gazebo_msgs::BodyRequest;
  services_.push_back(root_nh_.advertiseService<Body::Request, Body::Response>(
      "/gazebo/clear_body_wrenches", [this](Body::Request& req, Body::Response&) {
        std::lock_guard<std::mutex> lock(mutex_);
        Entity body;
        std::string status;
        if (!resolve(req.body_name, body, &status) || body.kind != Entity::Kind::RobotLink) {
          ROS_WARN_STREAM("mechsim: /gazebo/clear_body_wrenches: no body '" << req.body_name << "'");
          return true;
        }
        const BridgeResult r = body.robot->bridge().clear_link_wrenches(body.link);
        if (!r.ok) ROS_WARN_STREAM("mechsim: /gazebo/clear_body_wrenches: " << r.error);
        return true;
      }));

  using Joint = gazebo_msgs::JointRequest;
  services_.push_back(root_nh_.advertiseService<Joint::Request, Joint::Response>(
      "/gazebo/clear_joint_forces", [this, joint_of](Joint::Request& req, Joint::Response&) {
        std::lock_guard<std::mutex> lock(mutex_);
        std::string status;
        const auto [robot, joint] = joint_of(req.joint_name, &status);
        const BridgeResult r = robot == nullptr ? BridgeResult{false, status} : robot->bridge().clear_joint_efforts(joint);
        if (!r.ok) ROS_WARN_STREAM("mechsim: /gazebo/clear_joint_forces: " << r.error);
        return true;
      }));
}

}  // namespace mechsim::ros
