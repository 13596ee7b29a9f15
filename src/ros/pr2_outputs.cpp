// What pr2_controller_manager publishes itself (and the PR2 simulation's fake calibration), for
// a node driving a PR2 (~pr2, or the PR2's gazebo plugin in the URDF):
//   <robot ns>/joint_states          sensor_msgs/JointState, every non-fixed joint, at
//                                    /pr2_controller_manager/joint_state_publish_rate (Hz, sim
//                                    time, default 100); position, velocity, measured effort
//   <robot ns>/mechanism_statistics  pr2_mechanism_msgs/MechanismStatistics at
//                                    /pr2_controller_manager/mechanism_statistics_publish_rate
//                                    (Hz, sim time, default 1): actuators, joints (min/max
//                                    position, max |velocity|, max |effort| and violated_limits
//                                    over the period since the previous message), controllers
//                                    (running, mean/max update time, overruns)
//   /calibrated                      std_msgs/Bool true, latched (pr2_gazebo's
//                                    fake_joint_calibration: simulated joints need no homing)
// Stamps are whole publish periods of simulation time.
#include <cmath>

#include <pr2_mechanism_msgs/MechanismStatistics.h>
#include <sensor_msgs/JointState.h>
#include <std_msgs/Bool.h>

#include "ros/publish_helpers.hpp"
#include "ros/sim_node.hpp"

namespace mechsim::ros {

namespace {

double period_of(const ::ros::NodeHandle& nh, const char* key, double default_rate) {
  double rate = default_rate;
  nh.param(key, rate, default_rate);
  if (!std::isfinite(rate) || rate < 0.0) {
    ROS_WARN_STREAM("mechsim: " << nh.resolveName(key) << " = " << rate << " is not a rate (Hz >= 0); using "
                                << default_rate);
    rate = default_rate;
  }
  return rate > 0.0 ? 1.0 / rate : 0.0;
}

}  // namespace

void SimNode::advertise_pr2_outputs() {
  const ::ros::NodeHandle cm("/pr2_controller_manager");
  joint_state_period_ = period_of(cm, "joint_state_publish_rate", 100.0);
  statistics_period_ = period_of(cm, "mechanism_statistics_publish_rate", 1.0);
  // A queue: the simulation often runs faster than real time (at 100 Hz of sim time, several
  // hundred messages per wall second).
  pr2_joint_states_pub_ = robot_nh_.advertise<sensor_msgs::JointState>("joint_states", 10);
  pr2_statistics_pub_ = robot_nh_.advertise<pr2_mechanism_msgs::MechanismStatistics>("mechanism_statistics", 1);
  calibrated_pub_ = root_nh_.advertise<std_msgs::Bool>("/calibrated", 1, /*latch=*/true);
  std_msgs::Bool calibrated;
  calibrated.data = true;
  calibrated_pub_.publish(calibrated);
  next_joint_states_ = bridge_->time();
  next_statistics_ = bridge_->time();
}

void SimNode::publish_pr2_outputs(double time) {
  if (time + 1e-9 >= next_joint_states_) {
    next_joint_states_ = next_due_after(time, joint_state_period_);
    bridge_->mechanism_joint_states(pr2_joint_states_);
    pr2_joint_states_pub_.publish(to_msg(pr2_joint_states_));
  }
  if (time + 1e-9 >= next_statistics_) {
    next_statistics_ = next_due_after(time, statistics_period_);
    bridge_->take_mechanism_statistics(pr2_statistics_);
    const ::ros::Time stamp(pr2_statistics_.stamp);
    pr2_mechanism_msgs::MechanismStatistics msg;
    msg.header.stamp = stamp;
    for (const ActuatorStatisticsData& a : pr2_statistics_.actuators) {
      pr2_mechanism_msgs::ActuatorStatistics s;
      s.name = a.name;
      s.device_id = a.device_id;
      s.timestamp = stamp;
      s.position = a.position;
      s.velocity = a.velocity;
      s.encoder_velocity = a.velocity;
      s.is_enabled = true;
      s.halted = false;
      s.last_commanded_effort = a.commanded_effort;
      s.last_executed_effort = a.commanded_effort;  // the physics applies what it is given
      s.last_measured_effort = a.measured_effort;
      msg.actuator_statistics.push_back(s);
    }
    for (const JointStatisticsData& j : pr2_statistics_.joints) {
      pr2_mechanism_msgs::JointStatistics s;
      s.name = j.name;
      s.timestamp = stamp;
      s.position = j.position;
      s.velocity = j.velocity;
      s.measured_effort = j.measured_effort;
      s.commanded_effort = j.commanded_effort;
      s.is_calibrated = true;
      s.violated_limits = j.violated_limits;
      s.odometer = j.odometer;
      s.min_position = j.min_position;
      s.max_position = j.max_position;
      s.max_abs_velocity = j.max_abs_velocity;
      s.max_abs_effort = j.max_abs_effort;
      msg.joint_statistics.push_back(s);
    }
    for (const ControllerStatisticsData& c : pr2_statistics_.controllers) {
      pr2_mechanism_msgs::ControllerStatistics s;
      s.name = c.name;
      s.timestamp = stamp;
      s.running = c.running;
      s.max_time = ::ros::Duration(c.max_time);
      s.mean_time = ::ros::Duration(c.mean_time);
      s.num_control_loop_overruns = static_cast<std::int32_t>(c.overruns);
      msg.controller_statistics.push_back(s);
    }
    pr2_statistics_pub_.publish(msg);
  }
}

}  // namespace mechsim::ros
