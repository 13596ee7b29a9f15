#pragma once
// The PR2 gripper: one motor turns a lead screw (through a gearbox) whose nut drives a linkage
// that opens the fingers: pr2_mechanism_model/PR2GripperTransmission. The gap joint is the
// distance between the fingertips; the finger joints are passive.
//
// Parameters (<gap_joint> attributes; PR2 alpha2 defaults where absent, as the PR2 does):
//   n  mechanical_reduction (required; the PR2 uses 1)   s  screw_reduction, lead (m/rev)
//   g  gear_ratio (motor rev per screw rev)              L0 nut distance at motor zero (m)
//   a, b  linkage link lengths (m)    h  linkage offset (m)    r  finger length (m)
//   theta0, phi0  linkage angles at motor zero (rad)     t0  half gap at motor zero (m)
//
// actuator -> joint (theta_m motor angle, rad):
//   MR    = theta_m / (2 pi n)                            motor revolutions after the reduction
//   L     = L0 + MR s / g                                 nut position (m)
//   u     = (a^2 + b^2 - h^2 - L^2) / (2 a b), clamped to [-1, 1]   (law of cosines)
//   theta = theta0 - phi0 + acos(u)                       finger angle (rad)
//   t     = t0 + r (sin theta - sin theta0)               half gap (m)
//   gap joint position x = 2 t (m); each passive finger joint position = theta - theta0 (rad)
//   Jacobians (the PR2 evaluates them at MR >= 0 and floors 1 - u^2 at 1e-5):
//     du/dMR = -(s / g) L / (a b);  dtheta/dMR = -du/dMR / sqrt(1 - u^2)
//     dt/dMR = r cos(theta) dtheta/dMR
//     J_gap  = dx/dtheta_m = 2 dt/dMR / (2 pi n)   (m/rad);  J_fin = dtheta/dtheta_m = dtheta/dMR / (2 pi n)
//   velocities: v_gap = J_gap w_m (m/s);  w_finger = J_fin w_m (rad/s)
//   efforts (power preserving): F_gap = tau_m / J_gap (N); each of the N passive joints
//     tau_finger = tau_m / J_fin / N (N m), so that the fingers together carry the motor's power.
// joint -> actuator (x gap, m):
//   sin theta = (x/2 - t0) / r + sin theta0 (clamped);  theta = asin(...)
//   L = sqrt(a^2 + b^2 - h^2 - 2 a b cos(theta - theta0 + phi0));  MR = g (L - L0) / s
//   theta_m = 2 pi n MR;  w_m = v_gap / J_gap;  tau_m = F_gap J_gap  (J_gap at theta_m)
// Commands: joint -> actuator uses J_gap at the gap joint's measured position, actuator -> joint
// at the actuator's; the simulated screw joint gets the PR2 screw torque 2 F_gap / r_s
// (simulated_reduction r_s), the passive_actuated slider joint nothing.
// Deviations from the PR2 code: the PR2 divides the motor torque by n where power preservation
// multiplies by it (the same for the PR2's n = 1), and reports the whole finger torque on every
// passive joint instead of a 1/N share.
// Source: pr2_mechanism_model PR2GripperTransmission (PR2/pr2_mechanism; equations from
// Willow Garage's 090224_link_data spreadsheet), parameters from
// pr2_description/urdf/gripper_v0/gripper.transmission.xacro and the PR2 URDF.

#include <memory>

#include "mechanism/transmission.hpp"

namespace mechsim::mechanism {

class TransmissionBuilder;

struct GripperGeometry {
  double mechanical_reduction = 1.0;  // n
  double screw_reduction = 2.0 / 1000.0;  // s (m/rev)
  double gear_ratio = 29.16;              // g
  double theta0 = 2.97571 * 3.14159265358979323846 / 180.0;  // rad
  double phi0 = 29.98717 * 3.14159265358979323846 / 180.0;   // rad
  double t0 = -0.19543 / 1000.0;  // m
  double L0 = 34.70821 / 1000.0;  // m
  double h = 5.200 / 1000.0;      // m
  double a = 67.56801 / 1000.0;   // m
  double b = 48.97193 / 1000.0;   // m
  double r = 91.50000 / 1000.0;   // m
};

// The linkage at one motor angle.
struct GripperPoint {
  double gap;          // x (m)
  double finger;       // theta - theta0 (rad)
  double gap_jacobian;     // J_gap (m/rad), never zero
  double finger_jacobian;  // J_fin (rad/rad), never zero
};

class Pr2GripperTransmission final : public Transmission {
 public:
  // joints: {gap, passive..., [simulated screw], [passive_actuated slider]}; actuators: {motor}.
  Pr2GripperTransmission(std::string name, std::string type, int gap_joint, std::vector<int> passive_joints,
                         int screw_joint, int slider_joint, int actuator, GripperGeometry geometry,
                         double simulated_reduction = 1.0);

  const GripperGeometry& geometry() const { return g_; }
  GripperPoint at_motor(double theta_m) const;  // rad
  double motor_angle(double gap) const;         // rad, for a gap x (m)

  void actuator_to_joint_state(MechanismState& state) const override;
  void joint_to_actuator_state(MechanismState& state) const override;
  void joint_to_actuator_command(MechanismState& state) const override;
  void actuator_to_joint_command(MechanismState& state) const override;

 private:
  GripperGeometry g_;
  int passive_count_;
  int screw_;   // index into joints(), -1 when absent
  double simulated_reduction_;
};

std::unique_ptr<Transmission> build_pr2_gripper_transmission(TransmissionBuilder& b);

}  // namespace mechsim::mechanism
