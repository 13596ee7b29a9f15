// Physics: the wheel-soil model inside the step (physics.hpp, set_soil; terramechanics.hpp).
//
// Each step, for every wheel, from the state at the start of the step (after mj_step1: positions,
// velocities and their kinematics):
//  1. the ground under the wheel: the plane fitted to the surface at the wheel's centre and 0.5 r
//     either side (so that 5 cm height field cells do not make the force jump from triangle to
//     triangle), and the sinkage of the wheel's lowest point below it;
//  2. the wheel's contact frame (normal n, heading x = axle x n, axle y) and velocities: travel v
//     along x, r w of the rim, sideways velocity;
//  3. the soil's shear displacements at the rim's exit, along x and y: each grows with the
//     slip velocity (r w - v, and the sideways velocity) and relaxes as soil leaves the contact
//     patch, over its length L = r (theta_1 - theta_2):
//        dj/dt = v_slip - u / L j,   u = max(|r w|, |v|),
//     so that rolling at a steady slip gives Wong and Reece's j = slip L at the exit, and a wheel
//     that stands still holds like a spring (Janosi-Hanamoto's curve) instead of creeping at
//     the rate a slip ratio divided by nothing would allow. Integrated exactly over the step
//     (the exponential), so it is stable at any speed;
//  4. the soil model's forces at the slip j_x / L (terramechanics.hpp), in the frame of the
//     direction the wheel rolls (a wheel driven backwards mirrors the model). The rolling rim's
//     own shear and the compaction resistance (the horizontal part of the normal stress, against
//     the travel) build up as states over the contact length and over 5 mm of travel, so that a
//     wheel at rest is neither driven by a rim that does not roll nor pushed back by a rut it has
//     not made, and a wheel jittering about rest does not switch them from side to side each step;
//     damping on the sinkage rate and the shear rate (critical for the wheel's share of the load,
//     bounded for the explicit step by the wheel body's mass and its spin inertia at the rim);
//  5. the force and moment on the wheel's body (xfrc_applied), at its centre of mass.
// The shear state becomes the state only when the step succeeds (commit_soil).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "physics/hfield_surface.hpp"
#include "physics/physics_data.hpp"
#include "physics/sensing_internal.hpp"
#include "physics/terramechanics.hpp"

namespace mechsim::physics {
namespace {

constexpr double kPushLength = 0.005;  // m of travel over which the compaction resistance turns
constexpr double kMinContactLength = 0.005;  // m: shortest contact patch the shear relaxes over
constexpr double kDampingCap = 0.25;    // damping x dt / mass: the explicit step's bound


double dot(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
void cross(const double* a, const double* b, double* out) {
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}
bool normalize(double* v) {
  const double n = std::sqrt(dot(v, v));
  if (n < 1e-12) return false;
  for (int i = 0; i < 3; ++i) v[i] /= n;
  return true;
}

// The ground under the point (world frame): a point on the fitted plane and its normal. For a
// height field, the plane through the heights at the point and `spread` (m) either side along x
// and y; for a plane geom, that plane. False where there is no ground.
bool ground_plane_at(const mjModel* m, const mjData* d, int ground, const double p[3], double spread, double point[3],
                     double normal[3]) {
  const mjtNum* pos = d->geom_xpos + 3 * ground;
  const mjtNum* mat = d->geom_xmat + 9 * ground;  // row-major: world = mat * local
  if (m->geom_type[ground] == mjGEOM_PLANE) {
    for (int i = 0; i < 3; ++i) normal[i] = mat[3 * i + 2];
    const double above = (p[0] - pos[0]) * normal[0] + (p[1] - pos[1]) * normal[1] + (p[2] - pos[2]) * normal[2];
    for (int i = 0; i < 3; ++i) point[i] = p[i] - above * normal[i];
    return true;
  }
  const detail::HfieldSurface surface(detail::hfield_grid(m, ground));
  const double dif[3] = {p[0] - pos[0], p[1] - pos[1], p[2] - pos[2]};
  double l[3];
  for (int j = 0; j < 3; ++j) l[j] = mat[j] * dif[0] + mat[3 + j] * dif[1] + mat[6 + j] * dif[2];
  double hc, hxp, hxm, hyp, hym;
  if (!surface.height(l[0], l[1], hc) || !surface.height(l[0] + spread, l[1], hxp) ||
      !surface.height(l[0] - spread, l[1], hxm) || !surface.height(l[0], l[1] + spread, hyp) ||
      !surface.height(l[0], l[1] - spread, hym))
    return false;
  const double gx = (hxp - hxm) / (2.0 * spread), gy = (hyp - hym) / (2.0 * spread);
  double nl[3] = {-gx, -gy, 1.0};
  normalize(nl);
  const double h = (hc + hxp + hxm + hyp + hym) / 5.0;
  const double pl[3] = {l[0], l[1], h};
  for (int i = 0; i < 3; ++i) {
    normal[i] = mat[3 * i] * nl[0] + mat[3 * i + 1] * nl[1] + mat[3 * i + 2] * nl[2];
    point[i] = pos[i] + mat[3 * i] * pl[0] + mat[3 * i + 1] * pl[1] + mat[3 * i + 2] * pl[2];
  }
  return true;
}

// A state in [-1, 1] moved towards the sign of `speed` over `length` (m) of motion: exact over
// the step for constant speed.
double toward(double q, double speed, double length, double dt) {
  const double target = speed > 0.0 ? 1.0 : -1.0;
  return target + (q - target) * std::exp(-std::abs(speed) * dt / length);
}

// The shear displacement after a step of dt: exact for constant slip velocity and relaxation.
double relax(double j, double v_slip, double u, double length, double dt) {
  if (u < 1e-9) return j + v_slip * dt;
  const double steady = v_slip * length / u;
  return steady + (j - steady) * std::exp(-u * dt / length);
}

// Calls at(x, y) at points across the wheel's width on its axle line through its lowest point
// `low`, one per rut cell the width spans.
template <typename At>
void for_each_rut_cell(const double low[3], const double axle[3], double width, At&& at) {
  const int count = std::max(1, static_cast<int>(std::ceil(width / detail::kRutCell)));
  for (int k = 0; k < count; ++k) {
    const double u = width * ((k + 0.5) / count - 0.5);
    at(low[0] + u * axle[0], low[1] + u * axle[1]);
  }
}

// The world geom the soil lies on: the height field or the ground plane (group 2), or -1.
int find_ground(const mjModel* m) {
  for (int g = 0; g < m->ngeom; ++g)
    if (m->geom_group[g] == 2 && m->geom_bodyid[g] == 0 && (m->geom_type[g] == mjGEOM_HFIELD || m->geom_type[g] == mjGEOM_PLANE))
      return g;
  return -1;
}

}  // namespace

namespace {

// The collision geom of `body` the soil acts on when a link is made a wheel: its largest (by
// bounding sphere) geom that collides.
int largest_collision_geom(const mjModel* m, int body) {
  int best = -1;
  for (int g = 0; g < m->ngeom; ++g) {
    if (m->geom_bodyid[g] != body || (m->geom_contype[g] == 0 && m->geom_conaffinity[g] == 0)) continue;
    if (best < 0 || m->geom_rbound[g] > m->geom_rbound[best]) best = g;
  }
  return best;
}

// The soil's wheels: the model's, with the world's overrides (WheelOverride) applied. Throws
// std::invalid_argument naming the override.
std::vector<SoilWheelInfo> soil_wheel_list(const PhysicsModel& model, const mjModel* m, const std::vector<WheelOverride>& overrides,
                                           std::vector<std::string>& notes) {
  std::vector<SoilWheelInfo> list;
  for (const WheelInfo& w : model.wheels())
    list.push_back({w.link, w.joint, w.geom, w.body, {w.radius, w.width}, w.narrow, false,
                    w.narrow ? "its collision cylinder (narrow: an ellipsoid on rigid ground)" : "its collision cylinder"});
  for (const WheelOverride& o : overrides) {
    const std::string where = "world.wheels" + (o.origin.empty() ? std::string() : " (" + o.origin + ")") + ": link '" + o.link + "'";
    const auto it = std::find_if(list.begin(), list.end(), [&](const SoilWheelInfo& w) { return w.link == o.link; });
    if (!o.wheel) {
      if (it == list.end()) {
        if (!model.link_index(o.link)) throw std::invalid_argument(where + ": the model has no such link");
        continue;
      }
      notes.push_back("'" + o.link + "' is not a soil wheel: " + where + " says so");
      list.erase(it);
      continue;
    }
    SoilWheelInfo* w = it == list.end() ? nullptr : &*it;
    if (w == nullptr) {
      const auto link = model.link_index(o.link);
      if (!link) throw std::invalid_argument(where + ": the model has no such link");
      const int body = model.links()[*link].body;
      std::optional<std::size_t> joint;
      for (std::size_t j = 0; j < model.joints().size(); ++j) {
        const JointInfo& info = model.joints()[j];
        if (!info.prismatic && info.mj_joint >= 0 && m->jnt_bodyid[info.mj_joint] == body) joint = j;
      }
      const int geom = body > 0 ? largest_collision_geom(m, body) : -1;
      if (!joint || geom < 0)
        throw std::invalid_argument(where + ": a wheel must turn on its link's own revolute or continuous joint and have a collision geom");
      SoilWheelInfo info;
      info.link = o.link;
      info.joint = *joint;
      info.geom = geom;
      info.body = body;
      const double* size = m->geom_size + 3 * geom;
      if (m->geom_type[geom] == mjGEOM_CYLINDER) info.shape = {size[0], 2.0 * size[1]};
      else if (m->geom_type[geom] == mjGEOM_ELLIPSOID) info.shape = {size[0], 2.0 * size[2]};
      else info.axis_from_joint = true;
      info.origin = where;
      list.push_back(info);
      w = &list.back();
      if (w->axis_from_joint && (!o.radius || !o.width))
        throw std::invalid_argument(where + ": its collision geom is not a cylinder: give its radius and width (m)");
    }
    if (o.radius) w->shape.radius = *o.radius;
    if (o.width) w->shape.width = *o.width;
    if (!(w->shape.radius > 0.0) || !(w->shape.width > 0.0) || !std::isfinite(w->shape.radius) || !std::isfinite(w->shape.width))
      throw std::invalid_argument(where + ": radius and width must be > 0 (m)");
    if (!(o.grouser_height >= 0.0) || o.grouser_height > w->shape.radius || o.grouser_count < 0)
      throw std::invalid_argument(where + ": grousers: height must be in [0, radius] (m) and count >= 0");
    w->shape.grouser_height = o.grouser_height;
    w->shape.grouser_count = o.grouser_count;
    w->narrow = w->shape.width <= w->shape.radius;
    if (it != list.end()) w->origin += ", " + where;
  }
  return list;
}

}  // namespace

void Physics::set_soil(std::optional<SoilParameters> soil, std::vector<WheelOverride> overrides) {
  if (soil) {
    const std::string problem = check_soil(*soil);
    if (!problem.empty()) throw std::invalid_argument("soil" + (soil->name.empty() ? std::string() : " '" + soil->name + "'") + ": " + problem);
  }
  Data& data = *data_;
  mjModel* m = data.m;
  std::vector<std::string> notes;
  std::vector<SoilWheelInfo> wheels;
  if (soil) {
    wheels = soil_wheel_list(*model_, m, overrides, notes);
    for (const SoilWheelInfo& w : wheels)
      if (const std::string problem = check_soil_width(*soil, w.shape.width); !problem.empty())
        throw std::invalid_argument("soil '" + soil->name + "' under wheel '" + w.link + "': " + problem);
  }
  // The bedrock: under the earlier soil's wheels none, under this one's its depth.
  if (m->nuser_geom > 0) {
    for (const SoilWheelInfo& w : data.soil_wheels) m->geom_user[w.geom * m->nuser_geom] = 0.0;
    for (const SoilWheelInfo& w : wheels) m->geom_user[w.geom * m->nuser_geom] = soil->bedrock_depth;
  }
  data.soil = std::move(soil);
  data.soil_overrides = std::move(overrides);
  data.soil_wheels = std::move(wheels);
  data.soil_wheel_notes = std::move(notes);
  data.soil_ground = data.soil ? find_ground(m) : -1;
  const std::size_t n = data.soil_wheels.size();
  data.soil_state.assign(n, {});
  data.soil_pending.assign(n, {});
  data.soil_readings.assign(n, {});
  data.soil_pending_readings.assign(n, {});
  data.soil_press.assign(n, {});
  data.ruts.clear();
  data.stale = true;
}

const std::optional<SoilParameters>& Physics::soil() const { return data_->soil; }
const std::vector<WheelSoilReading>& Physics::wheel_soil() const { return data_->soil_readings; }
const std::vector<SoilWheelInfo>& Physics::soil_wheels() const { return data_->soil_wheels; }
const std::vector<std::string>& Physics::soil_wheel_notes() const { return data_->soil_wheel_notes; }

void Physics::mujoco_step() {
  mjModel* m = data_->m;
  mjData* d = data_->d;
  const bool tree_forces = model_->options().step_cost.tree_external_forces && m->opt.integrator != mjINT_RK4;
  if (!data_->soil && !tree_forces) {
    mj_step(m, d);
    return;
  }
  if (!data_->soil) {  // mj_step1 + mj_step2 is mj_step for Euler and implicit
    mj_step1(m, d);
    step2_with_tree_forces();
    return;
  }
  if (m->opt.integrator == mjINT_RK4) {
    // mj_step2 integrates with Euler: RK4 takes the soil's forces from fresh kinematics and holds
    // them over its stages.
    mj_kinematics(m, d);
    mj_comPos(m, d);
    mj_comVel(m, d);
    apply_soil();
    mj_step(m, d);
    return;
  }
  mj_step1(m, d);
  apply_soil();
  if (tree_forces) step2_with_tree_forces();
  else mj_step2(m, d);
}

void Physics::commit_soil() {
  if (!data_->soil) return;
  data_->soil_state = data_->soil_pending;
  data_->soil_readings = data_->soil_pending_readings;
  if (!data_->soil->multi_pass) return;
  const std::vector<SoilWheelInfo>& wheels = data_->soil_wheels;
  for (std::size_t i = 0; i < wheels.size(); ++i) {
    const Data::Press& p = data_->soil_press[i];
    if (!(p.sinkage > 0.0)) continue;
    for_each_rut_cell(p.low, p.axle, wheels[i].shape.width, [&](double x, double y) {
      data_->ruts.press(static_cast<int>(i), x, y, p.sinkage);
    });
  }
}

void Physics::apply_soil() {
  Data& data = *data_;
  const mjModel* m = data.m;
  mjData* d = data.d;
  const SoilParameters& soil = *data.soil;
  const std::vector<SoilWheelInfo>& wheels = data.soil_wheels;
  const double dt = m->opt.timestep;
  const double g = std::sqrt(dot(m->opt.gravity, m->opt.gravity));
  const double tan_phi = std::tan(soil.friction_angle);
  for (const SoilWheelInfo& w : wheels)
    for (int k = 0; k < 6; ++k) d->xfrc_applied[6 * w.body + k] = data.xfrc_base[6 * static_cast<std::size_t>(w.body) + k];

  for (std::size_t i = 0; i < wheels.size(); ++i) {
    const SoilWheelInfo& w = wheels[i];
    const Data::SoilWheel& before = data.soil_state[i];
    Data::SoilWheel& after = data.soil_pending[i];
    WheelSoilReading& reading = data.soil_pending_readings[i];
    after = before;
    reading = {};
    data.soil_press[i].sinkage = 0.0;
    const double r = w.shape.radius;
    const mjtNum* c = d->geom_xpos + 3 * w.geom;
    const mjtNum* R = d->geom_xmat + 9 * w.geom;
    const int mj_joint = model_->joints()[w.joint].mj_joint;
    // The axle: the cylinder's (or ellipsoid's) axis; a mesh's or sphere's joint's.
    double a[3] = {R[2], R[5], R[8]};
    if (w.axis_from_joint)
      for (int k = 0; k < 3; ++k) a[k] = d->xaxis[3 * mj_joint + k];
    double ground[3], n[3];
    if (data.soil_ground < 0 || !ground_plane_at(m, d, data.soil_ground, c, 0.5 * r, ground, n)) {
      after = {};
      continue;
    }
    // The wheel's lowest point along -n and its depth below the fitted plane.
    const double na = dot(n, a);
    double e[3] = {n[0] - na * a[0], n[1] - na * a[1], n[2] - na * a[2]};
    if (!normalize(e) || std::abs(na) > 0.95) {  // lying on its side: not rolling in the soil
      after = {};
      continue;
    }
    const double low[3] = {c[0] - r * e[0], c[1] - r * e[1], c[2] - r * e[2]};
    const double sinkage = (ground[0] - low[0]) * n[0] + (ground[1] - low[1]) * n[1] + (ground[2] - low[2]) * n[2];
    if (sinkage <= 0.0) {
      after = {};
      continue;
    }
    // Multi-pass: the ruts other wheels left across this one's width, on average.
    double rut = 0.0;
    if (soil.multi_pass) {
      int cells = 0;
      for_each_rut_cell(low, a, w.shape.width, [&](double x, double y) {
        rut += data.ruts.depth(static_cast<int>(i), x, y);
        ++cells;
      });
      rut /= cells;
      Data::Press& press = data.soil_press[i];
      for (int k = 0; k < 3; ++k) {
        press.low[k] = low[k];
        press.axle[k] = a[k];
      }
      press.sinkage = sinkage;
    }
    // Contact frame: heading x = axle x n, axle y = n x x.
    double x[3], y[3];
    cross(a, n, x);
    normalize(x);
    cross(n, x, y);
    mjtNum vel[6];  // angular, linear at the geom's centre (world)
    mj_objectVelocity(m, d, mjOBJ_GEOM, w.geom, vel, 0);
    const double v = dot(vel + 3, x), v_side = dot(vel + 3, y), v_normal = dot(vel + 3, n);
    const double rw = r * dot(vel, y);
    const double u = std::max(std::abs(rw), std::abs(v));

    // Shear displacements over the step, and the forces in the frame of the motion.
    const SoilParameters& s = soil;
    // The arc in the soil (in a rut: below its floor, terramechanics.hpp).
    const double below = std::min(sinkage, r) - rut;
    const double theta1 = std::acos(std::clamp(1.0 - below / r, -1.0, 1.0));
    const double theta2 = s.model == WheelSoilModel::Ding ? std::acos(std::clamp(1.0 - s.rear_ratio * below / r, -1.0, 1.0))
                                                          : s.exit_ratio * theta1;
    const double length = std::max(kMinContactLength, r * (theta1 + theta2));
    after.shear_x = std::clamp(relax(before.shear_x, rw - v, u, length, dt), -length, length);
    after.shear_y = std::clamp(relax(before.shear_y, v_side, u, length, dt), -length, length);
    // Rolling (rim and centre together) builds up over the contact's length; the compaction ahead
    // over kPushLength of travel. A wheel jittering about rest does neither, so neither the
    // rolling rim's shear nor the resistance switches sides with every step.
    const double mean = 0.5 * (v + rw);
    after.rolling = toward(before.rolling, mean, length, dt);
    after.pushing = toward(before.pushing, v, kPushLength, dt);
    const double dir = after.rolling >= 0.0 ? 1.0 : -1.0;
    const WheelSoilForces f = wheel_soil_forces(s, w.shape, sinkage, dir * after.shear_x / length, dir * after.shear_y,
                                                std::abs(after.rolling), rut);
    // The shear's thrust in the rolling's frame; the compaction resistance against the travel.
    double fx = dir * (f.drawbar + f.resistance) - after.pushing * f.resistance;
    double fy = dir * f.lateral;
    double fn = f.normal;

    // Damping, critical for the wheel's share of the load, within the explicit step's bound.
    const double load_mass = fn / std::max(g, 1e-9);
    // The bounds: the wheel body's mass across the ground, and the mass its spin inertia puts at
    // the rim (I / r^2: 0.57 kg for a CC8 wheel, half its body's mass) along it.
    const int dof = model_->joints()[w.joint].dof_adr;
    const double rim_mass = (m->dof_M0[dof] + m->dof_armature[dof]) / (r * r);
    const double cap_normal = kDampingCap * m->body_mass[w.body] / dt;
    const double cap_shear = kDampingCap * std::min(m->body_mass[w.body], rim_mass) / dt;
    // d(load)/d(sinkage): the stress grows as z^n and the arc as (z - rut)^(1/2).
    const double k_normal = fn * (s.n / std::max(sinkage, 1e-4) + 0.5 / std::max(sinkage - rut, 1e-4));
    fn = std::max(0.0, fn - std::min(cap_normal, 2.0 * std::sqrt(k_normal * load_mass)) * v_normal);
    const double capacity = s.cohesion * w.shape.width * length + fn * tan_phi;
    const double c_shear = std::min(cap_shear, 2.0 * std::sqrt(capacity / s.shear_modulus * load_mass));
    fx += c_shear * (after.shear_x - before.shear_x) / dt;
    fy -= c_shear * (after.shear_y - before.shear_y) / dt;

    // Force and moment at the wheel's centre, then at the body's centre of mass.
    double force[3], torque[3];
    for (int k = 0; k < 3; ++k) {
      force[k] = fx * x[k] + fy * y[k] + fn * n[k];
      torque[k] = dir * f.torque * y[k] + f.moment_normal * n[k] + dir * f.moment_heading * x[k];
    }
    const mjtNum* com = d->xipos + 3 * w.body;
    const double arm[3] = {c[0] - com[0], c[1] - com[1], c[2] - com[2]};
    double shift[3];
    cross(arm, force, shift);
    for (int k = 0; k < 3; ++k) {
      d->xfrc_applied[6 * w.body + k] += force[k];
      d->xfrc_applied[6 * w.body + 3 + k] += torque[k] + shift[k];
    }

    // Readings in the frame of the motion (heading dir x, axle dir y). Slip is a ratio of speeds:
    // defined at any speed a rig runs at, undefined (flagged, not zero) only at rest.
    reading.contact = true;
    reading.moving = u > kSlipRestSpeed;
    reading.slip = reading.moving ? dir * (rw - v) / u : 0.0;
    reading.sliding = std::hypot(v, v_side) > kSlipRestSpeed;
    reading.slip_angle = reading.sliding ? std::atan2(dir * v_side, std::abs(v)) : 0.0;
    reading.sinkage = sinkage;
    reading.normal_force = fn;
    reading.traction = dir * fx;
    reading.lateral_force = dir * fy;
    reading.torque = f.torque;
    reading.rut_depth = rut;
  }
}

}  // namespace mechsim::physics
