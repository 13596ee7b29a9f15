#include "physics/body_plan.hpp"

#include <cmath>
#include <map>
#include <set>

#include "description/mimic_plugin.hpp"
#include "physics/physics_error.hpp"
#include "physics/transform.hpp"
#include "physics/wheel_identify.hpp"

namespace mechsim::physics {
namespace {

using description::JointType;
using description::Link;
using description::RobotModel;

bool massless(const Link& link) { return !link.inertial || !(link.inertial->mass > 0.0); }

double parse_double(const std::string& text, const std::string& what) {
  try {
    std::size_t used = 0;
    const double v = std::stod(text, &used);
    if (used == 0 || !std::isfinite(v)) throw std::invalid_argument(text);
    return v;
  } catch (const std::exception&) {
    throw PhysicsError(what + ": '" + text + "' is not a number");
  }
}

// Unit vectors u, v with (u, v, n) right-handed and orthonormal.
std::pair<Vec3, Vec3> plane_basis(const Vec3& n) {
  const Vec3 seed = std::fabs(n.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  Vec3 u{n.y * seed.z - n.z * seed.y, n.z * seed.x - n.x * seed.z, n.x * seed.y - n.y * seed.x};
  const double nu = std::sqrt(u.x * u.x + u.y * u.y + u.z * u.z);
  u = {u.x / nu, u.y / nu, u.z / nu};
  const Vec3 v{n.y * u.z - n.z * u.y, n.z * u.x - n.x * u.z, n.x * u.y - n.y * u.x};
  return {v, u};  // v x u = n  ->  (v, u, n) right-handed
}

Vec3 unit(const Vec3& a, const std::string& joint) {
  const double n = std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
  if (!(n > 1e-12)) throw PhysicsError("joint '" + joint + "': axis has zero length");
  return {a.x / n, a.y / n, a.z / n};
}

class Planner {
 public:
  Planner(const RobotModel& robot, const BuildOptions& options) : robot_(robot), options_(options) {}

  BodyPlan run() {
    const Link* root = robot_.link(robot_.root_link);
    if (root == nullptr) throw PhysicsError("robot '" + robot_.name + "': root link '" + robot_.root_link + "' not found");
    const SpawnPose& s = options_.spawn;
    const Pose X_W_spawn{{s.x, s.y, s.z}, quat_from_rpy(s.roll, s.pitch, s.yaw)};
    if (root->name == "world") {
      plan_.fixed_to_world = true;
      visit(*root, -1, X_W_spawn);
    } else {
      PlannedBody body;
      body.name = root->name;
      body.X_PB = X_W_spawn;
      body.inertial = root->inertial;
      PlannedJoint free;
      free.name = root->name + ":free";
      free.kind = PlannedJoint::Kind::Free;
      body.joints.push_back(free);
      plan_.bodies.push_back(std::move(body));
      visit(*root, 0, Pose{});
    }
    plan_mimics();
    plan_differential();
    return std::move(plan_);
  }

 private:
  const description::GazeboLinkProperties& gz(const std::string& link) const {
    auto it = robot_.gazebo_links.find(link);
    return it == robot_.gazebo_links.end() ? no_gazebo_ : it->second;
  }

  // Why a shape has no volume ("" when it has one): a box, cylinder or sphere with a size of
  // exactly zero, or a mesh scaled to nothing, as public descriptions use for placeholders
  // (MuJoCo refuses them; Gazebo loads them). A negative size is an error in the description and
  // goes on to MuJoCo, whose rejection names the geom.
  static std::string degenerate(const description::Geometry& g) {
    switch (g.type) {
      case description::GeometryType::Box:
        if (g.size.x == 0.0 || g.size.y == 0.0 || g.size.z == 0.0) return "a box of size zero";
        break;
      case description::GeometryType::Cylinder:
        if (g.radius == 0.0 || g.length == 0.0) return "a cylinder of radius or length zero";
        break;
      case description::GeometryType::Sphere:
        if (g.radius == 0.0) return "a sphere of radius zero";
        break;
      case description::GeometryType::Mesh:
        if (!(g.mesh_scale.x != 0.0 && g.mesh_scale.y != 0.0 && g.mesh_scale.z != 0.0)) return "a mesh scaled by zero";
        break;
      default:
        break;
    }
    return "";
  }

  void add_geoms(const Link& link, int body, const Pose& X_BL) {
    const auto& g = gz(link.name);
    // One sliding coefficient per geom (contact_defaults.hpp, isotropic_friction); each contact
    // takes the smaller of its two geoms' (mjcf_writer.cpp's priorities), as ODE does.
    double mu = options_.contact.sliding_friction;
    if (g.mu1 || g.mu2) {
      mu = isotropic_friction(g.mu1, g.mu2);
      const double mu1 = g.mu1.value_or(kGazeboDefaultMu), mu2 = g.mu2.value_or(kGazeboDefaultMu);
      if (mu1 != mu2 && !link.collisions.empty())
        plan_.warnings.push_back("link '" + link.name + "': anisotropic friction mu1=" + std::to_string(mu1) +
                                 " mu2=" + std::to_string(mu2) + (g.mu1 && g.mu2 ? "" : " (Gazebo's default 1 where left out)") +
                                 " approximated by their mean " + std::to_string(mu) +
                                 " (MuJoCo 2.2.2's geoms have one sliding coefficient and its contact frames no set direction)");
    }
    if (g.gravity && !*g.gravity && !massless(link)) plan_.gravity_off_links.push_back(link.name);
    std::vector<PlannedGeom>& out = body < 0 ? plan_.world_geoms : plan_.bodies[body].geoms;
    std::optional<double> link_retro = g.laser_retro;
    for (std::size_t i = 0; i < link.collisions.size() && !link_retro; ++i) link_retro = link.collisions[i].laser_retro;
    for (std::size_t i = 0; i < link.collisions.size(); ++i) {
      if (const std::string why = degenerate(link.collisions[i].geometry); !why.empty()) {
        plan_.warnings.push_back("link '" + link.name + "': collision " + std::to_string(i) + " left out: " + why +
                                 " (Gazebo loads it and it never touches anything)");
        continue;
      }
      PlannedGeom geom;
      geom.name = link.name + "/collision/" + std::to_string(i);
      geom.link = link.name;
      geom.X_BG = compose(X_BL, link.collisions[i].origin);
      geom.geometry = link.collisions[i].geometry;
      geom.self_collide = g.self_collide.value_or(false);
      geom.friction = mu;
      geom.wheel = is_wheel_collision(robot_, link, link.collisions[i]);
      geom.narrow_wheel = is_narrow_wheel_collision(robot_, link, link.collisions[i]);
      geom.laser_retro = link.collisions[i].laser_retro.value_or(g.laser_retro.value_or(0.0));
      out.push_back(std::move(geom));
    }
    if (!options_.visuals) return;
    for (std::size_t i = 0; i < link.visuals.size(); ++i) {
      if (!degenerate(link.visuals[i].geometry).empty()) continue;  // nothing to draw
      PlannedGeom geom;
      geom.name = link.name + "/visual/" + std::to_string(i);
      geom.link = link.name;
      geom.X_BG = compose(X_BL, link.visuals[i].origin);
      geom.geometry = link.visuals[i].geometry;
      geom.visual = true;
      geom.rgba = link.visuals[i].rgba;
      geom.laser_retro = link_retro.value_or(0.0);
      out.push_back(std::move(geom));
    }
  }

  // Places `link` (whose frame is X_BL in body `body`) and recursively its children.
  void visit(const Link& link, int body, const Pose& X_BL) {
    if (++depth_guard_ > robot_.links.size() + 1)
      throw PhysicsError("robot '" + robot_.name + "': the link tree has a cycle at '" + link.name + "'");
    plan_.link_frames.push_back({link.name, body, X_BL});
    add_geoms(link, body, X_BL);
    for (const std::string& joint_name : link.child_joints) {
      const description::Joint* joint = robot_.joint(joint_name);
      if (joint == nullptr) throw PhysicsError("link '" + link.name + "': child joint '" + joint_name + "' not found");
      const Link* child = robot_.link(joint->child_link);
      if (child == nullptr)
        throw PhysicsError("joint '" + joint->name + "' (line " + std::to_string(joint->line) + "): child link '" +
                           joint->child_link + "' not found");
      const Pose X_BC = compose(X_BL, joint->origin);
      const bool movable = joint->type != JointType::Fixed;
      const bool lump = movable && massless(*child) && lump_fixed_descendants(*child);
      if (lumped_.count(child->name)) {  // its mass is already part of this body
        visit(*child, body, X_BC);
        continue;
      }
      if (massless(*child) && !lump) {
        if (movable) {
          plan_.warnings.push_back("joint '" + joint->name + "': its child link '" + child->name +
                                   "' has no mass, so it is merged into '" + link.name +
                                   "' and the joint is not simulated (Gazebo drops such links too)");
          plan_.dropped_joints.push_back(joint->name);
        }
        visit(*child, body, X_BC);
        continue;
      }
      PlannedBody nb;
      nb.name = child->name;
      nb.parent = body;
      nb.X_PB = X_BC;
      nb.inertial = lump ? lumped_inertial_ : child->inertial;
      add_joints(*joint, nb);
      const int index = static_cast<int>(plan_.bodies.size());
      plan_.bodies.push_back(std::move(nb));
      if (body >= 0) add_exclude(plan_.bodies[body].name, child->name);
      visit(*child, index, Pose{});
    }
  }

  // A massless link on a movable joint whose fixed-joint descendants carry mass: their
  // inertials are lumped into its body (exact for rigid attachments, as Gazebo lumps fixed
  // joints), so the joint is kept. Returns false when there is no such mass.
  bool lump_fixed_descendants(const Link& link) {
    std::vector<std::pair<Pose, description::Inertial>> parts;  // X_LI' = X_L<desc> * X_<desc>I
    std::vector<std::string> names;
    collect_fixed_mass(link, Pose{}, parts, names);
    if (parts.empty()) return false;
    double mass = 0.0;
    Vec3 com{};
    for (const auto& [X, in] : parts) {
      mass += in.mass;
      com.x += in.mass * X.position.x, com.y += in.mass * X.position.y, com.z += in.mass * X.position.z;
    }
    com = {com.x / mass, com.y / mass, com.z / mass};
    double I[3][3] = {};
    for (const auto& [X, in] : parts) {
      // Rotate the part's inertia into the link frame, then move it to the common centre of mass.
      const Quat& q = X.orientation;
      const double R[3][3] = {
          {1 - 2 * (q.y * q.y + q.z * q.z), 2 * (q.x * q.y - q.z * q.w), 2 * (q.x * q.z + q.y * q.w)},
          {2 * (q.x * q.y + q.z * q.w), 1 - 2 * (q.x * q.x + q.z * q.z), 2 * (q.y * q.z - q.x * q.w)},
          {2 * (q.x * q.z - q.y * q.w), 2 * (q.y * q.z + q.x * q.w), 1 - 2 * (q.x * q.x + q.y * q.y)}};
      const double Ip[3][3] = {{in.ixx, in.ixy, in.ixz}, {in.ixy, in.iyy, in.iyz}, {in.ixz, in.iyz, in.izz}};
      const double d[3] = {X.position.x - com.x, X.position.y - com.y, X.position.z - com.z};
      const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          double rot = 0.0;
          for (int k = 0; k < 3; ++k)
            for (int l = 0; l < 3; ++l) rot += R[i][k] * Ip[k][l] * R[j][l];
          I[i][j] += rot + in.mass * ((i == j ? dd : 0.0) - d[i] * d[j]);
        }
    }
    lumped_inertial_ = description::Inertial{};
    lumped_inertial_.origin.position = com;
    lumped_inertial_.mass = mass;
    lumped_inertial_.ixx = I[0][0], lumped_inertial_.iyy = I[1][1], lumped_inertial_.izz = I[2][2];
    lumped_inertial_.ixy = I[0][1], lumped_inertial_.ixz = I[0][2], lumped_inertial_.iyz = I[1][2];
    lumped_.insert(names.begin(), names.end());
    return true;
  }

  void collect_fixed_mass(const Link& link, const Pose& X_RL, std::vector<std::pair<Pose, description::Inertial>>& parts,
                          std::vector<std::string>& names) {
    for (const std::string& joint_name : link.child_joints) {
      const description::Joint* joint = robot_.joint(joint_name);
      if (joint == nullptr || joint->type != JointType::Fixed) continue;
      const Link* child = robot_.link(joint->child_link);
      if (child == nullptr) continue;
      const Pose X_RC = compose(X_RL, joint->origin);
      if (!massless(*child)) {
        parts.emplace_back(compose(X_RC, child->inertial->origin), *child->inertial);
        names.push_back(child->name);
      }
      collect_fixed_mass(*child, X_RC, parts, names);
    }
  }

  void add_exclude(const std::string& a, const std::string& b) {
    if (a == b) return;
    if (excluded_.insert(a < b ? std::make_pair(a, b) : std::make_pair(b, a)).second) plan_.excludes.emplace_back(a, b);
  }

  void add_joints(const description::Joint& joint, PlannedBody& body) {
    PlannedJoint pj;
    pj.name = joint.name;
    pj.urdf_joint = joint.name;
    if (joint.dynamics) {
      pj.damping = joint.dynamics->damping;
      pj.frictionloss = joint.dynamics->friction;
    }
    if (joint.limits) {
      pj.effort_limit = joint.limits->effort;
      pj.velocity_limit = joint.limits->velocity;
    }
    const auto set_range = [&](PlannedJoint& j) {
      if (!joint.limits) return;
      if (!(joint.limits->lower < joint.limits->upper)) {
        if (joint.limits->lower == joint.limits->upper && joint.limits->lower == 0.0) return;  // "no limits"
        throw PhysicsError("joint '" + joint.name + "' (line " + std::to_string(joint.line) + "): lower limit " +
                           std::to_string(joint.limits->lower) + " is not below upper limit " +
                           std::to_string(joint.limits->upper));
      }
      j.limited = true;
      j.lower = joint.limits->lower;
      j.upper = joint.limits->upper;
    };
    switch (joint.type) {
      case JointType::Revolute:
        pj.kind = PlannedJoint::Kind::Hinge;
        pj.axis = unit(joint.axis, joint.name);
        pj.one_dof_urdf = true;
        set_range(pj);
        body.joints.push_back(pj);
        break;
      case JointType::Continuous:
        pj.kind = PlannedJoint::Kind::Hinge;
        pj.axis = unit(joint.axis, joint.name);
        pj.one_dof_urdf = true;
        body.joints.push_back(pj);
        break;
      case JointType::Prismatic:
        pj.kind = PlannedJoint::Kind::Slide;
        pj.axis = unit(joint.axis, joint.name);
        pj.one_dof_urdf = true;
        set_range(pj);
        body.joints.push_back(pj);
        break;
      case JointType::Planar: {
        const Vec3 n = unit(joint.axis, joint.name);
        const auto [u, v] = plane_basis(n);
        PlannedJoint a = pj, b = pj, c = pj;
        a.name = joint.name + ":x", a.kind = PlannedJoint::Kind::Slide, a.axis = u;
        b.name = joint.name + ":y", b.kind = PlannedJoint::Kind::Slide, b.axis = v;
        c.name = joint.name + ":yaw", c.kind = PlannedJoint::Kind::Hinge, c.axis = n;
        body.joints.insert(body.joints.end(), {a, b, c});
        break;
      }
      case JointType::Floating: {
        if (body.parent < 0) {
          pj.kind = PlannedJoint::Kind::Free;
          body.joints.push_back(pj);
        } else {
          // MuJoCo allows free joints on top-level bodies only: three slides and a ball.
          const char* names[3] = {":x", ":y", ":z"};
          const Vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
          for (int i = 0; i < 3; ++i) {
            PlannedJoint s = pj;
            s.name = joint.name + names[i];
            s.kind = PlannedJoint::Kind::Slide;
            s.axis = axes[i];
            body.joints.push_back(s);
          }
          PlannedJoint ball = pj;
          ball.name = joint.name + ":ball";
          ball.kind = PlannedJoint::Kind::Ball;
          body.joints.push_back(ball);
        }
        break;
      }
      case JointType::Fixed: break;
    }
  }

  bool simulated_one_dof(const std::string& name) const {
    for (const PlannedBody& b : plan_.bodies)
      for (const PlannedJoint& j : b.joints)
        if (j.name == name && j.one_dof_urdf) return true;
    return false;
  }

  void plan_differential() {
    for (const description::GazeboPlugin& p : robot_.plugins) {
      if (p.filename.find("differential") == std::string::npos) continue;
      const auto get = [&](const char* key) -> std::string {
        auto it = p.parameters.find(key);
        if (it == p.parameters.end())
          throw PhysicsError("gazebo plugin '" + p.name + "' (" + p.filename + "): missing <" + key + ">");
        return it->second;
      };
      PlannedDifferential d;
      d.plugin = p.name;
      d.joint_a = get("jointA");
      d.joint_b = get("jointB");
      d.force_constant = parse_double(get("forceConstant"), "gazebo plugin '" + p.name + "' <forceConstant>");
      for (const std::string* j : {&d.joint_a, &d.joint_b})
        if (!simulated_one_dof(*j))
          throw PhysicsError("gazebo plugin '" + p.name + "': joint '" + *j + "' is not a simulated 1-DOF joint");
      plan_.differential = d;
      return;
    }
  }

  void plan_mimics() {
    // A mimic joint plugin sets its follower itself in Gazebo (which ignores URDF <mimic>): a
    // follower the plugin positions is a constraint here too, one it drives with a PID is left to
    // the plugin's controller, and either way the URDF tag of that follower gives no constraint.
    const std::vector<description::MimicPluginSpec> plugins = description::mimic_plugins(robot_);
    std::set<std::string> plugin_followers;
    for (const description::MimicPluginSpec& m : plugins) {
      plugin_followers.insert(m.mimic_joint);
      if (m.has_pid) continue;
      if (!simulated_one_dof(m.mimic_joint) || !simulated_one_dof(m.joint)) continue;  // the controller says why
      plan_.mimics.push_back({m.mimic_joint, m.joint, m.multiplier, m.offset, 2.0 * options_.timestep});
    }
    for (const description::Joint& joint : robot_.joints) {
      if (!joint.mimic || plugin_followers.count(joint.name) > 0) continue;
      if (!simulated_one_dof(joint.name) || !simulated_one_dof(joint.mimic->joint)) {
        plan_.warnings.push_back("joint '" + joint.name + "' mimics '" + joint.mimic->joint +
                                 "', but one of them is not a simulated 1-DOF joint: no constraint");
        continue;
      }
      if (options_.differential == DifferentialMode::PluginLaw && is_differential_pair(joint.name, joint.mimic->joint))
        continue;
      plan_.mimics.push_back({joint.name, joint.mimic->joint, joint.mimic->multiplier, joint.mimic->offset});
    }
  }

  bool is_differential_pair(const std::string& a, const std::string& b) const {
    for (const description::GazeboPlugin& p : robot_.plugins) {
      if (p.filename.find("differential") == std::string::npos) continue;
      auto ja = p.parameters.find("jointA"), jb = p.parameters.find("jointB");
      if (ja == p.parameters.end() || jb == p.parameters.end()) continue;
      if ((ja->second == a && jb->second == b) || (ja->second == b && jb->second == a)) return true;
    }
    return false;
  }

  const RobotModel& robot_;
  const BuildOptions& options_;
  BodyPlan plan_;
  std::set<std::pair<std::string, std::string>> excluded_;
  std::size_t depth_guard_ = 0;
  description::GazeboLinkProperties no_gazebo_;
  std::set<std::string> lumped_;  // links whose mass was lumped into an ancestor's body
  description::Inertial lumped_inertial_;
};

}  // namespace

namespace {

// A world model planned as a robot of its own, at its pose, its names prefixed.
BodyPlan plan_passive(const WorldModel& model, const BuildOptions& options) {
  if (model.name.empty()) throw PhysicsError("world: a passive model has no name");
  if (model.robot == nullptr) throw PhysicsError("world model '" + model.name + "': no description");
  BuildOptions own = options;
  own.spawn = {};
  own.world.models.clear();
  BodyPlan p = Planner(*model.robot, own).run();
  const std::string prefix = model.name + "::";
  for (PlannedBody& b : p.bodies) {
    b.name = prefix + b.name;
    if (b.parent < 0) b.X_PB = compose(model.pose, b.X_PB);
    for (PlannedJoint& j : b.joints) {
      j.name = prefix + j.name;
      j.urdf_joint = prefix + j.urdf_joint;
      j.one_dof_urdf = j.one_dof_urdf && model.actuated;  // an object's: nothing drives it
    }
    for (PlannedGeom& g : b.geoms) {
      g.name = prefix + g.name;
      g.link = prefix + g.link;
      // An object's cylinders are no wheels; another robot's wheels are (the soil acts on them).
      g.wheel = g.wheel && model.actuated;
      g.narrow_wheel = g.narrow_wheel && model.actuated;
    }
  }
  for (PlannedGeom& g : p.world_geoms) {
    g.name = prefix + g.name;
    g.link = prefix + g.link;
    g.X_BG = compose(model.pose, g.X_BG);
    g.wheel = false;  // welded to the world: it does not turn
    g.narrow_wheel = g.narrow_wheel && model.actuated;
  }
  for (LinkFrame& f : p.link_frames) f.link = prefix + f.link;
  for (PlannedMimic& m : p.mimics) {
    m.follower = prefix + m.follower;
    m.leader = prefix + m.leader;
  }
  for (auto& [a, b] : p.excludes) {
    a = prefix + a;
    b = prefix + b;
  }
  for (std::string& w : p.warnings) w = "world model '" + model.name + "': " + w;
  p.differential.reset();
  if (model.actuated)
    for (std::string& link : p.gravity_off_links) link = prefix + link;
  else
    p.gravity_off_links.clear();
  return p;
}

}  // namespace

BodyPlan plan_bodies(const description::RobotModel& robot, const BuildOptions& options) {
  BodyPlan plan = Planner(robot, options).run();
  std::set<std::string> names;
  int robots = 0;
  for (const WorldModel& model : options.world.models) {
    if (!names.insert(model.name).second) throw PhysicsError("world model '" + model.name + "': the name is used twice");
    if (model.actuated && robots == kMaxActuatedModels)
      throw PhysicsError("world model '" + model.name + "': one world holds at most " +
                         std::to_string(kMaxActuatedModels + 1) + " robots");
    BodyPlan p = plan_passive(model, options);
    if (model.actuated) p.robot_bit = 1 << (2 + robots++);
    plan.warnings.insert(plan.warnings.end(), p.warnings.begin(), p.warnings.end());
    p.warnings.clear();
    plan.passive.push_back(std::move(p));
  }
  return plan;
}

}  // namespace mechsim::physics
