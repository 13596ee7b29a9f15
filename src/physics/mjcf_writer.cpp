#include "physics/mjcf_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <optional>
#include <sstream>
#include <string_view>

#include "physics/collision_pairs.hpp"
#include "physics/mesh_loader.hpp"
#include "physics/physics_error.hpp"
#include "physics/terrain_tiles.hpp"
#include "physics/transform.hpp"

namespace mechsim::physics {
namespace {

using description::GeometryType;

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.17g", v);
  return buf;
}

std::string escape(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string vec(const Vec3& v) { return num(v.x) + " " + num(v.y) + " " + num(v.z); }
std::string quat(const Quat& q) { return num(q.w) + " " + num(q.x) + " " + num(q.y) + " " + num(q.z); }
std::string pose_attrs(const Pose& X) { return " pos=\"" + vec(X.position) + "\" quat=\"" + quat(X.orientation) + "\""; }

std::string mesh_key(const std::string& path, const Vec3& s) { return path + "|" + vec(s); }

// Rotates the inertia tensor given in frame I into the link frame: I_L = R I_I R^T.
std::array<double, 6> inertia_in_link_frame(const description::Inertial& in) {
  const Quat& q = in.origin.orientation;
  const double R[3][3] = {
      {1 - 2 * (q.y * q.y + q.z * q.z), 2 * (q.x * q.y - q.z * q.w), 2 * (q.x * q.z + q.y * q.w)},
      {2 * (q.x * q.y + q.z * q.w), 1 - 2 * (q.x * q.x + q.z * q.z), 2 * (q.y * q.z - q.x * q.w)},
      {2 * (q.x * q.z - q.y * q.w), 2 * (q.y * q.z + q.x * q.w), 1 - 2 * (q.x * q.x + q.y * q.y)}};
  const double I[3][3] = {{in.ixx, in.ixy, in.ixz}, {in.ixy, in.iyy, in.iyz}, {in.ixz, in.iyz, in.izz}};
  double RI[3][3] = {}, out[3][3] = {};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) RI[i][j] += R[i][k] * I[k][j];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) out[i][j] += RI[i][k] * R[j][k];
  return {out[0][0], out[1][1], out[2][2], out[0][1], out[0][2], out[1][2]};
}

}  // namespace

std::string left_out_mesh_warning(const PlannedGeom& g, const MeshAsset* asset) {
  // Once per geom, naming the link, the mesh as written and the file tried: a collision mesh
  // left out is a link that falls through the ground or through the robot.
  const description::Geometry& geo = g.geometry;
  std::string why;
  std::error_code ignored;
  if (geo.mesh_path.empty()) {
    why = "no file for it (an unknown package? --package NAME=DIR or ROS_PACKAGE_PATH)";
  } else {
    why = !std::filesystem::exists(geo.mesh_path, ignored) ? "no such file"
          : asset != nullptr && !asset->error.empty()      ? asset->error
                                                           : "MuJoCo could not compile it";
    why += " (path tried: " + geo.mesh_path + ")";
  }
  return "link '" + g.link + "': " + (g.visual ? "visual" : "collision") + " mesh '" + geo.mesh_uri + "' (geom '" +
         g.name + "') left out: " + why;
}

namespace {

class Writer {
 public:
  Writer(const BodyPlan& plan, const std::vector<MeshAsset>& meshes, const BuildOptions& options,
         const std::set<std::string>& skip, const ArenaSize& arena)
      : plan_(plan), options_(options), arena_(arena) {
    for (const MeshAsset& m : meshes) {
      if (!m.error.empty() || skip.count(m.name)) continue;
      usable_[mesh_key(m.path, m.scale)] = &m;
    }
    for (const MeshAsset& m : meshes) all_[mesh_key(m.path, m.scale)] = &m;
    children_ = children_of(plan);
    collect_frictions();
  }

  static std::vector<std::vector<std::size_t>> children_of(const BodyPlan& plan) {
    std::vector<std::vector<std::size_t>> children(plan.bodies.size());
    for (std::size_t i = 0; i < plan.bodies.size(); ++i)
      if (plan.bodies[i].parent >= 0) children[static_cast<std::size_t>(plan.bodies[i].parent)].push_back(i);
    return children;
  }

  // Every collision geom's sliding coefficient, for the priorities (contact_defaults.hpp): the
  // lower the friction, the higher the priority, so that MuJoCo, which takes the parameters of
  // the geom with the higher priority, gives each contact the smaller coefficient of its two
  // geoms, as ODE's min rule does. Equal coefficients share a priority (MuJoCo then takes the
  // larger, which is the same).
  void collect_frictions() {
    const auto add_plan = [&](const BodyPlan& p) {
      for (const PlannedGeom& g : p.world_geoms)
        if (!g.visual) frictions_.push_back(g.friction);
      for (const PlannedBody& b : p.bodies)
        for (const PlannedGeom& g : b.geoms)
          if (!g.visual) frictions_.push_back(g.friction);
    };
    add_plan(plan_);
    for (const BodyPlan& p : plan_.passive) add_plan(p);
    for (const WorldBox& b : options_.world.boxes) frictions_.push_back(box_friction(b));
    frictions_.push_back(ground_plane_friction());
    frictions_.push_back(options_.contact.ground_friction);
    std::sort(frictions_.begin(), frictions_.end());
    frictions_.erase(std::unique(frictions_.begin(), frictions_.end()), frictions_.end());
  }
  // The number of distinct coefficients above `mu`: 0 for the highest friction.
  int priority(double mu) const {
    return static_cast<int>(frictions_.end() - std::upper_bound(frictions_.begin(), frictions_.end(), mu));
  }
  static double box_friction(const WorldBox& b) { return isotropic_friction(b.mu, b.mu2); }
  double ground_plane_friction() const { return isotropic_friction(options_.world.ground_mu, options_.world.ground_mu2); }
  // A collision geom's contact attributes: friction (sliding, torsional, rolling) and its priority.
  std::string contact_attrs(double mu) const {
    const ContactDefaults& c = options_.contact;
    return " priority=\"" + std::to_string(priority(mu)) + "\" friction=\"" + num(mu) + " " + num(c.torsional_friction) + " " +
           num(c.rolling_friction) + "\"";
  }

  MjcfDocument write(const std::string& model_name) {
    const ContactDefaults& c = options_.contact;
    x_ << "<mujoco model=\"" << escape(model_name) << "\">\n";
    x_ << "  <compiler angle=\"radian\" inertiafromgeom=\"false\" balanceinertia=\"true\"/>\n";
    const char* integrator = options_.integrator == Integrator::Euler ? "Euler"
                             : options_.integrator == Integrator::Rk4 ? "RK4"
                                                                      : "implicit";
    x_ << "  <option timestep=\"" << num(options_.timestep) << "\" integrator=\"" << integrator
       << "\" gravity=\"0 0 " << num(-options_.world.gravity) << "\" cone=\""
       << (c.elliptic_cone ? "elliptic" : "pyramidal") << "\""
       << (options_.step_cost.sparse_jacobian ? " jacobian=\"sparse\"" : "") << kCollisionSlot << "/>\n";
    x_ << "  " << mjcf_size_element(arena_) << "\n";
    // One user number per geom: the depth (m) below the ground where a soil wheel's rigid contact
    // starts (Physics::set_soil writes it in its own copy of the model; 0 is rigid ground).
    x_ << "  <size nuser_geom=\"1\"/>\n";
    x_ << "  <default>\n    <geom condim=\"" << c.condim << "\" friction=\"" << num(c.sliding_friction) << " "
       << num(c.torsional_friction) << " " << num(c.rolling_friction) << "\" solref=\"" << num(c.solref[0]) << " "
       << num(c.solref[1]) << "\" solimp=\"" << num(c.solimp[0]) << " " << num(c.solimp[1]) << " "
       << num(c.solimp[2]) << " " << num(c.solimp[3]) << " " << num(c.solimp[4]) << "\" margin=\""
       << num(c.margin) << "\"/>\n    <joint solreflimit=\"" << num(c.limit_solref[0]) << " " << num(c.limit_solref[1])
       << "\"/>\n  </default>\n";
    write_assets();
    x_ << "  <worldbody>\n";
    write_world();
    for (const PlannedGeom& g : plan_.world_geoms) write_geom(g, 2);
    for (std::size_t i = 0; i < plan_.bodies.size(); ++i)
      if (plan_.bodies[i].parent < 0) write_body(plan_, children_, i, 2);
    // The world's passive models after the robot (its root joint stays the model's first), their
    // geoms colliding as world objects do.
    // The other robots (actuated models) last, after the objects: the bodies, joints and geoms
    // of everything else keep their indices when robots are spawned or deleted.
    for (const BodyPlan& p : plan_.passive) other_robot_bits_ |= p.robot_bit;
    const auto write_models = [&](bool robots) {
      for (const BodyPlan& p : plan_.passive) {
        if ((p.robot_bit != 0) != robots) continue;
        passive_ = true;
        robot_bit_ = p.robot_bit;
        for (const PlannedGeom& g : p.world_geoms) write_geom(g, 2);
        const auto children = children_of(p);
        for (std::size_t i = 0; i < p.bodies.size(); ++i)
          if (p.bodies[i].parent < 0) write_body(p, children, i, 2);
        passive_ = false;
        robot_bit_ = 0;
      }
    };
    write_models(false);
    write_boxes();
    write_models(true);
    x_ << "  </worldbody>\n";
    std::vector<std::pair<std::string, std::string>> excludes = plan_.excludes;
    std::vector<PlannedMimic> mimics = plan_.mimics;
    for (const BodyPlan& p : plan_.passive) {
      excludes.insert(excludes.end(), p.excludes.begin(), p.excludes.end());
      mimics.insert(mimics.end(), p.mimics.begin(), p.mimics.end());
    }
    // Listed pairs (StepCost::listed_pairs, collision_pairs.hpp): MuJoCo then tests these and
    // nothing else (the excludes stay for the broad phase, should PhysicsModel::build fall back).
    std::optional<std::vector<ListedPair>> pairs;
    if (options_.step_cost.listed_pairs) pairs = list_collision_pairs(written_bodies_, written_geoms_, excludes);
    if (!excludes.empty() || (pairs && !pairs->empty())) {
      x_ << "  <contact>\n";
      if (pairs)
        for (const ListedPair& p : *pairs) write_pair(p);
      for (const auto& [a, b] : excludes)
        x_ << "    <exclude body1=\"" << escape(a) << "\" body2=\"" << escape(b) << "\"/>\n";
      x_ << "  </contact>\n";
    }
    if (!mimics.empty()) {
      x_ << "  <equality>\n";
      for (const PlannedMimic& m : mimics) {
        x_ << "    <joint name=\"mimic:" << escape(m.follower) << "\" joint1=\"" << escape(m.follower)
           << "\" joint2=\"" << escape(m.leader) << "\" polycoef=\"" << num(m.offset) << " " << num(m.multiplier)
           << " 0 0 0\"";
        if (m.time_constant > 0.0) x_ << " solref=\"" << num(m.time_constant) << " 1\"";
        x_ << "/>\n";
      }
      x_ << "  </equality>\n";
    }
    write_actuators();
    x_ << "</mujoco>\n";
    doc_.xml = x_.str();
    const std::size_t slot = doc_.xml.find(kCollisionSlot);
    doc_.xml.replace(slot, std::string_view(kCollisionSlot).size(), pairs && !pairs->empty() ? " collision=\"predefined\"" : "");
    return std::move(doc_);
  }

 private:
  // Where the <option> element gets its collision attribute once the pairs are known.
  static constexpr const char* kCollisionSlot = "@collision@";

  // One listed pair with the parameters MuJoCo's dynamic collision would give it: the geoms'
  // common condim, solref, solimp and margin (ContactDefaults), the smaller sliding coefficient
  // (the priorities rank the geoms by it), the common torsional and rolling ones.
  void write_pair(const ListedPair& p) {
    const ContactDefaults& c = options_.contact;
    const double mu = std::min(p.geom1->friction, p.geom2->friction);
    x_ << "    <pair geom1=\"" << escape(p.geom1->name) << "\" geom2=\"" << escape(p.geom2->name) << "\" condim=\""
       << c.condim << "\" friction=\"" << num(mu) << " " << num(mu) << " " << num(c.torsional_friction) << " "
       << num(c.rolling_friction) << " " << num(c.rolling_friction) << "\" solref=\"" << num(c.solref[0]) << " "
       << num(c.solref[1]) << "\" solimp=\"" << num(c.solimp[0]) << " " << num(c.solimp[1]) << " " << num(c.solimp[2])
       << " " << num(c.solimp[3]) << " " << num(c.solimp[4]) << "\" margin=\"" << num(c.margin) << "\" gap=\"0\"/>\n";
  }

  // A collision geom on the body being written (body_), for the listed pairs.
  void record_geom(const std::string& name, int contype, int conaffinity, double friction, bool ground = false) {
    written_geoms_.push_back({name, body_, contype, conaffinity, ground, friction});
  }
  // A body that begins now under the body being written; returns the one it was under.
  int begin_body(const std::string& name, bool jointed) {
    written_bodies_.push_back({name, body_, jointed});
    const int parent = body_;
    body_ = static_cast<int>(written_bodies_.size()) - 1;
    return parent;
  }

  void write_assets() {
    std::vector<const MeshAsset*> used;
    for (const auto& [key, m] : usable_) used.push_back(m);
    std::sort(used.begin(), used.end(), [](const MeshAsset* a, const MeshAsset* b) { return a->name < b->name; });
    const bool terrain = options_.world.kind == WorldSpec::Kind::Heightmap;
    if (used.empty() && !terrain) return;
    x_ << "  <asset>\n";
    for (const MeshAsset* m : used)
      x_ << "    <mesh name=\"" << m->name << "\" file=\"" << m->vfs_file << "\" scale=\"" << vec(m->scale) << "\"/>\n";
    if (terrain) {
      const Heightmap& h = *options_.world.terrain;
      const auto [lo, hi] = std::minmax_element(h.heights.begin(), h.heights.end());
      const double range = std::max(static_cast<double>(*hi - *lo), 1e-6);
      // MuJoCo elevation = data * size[2] with data normalised to [0, 1]; the geom sits at the
      // grid's lowest height, so absolute height = min + normalised * (max - min).
      x_ << "    <hfield name=\"" << kTerrainName << "\" nrow=\"" << h.rows << "\" ncol=\"" << h.cols
         << "\" size=\"" << num(h.size_x / 2) << " " << num(h.size_y / 2) << " " << num(range) << " "
         << num(std::max(1.0, 0.1 * range)) << "\"/>\n";
      if (options_.render_terrain)
        // Each tile spans its own heights, its walls reaching kTileBase below its lowest sample
        // (terrain_tiles.hpp).
        for (const TerrainTile& t : plan_terrain_tiles(h))
          x_ << "    <hfield name=\"" << t.name << "\" nrow=\"" << t.nrow << "\" ncol=\"" << t.ncol << "\" size=\""
             << num((t.x1 - t.x0) / 2) << " " << num((t.y1 - t.y0) / 2) << " "
             << num(std::max(static_cast<double>(t.hi - t.lo), 1e-6)) << " " << num(kTileBase) << "\"/>\n";
    }
    x_ << "  </asset>\n";
  }

  void write_world() {
    const ContactDefaults& c = options_.contact;
    if (options_.world.kind == WorldSpec::Kind::Heightmap) {
      if (!options_.world.terrain) throw PhysicsError("world: heightmap world without a heightmap");
      const Heightmap& h = *options_.world.terrain;
      const double lo = static_cast<double>(*std::min_element(h.heights.begin(), h.heights.end()));
      x_ << "    <geom name=\"" << kTerrainName << "\" type=\"hfield\" hfield=\"" << kTerrainName << "\" pos=\"0 0 "
         << num(lo) << "\" contype=\"1\" conaffinity=\"1\" group=\"2\"" << contact_attrs(c.ground_friction) << "/>\n";
      record_geom(kTerrainName, 1, 1, c.ground_friction, true);
      if (options_.render_terrain)
        for (const TerrainTile& t : plan_terrain_tiles(h))
          x_ << "    <geom name=\"" << t.name << "\" type=\"hfield\" hfield=\"" << t.name << "\" pos=\""
             << num((t.x0 + t.x1) / 2) << " " << num((t.y0 + t.y1) / 2) << " " << num(t.lo) << "\" contype=\"0\""
             << " conaffinity=\"0\" group=\"" << kTileGroup << "\"/>\n";
    } else if (options_.world.ground_plane) {
      x_ << "    <geom name=\"" << kGroundName << "\" type=\"plane\" size=\"0 0 1\" contype=\"1\" conaffinity=\"1\""
         << " group=\"2\"" << contact_attrs(ground_plane_friction()) << "/>\n";
      record_geom(kGroundName, 1, 1, ground_plane_friction(), true);
    }
  }

  // Fixed objects (boxes, cylinders, spheres) as world geoms, free ones as bodies with a free joint (after the robot's bodies,
  // so that the robot's root joint stays the model's first free joint).
  void write_boxes() {
    std::set<std::string> names;
    for (const WorldBox& b : options_.world.boxes) {
      const std::string where = "world box '" + b.name + "'";
      if (b.name.empty()) throw PhysicsError("world: a box has no name");
      if (!names.insert(b.name).second) throw PhysicsError(where + ": the name is used twice");
      const std::string friction = contact_attrs(box_friction(b));
      if (b.shape == WorldBox::Shape::Mesh) {
        write_mesh_object(b, where, friction);
        continue;
      }
      if (!(b.size.x > 0.0 && b.size.y > 0.0 && b.size.z > 0.0) || !std::isfinite(b.size.x + b.size.y + b.size.z))
        throw PhysicsError(where + ": size must be finite and > 0 along x, y and z (m)");
      if (b.shape != WorldBox::Shape::Box && b.size.x != b.size.y)
        throw PhysicsError(where + ": a cylinder's or sphere's size must be equal along x and y (its diameter)");
      if (!b.fixed && !(b.mass > 0.0 && std::isfinite(b.mass))) throw PhysicsError(where + ": mass must be finite and > 0 (kg)");
      const double r = b.size.x / 2;
      std::string type = "box", size = vec({b.size.x / 2, b.size.y / 2, b.size.z / 2});
      // Solid bodies' inertia about their centre (the compiler takes no inertia from geoms).
      const double m = b.mass, xx = b.size.x * b.size.x, yy = b.size.y * b.size.y, zz = b.size.z * b.size.z;
      description::Vec3 inertia{m * (yy + zz) / 12.0, m * (xx + zz) / 12.0, m * (xx + yy) / 12.0};
      if (b.shape == WorldBox::Shape::Cylinder) {
        type = "cylinder";
        size = num(r) + " " + num(b.size.z / 2);
        const double side = m * (3.0 * r * r + zz) / 12.0;
        inertia = {side, side, m * r * r / 2.0};
      } else if (b.shape == WorldBox::Shape::Sphere) {
        type = "sphere";
        size = num(r);
        const double i = 0.4 * m * r * r;
        inertia = {i, i, i};
      }
      const std::string geom = "<geom name=\"box:" + escape(b.name) + "\" type=\"" + type + "\" size=\"" + size +
                               "\" contype=\"1\" conaffinity=\"1\" group=\"2\"" + friction;
      if (b.fixed) {
        x_ << "    " << geom << pose_attrs(b.pose) << "/>\n";
        record_geom("box:" + b.name, 1, 1, box_friction(b));
      } else {
        x_ << "    <body name=\"box:" << escape(b.name) << "\"" << pose_attrs(b.pose) << ">\n      <freejoint name=\"box:"
           << escape(b.name) << "\"/>\n      <inertial pos=\"0 0 0\" mass=\"" << num(b.mass) << "\" diaginertia=\""
           << vec(inertia) << "\"/>\n      " << geom << "/>\n    </body>\n";
        const int world = begin_body("box:" + b.name, true);
        record_geom("box:" + b.name, 1, 1, box_friction(b));
        body_ = world;
      }
    }
  }

  // A mesh object: a geom of its mesh asset (MuJoCo collides with its convex hull; rays and cameras
  // see its triangles), a world geom when fixed, else a body with a free joint. A free one's mass
  // is spread as a solid filling its bounds (centre of mass at the bounds' centre, a box's
  // inertia): MuJoCo 2.2.2's compiler takes inertia from all geoms or none, and mechsim gives
  // every body its own. One whose mesh could not be loaded or compiled is left out with a warning,
  // as a robot's mesh geom is.
  // `contact`: the geom's priority and friction attributes.
  void write_mesh_object(const WorldBox& b, const std::string& where, const std::string& contact) {
    if (!b.fixed && !(b.mass > 0.0 && std::isfinite(b.mass))) throw PhysicsError(where + ": mass must be finite and > 0 (kg)");
    const auto it = b.mesh_path.empty() ? usable_.end() : usable_.find(mesh_key(b.mesh_path, b.mesh_scale));
    if (it == usable_.end()) {
      const auto any = b.mesh_path.empty() ? all_.end() : all_.find(mesh_key(b.mesh_path, b.mesh_scale));
      const std::string why = any == all_.end() ? "no mesh file" : any->second->error.empty() ? "MuJoCo cannot compile it" : any->second->error;
      doc_.warnings.push_back(where + ": mesh '" + b.mesh_path + "' left out (" + why + ")");
      return;
    }
    const std::string geom = "<geom name=\"box:" + escape(b.name) + "\" type=\"mesh\" mesh=\"" + it->second->name +
                             "\" contype=\"1\" conaffinity=\"1\" group=\"2\"" + contact;
    if (b.fixed) {
      x_ << "    " << geom << pose_attrs(b.pose) << "/>\n";
      record_geom("box:" + b.name, 1, 1, box_friction(b));
      return;
    }
    if (!(b.size.x > 0.0 && b.size.y > 0.0 && b.size.z > 0.0))
      throw PhysicsError(where + ": a free mesh object needs bounds of some size along x, y and z");
    const double m = b.mass, xx = b.size.x * b.size.x, yy = b.size.y * b.size.y, zz = b.size.z * b.size.z;
    const description::Vec3 centre{b.mesh_min.x + b.size.x / 2, b.mesh_min.y + b.size.y / 2, b.mesh_min.z + b.size.z / 2};
    x_ << "    <body name=\"box:" << escape(b.name) << "\"" << pose_attrs(b.pose) << ">\n      <freejoint name=\"box:"
       << escape(b.name) << "\"/>\n      <inertial pos=\"" << vec(centre) << "\" mass=\"" << num(m) << "\" diaginertia=\""
       << vec({m * (yy + zz) / 12.0, m * (xx + zz) / 12.0, m * (xx + yy) / 12.0}) << "\"/>\n      " << geom
       << "/>\n    </body>\n";
    const int world = begin_body("box:" + b.name, true);
    record_geom("box:" + b.name, 1, 1, box_friction(b));
    body_ = world;
  }

  void write_body(const BodyPlan& plan, const std::vector<std::vector<std::size_t>>& children, std::size_t index,
                  int indent) {
    const PlannedBody& b = plan.bodies[index];
    const std::string pad(static_cast<std::size_t>(indent) * 2, ' ');
    x_ << pad << "<body name=\"" << escape(b.name) << "\"" << pose_attrs(b.X_PB) << ">\n";
    const int parent = begin_body(b.name, !b.joints.empty());
    if (b.inertial) {
      const auto I = inertia_in_link_frame(*b.inertial);
      x_ << pad << "  <inertial pos=\"" << vec(b.inertial->origin.position) << "\" mass=\"" << num(b.inertial->mass)
         << "\" fullinertia=\"" << num(I[0]) << " " << num(I[1]) << " " << num(I[2]) << " " << num(I[3]) << " "
         << num(I[4]) << " " << num(I[5]) << "\"/>\n";
    }
    for (const PlannedJoint& j : b.joints) write_joint(j, pad + "  ");
    for (const PlannedGeom& g : b.geoms) write_geom(g, indent + 1);
    for (std::size_t child : children[index]) write_body(plan, children, child, indent + 1);
    body_ = parent;
    x_ << pad << "</body>\n";
  }

  void write_joint(const PlannedJoint& j, const std::string& pad) {
    if (j.kind == PlannedJoint::Kind::Free) {
      x_ << pad << "<freejoint name=\"" << escape(j.name) << "\"/>\n";
      return;
    }
    const char* type = j.kind == PlannedJoint::Kind::Hinge ? "hinge" : j.kind == PlannedJoint::Kind::Slide ? "slide" : "ball";
    x_ << pad << "<joint name=\"" << escape(j.name) << "\" type=\"" << type << "\"";
    if (j.kind != PlannedJoint::Kind::Ball) x_ << " axis=\"" << vec(j.axis) << "\"";
    if (j.limited) x_ << " limited=\"true\" range=\"" << num(j.lower) << " " << num(j.upper) << "\"";
    else x_ << " limited=\"false\"";
    if (j.damping != 0.0) x_ << " damping=\"" << num(j.damping) << "\"";
    if (j.frictionloss != 0.0) x_ << " frictionloss=\"" << num(j.frictionloss) << "\"";
    x_ << "/>\n";
  }

  void write_geom(const PlannedGeom& g, int indent) {
    const std::string pad(static_cast<std::size_t>(indent) * 2, ' ');
    std::ostringstream shape;
    const description::Geometry& geo = g.geometry;
    switch (geo.type) {
      case GeometryType::Box:
        shape << " type=\"box\" size=\"" << num(geo.size.x / 2) << " " << num(geo.size.y / 2) << " " << num(geo.size.z / 2) << "\"";
        break;
      case GeometryType::Cylinder:
        if (g.narrow_wheel && !g.visual && options_.contact.point_contact_wheels)
          shape << " type=\"ellipsoid\" size=\"" << num(geo.radius) << " " << num(geo.radius) << " " << num(geo.length / 2) << "\"";
        else
          shape << " type=\"cylinder\" size=\"" << num(geo.radius) << " " << num(geo.length / 2) << "\"";
        break;
      case GeometryType::Sphere: shape << " type=\"sphere\" size=\"" << num(geo.radius) << "\""; break;
      case GeometryType::Mesh: {
        const std::string key = mesh_key(geo.mesh_path, geo.mesh_scale);
        auto it = geo.mesh_path.empty() ? usable_.end() : usable_.find(key);
        if (it == usable_.end()) {
          auto any = geo.mesh_path.empty() ? all_.end() : all_.find(key);
          doc_.warnings.push_back(left_out_mesh_warning(g, any != all_.end() ? any->second : nullptr));
          return;
        }
        shape << " type=\"mesh\" mesh=\"" << it->second->name << "\"";
        break;
      }
    }
    x_ << pad << "<geom name=\"" << escape(g.name) << "\"" << shape.str() << pose_attrs(g.X_BG);
    if (g.visual) {
      x_ << " contype=\"0\" conaffinity=\"0\" group=\"1\"";
      if (g.rgba) x_ << " rgba=\"" << num((*g.rgba)[0]) << " " << num((*g.rgba)[1]) << " " << num((*g.rgba)[2]) << " " << num((*g.rgba)[3]) << "\"";
    } else {
      int contype = 2, affinity = 0, group = 0;
      if (passive_ && robot_bit_ != 0) {
        // Another robot's geoms (an actuated world model): its own bit, touching the world (bit 0),
        // the first robot (bit 1) and the other robots; its own links as the first robot's do.
        contype = robot_bit_;
        affinity = 1 | 2 | (other_robot_bits_ & ~robot_bit_) | (g.self_collide ? robot_bit_ : 0);
      } else if (passive_) {
        // A passive model's geoms are world objects (bit 0): they touch the ground, the robot,
        // other objects and each other (MuJoCo skips a body and its parent).
        contype = affinity = 1;
        group = 2;
      } else {
        // bit 0: world; bit 1: this robot. Links without selfCollide do not accept bit 1, so two
        // of them never touch; a selfCollide link touches every link (SDF: collide if either).
        affinity = g.self_collide ? 3 : 1;
      }
      x_ << " contype=\"" << contype << "\" conaffinity=\"" << affinity << "\" group=\"" << group << "\"" << contact_attrs(g.friction);
      record_geom(g.name, contype, affinity, g.friction);
    }
    x_ << "/>\n";
  }

  void write_actuators() {
    bool any = false;
    std::vector<const PlannedBody*> bodies;
    for (const PlannedBody& b : plan_.bodies) bodies.push_back(&b);
    for (const BodyPlan& p : plan_.passive)
      if (p.robot_bit != 0)
        for (const PlannedBody& b : p.bodies) bodies.push_back(&b);
    for (const PlannedBody* b : bodies)
      for (const PlannedJoint& j : b->joints) {
        if (!j.one_dof_urdf) continue;
        if (!any) x_ << "  <actuator>\n";
        any = true;
        // Effort mode by default: force = ctrl. Position/velocity servos change gain and bias
        // at run time; forcerange bounds every mode by the joint's effort limit.
        x_ << "    <general name=\"" << escape(j.name) << "\" joint=\"" << escape(j.name)
           << "\" gaintype=\"fixed\" gainprm=\"1\" biastype=\"affine\" biasprm=\"0 0 0\" ctrllimited=\"false\"";
        if (j.effort_limit > 0.0)
          x_ << " forcelimited=\"true\" forcerange=\"" << num(-j.effort_limit) << " " << num(j.effort_limit) << "\"";
        x_ << "/>\n";
      }
    if (any) x_ << "  </actuator>\n";
  }

  const BodyPlan& plan_;
  std::vector<double> frictions_;  // distinct sliding coefficients of the collision geoms, ascending
  const BuildOptions& options_;
  ArenaSize arena_;
  std::map<std::string, const MeshAsset*> usable_, all_;
  std::vector<std::vector<std::size_t>> children_;
  bool passive_ = false;  // writing a passive model's geoms
  int robot_bit_ = 0;        // of the actuated model being written (BodyPlan::robot_bit), 0: none
  int other_robot_bits_ = 0;  // every actuated model's bit
  // What was written, for the listed pairs: the bodies in MuJoCo's order (the world first), the
  // collision geoms, the body being written.
  std::vector<WrittenBody> written_bodies_{{"world", 0, false}};
  std::vector<WrittenGeom> written_geoms_;
  int body_ = 0;
  std::ostringstream x_;
  MjcfDocument doc_;
};

void add_mesh(const std::string& path, const Vec3& scale, std::map<std::string, std::size_t>& index,
              std::vector<MeshAsset>& out) {
  const std::string key = mesh_key(path, scale);
  if (index.count(key)) return;
  MeshAsset asset;
  asset.name = "mesh" + std::to_string(out.size());
  asset.path = path;
  asset.scale = scale;
  out.push_back(std::move(asset));
  index[key] = out.size() - 1;
}

void collect_from(const std::vector<PlannedGeom>& geoms, std::map<std::string, std::size_t>& index,
                  std::vector<MeshAsset>& out) {
  for (const PlannedGeom& g : geoms) {
    if (g.geometry.type != GeometryType::Mesh || g.geometry.mesh_path.empty()) continue;
    add_mesh(g.geometry.mesh_path, g.geometry.mesh_scale, index, out);
  }
}

}  // namespace

std::vector<MeshAsset> collect_meshes(const BodyPlan& plan, const WorldSpec* world) {
  std::vector<MeshAsset> out;
  std::map<std::string, std::size_t> index;
  collect_from(plan.world_geoms, index, out);
  for (const PlannedBody& b : plan.bodies) collect_from(b.geoms, index, out);
  for (const BodyPlan& p : plan.passive) {
    collect_from(p.world_geoms, index, out);
    for (const PlannedBody& b : p.bodies) collect_from(b.geoms, index, out);
  }
  if (world != nullptr)
    for (const WorldBox& b : world->boxes)
      if (b.shape == WorldBox::Shape::Mesh && !b.mesh_path.empty()) add_mesh(b.mesh_path, b.mesh_scale, index, out);
  // One file may appear at several scales: read and convert it once.
  std::map<std::string, const MeshAsset*> loaded;
  for (MeshAsset& m : out) {
    auto it = loaded.find(m.path);
    if (it != loaded.end()) {
      m.bytes = it->second->bytes;
      m.error = it->second->error;
      m.vfs_file = m.name + it->second->vfs_file.substr(it->second->vfs_file.find('.'));
      continue;
    }
    try {
      MeshBytes mb = load_mesh_for_mujoco(m.path);
      m.bytes = std::move(mb.bytes);
      m.vfs_file = m.name + mb.extension;
    } catch (const PhysicsError& e) {
      m.error = e.what();
      m.vfs_file = m.name + ".stl";
    }
    loaded[m.path] = &m;
  }
  return out;
}

std::string mjcf_size_element(const ArenaSize& arena) {
  return "<size njmax=\"" + std::to_string(arena.constraints) + "\" nconmax=\"" + std::to_string(arena.contacts) + "\"/>";
}

MjcfDocument write_mjcf(const std::string& model_name, const BodyPlan& plan, const std::vector<MeshAsset>& meshes,
                        const BuildOptions& options, const std::set<std::string>& skip_meshes, const ArenaSize& arena) {
  return Writer(plan, meshes, options, skip_meshes, arena).write(model_name);
}

}  // namespace mechsim::physics
