#pragma once
// Kinematics of a rover with steered and fixed wheels (the CC8: four steered corners, two
// fixed middle wheels), as pure functions: body twist -> steering headings and wheel rolling
// speeds for each drive mode, and the inverse (odometry) by least squares over the wheels.
//
// Frames and conventions. Body frame B: the robot's base link, x forward, y left, z up.
// A heading is the angle of a wheel's rolling direction in B, counter-clockwise seen from above
// (rad). A rolling speed is the ground speed of the wheel along its heading (m/s). Joint
// coordinates differ by signs: steering joint angle = steering axis sign * heading; wheel joint
// velocity = wheel axis sign * rolling speed / wheel radius.
//
// Turn centre. The fixed wheels cannot steer, so a turn without slip has its instantaneous
// centre of rotation (ICR) on the line through their axles, x = axle_x. Ackermann and point
// turn commands are therefore read as the twist of the point A = (axle_x, 0): (vx, wz) puts the
// ICR at (axle_x, vx / wz); a point turn puts it at A. For the CC8 axle_x is -5e-5 m, so A is
// base_link's origin to within a tenth of a millimetre.
//
// Steered wheels whose tyre sits off the steering axis by `offset` along the axle (the fork's
// y) are handled exactly: the heading aligns the steering pivot's velocity, which leaves the
// tyre no lateral slip, and the rolling speed subtracts wz * offset.
//
// No function here allocates or throws; spans must have the sizes stated.

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace mechsim::control {

// How a body twist is realised.
enum class DriveMode : std::uint8_t {
  Auto,       // chosen from the twist (select_drive_mode)
  Ackermann,  // vx and wz: ICR on the fixed wheels' axle line
  Crab,       // vx and vy: all steered wheels parallel, no rotation
  PointTurn,  // wz only: ICR at A, the wheels tangent to circles around it
};

const char* drive_mode_name(DriveMode mode);                 // "auto", "ackermann", "crab", "point_turn"
bool parse_drive_mode(std::string_view text, DriveMode& out);  // false for an unknown name

// A planar body twist: linear (m/s) in B, angular (rad/s) about z.
struct PlanarTwist {
  double vx = 0.0;
  double vy = 0.0;
  double wz = 0.0;
};

struct RoverWheel {
  // m, in B at zero joint angles: the steering pivot (a point on the steering axis) for a
  // steered wheel, the tyre centre for a fixed one.
  double x = 0.0;
  double y = 0.0;
  int steering = -1;  // index of the steering joint carrying the wheel, -1 for a fixed wheel
  // m, steered wheels: the tyre centre's offset from the steering axis along the fork's y
  // (left at zero steering positive). 0 for fixed wheels.
  double offset = 0.0;
  double axis_sign = 1.0;  // +1: a positive joint velocity rolls the wheel forward
};

struct RoverKinematics {
  double wheel_radius = 0.0;  // m
  std::vector<RoverWheel> wheels;
  std::vector<double> steering_axis_signs;  // per steering joint: +1 axis up, -1 axis down
  std::vector<int> steering_wheel;          // per steering joint: index of its wheel
  double axle_x = 0.0;                      // m: x of the fixed wheels' axle line (0 when none)
  double max_steering_angle = 1.5707963267948966;  // rad: headings stay within +-this
  // m: converts an angular rate into the speed it moves the wheels at (the mean distance of
  // the wheels from A); used to find the nearest supported twist.
  double characteristic_length = 1.0;

  std::size_t wheel_count() const { return wheels.size(); }
  std::size_t steering_count() const { return steering_wheel.size(); }
};

// Fills axle_x, characteristic_length and steering_wheel from `wheels` (configuration time).
void finish_rover_kinematics(RoverKinematics& k);

// The result of choosing how to realise a command.
struct ModeChoice {
  DriveMode mode = DriveMode::Ackermann;  // never Auto
  PlanarTwist twist;                      // what is realised: the command without what the mode cannot do
  bool unsupported = false;               // components of the command were dropped
};

// Auto: vy != 0 and wz == 0 -> crab; vx == 0, vy == 0, wz != 0 -> point turn; vy == 0 ->
// Ackermann; vy and wz both non-zero is unsupported and mapped to the nearest realisable
// twist: crab (wz dropped) when |vy| > |wz| * characteristic_length, else Ackermann (vy
// dropped). A forced mode drops what it cannot do (Ackermann: vy; crab: wz; point turn: vx, vy)
// and reports it as unsupported. |v| below `deadband` (m/s, rad/s) counts as zero.
ModeChoice select_drive_mode(const RoverKinematics& k, DriveMode requested, const PlanarTwist& command,
                             double deadband = 1e-9);

// Target ground velocity (m/s, in B) of wheel `i`'s reference point (pivot or tyre) for a
// twist of point A (what select_drive_mode returns).
void wheel_point_velocity(const RoverKinematics& k, std::size_t i, const PlanarTwist& twist_A, double& vx,
                          double& vy) noexcept;

// Of the two headings that put a wheel's rolling line along (vx, vy) (theta and theta + pi),
// the one within +-max_angle nearest `reference` (rad); `reverse` is set when it is the one
// pointing against (vx, vy). When neither is within range (max_angle < pi/2) the nearer one is
// clamped into it.
double fold_heading(double vx, double vy, double max_angle, double reference, bool& reverse) noexcept;

// Inverse kinematics for a twist of A: for each steering joint its heading (rad), for each
// wheel its rolling speed (m/s). `hold_headings` (steering_count) are kept where a wheel's
// target velocity is below `min_speed` (m/s; a stopped rover keeps its steering);
// `reference_headings` (steering_count, usually the measured ones) choose between the
// forward and the reversed heading. Sizes: headings steering_count, speeds wheel_count.
void inverse_kinematics(const RoverKinematics& k, const PlanarTwist& twist_A, std::span<const double> hold_headings,
                        std::span<const double> reference_headings, std::span<double> headings,
                        std::span<double> speeds, double min_speed = 1e-6) noexcept;

// Rolling speed of wheel `i` (m/s) given its heading (0 for fixed wheels) and a twist of A.
double rolling_speed(const RoverKinematics& k, std::size_t i, double heading, const PlanarTwist& twist_A) noexcept;

// Odometry: the body twist of B's origin that best explains measured headings (steering_count)
// and rolling speeds (wheel_count), by least squares over every wheel's tyre: its velocity
// along the heading equals the rolling speed, across it is zero (no side slip). Returns false
// (and leaves `twist` alone) when the wheels do not determine a twist. `rms_residual` (m/s),
// when given, is the root mean square of the 2 x wheel_count residuals: a measure of slip.
// `fixed_lateral_weight` weighs the no-side-slip rows of the fixed wheels: 1 normally, 0 in
// crab, where the fixed wheels are dragged sideways and their rows would pull vy towards 0.
bool estimate_twist(const RoverKinematics& k, std::span<const double> headings, std::span<const double> speeds,
                    PlanarTwist& twist, double* rms_residual = nullptr, double fixed_lateral_weight = 1.0) noexcept;

// A planar pose of B in the odometry frame O: x, y (m), yaw (rad, in (-pi, pi]).
struct PlanarPose {
  double x = 0.0;
  double y = 0.0;
  double yaw = 0.0;
};

// Integrates a body twist held constant for dt seconds exactly (the SE(2) exponential): a
// constant twist moves B along a circular arc, and this lands on it.
PlanarPose integrate_pose(const PlanarPose& pose, const PlanarTwist& body_twist, double dt) noexcept;

}  // namespace mechsim::control
