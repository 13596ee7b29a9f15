#pragma once
// The odometry Gazebo's drive plugins read from the world rather than from the wheels (the diff
// drive's odometrySource "world", the skid steer, the planar move): the base's world pose, and
// its world velocity turned into the base's heading frame (x along the heading, y to its left,
// about z only), as those plugins compute it. Real-time: no allocation.

#include <array>
#include <string>

#include "controllers/drive/diff_drive_kinematics.hpp"  // EncoderOdometry
#include "controllers/drive/rover_drive_ports.hpp"  // OdometrySnapshot
#include "mechanism/base_state.hpp"

namespace mechsim::control {

// Yaw (rad) of an orientation: the heading of its x axis in the world's x-y plane.
double yaw_of(const description::Quat& q) noexcept;

// Fills `o` with the base's world pose (position with z, attitude) and twist: linear.x/y the
// world velocity rotated by -yaw, angular.z the world angular velocity's z. in_world is set.
void fill_world_odometry(OdometrySnapshot& o, const mechanism::BaseState& base, double time) noexcept;

// Fills `o` with the wheels' odometry (odometrySource "encoder" of the diff and tricycle drives):
// the integrated planar pose, yaw wrapped to (-pi, pi], the body twist along x and about z.
void fill_encoder_odometry(OdometrySnapshot& o, const EncoderOdometry& e, double time) noexcept;

// A prototype snapshot with frames and a pose covariance diagonal (x, y, z, roll, pitch, yaw) and a
// twist one (zeros when not given).
OdometrySnapshot plugin_odometry_prototype(const std::string& frame_id, const std::string& child_frame_id,
                                           const std::array<double, 6>& pose_diagonal,
                                           const std::array<double, 6>& twist_diagonal = {});

}  // namespace mechsim::control
