// mechsim_pose_ekf: robot_pose_ekf's node (the robot_pose_ekf package of src/ros/packages) over
// mechsim's fusion (ros/pose_fusion.hpp). Its names are robot_pose_ekf's:
//   subscribes  odom (nav_msgs/Odometry), imu_data (sensor_msgs/Imu)  (pr2_bringup.launch remaps
//               them to base_odometry/odom and torso_lift_imu/data)
//   publishes   ~odom_combined (geometry_msgs/PoseWithCovarianceStamped, frame ~output_frame)
//               and ~output_frame -> ~base_footprint_frame on /tf (unless ~publish_tf is false)
//   parameters  ~freq (30 Hz of ROS time: an estimate with the odometry message due then, so that
//               no period is lost on a loaded machine), ~sensor_timeout (1 s), ~odom_used, ~imu_used (true),
//               ~vo_used, ~gps_used (visual odometry and GPS are not fused: named once when set),
//               ~output_frame (odom_combined), ~base_footprint_frame (base_footprint), ~publish_tf
// Stamps: the older of the two sources' latest stamps, as robot_pose_ekf's filter time; an update
// happens only when that time has moved on (no repeated stamps on /tf). A source
// that has been silent for sensor_timeout (ROS time) is left out until it speaks again; without
// odometry nothing is published. robot_pose_ekf's ~get_status service is not offered.
#include <algorithm>
#include <cmath>

#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <sensor_msgs/Imu.h>
#include <tf2_msgs/TFMessage.h>

#include "ros/pose_fusion.hpp"

namespace {

using mechsim::ros::ImuAttitude;
using mechsim::ros::PlanarOdometry;
using mechsim::ros::PoseFusion;

void rpy_of(const geometry_msgs::Quaternion& q, double& roll, double& pitch, double& yaw) {
  roll = std::atan2(2.0 * (q.w * q.x + q.y * q.z), 1.0 - 2.0 * (q.x * q.x + q.y * q.y));
  pitch = std::asin(std::clamp(2.0 * (q.w * q.y - q.z * q.x), -1.0, 1.0));
  yaw = std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
}

geometry_msgs::Quaternion quaternion_of(double roll, double pitch, double yaw) {
  const double cr = std::cos(roll / 2), sr = std::sin(roll / 2), cp = std::cos(pitch / 2), sp = std::sin(pitch / 2);
  const double cy = std::cos(yaw / 2), sy = std::sin(yaw / 2);
  geometry_msgs::Quaternion q;
  q.w = cr * cp * cy + sr * sp * sy;
  q.x = sr * cp * cy - cr * sp * sy;
  q.y = cr * sp * cy + sr * cp * sy;
  q.z = cr * cp * sy - sr * sp * cy;
  return q;
}

class PoseEkfNode {
 public:
  PoseEkfNode() : pnh_("~") {
    output_frame_ = pnh_.param<std::string>("output_frame", "odom_combined");
    base_frame_ = pnh_.param<std::string>("base_footprint_frame", "base_footprint");
    timeout_ = pnh_.param("sensor_timeout", 1.0);
    publish_tf_ = pnh_.param("publish_tf", true);
    const double freq = std::max(pnh_.param("freq", 30.0), 1.0);
    if (pnh_.param("vo_used", true)) ROS_INFO("mechsim robot_pose_ekf: visual odometry (vo) is not fused");
    if (pnh_.param("gps_used", false)) ROS_INFO("mechsim robot_pose_ekf: GPS is not fused");
    pose_pub_ = pnh_.advertise<geometry_msgs::PoseWithCovarianceStamped>("odom_combined", 10);
    if (publish_tf_) tf_pub_ = nh_.advertise<tf2_msgs::TFMessage>("/tf", 100);
    if (pnh_.param("odom_used", true)) odom_sub_ = nh_.subscribe("odom", 10, &PoseEkfNode::on_odom, this);
    if (pnh_.param("imu_used", true)) imu_sub_ = nh_.subscribe("imu_data", 10, &PoseEkfNode::on_imu, this);
    period_ = 1.0 / freq;
    timer_ = nh_.createTimer(::ros::Duration(0.1), &PoseEkfNode::check_timeouts, this);
    ROS_INFO_STREAM("mechsim robot_pose_ekf: " << output_frame_ << " -> " << base_frame_ << " at " << freq
                                               << " Hz from odom and imu_data");
  }

 private:
  void on_odom(const nav_msgs::Odometry::ConstPtr& msg) {
    PlanarOdometry o;
    o.x = msg->pose.pose.position.x;
    o.y = msg->pose.pose.position.y;
    double roll = 0.0, pitch = 0.0;
    rpy_of(msg->pose.pose.orientation, roll, pitch, o.yaw);
    o.var_xy = msg->pose.covariance[0];
    o.var_yaw = msg->pose.covariance[35];
    fusion_.add_odometry(o);
    odom_stamp_ = msg->header.stamp;
    odom_seen_ = ::ros::Time::now();
    if (!odom_active_) ROS_INFO("mechsim robot_pose_ekf: odometry active");
    odom_active_ = true;
    // Due at ~freq of ROS time by the odometry's stamps, on its arrival rather than a timer's: a
    // timer that falls behind on a loaded machine skips periods, queued measurements are all taken.
    const ::ros::Time t = msg->header.stamp;
    if (next_due_.isZero() || t >= next_due_) {
      next_due_ = (next_due_.isZero() || (t - next_due_).toSec() > period_) ? t + ::ros::Duration(period_)
                                                                           : next_due_ + ::ros::Duration(period_);
      publish();
    }
  }

  void on_imu(const sensor_msgs::Imu::ConstPtr& msg) {
    ImuAttitude a;
    rpy_of(msg->orientation, a.roll, a.pitch, a.yaw);
    a.var_yaw = msg->orientation_covariance[8];
    fusion_.add_imu(a);
    imu_stamp_ = msg->header.stamp;
    imu_seen_ = ::ros::Time::now();
    if (!imu_active_) ROS_INFO("mechsim robot_pose_ekf: IMU active");
    imu_active_ = true;
  }

  // A source silent for ~sensor_timeout is left out until it speaks again.
  void check_timeouts(const ::ros::TimerEvent&) {
    const ::ros::Time now = ::ros::Time::now();
    if (odom_active_ && (now - odom_seen_).toSec() > timeout_) {
      odom_active_ = false;
      ROS_INFO("mechsim robot_pose_ekf: odometry not active any more");
    }
    if (imu_active_ && (now - imu_seen_).toSec() > timeout_) {
      imu_active_ = false;
      fusion_.drop_imu();
      ROS_INFO("mechsim robot_pose_ekf: IMU not active any more");
    }
  }

  void publish() {
    if (!odom_active_) return;
    ::ros::Time stamp = odom_stamp_;
    if (imu_active_ && imu_stamp_ < stamp) stamp = imu_stamp_;
    // Only newer measurements make a new estimate (robot_pose_ekf's filter updates only forward
    // in time): no repeated stamps on /tf while the clock stands (paused, or no new data).
    if (stamp <= last_stamp_) return;
    last_stamp_ = stamp;
    if (!fusion_.update()) return;
    const mechsim::ros::FusedPose& e = fusion_.estimate();
    geometry_msgs::PoseWithCovarianceStamped out;
    out.header.stamp = stamp;
    out.header.frame_id = output_frame_;
    out.pose.pose.position.x = e.x;
    out.pose.pose.position.y = e.y;
    out.pose.pose.position.z = e.z;
    out.pose.pose.orientation = quaternion_of(e.roll, e.pitch, e.yaw);
    std::copy(e.covariance.begin(), e.covariance.end(), out.pose.covariance.begin());
    pose_pub_.publish(out);
    if (!publish_tf_) return;
    tf2_msgs::TFMessage tf;
    tf.transforms.resize(1);
    geometry_msgs::TransformStamped& t = tf.transforms[0];
    t.header = out.header;
    t.child_frame_id = base_frame_;
    t.transform.translation.x = e.x;
    t.transform.translation.y = e.y;
    t.transform.translation.z = 0.0;
    t.transform.rotation = out.pose.pose.orientation;
    tf_pub_.publish(tf);
  }

  ::ros::NodeHandle nh_, pnh_;
  std::string output_frame_, base_frame_;
  double timeout_ = 1.0, period_ = 1.0 / 30.0;
  bool publish_tf_ = true;
  ::ros::Publisher pose_pub_, tf_pub_;
  ::ros::Subscriber odom_sub_, imu_sub_;
  ::ros::Timer timer_;
  PoseFusion fusion_;
  ::ros::Time odom_stamp_, imu_stamp_, odom_seen_, imu_seen_, last_stamp_, next_due_;
  bool odom_active_ = false, imu_active_ = false;
};

}  // namespace

int main(int argc, char** argv) {
  ::ros::init(argc, argv, "robot_pose_ekf");
  PoseEkfNode node;
  ::ros::spin();
  return 0;
}
