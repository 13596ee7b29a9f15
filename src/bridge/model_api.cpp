// SimBridge: Gazebo's model API (sim_bridge.hpp), each call run in the loop thread between ticks.
#include <cmath>
#include <memory>
#include <mutex>

#include "physics/transform.hpp"
#include "bridge/bridge_impl.hpp"

namespace mechsim::bridge {

namespace {

constexpr double kLoopTimeout = 5.0;  // s (wall) a call waits for the loop thread
// MuJoCo's mjMAXVAL: a position or velocity at or beyond it is what MuJoCo's step takes for a
// diverged state (it warns and resets its data), so a request for one would stop the simulation.
constexpr double kMaxStateValue = 1e10;

bool bounded(const description::Vec3& v) {
  return std::abs(v.x) < kMaxStateValue && std::abs(v.y) < kMaxStateValue && std::abs(v.z) < kMaxStateValue;
}

bool finite(const description::Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

bool finite(const description::Pose& p) {
  const description::Quat& q = p.orientation;
  return finite(p.position) && std::isfinite(q.w) && std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z);
}

BridgeResult refuse(const std::string& why) { return {false, why}; }

// A link or joint of the robot in the physics (an other robot's under "<name>::").
std::optional<std::size_t> link_of(const sim::Simulation& s, const std::string& link) {
  const physics::PhysicsModel& m = s.physics().model();
  if (link.empty() && &s.world_host() == &s) return m.link_index(m.root_link());
  return m.link_index(s.physics_name(link.empty() ? s.robot().root_link : link));
}

std::optional<std::size_t> joint_of(const sim::Simulation& s, const std::string& joint) {
  return s.physics().model().joint_index(s.physics_name(joint));
}

}  // namespace


BridgeResult SimBridge::Impl::in_loop(const std::function<BridgeResult(sim::Simulation&)>& command) const {
  // The command and its result outlive a caller that timed out (the loop may run it later): so
  // commands capture by value, and outputs go through shared state (out_of below).
  auto result = std::make_shared<std::pair<std::mutex, std::optional<BridgeResult>>>();
  simulation->post([command, result](sim::Simulation& s) {
    BridgeResult r;
    try {
      r = command(s);
    } catch (const std::exception& e) {
      r = {false, e.what()};
    }
    std::lock_guard<std::mutex> lock(result->first);
    result->second = std::move(r);
  });
  if (!simulation->wait_for_commands(kLoopTimeout)) return refuse("the simulation loop did not answer within 5 s");
  std::lock_guard<std::mutex> lock(result->first);
  return result->second ? *result->second : refuse("the simulation loop dropped the request");
}

// Runs `read` in the loop thread and copies what it wrote into `out` once it has run: a
// command that runs after its caller timed out writes into the shared copy only.
using LoopCommand = std::function<BridgeResult(sim::Simulation&)>;

template <class T, class InLoop>
BridgeResult read_in_loop(const InLoop& in_loop, T& out, std::function<BridgeResult(sim::Simulation&, T&)> read) {
  auto value = std::make_shared<T>(out);
  const BridgeResult r = in_loop([value, read](sim::Simulation& s) { return read(s, *value); });
  if (r.ok) out = *value;
  return r;
}

BridgeResult SimBridge::link_state(const std::string& link, EntityState& out) const {
  if (link.empty() && fixed_in_world()) {
    out = EntityState{};
    out.pose = spawn_pose();
    return {};
  }
  return read_in_loop<EntityState>([this](const LoopCommand& c) { return impl_->in_loop(c); }, out, [link](sim::Simulation& s, EntityState& o) -> BridgeResult {
    const auto l = link_of(s, link);
    if (!l) return refuse("no link '" + link + "' in model '" + s.robot().name + "'");
    o.pose = s.physics().link_pose(*l);
    const physics::Twist v = s.physics().link_twist(*l);
    o.linear = v.linear;
    o.angular = v.angular;
    return {};
  });
}

const std::vector<std::string>& SimBridge::link_names() const { return impl_->link_names; }

bool SimBridge::fixed_in_world() const {
  return impl_->host != nullptr && impl_->options.robot.root_link == "world";
}

description::Pose SimBridge::spawn_pose() const {
  const BridgeOptions& o = impl_->options;
  return {{o.x, o.y, o.z}, physics::quat_from_rpy(o.roll, o.pitch, o.yaw)};
}

void SimBridge::model_state_now(EntityState& out) const {
  out = EntityState{};
  if (fixed_in_world()) {
    out.pose = spawn_pose();
    return;
  }
  impl_->refresh();
  const physics::Physics& p = impl_->simulation->physics();
  const auto l = link_of(*impl_->simulation, "");
  if (!l) return;
  out.pose = p.link_pose(*l);
  const physics::Twist v = p.link_twist(*l);
  out.linear = v.linear;
  out.angular = v.angular;
}

void SimBridge::link_states_now(std::vector<EntityState>& out) const {
  impl_->refresh();
  const physics::Physics& p = impl_->simulation->physics();
  out.resize(impl_->link_index.size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i].pose = p.link_pose(impl_->link_index[i]);
    const physics::Twist v = p.link_twist(impl_->link_index[i]);
    out[i].linear = v.linear;
    out[i].angular = v.angular;
  }
}

namespace {

// The velocity of a point at r from a point moving at v, on a body turning at w: v + w x r.
description::Vec3 carried(const description::Vec3& v, const description::Vec3& w, const description::Vec3& r) {
  return {v.x + w.y * r.z - w.z * r.y, v.y + w.z * r.x - w.x * r.z, v.z + w.x * r.y - w.y * r.x};
}

EntityState world_model_state_of(const sim::Simulation& s, const std::vector<int>& bodies, std::size_t i) {
  const sim::World::ModelFrame& f = s.world().sdf_model_frames[i];
  EntityState out;
  const int body = bodies[i];
  if (body < 0) {
    out.pose = f.pose;
    return out;
  }
  const physics::Physics& p = s.physics();
  const description::Pose X_WB = p.body_pose(body);
  out.pose = physics::compose(X_WB, f.X_BM);
  const physics::Twist v = p.body_twist(body);
  // The model frame's origin moves with the body: v_M = v_B + w x (p_M - p_B).
  const description::Vec3 r{out.pose.position.x - X_WB.position.x, out.pose.position.y - X_WB.position.y,
                             out.pose.position.z - X_WB.position.z};
  out.linear = carried(v.linear, v.angular, r);
  out.angular = v.angular;
  return out;
}

// A state the physics can take: finite, bounded, a nonzero quaternion (normalised into `unit`);
// else why not.
std::string unusable(const EntityState& state, EntityState& unit) {
  if (!finite(state.pose) || !finite(state.linear) || !finite(state.angular)) return "the pose and twist must be finite";
  if (!bounded(state.pose.position) || !bounded(state.linear) || !bounded(state.angular)) {
    return "the pose and twist must be below 1e10 (m, m/s, rad/s) in magnitude";
  }
  const description::Quat& q = state.pose.orientation;
  const double norm = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  if (norm < 1e-9) return "the orientation quaternion is zero";
  unit = state;
  unit.pose.orientation = {q.w / norm, q.x / norm, q.y / norm, q.z / norm};
  return "";
}


}  // namespace

void SimBridge::world_model_states_now(std::vector<EntityState>& out) const {
  impl_->refresh();
  const sim::Simulation& s = *impl_->simulation;
  out.resize(impl_->world_model_body.size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = world_model_state_of(s, impl_->world_model_body, i);
}

BridgeResult SimBridge::world_model_state(std::size_t index, EntityState& out) const {
  return read_in_loop<EntityState>([this](const LoopCommand& c) { return impl_->in_loop(c); }, out,
                                   [this, index](sim::Simulation& s, EntityState& o) -> BridgeResult {
                                     impl_->refresh();
                                     if (index >= impl_->world_model_body.size()) return refuse("no such world model");
                                     o = world_model_state_of(s, impl_->world_model_body, index);
                                     return {};
                                   });
}

std::vector<std::string> SimBridge::stop_all_controllers_now() {
  if (impl_->host != nullptr) {  // an other robot: the world's loop runs on, so there
    std::vector<std::string> loaded;
    read_in_loop<std::vector<std::string>>([this](const LoopCommand& c) { return impl_->in_loop(c); }, loaded,
                                           [this](sim::Simulation&, std::vector<std::string>& o) -> BridgeResult {
                                             o = stop_controllers(*impl_->simulation);
                                             return {};
                                           });
    return loaded;
  }
  return stop_controllers(*impl_->simulation);
}

std::vector<std::string> SimBridge::stop_controllers(sim::Simulation& s) {
  control::ControllerManager& cm = s.controllers();
  const double now = s.time();
  cm.apply_pending_switch(now);  // a switch waiting for the next tick (paused) first
  std::vector<std::string> loaded, running;
  for (const control::ControllerInfo& info : cm.list_controllers()) {
    loaded.push_back(info.name);
    if (info.state == control::ControllerLifecycle::Running) running.push_back(info.name);
  }
  if (!running.empty()) cm.switch_controllers({}, running, control::SwitchStrictness::BestEffort);
  cm.apply_pending_switch(now);
  return loaded;
}


BridgeResult SimBridge::set_world_model_state(std::size_t index, const EntityState& state) {
  EntityState unit;
  if (const std::string why = unusable(state, unit); !why.empty()) return refuse(why);
  return impl_->in_loop([this, index, unit](sim::Simulation& s) -> BridgeResult {
    impl_->refresh();
    if (index >= impl_->world_model_body.size()) return refuse("no such model of the world");
    const sim::World::ModelFrame& f = s.world().sdf_model_frames[index];
    const int body = impl_->world_model_body[index];
    if (body < 0) return refuse("model '" + f.name + "' is static (or jointed to the world): it does not move");
    // The model frame M to its body B: X_WB = X_WM X_MB, v_B = v_M + w x (p_B - p_M).
    const description::Pose X_WB = physics::compose(unit.pose, physics::inverse(f.X_BM));
    const description::Vec3 r{X_WB.position.x - unit.pose.position.x, X_WB.position.y - unit.pose.position.y,
                              X_WB.position.z - unit.pose.position.z};
    const physics::Twist V{carried(unit.linear, unit.angular, r), unit.angular};
    if (!s.physics().set_free_body_state(body, X_WB, V)) {
      return refuse("model '" + f.name + "' does not float freely (its root is jointed to the world)");
    }
    s.state_changed();
    return {};
  });
}

BridgeResult SimBridge::set_root_state(const EntityState& state) {
  EntityState unit;
  if (const std::string why = unusable(state, unit); !why.empty()) return refuse(why);
  return impl_->in_loop([unit](sim::Simulation& s) -> BridgeResult {
    if (!s.floating()) return refuse("model '" + s.robot().name + "' is fixed to the world: its pose cannot be set");
    if (&s.world_host() != &s) {  // an other robot: its root floats on a free joint of its own
      const int body = s.physics().model().body_index(s.physics_name(s.robot().root_link));
      if (body < 1 || !s.physics().set_free_body_state(body, unit.pose, {unit.linear, unit.angular}))
        return refuse("model '" + s.robot().name + "': its root link does not float freely");
    } else {
      s.physics().set_base_pose(unit.pose);
      s.physics().set_base_twist({unit.linear, unit.angular});
    }
    s.state_changed();
    return {};
  });
}

BridgeResult SimBridge::set_joint_positions(const std::vector<std::string>& joints, const std::vector<double>& positions) {
  if (joints.size() != positions.size()) {
    return refuse("joint_names has " + std::to_string(joints.size()) + " names but joint_positions " +
                  std::to_string(positions.size()) + " values");
  }
  for (std::size_t i = 0; i < joints.size(); ++i)
    if (!std::isfinite(positions[i]) || std::abs(positions[i]) >= kMaxStateValue) {
      return refuse("joint '" + joints[i] + "': the position must be finite and below 1e10 in magnitude");
    }
  return impl_->in_loop([joints, positions](sim::Simulation& s) -> BridgeResult {
    std::vector<std::size_t> index;
    for (const std::string& j : joints) {
      const auto p = joint_of(s, j);
      if (!p) return refuse("no joint '" + j + "' in model '" + s.robot().name + "'");
      index.push_back(*p);
    }
    for (std::size_t i = 0; i < index.size(); ++i) s.physics().set_joint_state(index[i], positions[i], 0.0);
    s.state_changed();
    return {};
  });
}

BridgeResult SimBridge::joint_properties(const std::string& joint, JointPropertiesData& out) const {
  return read_in_loop<JointPropertiesData>([this](const LoopCommand& c) { return impl_->in_loop(c); }, out, [joint](sim::Simulation& s, JointPropertiesData& o) -> BridgeResult {
    const description::Joint* j = s.robot().joint(joint);
    if (j == nullptr) return refuse("no joint '" + joint + "' in model '" + s.robot().name + "'");
    switch (j->type) {
      case description::JointType::Revolute: o.type = 0; break;
      case description::JointType::Continuous: o.type = 1; break;
      case description::JointType::Prismatic: o.type = 2; break;
      default: o.type = 3; break;
    }
    o.damping = j->dynamics ? j->dynamics->damping : 0.0;
    o.position = o.rate = 0.0;
    if (const auto p = joint_of(s, joint)) {
      o.position = s.physics().position(*p);
      o.rate = s.physics().velocity(*p);
      o.damping = s.physics().joint_damping(*p);
    }
    return {};
  });
}

BridgeResult SimBridge::link_properties(const std::string& link, LinkPropertiesData& out) const {
  // In the loop thread: a spawn or delete replaces the physics model read here.
  const BridgeResult r = read_in_loop<LinkPropertiesData>([this](const LoopCommand& c) { return impl_->in_loop(c); }, out,
                                          [link](sim::Simulation& s, LinkPropertiesData& o) -> BridgeResult {
    const description::Link* l = s.robot().link(link);
    if (l == nullptr) return refuse("no link '" + link + "' in model '" + s.robot().name + "'");
    o = LinkPropertiesData{};
    if (l->inertial) {
      const description::Inertial& i = *l->inertial;
      o.com = i.origin;
      o.mass = i.mass;
      o.ixx = i.ixx, o.ixy = i.ixy, o.ixz = i.ixz, o.iyy = i.iyy, o.iyz = i.iyz, o.izz = i.izz;
    }
    for (const std::string& off : s.physics().model().gravity_off_links())
      if (off == s.physics_name(link)) o.gravity_mode = false;
    return {};
  });
  if (r.ok) {
    std::lock_guard<std::mutex> lock(impl_->overrides_mutex);
    if (const auto it = impl_->link_overrides.find(link); it != impl_->link_overrides.end()) out = it->second;
  }
  return r;
}

BridgeResult SimBridge::set_joint_properties(const std::string& joint, const JointPropertyChange& change) {
  if ((change.damping && !(std::isfinite(*change.damping) && *change.damping >= 0.0)))
    return refuse("damping must be finite and >= 0");
  if ((change.lower && !std::isfinite(*change.lower)) || (change.upper && !std::isfinite(*change.upper)))
    return refuse("hiStop and loStop must be finite");
  const BridgeResult r = impl_->in_loop([joint, change](sim::Simulation& s) -> BridgeResult {
    const auto j = joint_of(s, joint);
    if (!j) return refuse("no joint '" + joint + "' in model '" + s.robot().name + "'");
    physics::Physics& p = s.physics();
    auto [lower, upper] = p.joint_limits(*j);
    if (change.lower) lower = *change.lower;
    if (change.upper) upper = *change.upper;
    if ((change.lower || change.upper) && lower > upper)
      return refuse("loStop " + std::to_string(lower) + " is above hiStop " + std::to_string(upper));
    if (change.damping) p.set_joint_damping(*j, *change.damping);
    if (change.lower || change.upper) p.set_joint_limits(*j, lower, upper);
    return {};
  });
  if (r.ok) {
    // Kept for the physics built again when a model comes or goes (Impl::refresh applies them).
    std::lock_guard<std::mutex> lock(impl_->overrides_mutex);
    JointPropertyChange& kept = impl_->joint_overrides[joint];
    if (change.damping) kept.damping = change.damping;
    if (change.lower) kept.lower = change.lower;
    if (change.upper) kept.upper = change.upper;
  }
  return r;
}

BridgeResult SimBridge::set_link_properties(const std::string& link, const LinkPropertiesData& p) {
  LinkPropertiesData now;
  if (const BridgeResult r = link_properties(link, now); !r.ok) return r;
  if (p.gravity_mode != now.gravity_mode) {
    return refuse(std::string("gravity_mode: mechsim sets a link's gravity when the model is built (<gravity> / ") +
                  "<turnGravityOff> in its description), not while it runs");
  }
  const BridgeResult r = impl_->in_loop([link, p](sim::Simulation& s) -> BridgeResult {
    const auto l = link_of(s, link);
    if (!l || link.empty()) return refuse("no link '" + link + "' in model '" + s.robot().name + "'");
    const std::string why = s.physics().set_link_inertial(*l, p.mass, p.com, {p.ixx, p.ixy, p.ixz, p.iyy, p.iyz, p.izz});
    return why.empty() ? BridgeResult{} : refuse(why);
  });
  if (r.ok) {
    std::lock_guard<std::mutex> lock(impl_->overrides_mutex);
    impl_->link_overrides[link] = p;
  }
  return r;
}

BridgeResult SimBridge::apply_link_wrench(const std::string& link, const description::Vec3& force_W,
                                          const description::Vec3& torque_W, const description::Vec3& offset_W,
                                          double start, double duration) {
  if (!finite(force_W) || !finite(torque_W) || !finite(offset_W)) return refuse("the wrench and its point must be finite");
  if (!std::isfinite(start) || !std::isfinite(duration)) return refuse("start_time and duration must be finite");
  return impl_->in_loop([=](sim::Simulation& s) -> BridgeResult {
    const auto l = link_of(s, link);
    if (!l || link.empty()) return refuse("no link '" + link + "' in model '" + s.robot().name + "'");
    s.world_host().external_forces().add_wrench({*l, force_W, torque_W, offset_W},
                                                sim::force_window(s.time(), s.period(), start, duration));
    return {};
  });
}

BridgeResult SimBridge::apply_joint_effort(const std::string& joint, double effort, double start, double duration) {
  if (!std::isfinite(effort) || !std::isfinite(start) || !std::isfinite(duration)) {
    return refuse("effort, start_time and duration must be finite");
  }
  return impl_->in_loop([=](sim::Simulation& s) -> BridgeResult {
    const auto j = joint_of(s, joint);
    if (!j) return refuse("no joint '" + joint + "' in model '" + s.robot().name + "'");
    s.world_host().external_forces().add_effort(*j, effort, sim::force_window(s.time(), s.period(), start, duration));
    return {};
  });
}

BridgeResult SimBridge::clear_link_wrenches(const std::string& link) {
  return impl_->in_loop([link](sim::Simulation& s) -> BridgeResult {
    const auto l = link_of(s, link);
    if (!l || link.empty()) return refuse("no link '" + link + "' in model '" + s.robot().name + "'");
    s.world_host().external_forces().clear_wrenches(*l);  // gone from the next step on
    return {};
  });
}

BridgeResult SimBridge::clear_joint_efforts(const std::string& joint) {
  return impl_->in_loop([joint](sim::Simulation& s) -> BridgeResult {
    const auto j = joint_of(s, joint);
    if (!j) return refuse("no joint '" + joint + "' in model '" + s.robot().name + "'");
    s.world_host().external_forces().clear_efforts(*j);
    return {};
  });
}

description::Vec3 SimBridge::gravity() const {
  description::Vec3 g{0.0, 0.0, -9.81};
  read_in_loop<description::Vec3>([this](const LoopCommand& c) { return impl_->in_loop(c); }, g, [](sim::Simulation& s, description::Vec3& o) -> BridgeResult {
    o = s.physics().gravity();
    return {};
  });
  return g;
}

BridgeResult SimBridge::set_gravity(const description::Vec3& g_W) {
  if (!finite(g_W)) return refuse("gravity must be finite");
  return impl_->in_loop([g_W](sim::Simulation& s) -> BridgeResult {
    s.physics().set_gravity(g_W);
    return {};
  });
}

bool SimBridge::fixed_to_world() const { return !impl_->simulation->floating(); }

double SimBridge::real_time_factor() const {
  double f = 0.0;
  read_in_loop<double>([this](const LoopCommand& c) { return impl_->in_loop(c); }, f, [](sim::Simulation& s, double& o) -> BridgeResult {
    o = s.world_host().options().real_time_factor;
    return {};
  });
  return f;
}

void SimBridge::set_real_time_factor(double factor) {
  impl_->in_loop([factor](sim::Simulation& s) -> BridgeResult {
    s.world_host().set_real_time_factor(factor);
    return {};
  });
}

double SimBridge::measured_real_time_factor() const {
  return impl_->simulation->world_host().measured_real_time_factor();
}

void SimBridge::request_steps(std::uint64_t count) { impl_->simulation->world_host().request_steps(count); }
std::uint64_t SimBridge::pending_steps() const { return impl_->simulation->world_host().pending_steps(); }
void SimBridge::cancel_steps() { impl_->simulation->world_host().cancel_steps(); }

}  // namespace mechsim::bridge
