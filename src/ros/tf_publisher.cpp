#include "ros/tf_publisher.hpp"

#include <cmath>

namespace mechsim::ros {

namespace {

using description::Pose;
using description::Quat;
using description::Vec3;

Quat multiply(const Quat& a, const Quat& b) {
  return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
          a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

Vec3 rotate(const Quat& q, const Vec3& v) {
  const Quat p{0.0, v.x, v.y, v.z};
  const Quat r = multiply(multiply(q, p), Quat{q.w, -q.x, -q.y, -q.z});
  return {r.x, r.y, r.z};
}

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

bool moving(const description::Joint& j) {
  using description::JointType;
  return j.type == JointType::Revolute || j.type == JointType::Continuous || j.type == JointType::Prismatic;
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
  // origin * motion: translate by origin + R_origin * t_motion, rotate by R_origin * R_motion.
  Pose X;
  const Vec3 t = rotate(joint.origin.orientation, motion.position);
  X.position = {joint.origin.position.x + t.x, joint.origin.position.y + t.y, joint.origin.position.z + t.z};
  X.orientation = multiply(joint.origin.orientation, motion.orientation);
  return X;
}

TfPublisher::TfPublisher(::ros::NodeHandle& nh, const description::RobotModel& robot, std::string odom_frame)
    : robot_(robot), odom_frame_(std::move(odom_frame)) {
  tf_pub_ = nh.advertise<tf2_msgs::TFMessage>("/tf", 100);
  static_pub_ = nh.advertise<tf2_msgs::TFMessage>("/tf_static", 100, /*latch=*/true);
}

void TfPublisher::publish_static(double time) {
  tf2_msgs::TFMessage msg;
  const ::ros::Time stamp(time);
  for (const description::Joint& j : robot_.joints) {
    if (!moving(j)) msg.transforms.push_back(to_msg(j.origin, j.parent_link, j.child_link, stamp));
  }
  static_pub_.publish(msg);
}

void TfPublisher::publish(double time, const std::vector<double>& q, const description::Pose& X_OB) {
  const ::ros::Time stamp(time);
  message_.transforms.clear();
  for (std::size_t i = 0; i < robot_.joints.size() && i < q.size(); ++i) {
    const description::Joint& j = robot_.joints[i];
    if (moving(j)) message_.transforms.push_back(to_msg(joint_transform(j, q[i]), j.parent_link, j.child_link, stamp));
  }
  if (!odom_frame_.empty()) message_.transforms.push_back(to_msg(X_OB, odom_frame_, robot_.root_link, stamp));
  if (!message_.transforms.empty()) tf_pub_.publish(message_);
}

}  // namespace mechsim::ros
