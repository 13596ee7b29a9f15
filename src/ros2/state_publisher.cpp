// The robot state publisher (state_publisher.hpp).
#include "ros2/state_publisher.hpp"

#include <cmath>

#include "bridge/robot_frames.hpp"
#include "ros2/conversions.hpp"

namespace mechsim::ros2 {

namespace {

using description::Pose;

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
  for (const bridge::JointFrame& f : bridge::fixed_frames(robot_))
    msg.transforms.push_back(transform(f.X_PC, f.joint->parent_link, f.joint->child_link, stamp));
  static_pub_->publish(msg);
}

void StatePublisher::publish(double time, const std::vector<double>& q, const description::Pose& X_OB) {
  if (tf_pub_->matched() == 0) return;  // volatile: nobody misses what is not sent
  const auto stamp = to_time(time);
  auto message = std::make_shared<tf2_msgs::msg::TFMessage>();
  message->transforms.reserve(robot_.joints.size() + 1);
  bridge::moving_frames(robot_, q, frames_);
  for (const bridge::JointFrame& f : frames_)
    message->transforms.push_back(transform(f.X_PC, f.joint->parent_link, f.joint->child_link, stamp));
  if (!odom_frame_.empty()) message->transforms.push_back(transform(X_OB, odom_frame_, robot_.root_link, stamp));
  if (message->transforms.empty()) return;
  auto pub = tf_pub_;
  outbox_.post([pub, message] { pub->publish(*message); });
}

}  // namespace mechsim::ros2
