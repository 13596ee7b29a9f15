// Each loaded controller's ROS interface, as ros_controllers names it, made at load and removed
// at unload:
//   command ports     <robot ns>/<controller>/<port> (std_msgs/Float64, Float64MultiArray,
//                     geometry_msgs/Twist for the rover drive's "cmd_vel")
//   "state"           <robot ns>/<controller>/state (control_msgs/JointControllerState) at the
//                     controller's state_publish_rate, else the node's (default 50 Hz sim time)
//   "joint_states"    <robot ns>/joint_states (sensor_msgs/JointState) whenever the controller
//                     fills it (its publish_rate)
//   "odom"            <robot ns>/<controller>/odom (nav_msgs/Odometry) at the controller's
//                     publish_rate (default 50 Hz), and odom -> base on /tf unless enable_odom_tf
//                     is false (diff_drive_controller's behaviour)
//   sensor ports      imu_sensor_controller / force_torque_sensor_controller: each handle's port
//                     on <robot ns>/<handle name> (sensor_msgs/Imu, geometry_msgs/WrenchStamped)
//                     whenever the controller fills it (its publish_rate): ros_controllers
//                     advertises them on the controller manager's namespace, not its own
//   "cmd_vel_out"     <robot ns>/<controller>/cmd_vel_out (geometry_msgs/TwistStamped):
//                     diff_drive_controller's limited command with publish_cmd, every update
//   cmd_vel           with allow_multiple_cmd_vel_publishers: false, diff_drive_controller
//                     ignores cmd_vel while more than one node publishes it (an error, throttled)
//   trajectories      <robot ns>/<controller>/command (trajectory_msgs/JointTrajectory),
//                     <robot ns>/<controller>/state (control_msgs/JointTrajectoryControllerState,
//                     at the state rate), <robot ns>/<controller>/follow_joint_trajectory (action),
//                     <robot ns>/<controller>/query_state (control_msgs/QueryTrajectoryState:
//                     the desired state at a time; fails while the controller is not running)
// PR2 controller types (robot_mechanism_controllers/*, pr2_mechanism_controllers/*) speak the
// PR2's messages instead (pr2_actions.hpp):
//   state topics      pr2_controllers_msgs/JointControllerState, JointTrajectoryControllerState
//   JointTrajectoryActionController  also <controller>/joint_trajectory_action
//                     (pr2_controllers_msgs/JointTrajectoryAction) beside follow_joint_trajectory;
//                     query_state is pr2_controllers_msgs/QueryTrajectoryState
//   Pr2GripperController  <controller>/command (pr2_controllers_msgs/Pr2GripperCommand),
//                     <controller>/gripper_action (pr2_controllers_msgs/Pr2GripperCommandAction)
//   LaserScannerTrajController  <controller>/set_periodic_cmd and set_traj_cmd, each a topic
//                     (pr2_msgs/PeriodicCmd, LaserTrajCmd) and a service (pr2_msgs/SetPeriodicCmd,
//                     SetLaserTrajCmd: start_time is the sim time of the call; false when refused)
// position_ and effort_controllers/GripperActionController: <controller>/gripper_cmd
//                     (control_msgs/GripperCommandAction, gripper_command_action.hpp)
//   Pr2Odometry       <controller>/odom at odom_publish_rate (default 30 Hz) and odom ->
//                     base_footprint on /tf unless publish_tf is false (the PR2's parameters)
// A controller parameter <port>_topic (e.g. cmd_vel_topic: /cc8/cmd_vel) renames a topic;
// relative names resolve in the controller's namespace. Remapping the full name works too.

#include <ros/names.h>

#include <geometry_msgs/Twist.h>
#include <geometry_msgs/TwistStamped.h>
#include <nav_msgs/Odometry.h>
#include <sensor_msgs/JointState.h>
#include <std_msgs/Float64.h>
#include <std_msgs/Float64MultiArray.h>
#include <tf2_msgs/TFMessage.h>

#include <control_msgs/JointControllerState.h>
#include <control_msgs/QueryTrajectoryState.h>
#include <pr2_controllers_msgs/JointControllerState.h>
#include <pr2_controllers_msgs/JointTrajectoryControllerState.h>
#include <pr2_controllers_msgs/Pr2GripperCommand.h>
#include <pr2_controllers_msgs/QueryTrajectoryState.h>
#include <pr2_msgs/LaserTrajCmd.h>
#include <pr2_msgs/PeriodicCmd.h>
#include <pr2_msgs/SetLaserTrajCmd.h>
#include <pr2_msgs/SetPeriodicCmd.h>

#include "ros/gripper_command_action.hpp"
#include "ros/pr2_actions.hpp"
#include "ros/sensor_messages.hpp"
#include "ros/publish_helpers.hpp"
#include "ros/sim_node.hpp"
#include "ros/trajectory_action.hpp"

namespace mechsim::ros {

struct SimNode::Binding {
  PortRef port;
  bool alive = true;  // under bindings_mutex_: false once unbinding started
  bool pr2 = false;   // a PR2 controller type: pr2_controllers_msgs state messages
  ::ros::Subscriber subscriber;
  ::ros::Publisher publisher;
  ::ros::Publisher tf_publisher;  // odometry only
  double period = 0.0;            // s (sim time) between state messages; 0: every new snapshot
  double next_due = 0.0;
  std::uint64_t sequence = 0;
  JointControllerStateData jcs;
  JointStatesData joint_states;
  OdometryData odom;
  TwistStampedData twist;
  control::JointTrajectoryControllerState trajectory_state;
  std::unique_ptr<TrajectoryActionServer> action;
  std::unique_ptr<Pr2TrajectoryActionServer> pr2_action;  // JointTrajectoryActionController only
  std::unique_ptr<GripperActionServer> gripper_action;
  std::unique_ptr<ControlGripperActionServer> gripper_command_action;  // GripperActionController
  ::ros::ServiceServer service;  // query_state; set_periodic_cmd
  // The laser tilt controller's second topic and service (set_traj_cmd).
  ::ros::Subscriber subscriber2;
  ::ros::ServiceServer service2;
};

namespace {

// query_state: the request's time sampled on the controller's trajectory (both message
// packages define the service alike).
template <class Srv, class Binding>
::ros::ServiceServer advertise_query(::ros::NodeHandle& nh, const std::string& name, std::mutex& mutex,
                                     std::weak_ptr<Binding> weak) {
  using Req = typename Srv::Request;
  using Res = typename Srv::Response;
  return nh.advertiseService<Req, Res>(name, [&mutex, weak](Req& req, Res& res) {
    std::lock_guard<std::mutex> lock(mutex);  // the port lives while its binding is alive
    auto self = weak.lock();
    if (!self || !self->alive) return false;
    TrajectorySample sample;
    std::string error;
    if (!query_trajectory(self->port, req.time.toSec(), sample, &error)) {
      ROS_WARN_STREAM("mechsim: " << self->port.controller << "/query_state: " << error);
      return false;
    }
    res.name = sample.names;
    res.position = sample.position;
    res.velocity = sample.velocity;
    res.acceleration = sample.acceleration;
    return true;
  });
}

double rate_param(const control::Params& params, const std::string& controller, const char* key, double fallback) {
  try {
    if (auto c = params.find(controller); c && c->has(key)) return c->get<double>(key);
  } catch (const std::exception& e) {
    ROS_WARN_STREAM("mechsim: " << e.what());
  }
  return fallback;
}

std::string topic_param(const control::Params& params, const std::string& controller, const std::string& port) {
  try {
    if (auto c = params.find(controller); c && c->has(port + "_topic")) return c->get<std::string>(port + "_topic");
  } catch (const std::exception& e) {
    ROS_WARN_STREAM("mechsim: " << e.what());
  }
  return port;
}

bool starts_with(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

// The PR2's controller packages (pr2_controller_manager's types).
bool is_pr2_type(const std::string& type) {
  return starts_with(type, "robot_mechanism_controllers/") || starts_with(type, "pr2_mechanism_controllers/");
}

constexpr const char* kPr2TrajectoryActionType = "robot_mechanism_controllers/JointTrajectoryActionController";
constexpr const char* kPr2OdometryType = "pr2_mechanism_controllers/Pr2Odometry";

template <class Msg>
void fill_state(Msg& msg, const JointControllerStateData& d) {
  msg.header.stamp = ::ros::Time(d.stamp);
  msg.set_point = d.set_point;
  msg.process_value = d.process_value;
  msg.process_value_dot = d.process_value_dot;
  msg.error = d.error;
  msg.time_step = d.time_step;
  msg.command = d.command;
  msg.p = d.p;
  msg.i = d.i;
  msg.d = d.d;
  msg.i_clamp = d.i_clamp;
}

// A command topic of binding `weak`: each message is written to the port with `write(port, msg,
// &error)` under `mutex` (bindings_mutex_) while the binding is alive; a refused command is
// warned about at most once a second (per call site: each one is its own instantiation).
template <class Msg, class B, class Write>
::ros::Subscriber subscribe_command(::ros::NodeHandle& nh, const std::string& topic, std::mutex& mutex,
                                    std::weak_ptr<B> weak, const char* what, Write write) {
  return nh.subscribe<Msg>(topic, 1, [&mutex, weak, what, write](const typename Msg::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex);
    auto self = weak.lock();
    std::string error;
    if (self && self->alive && !write(self->port, *msg, &error)) {
      ROS_WARN_STREAM_THROTTLE(1.0, "mechsim: " << self->port.controller << ": " << what << " rejected: " << error);
    }
  });
}

bool write_scan(const PortRef& p, const pr2_msgs::PeriodicCmd& c, std::string* error) {
  return write_periodic_command(p, c.profile, c.period, c.amplitude, c.offset, error);
}

bool write_scan(const PortRef& p, const pr2_msgs::LaserTrajCmd& c, std::string* error) {
  std::vector<double> times;
  times.reserve(c.time_from_start.size());
  for (const ::ros::Duration& d : c.time_from_start) times.push_back(d.toSec());
  return write_laser_traj_command(p, c.profile, c.position, times, c.max_velocity, c.max_acceleration, error);
}

// set_periodic_cmd / set_traj_cmd as services: the command is written to the port; start_time
// is `now()` (the sim time of the call, as the PR2's node answers ros::Time::now()).
template <class Srv, class Binding, class Now>
::ros::ServiceServer advertise_scan(::ros::NodeHandle& nh, const std::string& name, std::mutex& mutex,
                                    std::weak_ptr<Binding> weak, Now now) {
  using Req = typename Srv::Request;
  using Res = typename Srv::Response;
  return nh.advertiseService<Req, Res>(name, [&mutex, weak, name, now](Req& req, Res& res) {
    std::lock_guard<std::mutex> lock(mutex);
    auto self = weak.lock();
    if (!self || !self->alive) return false;
    std::string error;
    if (!write_scan(self->port, req.command, &error)) {
      ROS_WARN_STREAM("mechsim: " << self->port.controller << "/" << name << ": " << error);
      return false;
    }
    res.start_time = ::ros::Time(now());
    return true;
  });
}

}  // namespace

BridgeResult SimNode::load(const std::string& name) {
  // The controller's parameters and topics live under <ns>/<name>: roscpp throws on a name it
  // cannot resolve, which failed the whole service call instead of answering ok: false (as
  // ros_control does, which catches the same exception).
  std::string why;
  if (!name.empty() && !::ros::names::validate(controller_ns(name), why)) {
    return {false, "'" + name + "' cannot be a controller name: " + why};
  }
  std::lock_guard<std::mutex> lock(manager_mutex_);
  refresh_params(name);
  BridgeResult r = bridge_->load_controller(name);
  if (r.ok) bind(name);
  return r;
}

BridgeResult SimNode::unload(const std::string& name) {
  std::lock_guard<std::mutex> lock(manager_mutex_);
  if (!bridge_->is_loaded(name)) return {false, "controller '" + name + "' is not loaded"};
  for (const ControllerSummary& c : bridge_->list_controllers()) {
    if (c.name == name && c.state == "running") return {false, "controller '" + name + "' is running: stop it first"};
  }
  unbind(name);  // no PortRef may outlive the controller
  BridgeResult r = bridge_->unload_controller(name);
  if (!r.ok) bind(name);
  return r;
}

std::vector<std::string> SimNode::unload_all_controllers() {
  std::lock_guard<std::mutex> lock(manager_mutex_);
  const std::vector<std::string> names = bridge_->stop_all_controllers_now();
  for (auto it = names.rbegin(); it != names.rend(); ++it) {
    unbind(*it);
    const BridgeResult r = bridge_->unload_controller(*it);
    if (!r.ok) ROS_WARN_STREAM("mechsim: could not unload controller '" << *it << "': " << r.error);
  }
  return names;
}

void SimNode::bind(const std::string& controller) {
  const control::Params params = bridge_->controller_params();
  ::ros::NodeHandle controller_nh(controller_ns(controller));
  std::vector<std::shared_ptr<Binding>> made;
  for (const PortRef& port : bridge_->ports(controller)) {
    auto b = std::make_shared<Binding>();
    b->port = port;
    b->pr2 = is_pr2_type(port.controller_type);
    std::weak_ptr<Binding> weak = b;
    const std::string topic = topic_param(params, controller, port.name);
    switch (port.type) {
      case PortType::ScalarCommand:
        b->subscriber = subscribe_command<std_msgs::Float64>(
            controller_nh, topic, bindings_mutex_, weak, "command",
            [](const PortRef& p, const std_msgs::Float64& msg, std::string* error) {
              return write_scalar(p, msg.data, error);
            });
        break;
      case PortType::ArrayCommand:
        b->subscriber = subscribe_command<std_msgs::Float64MultiArray>(
            controller_nh, topic, bindings_mutex_, weak, "command",
            [](const PortRef& p, const std_msgs::Float64MultiArray& msg, std::string* error) {
              return write_array(p, msg.data, error);
            });
        break;
      case PortType::TwistCommand: {
        bool allow_multiple = true;
        try {
          if (auto c = params.find(controller)) allow_multiple = c->get<bool>("allow_multiple_cmd_vel_publishers", true);
        } catch (const std::exception& e) {
          ROS_WARN_STREAM("mechsim: " << e.what());
        }
        b->subscriber = subscribe_command<geometry_msgs::Twist>(
            controller_nh, topic, bindings_mutex_, weak, "cmd_vel",
            [allow_multiple, weak](const PortRef& p, const geometry_msgs::Twist& msg, std::string* error) {
              // Under bindings_mutex_: the binding (and its subscriber) is alive.
              if (!allow_multiple) {
                const auto self = weak.lock();
                const std::uint32_t publishers = self ? self->subscriber.getNumPublishers() : 0;
                if (publishers > 1) {
                  *error = std::to_string(publishers) + " publishers on cmd_vel, and allow_multiple_cmd_vel_publishers is false";
                  return false;
                }
              }
              return write_twist(p, msg.linear.x, msg.linear.y, msg.linear.z, msg.angular.x, msg.angular.y,
                                 msg.angular.z, error);
            });
        break;
      }
      case PortType::TwistState:
        b->publisher = controller_nh.advertise<geometry_msgs::TwistStamped>(topic, 100);
        break;
      case PortType::JointControllerState: {
        b->publisher = b->pr2 ? controller_nh.advertise<pr2_controllers_msgs::JointControllerState>(topic, 1)
                              : controller_nh.advertise<control_msgs::JointControllerState>(topic, 1);
        const double rate = rate_param(params, controller, "state_publish_rate", options_.state_publish_rate);
        b->period = rate > 0.0 ? 1.0 / rate : 0.0;
        break;
      }
      case PortType::JointStates:
        // joint_state_controller publishes in the robot namespace, not its own.
        b->publisher = robot_nh_.advertise<sensor_msgs::JointState>(topic, 1);
        break;
      case PortType::ImuState:  // the same namespace as joint_states (ros_controllers' root_nh)
        b->publisher = robot_nh_.advertise<sensor_msgs::Imu>(topic, 4);
        break;
      case PortType::WrenchState:
        b->publisher = robot_nh_.advertise<geometry_msgs::WrenchStamped>(topic, 4);
        break;
      case PortType::Odometry: {
        b->publisher = controller_nh.advertise<nav_msgs::Odometry>(topic, 1);
        // pr2_mechanism_controllers/Pr2Odometry names its rate and TF switch differently from
        // diff_drive_controller (and publishes at 30 Hz by default).
        const bool pr2_odometry = port.controller_type == kPr2OdometryType;
        const double rate = pr2_odometry ? rate_param(params, controller, "odom_publish_rate", 30.0)
                                         : rate_param(params, controller, "publish_rate", options_.odom_publish_rate);
        b->period = rate > 0.0 ? 1.0 / rate : 0.0;
        bool odom_tf = true;
        try {
          if (auto c = params.find(controller)) odom_tf = c->get<bool>(pr2_odometry ? "publish_tf" : "enable_odom_tf", true);
        } catch (const std::exception& e) {
          ROS_WARN_STREAM("mechsim: " << e.what());
        }
        if (odom_tf) b->tf_publisher = root_nh_.advertise<tf2_msgs::TFMessage>("/tf", 100);
        break;
      }
      case PortType::TrajectoryCommand:
        b->subscriber = controller_nh.subscribe<trajectory_msgs::JointTrajectory>(
            topic, 1, [this, weak](const trajectory_msgs::JointTrajectory::ConstPtr& msg) {
              const control::JointTrajectory trajectory = from_msg(*msg);
              std::lock_guard<std::mutex> lock(bindings_mutex_);
              auto self = weak.lock();
              std::string error;
              if (self && self->alive && !write_trajectory(self->port, trajectory, &error)) {
                ROS_WARN_STREAM("mechsim: " << self->port.controller << ": trajectory rejected: " << error);
              }
            });
        break;
      case PortType::TrajectoryState: {
        b->publisher = b->pr2 ? controller_nh.advertise<pr2_controllers_msgs::JointTrajectoryControllerState>(topic, 1)
                              : controller_nh.advertise<control_msgs::JointTrajectoryControllerState>(topic, 1);
        const double rate = rate_param(params, controller, "state_publish_rate", options_.state_publish_rate);
        b->period = rate > 0.0 ? 1.0 / rate : 0.0;
        break;
      }
      case PortType::TrajectoryGoal:
        b->action = std::make_unique<TrajectoryActionServer>(controller_nh, topic, port);
        if (port.controller_type == kPr2TrajectoryActionType) {
          b->pr2_action = std::make_unique<Pr2TrajectoryActionServer>(
              controller_nh, topic_param(params, controller, "joint_trajectory_action"), port);
        }
        break;
      case PortType::GripperCommand:
        b->subscriber = subscribe_command<pr2_controllers_msgs::Pr2GripperCommand>(
            controller_nh, topic, bindings_mutex_, weak, "command",
            [](const PortRef& p, const pr2_controllers_msgs::Pr2GripperCommand& msg, std::string* error) {
              return write_gripper_command(p, msg.position, msg.max_effort, error);
            });
        break;
      case PortType::GripperGoal:
        if (b->pr2) b->gripper_action = std::make_unique<GripperActionServer>(controller_nh, topic, port);
        else b->gripper_command_action = std::make_unique<ControlGripperActionServer>(controller_nh, topic, port);
        break;
      case PortType::TrajectoryQuery:
        b->service = b->pr2 ? advertise_query<pr2_controllers_msgs::QueryTrajectoryState>(controller_nh, topic,
                                                                                        bindings_mutex_, weak)
                            : advertise_query<control_msgs::QueryTrajectoryState>(controller_nh, topic,
                                                                                  bindings_mutex_, weak);
        break;
      case PortType::ScanCommand: {
        const auto now = [this] { return bridge_->time(); };
        b->subscriber = subscribe_command<pr2_msgs::PeriodicCmd>(
            controller_nh, "set_periodic_cmd", bindings_mutex_, weak, "set_periodic_cmd",
            [](const PortRef& p, const pr2_msgs::PeriodicCmd& msg, std::string* error) { return write_scan(p, msg, error); });
        b->subscriber2 = subscribe_command<pr2_msgs::LaserTrajCmd>(
            controller_nh, "set_traj_cmd", bindings_mutex_, weak, "set_traj_cmd",
            [](const PortRef& p, const pr2_msgs::LaserTrajCmd& msg, std::string* error) { return write_scan(p, msg, error); });
        b->service = advertise_scan<pr2_msgs::SetPeriodicCmd>(controller_nh, "set_periodic_cmd", bindings_mutex_, weak, now);
        b->service2 = advertise_scan<pr2_msgs::SetLaserTrajCmd>(controller_nh, "set_traj_cmd", bindings_mutex_, weak, now);
        break;
      }
      case PortType::Other:
        continue;
    }
    made.push_back(std::move(b));
  }
  std::lock_guard<std::mutex> lock(bindings_mutex_);
  for (auto& b : made) bindings_.push_back(std::move(b));
}

void SimNode::unbind(const std::string& controller) {
  std::vector<std::shared_ptr<Binding>> removed;
  {
    std::lock_guard<std::mutex> lock(bindings_mutex_);
    for (auto it = bindings_.begin(); it != bindings_.end();) {
      if ((*it)->port.controller == controller) {
        (*it)->alive = false;
        removed.push_back(std::move(*it));
        it = bindings_.erase(it);
      } else {
        ++it;
      }
    }
  }
  // Shut the subscribers down outside the lock: roscpp waits for a running callback, which may
  // be waiting for the lock.
  for (auto& b : removed) {
    if (b->action) {
      b->action->shutdown();
      b->action.reset();
    }
    if (b->pr2_action) {
      b->pr2_action->shutdown();
      b->pr2_action.reset();
    }
    if (b->gripper_action) {
      b->gripper_action->shutdown();
      b->gripper_action.reset();
    }
    if (b->gripper_command_action) {
      b->gripper_command_action->shutdown();
      b->gripper_command_action.reset();
    }
    b->subscriber.shutdown();
    b->subscriber2.shutdown();
    b->service.shutdown();
    b->service2.shutdown();
    b->publisher.shutdown();
    b->tf_publisher.shutdown();
  }
}

void SimNode::publish_controller_states(double time) {
  std::lock_guard<std::mutex> lock(bindings_mutex_);
  for (const std::shared_ptr<Binding>& bp : bindings_) {
    Binding& b = *bp;
    switch (b.port.type) {
      case PortType::JointControllerState: {
        if (time + 1e-9 < b.next_due) break;
        if (!read_joint_controller_state(b.port, b.jcs, &b.sequence)) break;
        b.next_due = next_due_after(time, b.period);
        if (b.pr2) {
          pr2_controllers_msgs::JointControllerState msg;
          fill_state(msg, b.jcs);
          b.publisher.publish(msg);
          break;
        }
        control_msgs::JointControllerState msg;
        fill_state(msg, b.jcs);
        msg.antiwindup = b.jcs.antiwindup;
        b.publisher.publish(msg);
        break;
      }
      case PortType::JointStates: {
        if (!read_joint_states(b.port, b.joint_states, &b.sequence)) break;
        b.publisher.publish(to_msg(b.joint_states));
        break;
      }
      case PortType::Odometry: {
        if (time + 1e-9 < b.next_due) break;
        if (!read_odometry(b.port, b.odom, &b.sequence)) break;
        b.next_due = next_due_after(time, b.period);
        nav_msgs::Odometry msg;
        msg.header.stamp = ::ros::Time(b.odom.stamp);
        msg.header.frame_id = b.odom.frame_id;
        msg.child_frame_id = b.odom.child_frame_id;
        msg.pose.pose.position.x = b.odom.x;
        msg.pose.pose.position.y = b.odom.y;
        msg.pose.pose.orientation.w = b.odom.qw;
        msg.pose.pose.orientation.x = b.odom.qx;
        msg.pose.pose.orientation.y = b.odom.qy;
        msg.pose.pose.orientation.z = b.odom.qz;
        msg.twist.twist.linear.x = b.odom.vx;
        msg.twist.twist.linear.y = b.odom.vy;
        msg.twist.twist.angular.z = b.odom.wz;
        for (std::size_t k = 0; k < 36 && k < b.odom.pose_covariance.size(); ++k) {
          msg.pose.covariance[k] = b.odom.pose_covariance[k];
          msg.twist.covariance[k] = b.odom.twist_covariance[k];
        }
        b.publisher.publish(msg);
        if (b.tf_publisher) {
          tf2_msgs::TFMessage tf;
          geometry_msgs::TransformStamped t;
          t.header = msg.header;
          t.child_frame_id = msg.child_frame_id;
          t.transform.translation.x = b.odom.x;
          t.transform.translation.y = b.odom.y;
          t.transform.rotation = msg.pose.pose.orientation;
          tf.transforms.push_back(t);
          b.tf_publisher.publish(tf);
        }
        break;
      }
      case PortType::ImuState: {
        double stamp = 0.0;
        sensors::ImuReading reading;
        sensor_msgs::Imu msg;
        if (!read_imu_state(b.port, stamp, msg.header.frame_id, reading, &b.sequence)) break;
        fill_imu(reading, msg);
        msg.header.stamp = ::ros::Time(stamp);
        b.publisher.publish(msg);
        break;
      }
      case PortType::WrenchState: {
        double stamp = 0.0;
        sensors::WrenchReading reading;
        geometry_msgs::WrenchStamped msg;
        if (!read_wrench_state(b.port, stamp, msg.header.frame_id, reading, &b.sequence)) break;
        fill_wrench(reading, msg);
        msg.header.stamp = ::ros::Time(stamp);
        b.publisher.publish(msg);
        break;
      }
      case PortType::TwistState: {
        if (!read_twist_state(b.port, b.twist, &b.sequence)) break;
        geometry_msgs::TwistStamped msg;
        msg.header.stamp = ::ros::Time(b.twist.stamp);
        msg.header.frame_id = b.twist.frame_id;
        msg.twist.linear.x = b.twist.vx;
        msg.twist.linear.y = b.twist.vy;
        msg.twist.linear.z = b.twist.vz;
        msg.twist.angular.x = b.twist.wx;
        msg.twist.angular.y = b.twist.wy;
        msg.twist.angular.z = b.twist.wz;
        b.publisher.publish(msg);
        break;
      }
      case PortType::TrajectoryState: {
        if (time + 1e-9 < b.next_due) break;
        if (!read_trajectory_state(b.port, b.trajectory_state, &b.sequence)) break;
        b.next_due = next_due_after(time, b.period);
        if (b.pr2) {
          b.publisher.publish(
              trajectory_state_msg<pr2_controllers_msgs::JointTrajectoryControllerState>(b.trajectory_state));
        } else {
          b.publisher.publish(to_msg(b.trajectory_state));
        }
        break;
      }
      default:
        break;
    }
  }
}

}  // namespace mechsim::ros
