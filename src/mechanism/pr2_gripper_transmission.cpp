#include "mechanism/pr2_gripper_transmission.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "mechanism/mechanism_model.hpp"
#include "mechanism/transmission_builder.hpp"

namespace mechsim::mechanism {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kTol = 1e-5;            // the PR2's floor on 1 - u^2
constexpr double kMinJacobian = 1e-12;   // keeps the effort maps finite at a singular pose

double clamp1(double v) { return std::min(1.0, std::max(-1.0, v)); }

double nonzero(double j) { return std::abs(j) < kMinJacobian ? std::copysign(kMinJacobian, j) : j; }

std::vector<int> joint_list(int gap, const std::vector<int>& passive, int screw, int slider) {
  std::vector<int> out{gap};
  out.insert(out.end(), passive.begin(), passive.end());
  if (screw >= 0) out.push_back(screw);
  if (slider >= 0) out.push_back(slider);
  return out;
}

}  // namespace

Pr2GripperTransmission::Pr2GripperTransmission(std::string name, std::string type, int gap_joint,
                                               std::vector<int> passive_joints, int screw_joint, int slider_joint,
                                               int actuator, GripperGeometry geometry, double simulated_reduction)
    : Transmission(std::move(name), std::move(type), joint_list(gap_joint, passive_joints, screw_joint, slider_joint),
                   {actuator}),
      g_(geometry),
      passive_count_(static_cast<int>(passive_joints.size())),
      screw_(screw_joint >= 0 ? 1 + static_cast<int>(passive_joints.size()) : -1),
      simulated_reduction_(simulated_reduction) {}

GripperPoint Pr2GripperTransmission::at_motor(double theta_m) const {
  const double lead = g_.screw_reduction / g_.gear_ratio;  // m per motor revolution
  const double ab = g_.a * g_.b;
  const double k = g_.a * g_.a + g_.b * g_.b - g_.h * g_.h;
  const auto u_of = [&](double mr) {
    const double L = g_.L0 + mr * lead;
    return clamp1((k - L * L) / (2.0 * ab));
  };
  const double mr = theta_m / (kTwoPi * g_.mechanical_reduction);
  const double theta = g_.theta0 - g_.phi0 + std::acos(u_of(mr));
  GripperPoint p{};
  p.gap = 2.0 * (g_.t0 + g_.r * (std::sin(theta) - std::sin(g_.theta0)));
  p.finger = theta - g_.theta0;

  // Jacobians at MR >= 0, as the PR2 computes them.
  const double mr_j = std::max(mr, 0.0);
  const double u_j = u_of(mr_j);
  const double theta_j = g_.theta0 - g_.phi0 + std::acos(u_j);
  const double du_dmr = -lead * (g_.L0 + mr_j * lead) / ab;
  const double dtheta_dmr = -du_dmr / std::sqrt(std::max(1.0 - u_j * u_j, kTol));
  const double dt_dmr = g_.r * std::cos(theta_j) * dtheta_dmr;
  const double per_rad = 1.0 / (kTwoPi * g_.mechanical_reduction);  // MR per motor radian
  p.gap_jacobian = nonzero(2.0 * dt_dmr * per_rad);
  p.finger_jacobian = nonzero(dtheta_dmr * per_rad);
  return p;
}

double Pr2GripperTransmission::motor_angle(double gap) const {
  const double sin_theta = clamp1((gap / 2.0 - g_.t0) / g_.r + std::sin(g_.theta0));
  const double theta = std::asin(sin_theta);
  const double L2 = g_.a * g_.a + g_.b * g_.b - g_.h * g_.h - 2.0 * g_.a * g_.b * std::cos(theta - g_.theta0 + g_.phi0);
  const double L = std::sqrt(std::max(L2, 0.0));
  const double mr = g_.gear_ratio * (L - g_.L0) / g_.screw_reduction;
  return kTwoPi * g_.mechanical_reduction * mr;
}

void Pr2GripperTransmission::actuator_to_joint_state(MechanismState& s) const {
  const ActuatorState& a = s.actuators[actuators()[0]];
  const GripperPoint p = at_motor(a.position);
  JointState& gap = s.joints[joints()[0]];
  gap.position = p.gap;
  gap.velocity = p.gap_jacobian * a.velocity;
  gap.measured_effort = a.last_measured_effort / p.gap_jacobian;
  for (int i = 1; i <= passive_count_; ++i) {
    JointState& f = s.joints[joints()[i]];
    f.position = p.finger;
    f.velocity = p.finger_jacobian * a.velocity;
    f.measured_effort = a.last_measured_effort / p.finger_jacobian / passive_count_;
  }
}

void Pr2GripperTransmission::joint_to_actuator_state(MechanismState& s) const {
  const JointState& gap = s.joints[joints()[0]];
  ActuatorState& a = s.actuators[actuators()[0]];
  a.position = motor_angle(gap.position);
  const GripperPoint p = at_motor(a.position);
  a.velocity = gap.velocity / p.gap_jacobian;
  a.last_measured_effort = gap.measured_effort * p.gap_jacobian;
}

void Pr2GripperTransmission::joint_to_actuator_command(MechanismState& s) const {
  const JointState& gap = s.joints[joints()[0]];
  ActuatorState& a = s.actuators[actuators()[0]];
  const GripperPoint p = at_motor(motor_angle(gap.position));
  a.commanded_effort = gap.commanded_effort * p.gap_jacobian;
  a.commanded_position = motor_angle(gap.commanded_position);
  a.commanded_velocity = gap.commanded_velocity / p.gap_jacobian;
  a.command_mode = gap.command_mode;
}

void Pr2GripperTransmission::actuator_to_joint_command(MechanismState& s) const {
  const ActuatorState& a = s.actuators[actuators()[0]];
  const GripperPoint p = at_motor(a.position);
  const GripperPoint target = at_motor(a.commanded_position);
  JointState& gap = s.joints[joints()[0]];
  gap.commanded_effort = a.commanded_effort / p.gap_jacobian;
  gap.commanded_position = target.gap;
  gap.commanded_velocity = p.gap_jacobian * a.commanded_velocity;
  for (int i = 1; i <= passive_count_; ++i) {
    JointState& f = s.joints[joints()[i]];
    f.commanded_effort = a.commanded_effort / p.finger_jacobian / passive_count_;
    f.commanded_position = target.finger;
    f.commanded_velocity = p.finger_jacobian * a.commanded_velocity;
    f.command_mode = a.command_mode;
  }
  if (screw_ >= 0) {
    JointState& screw = s.joints[joints()[screw_]];
    screw.commanded_effort = 2.0 * gap.commanded_effort / simulated_reduction_;
    screw.command_mode = HardwareInterface::Effort;
  }
}

std::unique_ptr<Transmission> build_pr2_gripper_transmission(TransmissionBuilder& b) {
  const description::Transmission& spec = b.spec();
  const description::TransmissionActuator& motor = b.actuator_entry("");
  const description::TransmissionJoint& gap_entry = b.joint_entry("gap");
  for (const description::TransmissionJoint& j : spec.joints)
    if (j.role != "gap" && j.role != "passive" && j.role != "simulated_actuated")
      b.fail("joint '" + j.name + "' is not a <gap_joint>, <passive_joint> or <simulated_actuated_joint>", j.name,
             b.line_of(j.name));

  const int actuator = b.actuator(motor);
  const int gap = b.joint(gap_entry, JointRole::Actuated);
  std::vector<int> passive;
  for (const description::TransmissionJoint* p : b.joint_entries("passive"))
    passive.push_back(b.joint(*p, JointRole::Passive));

  GripperGeometry g;
  const description::XmlNode none = description::XmlNode{"gap_joint", {}, "", {}, b.line_of(gap_entry.name)};
  const description::XmlNode* gx = b.xml_child("gap_joint", gap_entry.name);
  const description::XmlNode& node = gx ? *gx : none;
  const std::string& gname = gap_entry.name;
  // The PR2 requires mechanical_reduction on the <gap_joint>.
  const std::optional<double> n = gx && gx->attribute("mechanical_reduction")
                                      ? std::optional<double>(b.number_attribute(node, "mechanical_reduction", {}, gname))
                                      : gap_entry.mechanical_reduction;
  g.mechanical_reduction = b.reduction(n, std::nullopt, "mechanical_reduction of the gap_joint", gname, node.line);
  g.screw_reduction = b.reduction(b.number_attribute(node, "screw_reduction", g.screw_reduction, gname), std::nullopt,
                                  "screw_reduction", gname, node.line);
  g.gear_ratio = b.reduction(b.number_attribute(node, "gear_ratio", g.gear_ratio, gname), std::nullopt, "gear_ratio",
                             gname, node.line);
  g.theta0 = b.number_attribute(node, "theta0", g.theta0, gname);
  g.phi0 = b.number_attribute(node, "phi0", g.phi0, gname);
  g.t0 = b.number_attribute(node, "t0", g.t0, gname);
  g.L0 = b.number_attribute(node, "L0", g.L0, gname);
  g.h = b.number_attribute(node, "h", g.h, gname);
  g.a = b.number_attribute(node, "a", g.a, gname);
  g.b = b.number_attribute(node, "b", g.b, gname);
  g.r = b.number_attribute(node, "r", g.r, gname);
  for (const auto& [what, value] : {std::pair{"a", g.a}, std::pair{"b", g.b}, std::pair{"r", g.r}})
    if (!(value > 0.0)) b.fail(std::string("gap_joint ") + what + " must be positive", gname, node.line);

  int screw = -1;
  int slider = -1;
  double simulated_reduction = 1.0;
  const auto sims = b.joint_entries("simulated_actuated");
  if (sims.size() > 1) b.fail("more than one simulated_actuated_joint", sims[1]->name, b.line_of(sims[1]->name));
  if (!sims.empty()) {
    const description::TransmissionJoint& s = *sims[0];
    screw = b.joint(s, JointRole::SimulatedActuated);
    const description::XmlNode* sx = b.xml_child("simulated_actuated_joint", s.name);
    if (!sx) b.fail("simulated_actuated_joint '" + s.name + "' has no simulated_reduction", s.name, b.line_of(s.name));
    simulated_reduction = b.reduction(b.number_attribute(*sx, "simulated_reduction", std::nullopt, s.name), std::nullopt,
                                      "simulated_reduction of '" + s.name + "'", s.name, sx->line);
    // The PR2 adds the slider joint of its screw model when the robot has it, silently otherwise.
    if (const auto slider_name = sx->attribute("passive_actuated_joint"); slider_name && !slider_name->empty())
      slider = b.has_robot_joint(*slider_name) ? b.joint(*slider_name, JointRole::SimulatedActuated, sx->line) : -1;
  }
  return std::make_unique<Pr2GripperTransmission>(spec.name, spec.type, gap, passive, screw, slider, actuator, g,
                                                  simulated_reduction);
}

}  // namespace mechsim::mechanism
