#pragma once
// Configuration of the PR2 base controllers (controllers/drive/pr2_base_controller.hpp) and of the PR2
// odometry (controllers/drive/pr2_odometry.hpp): reading their parameters, and filling the base geometry
// from a robot description when the YAML leaves it out (the PR2's own controllers read it from
// the URDF; ours see only the mechanism, so the simulation fills the parameters first, as for
// the rover drive). Configuration time only: allocates and throws ControllerConfigError or
// ParamsError, each naming the parameter path.
//
// Geometry parameters, shared by both controllers (units in brackets):
//   caster_joints        [string]  caster rotation joints, e.g. [fl_caster_rotation_joint, ...]
//   wheel_joints         [string]  wheel joints, e.g. [fl_caster_l_wheel_joint, fl_caster_r_wheel_joint, ...]
//   wheel_radius         [m]       nominal tyre radius (the PR2: 0.074792)
//   wheel_radius_multiplier [-]    calibration factor on the radius, default 1.0 (as the PR2)
//   caster_positions     {caster joint: [x, y(, z)]}  pivot in the base frame [m]
//   caster_axis_signs    {caster joint: +1|-1}  default +1 (axis up)
//   wheel_casters        {wheel joint: caster joint}  the caster carrying each wheel
//   wheel_offsets        {wheel joint: offset}  along the caster's y axis from its pivot [m]
//   wheel_axis_signs     {wheel joint: +1|-1}   default +1 (axis along the caster's +y)
//   caster_names         [string] or "a b c"  the PR2's YAML names caster LINKS; only
//                        fill_pr2_base_geometry reads it (to find caster_joints/wheel_joints)
//   base_link_frame      the link the geometry is measured in (default base_link)

#include <string>
#include <vector>

#include "control/hardware.hpp"
#include "control/params.hpp"
#include "controllers/drive/pr2_base_kinematics.hpp"
#include "description/robot_model.hpp"

namespace mechsim::control {

inline constexpr const char* kPr2BaseController2Type = "pr2_mechanism_controllers/Pr2BaseController2";
inline constexpr const char* kPr2BaseControllerType = "pr2_mechanism_controllers/Pr2BaseController";
inline constexpr const char* kPr2OdometryType = "pr2_mechanism_controllers/Pr2Odometry";

struct Pr2BaseGeometry {
  std::vector<std::string> caster_joints;
  std::vector<std::string> wheel_joints;
  Pr2BaseKinematics kinematics;  // wheel_radius already multiplied
};

// Reads the geometry parameters above (all but caster_names). Every wheel's caster must be one
// of caster_joints; every caster must carry at least one wheel.
Pr2BaseGeometry read_pr2_base_geometry(const Params& params);

// The base controller's limits and behaviour (see pr2_base_controller.hpp for the list).
struct Pr2BaseConfig {
  Pr2BaseGeometry geometry;
  double max_translational_velocity = 0.5;      // m/s, of |(vx, vy)|
  double max_rotational_velocity = 10.0;        // rad/s
  double max_translational_acceleration_x = 0.2;  // m/s^2
  double max_translational_acceleration_y = 0.2;  // m/s^2
  double max_rotational_acceleration = 10.0;    // rad/s^2
  double timeout = 0.2;                         // s; <= 0: never
  double caster_hold_speed = 1e-5;              // m/s: below it a caster keeps its heading
};

Pr2BaseConfig read_pr2_base_config(const Params& params);

// Sets the geometry parameters the controller at `params` lacks from `model` (caster and wheel
// joint poses at zero, collision cylinder radius): caster_joints (from caster_names when
// absent), wheel_joints (the lateral-axis joints below the casters' links when absent), wheel_radius, caster_positions, caster_axis_signs, wheel_casters,
// wheel_offsets, wheel_axis_signs. Values present are kept. Returns the number of parameters
// set. Throws ControllerConfigError naming the parameter path and the joint when the
// description does not fit (unknown joint or link, a caster axis not vertical, a wheel axis not
// along the caster's y, a wheel ahead of or behind its pivot).
int fill_pr2_base_geometry(const Params& params, const description::RobotModel& model);

// Calls fill_pr2_base_geometry for every controller under `ns` whose type is one of the three
// above. Returns the number of controllers filled.
int fill_pr2_base_geometry_all(const Params& ns, const description::RobotModel& model);

}  // namespace mechsim::control
