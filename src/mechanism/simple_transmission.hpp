#pragma once
// One actuator, one joint, a gear ratio and an offset: ros_control's
// transmission_interface/SimpleTransmission and pr2_mechanism_model/SimpleTransmission.
//
//   n      mechanical reduction (dimensionless, nonzero; negative flips the direction)
//   x_off  joint offset (rad or m): the joint position where the actuator reads zero
//
//   actuator -> joint:  x_j = x_a / n + x_off     (rad or m from rad)
//                       v_j = v_a / n             (rad/s or m/s)
//                       tau_j = n * tau_a         (N m or N from N m)
//   joint -> actuator:  x_a = n * (x_j - x_off)
//                       v_a = n * v_j
//                       tau_a = tau_j / n
//   power: tau_j * v_j = (n tau_a)(v_a / n) = tau_a * v_a.
//
// The PR2 variant may name a simulated_actuated_joint with a simulated_reduction r_s (the
// Gazebo screw joint of the torso: screw angle = r_s * lift). Its commanded effort is the PR2
// screw torque tau_s = n * tau_a / r_s (N m); its state is left as the physics reports it. The
// PR2 then applies only the screw torque (Gazebo's screw joint moves the lift); here the actuated
// joint also gets tau_j = n * tau_a, for a physics without the screw (physics_applies_command).
// Sources: ros_control transmission_interface SimpleTransmission documentation;
// pr2_mechanism_model SimpleTransmission (PR2/pr2_mechanism).

#include <memory>

#include "description/robot_model.hpp"
#include "mechanism/transmission.hpp"

namespace mechsim::mechanism {

class TransmissionBuilder;
struct MechanismModel;

class SimpleTransmission final : public Transmission {
 public:
  // joints: {joint} or {joint, simulated screw joint}; actuators: {actuator}.
  SimpleTransmission(std::string name, std::string type, int joint, int actuator, double reduction,
                     double offset = 0.0, int simulated_joint = -1, double simulated_reduction = 1.0);

  double reduction() const { return reduction_; }
  double offset() const { return offset_; }
  double simulated_reduction() const { return simulated_reduction_; }
  bool has_simulated_joint() const { return joints().size() == 2; }

  void actuator_to_joint_state(MechanismState& state) const override;
  void joint_to_actuator_state(MechanismState& state) const override;
  void joint_to_actuator_command(MechanismState& state) const override;
  void actuator_to_joint_command(MechanismState& state) const override;

 private:
  double reduction_;
  double offset_;
  double simulated_reduction_;
};

// From the URDF: ros_control format (<actuator><mechanicalReduction>, <joint><offset>) or the
// PR2 format (top-level <mechanicalReduction>, <simulated_actuated_joint>).
std::unique_ptr<Transmission> build_simple_transmission(TransmissionBuilder& b);

// ros_control descriptions may give one joint several SimpleTransmissions, one per hardware
// interface (transmission_interface and gazebo_ros_control register a handle per interface). When
// b.spec() is a SimpleTransmission of one joint that an earlier SimpleTransmission (`model`'s)
// already drives, this adds its interfaces to that joint and returns true: no second transmission
// is built, and an actuator name it adds is not a second motor (the joint has one, the first's).
// Throws, naming both transmissions and their lines, when the two disagree on the reduction or
// the offset (two motors driving one joint in conflicting ways) or when its actuator belongs to a
// transmission of another joint. Returns false for anything else (built as usual).
bool add_to_driven_joint(TransmissionBuilder& b, const description::RobotModel& robot, const MechanismModel& model);

}  // namespace mechsim::mechanism
