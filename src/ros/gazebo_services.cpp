// GazeboWorld: gazebo_ros' model state, property and force services, each mapping gazebo_msgs
// onto bridge::World (whose header says how names, frames and refusals work).
#include <gazebo_msgs/ApplyBodyWrench.h>
#include <gazebo_msgs/ApplyJointEffort.h>
#include <gazebo_msgs/BodyRequest.h>
#include <gazebo_msgs/DeleteLight.h>
#include <gazebo_msgs/GetLightProperties.h>
#include <gazebo_msgs/GetJointProperties.h>
#include <gazebo_msgs/GetLinkProperties.h>
#include <gazebo_msgs/GetLinkState.h>
#include <gazebo_msgs/GetModelProperties.h>
#include <gazebo_msgs/GetModelState.h>
#include <gazebo_msgs/GetPhysicsProperties.h>
#include <gazebo_msgs/GetWorldProperties.h>
#include <gazebo_msgs/JointRequest.h>
#include <gazebo_msgs/ModelStates.h>
#include <gazebo_msgs/SetJointProperties.h>
#include <gazebo_msgs/SetLightProperties.h>
#include <gazebo_msgs/SetLinkProperties.h>
#include <gazebo_msgs/SetLinkState.h>
#include <gazebo_msgs/SetModelConfiguration.h>
#include <gazebo_msgs/SetModelState.h>
#include <gazebo_msgs/SetPhysicsProperties.h>

#include "ros/gazebo_world.hpp"

namespace mechsim::ros {

namespace {

using description::Pose;
using description::Vec3;

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

EntityState state_from(const geometry_msgs::Pose& pose, const geometry_msgs::Twist& twist) {
  EntityState s;
  s.pose = pose_from(pose);
  s.linear = vec_from(twist.linear);
  s.angular = vec_from(twist.angular);
  return s;
}

// success, status_message: the world's refusal, or `done` when it took the request.
template <class Response>
void answer(const BridgeResult& r, const char* done, Response& res) {
  res.success = r.ok;
  res.status_message = r.ok ? done : r.error;
}

}  // namespace

void GazeboWorld::advertise_model_services() {
  using GetModelState = gazebo_msgs::GetModelState;
  services_.push_back(root_nh_.advertiseService<GetModelState::Request, GetModelState::Response>(
      "/gazebo/get_model_state", [this](GetModelState::Request& req, GetModelState::Response& res) {
        EntityState s;
        answer(world_.model_state(req.model_name, req.relative_entity_name, s), "GetModelState: got properties", res);
        if (!res.success) return true;
        res.header.stamp = ::ros::Time(world_.time());
        res.header.frame_id = req.relative_entity_name;
        res.pose = to_msg(s.pose);
        res.twist.linear = to_msg(s.linear);
        res.twist.angular = to_msg(s.angular);
        return true;
      }));

  using GetLinkState = gazebo_msgs::GetLinkState;
  services_.push_back(root_nh_.advertiseService<GetLinkState::Request, GetLinkState::Response>(
      "/gazebo/get_link_state", [this](GetLinkState::Request& req, GetLinkState::Response& res) {
        EntityState s;
        answer(world_.link_state(req.link_name, req.reference_frame, s), "GetLinkState: got state", res);
        if (!res.success) return true;
        res.link_state.link_name = req.link_name;
        res.link_state.reference_frame = req.reference_frame;
        res.link_state.pose = to_msg(s.pose);
        res.link_state.twist.linear = to_msg(s.linear);
        res.link_state.twist.angular = to_msg(s.angular);
        return true;
      }));

  using SetModelState = gazebo_msgs::SetModelState;
  services_.push_back(root_nh_.advertiseService<SetModelState::Request, SetModelState::Response>(
      "/gazebo/set_model_state", [this](SetModelState::Request& req, SetModelState::Response& res) {
        const gazebo_msgs::ModelState& s = req.model_state;
        answer(world_.set_model_state(s.model_name, s.reference_frame, state_from(s.pose, s.twist)),
               "SetModelState: set model state done", res);
        return true;
      }));
  // The topic forms of set_model_state and set_link_state, and set_model_states (every model of
  // the message, world frame), as gazebo_ros subscribes to them.
  subscribers_.push_back(root_nh_.subscribe<gazebo_msgs::ModelState>(
      "/gazebo/set_model_state", 10, [this](const gazebo_msgs::ModelState::ConstPtr& s) {
        const BridgeResult r = world_.set_model_state(s->model_name, s->reference_frame, state_from(s->pose, s->twist));
        if (!r.ok) ROS_WARN_STREAM("mechsim: /gazebo/set_model_state: " << r.error);
      }));
  subscribers_.push_back(root_nh_.subscribe<gazebo_msgs::LinkState>(
      "/gazebo/set_link_state", 10, [this](const gazebo_msgs::LinkState::ConstPtr& s) {
        const BridgeResult r = world_.set_link_state(s->link_name, s->reference_frame, state_from(s->pose, s->twist));
        if (!r.ok) ROS_WARN_STREAM("mechsim: /gazebo/set_link_state: " << r.error);
      }));
  subscribers_.push_back(root_nh_.subscribe<gazebo_msgs::ModelStates>(
      "/gazebo/set_model_states", 10, [this](const gazebo_msgs::ModelStates::ConstPtr& s) {
        if (s->pose.size() != s->name.size() || s->twist.size() != s->name.size()) {
          ROS_WARN_STREAM("mechsim: /gazebo/set_model_states: " << s->name.size() << " names, " << s->pose.size()
                                                                << " poses, " << s->twist.size() << " twists: ignored");
          return;
        }
        for (std::size_t i = 0; i < s->name.size(); ++i) {
          const BridgeResult r = world_.set_model_state(s->name[i], "", state_from(s->pose[i], s->twist[i]));
          if (!r.ok) ROS_WARN_STREAM("mechsim: /gazebo/set_model_states: " << r.error);
        }
      }));

  using SetLinkState = gazebo_msgs::SetLinkState;
  services_.push_back(root_nh_.advertiseService<SetLinkState::Request, SetLinkState::Response>(
      "/gazebo/set_link_state", [this](SetLinkState::Request& req, SetLinkState::Response& res) {
        const gazebo_msgs::LinkState& s = req.link_state;
        answer(world_.set_link_state(s.link_name, s.reference_frame, state_from(s.pose, s.twist)),
               "SetLinkState: set link state done", res);
        return true;
      }));

  using GetWorld = gazebo_msgs::GetWorldProperties;
  services_.push_back(root_nh_.advertiseService<GetWorld::Request, GetWorld::Response>(
      "/gazebo/get_world_properties", [this](GetWorld::Request&, GetWorld::Response& res) {
        res.sim_time = world_.time();
        res.model_names = world_.model_names();
        res.rendering_enabled = false;
        res.success = true;
        res.status_message = "GetWorldProperties: got properties";
        return true;
      }));

  using GetModel = gazebo_msgs::GetModelProperties;
  services_.push_back(root_nh_.advertiseService<GetModel::Request, GetModel::Response>(
      "/gazebo/get_model_properties", [this](GetModel::Request& req, GetModel::Response& res) {
        bridge::ModelProperties p;
        answer(world_.model_properties(req.model_name, p), "GetModelProperties: got properties", res);
        res.parent_model_name = p.parent_model_name;
        res.canonical_body_name = p.canonical_body_name;
        res.body_names = p.body_names;
        res.geom_names = p.geom_names;
        res.joint_names = p.joint_names;
        res.child_model_names = p.child_model_names;
        res.is_static = p.is_static;
        return true;
      }));

  using GetJoint = gazebo_msgs::GetJointProperties;
  services_.push_back(root_nh_.advertiseService<GetJoint::Request, GetJoint::Response>(
      "/gazebo/get_joint_properties", [this](GetJoint::Request& req, GetJoint::Response& res) {
        JointPropertiesData p;
        answer(world_.joint_properties(req.joint_name, p), "GetJointProperties: got properties", res);
        if (!res.success) return true;
        res.type = static_cast<std::uint8_t>(p.type);
        res.damping = {p.damping};
        res.position = {p.position};
        res.rate = {p.rate};
        return true;
      }));

  using GetLink = gazebo_msgs::GetLinkProperties;
  services_.push_back(root_nh_.advertiseService<GetLink::Request, GetLink::Response>(
      "/gazebo/get_link_properties", [this](GetLink::Request& req, GetLink::Response& res) {
        LinkPropertiesData p;
        answer(world_.link_properties(req.link_name, p), "GetLinkProperties: got properties", res);
        res.com = to_msg(p.com);
        res.gravity_mode = p.gravity_mode;
        res.mass = p.mass;
        res.ixx = p.ixx, res.ixy = p.ixy, res.ixz = p.ixz, res.iyy = p.iyy, res.iyz = p.iyz, res.izz = p.izz;
        return true;
      }));

  using GetPhysics = gazebo_msgs::GetPhysicsProperties;
  services_.push_back(root_nh_.advertiseService<GetPhysics::Request, GetPhysics::Response>(
      "/gazebo/get_physics_properties", [this](GetPhysics::Request&, GetPhysics::Response& res) {
        const bridge::PhysicsProperties p = world_.physics_properties();
        res.time_step = p.time_step;
        res.pause = p.paused;
        res.max_update_rate = p.max_update_rate;
        res.gravity = to_msg(p.gravity);
        res.success = true;
        res.status_message = "GetPhysicsProperties: mechsim steps MuJoCo; ode_config is not used";
        return true;
      }));

  using SetPhysics = gazebo_msgs::SetPhysicsProperties;
  services_.push_back(root_nh_.advertiseService<SetPhysics::Request, SetPhysics::Response>(
      "/gazebo/set_physics_properties", [this](SetPhysics::Request& req, SetPhysics::Response& res) {
        bridge::PhysicsProperties p;
        p.time_step = req.time_step;
        p.max_update_rate = req.max_update_rate;
        p.gravity = vec_from(req.gravity);
        answer(world_.set_physics_properties(p), "SetPhysicsProperties: physics properties set (ode_config not used)",
               res);
        return true;
      }));

  using SetConfig = gazebo_msgs::SetModelConfiguration;
  services_.push_back(root_nh_.advertiseService<SetConfig::Request, SetConfig::Response>(
      "/gazebo/set_model_configuration", [this](SetConfig::Request& req, SetConfig::Response& res) {
        answer(world_.set_model_configuration(req.model_name, req.joint_names, req.joint_positions),
               "SetModelConfiguration: success", res);
        return true;
      }));

  using Wrench = gazebo_msgs::ApplyBodyWrench;
  services_.push_back(root_nh_.advertiseService<Wrench::Request, Wrench::Response>(
      "/gazebo/apply_body_wrench", [this](Wrench::Request& req, Wrench::Response& res) {
        const Vec3 point{req.reference_point.x, req.reference_point.y, req.reference_point.z};
        answer(world_.apply_body_wrench(req.body_name, req.reference_frame, vec_from(req.wrench.force),
                                        vec_from(req.wrench.torque), point, req.start_time.toSec(),
                                        req.duration.toSec()),
               "ApplyBodyWrench: success", res);
        return true;
      }));

  using Effort = gazebo_msgs::ApplyJointEffort;
  services_.push_back(root_nh_.advertiseService<Effort::Request, Effort::Response>(
      "/gazebo/apply_joint_effort", [this](Effort::Request& req, Effort::Response& res) {
        answer(world_.apply_joint_effort(req.joint_name, req.effort, req.start_time.toSec(), req.duration.toSec()),
               "ApplyJointEffort: effort set", res);
        return true;
      }));

  using SetJoint = gazebo_msgs::SetJointProperties;
  services_.push_back(root_nh_.advertiseService<SetJoint::Request, SetJoint::Response>(
      "/gazebo/set_joint_properties", [this](SetJoint::Request& req, SetJoint::Response& res) {
        // The joint's first axis, as mechsim's joints have one; ODE's erp, cfm, stop_erp,
        // stop_cfm, fudge_factor, fmax and vel have no MuJoCo counterpart here.
        const gazebo_msgs::ODEJointProperties& c = req.ode_joint_config;
        bridge::JointPropertyChange change;
        if (!c.damping.empty()) change.damping = c.damping.front();
        if (!c.hiStop.empty()) change.upper = c.hiStop.front();
        if (!c.loStop.empty()) change.lower = c.loStop.front();
        const bool ignored = !(c.erp.empty() && c.cfm.empty() && c.stop_erp.empty() && c.stop_cfm.empty() &&
                               c.fudge_factor.empty() && c.fmax.empty() && c.vel.empty());
        answer(world_.set_joint_properties(req.joint_name, change),
               ignored ? "SetJointProperties: damping and stops set (erp, cfm, fudge_factor, fmax and vel are ODE's: "
                         "not used)"
                       : "SetJointProperties: properties set",
               res);
        return true;
      }));

  using SetLink = gazebo_msgs::SetLinkProperties;
  services_.push_back(root_nh_.advertiseService<SetLink::Request, SetLink::Response>(
      "/gazebo/set_link_properties", [this](SetLink::Request& req, SetLink::Response& res) {
        LinkPropertiesData p;
        p.com = pose_from(req.com);
        p.gravity_mode = req.gravity_mode;
        p.mass = req.mass;
        p.ixx = req.ixx, p.ixy = req.ixy, p.ixz = req.ixz, p.iyy = req.iyy, p.iyz = req.iyz, p.izz = req.izz;
        answer(world_.set_link_properties(req.link_name, p), "SetLinkProperties: properties set", res);
        return true;
      }));

  using Body = gazebo_msgs::BodyRequest;
  services_.push_back(root_nh_.advertiseService<Body::Request, Body::Response>(
      "/gazebo/clear_body_wrenches", [this](Body::Request& req, Body::Response&) {
        const BridgeResult r = world_.clear_body_wrenches(req.body_name);
        if (!r.ok) ROS_WARN_STREAM("mechsim: /gazebo/clear_body_wrenches: " << r.error);
        return true;
      }));

  using Joint = gazebo_msgs::JointRequest;
  services_.push_back(root_nh_.advertiseService<Joint::Request, Joint::Response>(
      "/gazebo/clear_joint_forces", [this](Joint::Request& req, Joint::Response&) {
        const BridgeResult r = world_.clear_joint_forces(req.joint_name);
        if (!r.ok) ROS_WARN_STREAM("mechsim: /gazebo/clear_joint_forces: " << r.error);
        return true;
      }));
}

void GazeboWorld::advertise_light_services() {
  using GetLight = gazebo_msgs::GetLightProperties;
  services_.push_back(root_nh_.advertiseService<GetLight::Request, GetLight::Response>(
      "/gazebo/get_light_properties", [this](GetLight::Request& req, GetLight::Response& res) {
        bridge::LightProperties l;
        answer(world_.light_properties(req.light_name, l), "GetLightProperties: got properties", res);
        if (!res.success) {
          res.status_message = "getLightProperties: Requested light " + req.light_name + " not found!";
          return true;
        }
        res.diffuse.r = static_cast<float>(l.diffuse[0]);
        res.diffuse.g = static_cast<float>(l.diffuse[1]);
        res.diffuse.b = static_cast<float>(l.diffuse[2]);
        res.diffuse.a = static_cast<float>(l.diffuse[3]);
        res.attenuation_constant = l.attenuation_constant;
        res.attenuation_linear = l.attenuation_linear;
        res.attenuation_quadratic = l.attenuation_quadratic;
        return true;
      }));

  using SetLight = gazebo_msgs::SetLightProperties;
  services_.push_back(root_nh_.advertiseService<SetLight::Request, SetLight::Response>(
      "/gazebo/set_light_properties", [this](SetLight::Request& req, SetLight::Response& res) {
        bridge::LightProperties l;
        l.name = req.light_name;
        l.cast_shadows = req.cast_shadows;
        l.diffuse = {req.diffuse.r, req.diffuse.g, req.diffuse.b, req.diffuse.a};
        l.specular = {req.specular.r, req.specular.g, req.specular.b, req.specular.a};
        l.attenuation_constant = req.attenuation_constant;
        l.attenuation_linear = req.attenuation_linear;
        l.attenuation_quadratic = req.attenuation_quadratic;
        l.direction = vec_from(req.direction);
        l.pose = pose_from(req.pose);
        answer(world_.set_light_properties(l), "setLightProperties: properties set", res);
        return true;
      }));

  using DeleteLight = gazebo_msgs::DeleteLight;
  services_.push_back(root_nh_.advertiseService<DeleteLight::Request, DeleteLight::Response>(
      "/gazebo/delete_light", [this](DeleteLight::Request& req, DeleteLight::Response& res) {
        answer(world_.delete_light(req.light_name), "", res);
        if (res.success) res.status_message = "DeleteLight: " + req.light_name + " successfully deleted";
        else res.status_message = "DeleteLight: " + res.status_message;
        return true;
      }));
}

}  // namespace mechsim::ros
