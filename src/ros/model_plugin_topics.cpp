#include "ros/model_plugin_topics.hpp"

#include <cmath>

#include <geometry_msgs/Pose.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <tf2_msgs/TFMessage.h>

#include "ros/publish_helpers.hpp"
#include "ros/tf_publisher.hpp"

namespace mechsim::ros {

struct ModelPluginTopics::Output {
  PortRef port;
  ::ros::Publisher publisher;
  std::uint64_t sequence = 0;
  bool odom_tf = false;
  std::vector<const description::Joint*> wheel_tf;  // publishWheelTF
  std::vector<std::pair<std::string, std::string>> wheel_frames;  // parent, child
  OdometryData odom;
  JointStatesData joint_states;
};

namespace {

// gazebo_plugins resolve frames with tf::resolve: a leading '/' goes.
std::string frame(const std::string& f) { return !f.empty() && f.front() == '/' ? f.substr(1) : f; }

// tf::resolve(prefix, name) (controllers/plugins/gazebo_ros_names.hpp's tf_resolve).
std::string resolved(const std::string& prefix, const std::string& name) {
  if (!name.empty() && name.front() == '/') return name.substr(1);
  if (prefix.empty()) return name;
  return (prefix.front() == '/' ? prefix.substr(1) : prefix) + "/" + name;
}

}  // namespace

ModelPluginTopics::ModelPluginTopics(::ros::NodeHandle& root, SimBridge& bridge) : bridge_(bridge) {
  for (const std::string& note : bridge_.plugin_notes()) ROS_WARN_STREAM("mechsim: " << note);
  const std::vector<ModelPluginSummary> plugins = bridge_.model_plugins();
  plugins_ = plugins.size();
  bool any_tf = false;
  for (const ModelPluginSummary& plugin : plugins) {
    ::ros::NodeHandle nh(root, plugin.robot_namespace);
    for (const PluginTopicRef& t : plugin.topics) {
      switch (t.port.type) {
        case PortType::TwistCommand: {
          const PortRef port = t.port;
          if (t.message == "geometry_msgs/Pose") {
            // Gazebo's DiffDrivePlugin takes a gazebo.msgs.Pose: position.x the speed, the
            // orientation's yaw the turn rate.
            subscribers_.push_back(nh.subscribe<geometry_msgs::Pose>(t.topic, 1, [port](const geometry_msgs::Pose::ConstPtr& m) {
              const geometry_msgs::Quaternion& q = m->orientation;
              const double yaw = std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
              std::string error;
              if (!write_twist(port, m->position.x, 0.0, 0.0, 0.0, 0.0, yaw, &error)) {
                ROS_WARN_STREAM_THROTTLE(1.0, "mechsim: " << port.controller << ": vel_cmd rejected: " << error);
              }
            }));
            break;
          }
          subscribers_.push_back(nh.subscribe<geometry_msgs::Twist>(t.topic, 1, [port](const geometry_msgs::Twist::ConstPtr& m) {
            std::string error;
            if (!write_twist(port, m->linear.x, m->linear.y, m->linear.z, m->angular.x, m->angular.y, m->angular.z, &error)) {
              ROS_WARN_STREAM_THROTTLE(1.0, "mechsim: " << port.controller << ": cmd_vel rejected: " << error);
            }
          }));
          break;
        }
        case PortType::Odometry: {
          Output out;
          out.port = t.port;
          out.publisher = nh.advertise<nav_msgs::Odometry>(t.topic, 1);
          out.odom_tf = plugin.odom_tf;
          any_tf = any_tf || out.odom_tf;
          outputs_.push_back(std::move(out));
          break;
        }
        case PortType::JointStates: {
          Output out;
          out.port = t.port;
          // No topic: the port only feeds publishWheelTF.
          if (!t.topic.empty()) out.publisher = nh.advertise<sensor_msgs::JointState>(t.topic, 1000);
          for (const std::string& j : plugin.wheel_tf_joints) {
            if (const description::Joint* joint = bridge_.robot().joint(j)) {
              out.wheel_tf.push_back(joint);
              out.wheel_frames.emplace_back(resolved(plugin.tf_prefix, joint->parent_link),
                                            resolved(plugin.tf_prefix, plugin.wheel_tf_child_is_joint ? joint->name : joint->child_link));
            }
          }
          any_tf = any_tf || !out.wheel_tf.empty();
          outputs_.push_back(std::move(out));
          break;
        }
        default:
          break;
      }
    }
    ROS_INFO_STREAM("mechsim: gazebo plugin '" << plugin.name << "' (" << plugin.filename << ") simulated, namespace '"
                                               << plugin.robot_namespace << "'");
  }
  if (any_tf) tf_pub_ = root.advertise<tf2_msgs::TFMessage>("/tf", 100);
}

ModelPluginTopics::~ModelPluginTopics() = default;

void ModelPluginTopics::publish_odometry(Output& out) {
  if (!read_odometry(out.port, out.odom, &out.sequence)) return;
  const OdometryData& o = out.odom;
  nav_msgs::Odometry msg;
  msg.header.stamp = ::ros::Time(o.stamp);
  msg.header.frame_id = frame(o.frame_id);
  msg.child_frame_id = frame(o.child_frame_id);
  msg.pose.pose.position.x = o.x;
  msg.pose.pose.position.y = o.y;
  msg.pose.pose.position.z = o.z;
  msg.pose.pose.orientation.w = o.qw;
  msg.pose.pose.orientation.x = o.qx;
  msg.pose.pose.orientation.y = o.qy;
  msg.pose.pose.orientation.z = o.qz;
  msg.twist.twist.linear.x = o.vx;
  msg.twist.twist.linear.y = o.vy;
  msg.twist.twist.angular.z = o.wz;
  for (std::size_t k = 0; k < 36 && k < o.pose_covariance.size(); ++k) {
    msg.pose.covariance[k] = o.pose_covariance[k];
    msg.twist.covariance[k] = o.twist_covariance[k];
  }
  out.publisher.publish(msg);
  if (!out.odom_tf) return;
  tf2_msgs::TFMessage tf;
  geometry_msgs::TransformStamped t;
  t.header = msg.header;
  t.child_frame_id = msg.child_frame_id;
  t.transform.translation.x = o.x;
  t.transform.translation.y = o.y;
  t.transform.translation.z = o.z;
  t.transform.rotation = msg.pose.pose.orientation;
  tf.transforms.push_back(t);
  tf_pub_.publish(tf);
}

void ModelPluginTopics::publish_joint_states(Output& out) {
  if (!read_joint_states(out.port, out.joint_states, &out.sequence)) return;
  if (out.publisher) out.publisher.publish(to_msg(out.joint_states));
  if (out.wheel_tf.empty()) return;
  tf2_msgs::TFMessage tf;
  for (std::size_t k = 0; k < out.wheel_tf.size(); ++k) {
    const description::Joint* joint = out.wheel_tf[k];
    double q = 0.0;
    for (std::size_t i = 0; i < out.joint_states.names.size(); ++i) {
      if (out.joint_states.names[i] == joint->name && i < out.joint_states.position.size()) q = out.joint_states.position[i];
    }
    const description::Pose X = joint_transform(*joint, q);
    geometry_msgs::TransformStamped t;
    t.header.stamp = ::ros::Time(out.joint_states.stamp);
    t.header.frame_id = out.wheel_frames[k].first;
    t.child_frame_id = out.wheel_frames[k].second;
    t.transform.translation.x = X.position.x;
    t.transform.translation.y = X.position.y;
    t.transform.translation.z = X.position.z;
    t.transform.rotation.w = X.orientation.w;
    t.transform.rotation.x = X.orientation.x;
    t.transform.rotation.y = X.orientation.y;
    t.transform.rotation.z = X.orientation.z;
    tf.transforms.push_back(t);
  }
  tf_pub_.publish(tf);
}

void ModelPluginTopics::publish(double /*time*/) {
  for (Output& out : outputs_) {
    if (out.port.type == PortType::Odometry) publish_odometry(out);
    else publish_joint_states(out);
  }
}

}  // namespace mechsim::ros
