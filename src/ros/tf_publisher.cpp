#include "ros/tf_publisher.hpp"

#include <cmath>

namespace mechsim::ros {

namespace {

using description::Pose;

geometry_msgs::TransformStamped to_msg(const Pose& X, const std::string& parent, const std::string& child,
                                       const ::ros::Time& stamp) {
  geometry_msgs::TransformStamped t;
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

TfPublisher::TfPublisher(::ros::NodeHandle& nh, const description::RobotModel& robot, std::string odom_frame)
    : robot_(robot), odom_frame_(std::move(odom_frame)) {
  tf_pub_ = nh.advertise<tf2_msgs::TFMessage>("/tf", 100);
  static_pub_ = nh.advertise<tf2_msgs::TFMessage>("/tf_static", 100, /*latch=*/true);
}

void TfPublisher::publish_static(double time) {
  tf2_msgs::TFMessage msg;
  const ::ros::Time stamp(time);
  for (const JointFrame& f : fixed_frames(robot_))
    msg.transforms.push_back(to_msg(f.X_PC, f.joint->parent_link, f.joint->child_link, stamp));
  static_pub_.publish(msg);
}

void TfPublisher::publish(double time, const std::vector<double>& q, const description::Pose& X_OB) {
  const ::ros::Time stamp(time);
  message_.transforms.clear();
  moving_frames(robot_, q, frames_);
  for (const JointFrame& f : frames_)
    message_.transforms.push_back(to_msg(f.X_PC, f.joint->parent_link, f.joint->child_link, stamp));
  if (!odom_frame_.empty()) message_.transforms.push_back(to_msg(X_OB, odom_frame_, robot_.root_link, stamp));
  if (!message_.transforms.empty()) tf_pub_.publish(message_);
}

}  // namespace mechsim::ros
