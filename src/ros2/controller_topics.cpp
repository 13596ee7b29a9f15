// Each loaded controller as ros2_control presents it: a node named after the controller in the
// controller manager's namespace, with ros2_controllers' topic names and types (README.md,
// "Controllers"). Made at load, removed at unload.
//
//   ArrayCommand      ~/commands          std_msgs/msg/Float64MultiArray  (forward_command_controller,
//                                                                           JointGroup*Controller)
//   ScalarCommand     ~/command           std_msgs/msg/Float64            (mechsim's single-joint
//                                                                           controllers; ROS 2 has none)
//   TwistCommand      ~/cmd_vel           geometry_msgs/msg/TwistStamped  (diff_drive_controller: Jazzy;
//                                                                           Humble with use_stamped_vel)
//                     ~/cmd_vel_unstamped geometry_msgs/msg/Twist         (Humble, use_stamped_vel false)
//   TrajectoryCommand ~/joint_trajectory  trajectory_msgs/msg/JointTrajectory (joint_trajectory_controller)
//   JointStates       joint_states        sensor_msgs/msg/JointState      (joint_state_broadcaster: in
//                                                                           the manager's namespace;
//                                                                           ~/joint_states with
//                                                                           use_local_topics)
//   Odometry          ~/odom              nav_msgs/msg/Odometry, and odom -> base on /tf unless
//                                         enable_odom_tf is false, at publish_rate (default 50 Hz)
//   ImuState          ~/imu               sensor_msgs/msg/Imu             (imu_sensor_broadcaster; with
//                                                                           several IMUs ~/<sensor name>)
//   TwistState        ~/cmd_vel_out       geometry_msgs/msg/TwistStamped  (publish_limited_velocity)
//   TrajectoryGoal    ~/follow_joint_trajectory  control_msgs/action/FollowJointTrajectory (actions.hpp)
//   GripperGoal       ~/gripper_cmd       control_msgs/action/GripperCommand (gripper_action_controller)
// A controller parameter <port>_topic renames a topic (relative names resolve in the
// controller's node). Subscriptions ask for best effort, volatile, keep last 1 (every writer
// matches: qos.hpp); publishers offer what rmw_fastrtps makes of ros2_controllers'
// SystemDefaultsQoS, Fast DDS's default writer: reliable, transient local, keep last 1.

#include <mechsim_ros2_msgs/geometry_msgs.hpp>
#include <mechsim_ros2_msgs/nav_msgs.hpp>
#include <mechsim_ros2_msgs/sensor_msgs.hpp>
#include <mechsim_ros2_msgs/std_msgs.hpp>
#include <mechsim_ros2_msgs/tf2_msgs.hpp>
#include <mechsim_ros2_msgs/trajectory_msgs.hpp>

#include "ros2/actions.hpp"
#include "ros2/conversions.hpp"
#include "ros2/sim_node.hpp"

namespace mechsim::ros2 {

struct SimNode::Binding {
  bridge::PortRef port;
  bool alive = true;  // under bindings_mutex_: false once unbinding started
  std::shared_ptr<void> subscription;  // a Subscription<M>
  // Shared with the outbox's jobs (outbox.hpp), which write what the loop thread filled.
  std::shared_ptr<Publisher<sensor_msgs::msg::JointState>> joint_states;
  std::shared_ptr<Publisher<nav_msgs::msg::Odometry>> odom;
  std::shared_ptr<Publisher<tf2_msgs::msg::TFMessage>> odom_tf;
  std::shared_ptr<Publisher<sensor_msgs::msg::Imu>> imu;
  std::shared_ptr<Publisher<geometry_msgs::msg::TwistStamped>> twist_out;
  ControllerAction action;  // goal ports: the action server (polled by the SimNode's poller)
  double period = 0.0;  // s (sim time) between messages; 0: every new snapshot
  double next_due = 0.0;
  std::uint64_t sequence = 0;
  bridge::JointStatesData joint_data;
  bridge::OdometryData odom_data;
  bridge::TwistStampedData twist_data;
};

namespace {

// A controller parameter, or `fallback` when it is absent or unreadable (logged).
template <class T>
T controller_param(const control::Params& params, const std::string& controller, const std::string& key, T fallback,
                   Participant& log) {
  try {
    if (auto c = params.find(controller); c && c->has(key)) return c->get<T>(key);
  } catch (const std::exception& e) {
    log.log(e.what());
  }
  return fallback;
}

// A command subscription: each sample is written to the binding's port (lookup) with
// write(port, message, &error) under `mutex` while the binding is alive; a refused command is
// logged at most once a second per subscription.
template <class M, class Write>
std::shared_ptr<void> subscribe_command_impl(Node& node, const std::string& topic, std::mutex& mutex,
                                             const std::function<bool(const bridge::PortRef*&)>& lookup,
                                             std::atomic<std::uint64_t>& written, std::atomic<std::uint64_t>& rejected,
                                             Write write) {
  auto last_log = std::make_shared<std::chrono::steady_clock::time_point>();
  Participant* participant = &node.participant();
  const std::string name = node.resolve(topic);
  std::function<void(const M&)> callback = [&mutex, lookup, &written, &rejected, write, last_log, participant,
                                            name](const M& msg) {
    std::lock_guard<std::mutex> lock(mutex);
    const bridge::PortRef* port = nullptr;
    if (!lookup(port) || port == nullptr) return;
    std::string error;
    if (write(*port, msg, &error)) {
      written.fetch_add(1, std::memory_order_relaxed);
      return;
    }
    rejected.fetch_add(1, std::memory_order_relaxed);
    const auto now = std::chrono::steady_clock::now();
    if (now - *last_log >= std::chrono::seconds(1)) {
      *last_log = now;
      participant->log(name + ": command rejected by controller '" + port->controller + "': " + error);
    }
  };
  return std::shared_ptr<void>(node.create_subscription<M>(topic, Qos::command_reader(), std::move(callback)));
}

}  // namespace

void SimNode::bind(const std::string& controller) {
  const control::Params params = bridge_->controller_params();
  auto node = std::make_unique<Node>(*participant_, options_.robot_namespace, controller, options_.controller_remaps);
  std::vector<std::shared_ptr<Binding>> made;
  std::vector<std::string> lines;
  const Qos state_qos{Reliability::Reliable, Durability::TransientLocal, 1};
  const std::vector<bridge::PortRef> ports = bridge_->ports(controller);
  int imu_ports = 0;
  for (const bridge::PortRef& p : ports) imu_ports += p.type == bridge::PortType::ImuState ? 1 : 0;
  for (const bridge::PortRef& port : ports) {
    auto b = std::make_shared<Binding>();
    b->port = port;
    // A raw pointer: the binding outlives every callback of its subscription (destroying the
    // subscription waits for a running one), and `alive` turns false under bindings_mutex_ first.
    // (A weak_ptr locked in the callback could make the callback the binding's last owner, which
    // would destroy the subscription from inside its own callback.)
    Binding* raw = b.get();
    auto lookup = [raw](const bridge::PortRef*& out) {
      if (!raw->alive) return false;
      out = &raw->port;
      return true;
    };
    auto topic_for = [&](const std::string& fallback) {
      return controller_param<std::string>(params, controller, port.name + "_topic", fallback, *participant_);
    };
    auto note = [&](const std::string& topic, const char* type) {
      lines.push_back(node->resolve(topic) + " (" + type + ", controller " + controller + ")");
    };
    switch (port.type) {
      case bridge::PortType::ScalarCommand: {
        const std::string topic = topic_for("~/" + port.name);
        b->subscription = subscribe_command_impl<std_msgs::msg::Float64>(
            *node, topic, bindings_mutex_, lookup, commands_, commands_rejected_,
            [](const bridge::PortRef& p, const std_msgs::msg::Float64& m, std::string* e) { return bridge::write_scalar(p, m.data, e); });
        note(topic, "std_msgs/msg/Float64, subscribed");
        break;
      }
      case bridge::PortType::ArrayCommand: {
        const std::string topic = topic_for(port.name == "command" ? "~/commands" : "~/" + port.name);
        b->subscription = subscribe_command_impl<std_msgs::msg::Float64MultiArray>(
            *node, topic, bindings_mutex_, lookup, commands_, commands_rejected_,
            [](const bridge::PortRef& p, const std_msgs::msg::Float64MultiArray& m, std::string* e) {
              return bridge::write_array(p, m.data, e);
            });
        note(topic, "std_msgs/msg/Float64MultiArray, subscribed");
        break;
      }
      case bridge::PortType::TwistCommand: {
        const bool stamped = participant_->distro() == Distro::Jazzy ||
                             controller_param<bool>(params, controller, "use_stamped_vel", options_.use_stamped_vel, *participant_);
        if (stamped) {
          const std::string topic = topic_for("~/" + port.name);
          b->subscription = subscribe_command_impl<geometry_msgs::msg::TwistStamped>(
              *node, topic, bindings_mutex_, lookup, commands_, commands_rejected_,
              [](const bridge::PortRef& p, const geometry_msgs::msg::TwistStamped& m, std::string* e) {
                const auto& t = m.twist;
                return bridge::write_twist(p, t.linear.x, t.linear.y, t.linear.z, t.angular.x, t.angular.y, t.angular.z, e);
              });
          note(topic, "geometry_msgs/msg/TwistStamped, subscribed");
        } else {
          const std::string topic = topic_for("~/" + port.name + "_unstamped");
          b->subscription = subscribe_command_impl<geometry_msgs::msg::Twist>(
              *node, topic, bindings_mutex_, lookup, commands_, commands_rejected_,
              [](const bridge::PortRef& p, const geometry_msgs::msg::Twist& t, std::string* e) {
                return bridge::write_twist(p, t.linear.x, t.linear.y, t.linear.z, t.angular.x, t.angular.y, t.angular.z, e);
              });
          note(topic, "geometry_msgs/msg/Twist, subscribed");
        }
        break;
      }
      case bridge::PortType::TrajectoryCommand: {
        const std::string topic = topic_for("~/joint_trajectory");
        b->subscription = subscribe_command_impl<trajectory_msgs::msg::JointTrajectory>(
            *node, topic, bindings_mutex_, lookup, commands_, commands_rejected_,
            [](const bridge::PortRef& p, const trajectory_msgs::msg::JointTrajectory& m, std::string* e) {
              return bridge::write_trajectory(p, trajectory_of(m), e);
            });
        note(topic, "trajectory_msgs/msg/JointTrajectory, subscribed");
        break;
      }
      case bridge::PortType::JointStates: {
        // joint_state_broadcaster: in the manager's namespace, or its own with use_local_topics.
        const bool local = controller_param<bool>(params, controller, "use_local_topics", false, *participant_);
        const std::string topic = topic_for(local ? "~/joint_states" : "joint_states");
        b->joint_states = node->create_publisher<sensor_msgs::msg::JointState>(topic, state_qos);
        note(topic, "sensor_msgs/msg/JointState");
        break;
      }
      case bridge::PortType::Odometry: {
        const std::string topic = topic_for("~/odom");
        b->odom = node->create_publisher<nav_msgs::msg::Odometry>(topic, state_qos);
        const double rate = controller_param<double>(params, controller, "publish_rate", 50.0, *participant_);
        b->period = rate > 0.0 ? 1.0 / rate : 0.0;
        note(topic, "nav_msgs/msg/Odometry");
        if (controller_param<bool>(params, controller, "enable_odom_tf", true, *participant_)) {
          b->odom_tf = node->create_publisher<tf2_msgs::msg::TFMessage>("/tf", Qos::tf());
          note("/tf", "tf2_msgs/msg/TFMessage, odometry");
        }
        break;
      }
      case bridge::PortType::ImuState: {
        const std::string topic = topic_for(imu_ports > 1 ? "~/" + port.name : "~/imu");
        b->imu = node->create_publisher<sensor_msgs::msg::Imu>(topic, state_qos);
        note(topic, "sensor_msgs/msg/Imu");
        break;
      }
      case bridge::PortType::TwistState: {
        const std::string topic = topic_for("~/cmd_vel_out");
        b->twist_out = node->create_publisher<geometry_msgs::msg::TwistStamped>(topic, state_qos);
        note(topic, "geometry_msgs/msg/TwistStamped");
        break;
      }
      case bridge::PortType::TrajectoryGoal:
      case bridge::PortType::GripperGoal: {
        const std::string name = topic_for(default_action_name(port));
        bridge::SimBridge* bridge = bridge_;
        b->action = make_controller_action(*node, name, port, [bridge] { return bridge->time(); });
        lines.push_back(b->action.name + " (" + b->action.type + " action, controller " + controller + ")");
        break;
      }
      default:
        continue;  // state topics (control_msgs) and services: not on ROS 2 yet
    }
    made.push_back(std::move(b));
  }
  for (const auto& b : made)
    if (b->action.server) poller_->add(b->action.server);
  std::lock_guard<std::mutex> lock(bindings_mutex_);
  for (auto& b : made) bindings_.push_back(std::move(b));
  controller_nodes_.push_back(std::move(node));
  for (auto& l : lines) topic_lines_.push_back(std::move(l));
}

void SimNode::unbind(const std::string& controller) {
  std::vector<std::shared_ptr<Binding>> removed;
  std::unique_ptr<Node> node;
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
    for (auto it = controller_nodes_.begin(); it != controller_nodes_.end(); ++it) {
      if ((*it)->name() == controller) {
        node = std::move(*it);
        controller_nodes_.erase(it);
        break;
      }
    }
    const std::string tag = ", controller " + controller + ")";
    std::erase_if(topic_lines_, [&](const std::string& l) { return l.size() >= tag.size() && l.ends_with(tag); });
  }
  // The actions' goals end (CANCELED, as ros2_controllers' deactivation) before the port goes;
  // the endpoints go outside the lock: a command callback may be waiting for it, and deleting its
  // reader waits for the callback.
  for (const auto& b : removed) {
    if (!b->action.server) continue;
    poller_->remove(b->action.server.get());
    b->action.shutdown("controller '" + controller + "' is unloading");
  }
  removed.clear();
  node.reset();
}

ActionStats SimNode::action_stats() const {
  std::vector<std::function<ActionStats()>> each;
  {
    std::lock_guard<std::mutex> lock(bindings_mutex_);
    for (const auto& b : bindings_)
      if (b->action.stats) each.push_back(b->action.stats);
  }
  ActionStats sum;
  for (const auto& f : each) sum += f();
  return sum;
}

void SimNode::stop_actions(const std::string& why) {
  std::vector<ControllerAction> actions;
  {
    std::lock_guard<std::mutex> lock(bindings_mutex_);
    for (const auto& b : bindings_)
      if (b->action.server) actions.push_back(b->action);
  }
  for (const ControllerAction& a : actions) {
    poller_->remove(a.server.get());
    a.shutdown(why);
  }
}

void SimNode::publish_controller_states(double time) {
  // A message filled here and written by the outbox thread; nothing while nobody subscribes (the
  // port's snapshot is not even read).
  auto send = [this](const auto& publisher, auto message) {
    auto pub = publisher;
    outbox_->post([pub, message] { pub->publish(*message); });
  };
  std::lock_guard<std::mutex> lock(bindings_mutex_);
  for (const std::shared_ptr<Binding>& bp : bindings_) {
    Binding& b = *bp;
    switch (b.port.type) {
      case bridge::PortType::JointStates: {
        if (b.joint_states->matched() == 0) break;
        if (!bridge::read_joint_states(b.port, b.joint_data, &b.sequence)) break;
        auto msg = std::make_shared<sensor_msgs::msg::JointState>();
        fill_joint_state(b.joint_data, *msg);
        send(b.joint_states, msg);
        break;
      }
      case bridge::PortType::Odometry: {
        if (time + 1e-9 < b.next_due) break;
        if (b.odom->matched() == 0 && (!b.odom_tf || b.odom_tf->matched() == 0)) break;
        if (!bridge::read_odometry(b.port, b.odom_data, &b.sequence)) break;
        b.next_due = next_due_after(time, b.period);
        auto msg = std::make_shared<nav_msgs::msg::Odometry>();
        fill_odometry(b.odom_data, *msg);
        if (b.odom_tf && b.odom_tf->matched() > 0) {
          auto tf = std::make_shared<tf2_msgs::msg::TFMessage>();
          auto& t = tf->transforms.emplace_back();
          t.header = msg->header;
          t.child_frame_id = msg->child_frame_id;
          t.transform.translation.x = b.odom_data.x;
          t.transform.translation.y = b.odom_data.y;
          t.transform.translation.z = b.odom_data.z;
          t.transform.rotation = msg->pose.pose.orientation;
          send(b.odom_tf, tf);
        }
        if (b.odom->matched() > 0) send(b.odom, msg);
        break;
      }
      case bridge::PortType::ImuState: {
        if (b.imu->matched() == 0) break;
        double stamp = 0.0;
        sensors::ImuReading reading;
        auto msg = std::make_shared<sensor_msgs::msg::Imu>();
        if (!bridge::read_imu_state(b.port, stamp, msg->header.frame_id, reading, &b.sequence)) break;
        fill_imu(reading, *msg);
        msg->header.stamp = to_time(stamp);
        send(b.imu, msg);
        break;
      }
      case bridge::PortType::TwistState: {
        if (b.twist_out->matched() == 0) break;
        if (!bridge::read_twist_state(b.port, b.twist_data, &b.sequence)) break;
        auto msg = std::make_shared<geometry_msgs::msg::TwistStamped>();
        msg->header.stamp = to_time(b.twist_data.stamp);
        msg->header.frame_id = b.twist_data.frame_id;
        msg->twist.linear.x = b.twist_data.vx;
        msg->twist.linear.y = b.twist_data.vy;
        msg->twist.linear.z = b.twist_data.vz;
        msg->twist.angular.x = b.twist_data.wx;
        msg->twist.angular.y = b.twist_data.wy;
        msg->twist.angular.z = b.twist_data.wz;
        send(b.twist_out, msg);
        break;
      }
      default:
        break;
    }
  }
}

}  // namespace mechsim::ros2
