// Physics: changing a built model's joint damping and limits and a link's inertia at run time
// (Gazebo's set_joint_properties and set_link_properties). This instance's model copy only.
#include <cmath>
#include <stdexcept>

#include "physics/mujoco_internal.hpp"
#include "physics/physics.hpp"
#include "physics/physics_data.hpp"
#include "physics/transform.hpp"

namespace mechsim::physics {

namespace {

bool finite(double v) { return std::isfinite(v); }

}  // namespace

void Physics::set_joint_damping(std::size_t j, double damping) {
  const JointInfo& info = model_->joints()[j];
  if (!finite(damping) || damping < 0.0)
    throw std::invalid_argument("damping of joint '" + info.name + "' must be finite and >= 0, got " + std::to_string(damping));
  data_->m->dof_damping[info.dof_adr] = damping;
}

void Physics::set_joint_limits(std::size_t j, double lower, double upper) {
  const JointInfo& info = model_->joints()[j];
  if (!finite(lower) || !finite(upper) || lower > upper) {
    throw std::invalid_argument("limits of joint '" + info.name + "' must be finite with lower <= upper, got [" +
                                std::to_string(lower) + ", " + std::to_string(upper) + "]");
  }
  mjModel* m = data_->m;
  m->jnt_range[2 * info.mj_joint] = lower;
  m->jnt_range[2 * info.mj_joint + 1] = upper;
  m->jnt_limited[info.mj_joint] = 1;
  data_->stale = true;
}

std::pair<double, double> Physics::joint_limits(std::size_t j) const {
  const JointInfo& info = model_->joints()[j];
  const mjModel* m = data_->m;
  if (!m->jnt_limited[info.mj_joint]) return {-INFINITY, INFINITY};
  return {m->jnt_range[2 * info.mj_joint], m->jnt_range[2 * info.mj_joint + 1]};
}

std::string Physics::set_link_inertial(std::size_t link, double mass, const description::Pose& X_LC,
                                       const std::array<double, 6>& inertia) {
  const LinkInfo& info = model_->links()[link];
  if (info.body <= 0) return "link '" + info.name + "' is fixed to the world: it has no mass to set";
  for (const LinkInfo& other : model_->links())
    if (&other != &info && other.body == info.body)
      return "link '" + info.name + "' shares its physics body with link '" + other.name +
             "' (they are joined by a fixed joint): mechsim sets the inertia of a link that moves alone only";
  if (!finite(mass) || mass <= 0.0) return "mass must be finite and > 0, got " + std::to_string(mass);
  for (double v : inertia)
    if (!finite(v)) return "the inertia must be finite";
  const auto [ixx, ixy, ixz, iyy, iyz, izz] = inertia;
  // Principal moments and axes of the tensor given in the centre-of-mass frame C.
  const mjtNum I_C[9] = {ixx, ixy, ixz, ixy, iyy, iyz, ixz, iyz, izz};
  mjtNum moments[3], axes[9], q_CP[4];
  mju_eig3(moments, axes, q_CP, I_C);
  if (moments[0] < 0.0 || moments[1] < 0.0 || moments[2] < 0.0 || moments[0] + moments[1] < moments[2] ||
      moments[1] + moments[2] < moments[0] || moments[0] + moments[2] < moments[1])
    return "the inertia is not physical (a negative principal moment, or one larger than the other two together)";
  const description::Pose X_BC = compose(info.X_BL, X_LC);
  const description::Quat q_BP = quat_multiply(X_BC.orientation, {q_CP[0], q_CP[1], q_CP[2], q_CP[3]});
  mjModel* m = data_->m;
  const int b = info.body;
  m->body_mass[b] = mass;
  m->body_ipos[3 * b] = X_BC.position.x;
  m->body_ipos[3 * b + 1] = X_BC.position.y;
  m->body_ipos[3 * b + 2] = X_BC.position.z;
  m->body_iquat[4 * b] = q_BP.w;
  m->body_iquat[4 * b + 1] = q_BP.x;
  m->body_iquat[4 * b + 2] = q_BP.y;
  m->body_iquat[4 * b + 3] = q_BP.z;
  for (int k = 0; k < 3; ++k) m->body_inertia[3 * b + k] = moments[k];
  data_->constants_stale = true;
  data_->stale = true;
  return "";
}

}  // namespace mechsim::physics
