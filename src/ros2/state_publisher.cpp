// The robot state publisher (state_publisher.hpp).
#include "ros2/state_publisher.hpp"

#include <cmath>

#include "physics/transform.hpp"
#include "ros2/conversions.hpp"

namespace mechsim::ros2 {

namespace {

using description::Pose;

bool moving(const description::Joint& j) {
  using description::JointType;
  return j.type == JointType::Revolute || j.type == JointType::Continuous || j.type == JointType::Prismatic;
}

geometry_msgs::msg::TransformStamped transform(const Pose& X, const std::string& parent, const std::string& child,
                                               const builtin_interfaces::msg::Time& stamp) {
  geometry_msgs::msg::TransformStamped t;
  t.header.stamp = stamp;
  t.header.frame_id = parent;
  t.child_frame_id = child;
  t.transform.translation.x = X.position.x;
  t.transform.translation.y = X.position.y;
  t.transform.translation.z = X.position.z;
  t.transform.rotation.w = X.orientation.w;
  t.transform.rotation.x = X.orientation.x;
  t.transform.rotation.y = X.orientation.y;
  t.transform.rotation.z = X.orientation.z;
  return t;
}

}  // namespace

Pose joint_transform(const description::Joint& joint, double q) {
  using description::JointType;
  Pose motion;
  if (joint.type == JointType::Revolute || joint.type == JointType::Continuous) {
    const double s = std::sin(0.5 * q);
    motion.orientation = {std::cos(0.5 * q), joint.axis.x * s, joint.axis.y * s, joint.axis.z * s};
  } else if (joint.type == JointType::Prismatic) {
    motion.position = {joint.axis.x * q, joint.axis.y * q, joint.axis.z * q};
  }
  return physics::compose(joint.origin, motion);
}

StatePublisher::StatePublisher(Participant& participant, Outbox& outbox, const std::string& ns,
                               const description::RobotModel& robot, const std::string& urdf, std::string odom_frame)
    : robot_(robot), outbox_(outbox), odom_frame_(std::move(odom_frame)), node_(participant, ns, "robot_state_publisher") {
  description_pub_ = node_.create_publisher<std_msgs::msg::String>("robot_description", Qos::latched());
  tf_pub_ = node_.create_publisher<tf2_msgs::msg::TFMessage>("/tf", Qos::tf());
  static_pub_ = node_.create_publisher<tf2_msgs::msg::TFMessage>("/tf_static", Qos::latched());
  std_msgs::msg::String text;
  text.data = urdf;
  description_pub_->publish(text);
}

void StatePublisher::publish_static(double time) {
  tf2_msgs::msg::TFMessage msg;
  const auto stamp = to_time(time);
  for (const description::Joint& j : robot_.joints) {
    if (!moving(j)) msg.transforms.push_back(transform(j.origin, j.parent_link, j.child_link, stamp));
  }
  static_pub_->publish(msg);
}

void StatePublisher::publish(double time, const std::vector<double>& q, const description::Pose& X_OB) {
  if (tf_pub_->matched() == 0) return;  // volatile: nobody misses what is not sent
  const auto stamp = to_time(time);
  auto message = std::make_shared<tf2_msgs::msg::TFMessage>();
  message->transforms.reserve(robot_.joints.size() + 1);
  for (std::size_t i = 0; i < robot_.joints.size() && i < q.size(); ++i) {
    const description::Joint& j = robot_.joints[i];
    if (moving(j)) message->transforms.push_back(transform(joint_transform(j, q[i]), j.parent_link, j.child_link, stamp));
  }
  if (!odom_frame_.empty()) message->transforms.push_back(transform(X_OB, odom_frame_, robot_.root_link, stamp));
  if (message->transforms.empty()) return;
  auto pub = tf_pub_;
  outbox_.post([pub, message] { pub->publish(*message); });
}

}  // namespace mechsim::ros2
