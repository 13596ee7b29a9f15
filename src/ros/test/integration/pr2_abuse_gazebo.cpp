// The abuse test's /gazebo/* requests (pr2_abuse_fixture.hpp): gazebo_ros' model, link, joint,
// physics, force, spawn and delete services with bad arguments (and reads with good ones), and
// the paused phase: pause, unpause, step (small and absurd counts), both resets, and switches
// with absurd timeouts that cannot apply while paused.
#include <cmath>
#include <limits>

#include <gazebo_msgs/ApplyBodyWrench.h>
#include <gazebo_msgs/ApplyJointEffort.h>
#include <gazebo_msgs/BodyRequest.h>
#include <gazebo_msgs/DeleteModel.h>
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
#include <gazebo_msgs/SpawnModel.h>
#include <mechsim_msgs/StepSimulation.h>
#include <std_srvs/Empty.h>

#include "pr2_abuse_fixture.hpp"

namespace mechsim::ros::test {

// Never a usable pose: a zero quaternion or a non-finite number (a robot teleported at random is
// no abuse).
geometry_msgs::Pose bad_pose(AbuseInputs& in) {
  geometry_msgs::Pose p;
  p.position.x = in.nasty(1.0);
  p.position.y = in.nasty(1.0);
  p.position.z = in.nasty(1.0);
  p.orientation.w = in.chance(0.3) ? 0.0 : in.nasty(1.0);
  if (in.chance(0.5)) {
    p.orientation.x = p.orientation.y = p.orientation.z = p.orientation.w = 0.0;
  } else {
    p.position.z = std::numeric_limits<double>::quiet_NaN();
  }
  return p;
}

// One /gazebo/* service call with bad arguments (or a read with good ones): refusals answer
// success = false, reads of the robot are finite.
void Pr2Abuse::gazebo_request(AbuseInputs& in) {
  auto refused = [&](bool answered, bool success, const std::string& msg, const std::string& what) {
    if (answered && success) inconsistent_.push_back(what + " accepted a bad request (" + msg + ")");
  };
  const std::string model = in.chance(0.5) ? "pr2" : in.bad_name();
  const std::string link = in.chance(0.5) ? in.pick(std::vector<std::string>{"base_link", "r_gripper_palm_link", "torso_lift_link"})
                                          : in.bad_name();
  switch (in.below(17)) {
    case 0: {
      gazebo_msgs::GetModelState s;
      s.request.model_name = model;
      s.request.relative_entity_name = in.chance(0.5) ? "" : (in.chance(0.5) ? link : in.bad_name());
      if (must_answer("/gazebo/get_model_state", s, "gazebo get_model_state") && s.response.success &&
          !std::isfinite(s.response.pose.position.z + s.response.pose.orientation.w + s.response.twist.linear.x)) {
        inconsistent_.push_back("get_model_state: non-finite state");
      }
      break;
    }
    case 1: {
      gazebo_msgs::GetLinkState s;
      s.request.link_name = link;
      s.request.reference_frame = in.chance(0.5) ? "" : in.bad_name();
      must_answer("/gazebo/get_link_state", s, "gazebo get_link_state");
      break;
    }
    case 2: {
      gazebo_msgs::SetModelState s;
      s.request.model_state.model_name = in.chance(0.7) ? "pr2" : (in.chance(0.5) ? "ground_plane" : in.bad_name());
      s.request.model_state.pose = bad_pose(in);
      s.request.model_state.twist.linear.x = in.nasty(1.0);
      const bool a = must_answer("/gazebo/set_model_state", s, "gazebo set_model_state");
      refused(a, s.response.success, s.response.status_message, "set_model_state");
      break;
    }
    case 3: {
      gazebo_msgs::SetLinkState s;
      s.request.link_state.link_name = in.chance(0.5) ? "r_gripper_palm_link" : in.bad_name();
      s.request.link_state.pose = bad_pose(in);
      const bool a = must_answer("/gazebo/set_link_state", s, "gazebo set_link_state");
      refused(a, s.response.success, s.response.status_message, "set_link_state");
      break;
    }
    case 4: {
      gazebo_msgs::GetWorldProperties s;
      must_answer("/gazebo/get_world_properties", s, "gazebo get_world_properties");
      break;
    }
    case 5: {
      gazebo_msgs::GetModelProperties s;
      s.request.model_name = model;
      must_answer("/gazebo/get_model_properties", s, "gazebo get_model_properties");
      break;
    }
    case 6: {
      gazebo_msgs::GetJointProperties s;
      s.request.joint_name = in.chance(0.5) ? in.pick(kAbuseRightArm) : in.bad_name();
      must_answer("/gazebo/get_joint_properties", s, "gazebo get_joint_properties");
      break;
    }
    case 7: {
      gazebo_msgs::GetLinkProperties s;
      s.request.link_name = link;
      must_answer("/gazebo/get_link_properties", s, "gazebo get_link_properties");
      break;
    }
    case 8: {
      gazebo_msgs::GetPhysicsProperties s;
      must_answer("/gazebo/get_physics_properties", s, "gazebo get_physics_properties");
      break;
    }
    case 9: {
      // Always one bad field (a changed rate would change the real-time factor: not abuse).
      gazebo_msgs::SetPhysicsProperties s;
      s.request.time_step = 0.001;
      s.request.max_update_rate = 1000.0;
      s.request.gravity.z = -9.81;
      switch (in.below(3)) {
        case 0: s.request.time_step = in.chance(0.5) ? in.nasty(0.01) : 0.002; break;
        case 1: s.request.max_update_rate = in.chance(0.5) ? -1.0 : std::numeric_limits<double>::quiet_NaN(); break;
        default: s.request.gravity.x = in.chance(0.5) ? std::numeric_limits<double>::infinity() : std::nan(""); break;
      }
      const bool a = must_answer("/gazebo/set_physics_properties", s, "gazebo set_physics_properties");
      refused(a, s.response.success, s.response.status_message, "set_physics_properties");
      break;
    }
    case 10: {
      gazebo_msgs::SetModelConfiguration s;
      s.request.model_name = model;
      s.request.urdf_param_name = in.bad_name();
      s.request.joint_names = {in.pick(kAbuseRightArm), in.bad_name()};
      for (int n = in.below(4); n > 0; --n) s.request.joint_positions.push_back(in.nasty(1.0));
      if (s.request.joint_positions.size() == 2) s.request.joint_positions[1] = std::nan("");
      const bool a = must_answer("/gazebo/set_model_configuration", s, "gazebo set_model_configuration");
      refused(a, s.response.success, s.response.status_message, "set_model_configuration");
      break;
    }
    case 11: {
      gazebo_msgs::ApplyBodyWrench s;
      s.request.body_name = in.chance(0.5) ? "pr2::base_link" : in.bad_name();
      s.request.reference_frame = in.chance(0.5) ? "" : in.bad_name();
      s.request.wrench.force.x = std::nan("");
      s.request.wrench.torque.z = in.nasty(1.0);
      s.request.duration = in.bad_duration();
      const bool a = must_answer("/gazebo/apply_body_wrench", s, "gazebo apply_body_wrench");
      refused(a, s.response.success, s.response.status_message, "apply_body_wrench");
      break;
    }
    case 12: {
      gazebo_msgs::ApplyJointEffort s;
      const bool known = in.chance(0.5);
      s.request.joint_name = known ? in.pick(kAbuseRightArm) : in.bad_name();
      s.request.effort = known ? (in.chance(0.5) ? std::numeric_limits<double>::infinity() : std::nan("")) : in.nasty(1.0);
      s.request.duration = in.bad_duration();
      const bool a = must_answer("/gazebo/apply_joint_effort", s, "gazebo apply_joint_effort");
      refused(a, s.response.success, s.response.status_message, "apply_joint_effort");
      break;
    }
    case 13: {
      gazebo_msgs::BodyRequest s;
      s.request.body_name = link;
      must_answer("/gazebo/clear_body_wrenches", s, "gazebo clear_body_wrenches");
      gazebo_msgs::JointRequest j;
      j.request.joint_name = in.chance(0.5) ? in.pick(kAbuseRightArm) : in.bad_name();
      must_answer("/gazebo/clear_joint_forces", j, "gazebo clear_joint_forces");
      break;
    }
    case 14: {
      gazebo_msgs::SpawnModel s;
      s.request.model_name = in.chance(0.3) ? "pr2" : (in.chance(0.5) ? "" : in.bad_name());
      switch (in.below(4)) {
        case 0: s.request.model_xml = "<robot name='x'><link name='a'/>"; break;  // not closed
        case 1: s.request.model_xml = ""; break;
        case 2: s.request.model_xml = std::string(100000, '<'); break;
        default: s.request.model_xml = "<robot name='y'><link name='a'/></robot>"; break;  // well formed (the pose is not)
      }
      s.request.initial_pose = bad_pose(in);
      s.request.reference_frame = in.bad_name();
      const std::string service = in.chance(0.5) ? "/gazebo/spawn_urdf_model" : "/gazebo/spawn_sdf_model";
      const bool a = must_answer(service, s, "gazebo spawn_model");
      refused(a, s.response.success, s.response.status_message, "spawn_model");
      break;
    }
    case 15: {
      gazebo_msgs::DeleteModel s;
      s.request.model_name = in.chance(0.2) ? "ground_plane" : in.bad_name();
      const bool a = must_answer("/gazebo/delete_model", s, "gazebo delete_model");
      refused(a, s.response.success, s.response.status_message, "delete_model");
      break;
    }
    default: {
      mechsim_msgs::StepSimulation s;  // while running: refused
      s.request.steps = in.chance(0.5) ? 1 : std::numeric_limits<std::uint64_t>::max();
      const bool a = must_answer("/mechsim/step_simulation", s, "gazebo step_simulation");
      refused(a, s.response.success, s.response.status_message, "step_simulation while running");
      break;
    }
  }
}

// The paused phase: pause, unpause, step (small and absurd counts), both resets, and switches
// (with absurd timeouts) that cannot apply while paused.
void Pr2Abuse::paused_phase_request(AbuseInputs& in) {
  bool& paused = paused_;
  // A step or an unpause applies what a switch left pending: the test's model follows the list.
  auto follow_list = [&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    Names now_running, now_loaded;
    if (list(now_running, now_loaded)) running_ = now_running, loaded_ = now_loaded;
  };
  switch (in.below(6)) {
    case 0: {
      std_srvs::Empty s;
      if (must_answer("/gazebo/pause_physics", s, "gazebo pause_physics")) paused = true;
      break;
    }
    case 1: {
      std_srvs::Empty s;
      if (must_answer("/gazebo/unpause_physics", s, "gazebo unpause_physics")) paused = false;
      follow_list();
      break;
    }
    case 2: {
      std_srvs::Empty s;
      must_answer(in.chance(0.5) ? "/gazebo/reset_simulation" : "/gazebo/reset_world", s, "gazebo reset");
      break;
    }
    case 3: {
      mechsim_msgs::StepSimulation s;
      const bool absurd = in.chance(0.3);
      s.request.steps = absurd ? (in.chance(0.5) ? std::numeric_limits<std::uint64_t>::max() : 1000000000000ULL)
                               : static_cast<std::uint64_t>(in.below(20));
      const bool a = must_answer("/mechsim/step_simulation", s, "gazebo step_simulation");
      if (a && absurd && s.response.success) {
        inconsistent_.push_back("step_simulation of " + std::to_string(s.request.steps) + " steps accepted");
      }
      if (a && s.response.success && s.request.steps > 0) follow_list();
      break;
    }
    default: {
      switch_request(in, paused);
      break;
    }
  }
}
}  // namespace mechsim::ros::test
