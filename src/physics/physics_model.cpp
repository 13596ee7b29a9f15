#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <mutex>
#include <new>
#include <set>

#include "physics/arena_estimate.hpp"
#include "physics/collision_pairs.hpp"
#include "physics/body_plan.hpp"
#include "physics/wheel_identify.hpp"
#include "physics/mjcf_writer.hpp"
#include "physics/mujoco_internal.hpp"
#include "physics/physics_error.hpp"
#include "physics/terrain_tiles.hpp"
#include "physics/wheel_terrain_contact.hpp"

namespace mechsim::physics {
namespace {

constexpr const char* kModelFile = "mechsim_model.xml";

struct VfsDeleter {
  void operator()(mjVFS* vfs) const {
    mj_deleteVFS(vfs);
    std::free(vfs);
  }
};

// An empty MuJoCo virtual file system. mjVFS holds 2000 file names of 1000 bytes (2 MB) and
// mj_defaultVFS zeroes all of it; calloc gives the same zeroes from pages the kernel maps only when
// a name is written, which spared 10 ms of the PR2's start-up (page faults of a 2 MB memset).
std::unique_ptr<mjVFS, VfsDeleter> empty_vfs() {
  void* memory = std::calloc(1, sizeof(mjVFS));
  if (memory == nullptr) throw std::bad_alloc();
  return std::unique_ptr<mjVFS, VfsDeleter>(static_cast<mjVFS*>(memory));
}

void add_vfs_file(mjVFS& vfs, const std::string& name, const char* data, std::size_t size) {
  if (mj_makeEmptyFileVFS(&vfs, name.c_str(), static_cast<int>(size)) != 0)
    throw PhysicsError("MuJoCo virtual file system: cannot add '" + name + "' (full or repeated)");
  const int i = mj_findFileVFS(&vfs, name.c_str());
  if (i < 0) throw PhysicsError("MuJoCo virtual file system: '" + name + "' vanished");
  std::memcpy(vfs.filedata[i], data, size);
}

// mj_loadXML keeps its parsed document in a process-global slot in MuJoCo 2.2.2, so two loads
// must not overlap; this lock is the only shared state and guards nothing of mechsim's.
std::mutex& load_mutex() {
  static std::mutex m;
  return m;
}

// Compiles `xml` with the meshes in a fresh VFS. Returns null and fills `error` on failure.
mjModel* compile(const std::string& xml, const std::vector<MeshAsset>& meshes, std::string& error) {
  std::unique_ptr<mjVFS, VfsDeleter> vfs = empty_vfs();
  add_vfs_file(*vfs, kModelFile, xml.data(), xml.size());
  for (const MeshAsset& m : meshes)
    if (m.error.empty() && xml.find("file=\"" + m.vfs_file + "\"") != std::string::npos)
      add_vfs_file(*vfs, m.vfs_file, m.bytes.data(), m.bytes.size());
  char err[1024] = "";
  mjModel* model = nullptr;
  {
    std::lock_guard<std::mutex> lock(load_mutex());
    model = mj_loadXML(kModelFile, vfs.get(), err, sizeof(err));
  }
  if (model == nullptr) error = err;
  return model;
}

// "Object name = mesh3, ..." in a MuJoCo compile error -> "mesh3".
std::string error_object(const std::string& error) {
  const std::string key = "Object name = ";
  const auto at = error.find(key);
  if (at == std::string::npos) return {};
  const auto start = at + key.size();
  const auto end = error.find_first_of(",\n", start);
  return error.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

std::string one_line(std::string s) {
  std::replace(s.begin(), s.end(), '\n', ' ');
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

void validate_options(const BuildOptions& o) {
  if (!(o.timestep > 0.0) || !std::isfinite(o.timestep))
    throw PhysicsError("physics option timestep: must be a positive number of seconds, got " + std::to_string(o.timestep));
  if (o.world.kind == WorldSpec::Kind::Heightmap) {
    if (!o.world.terrain) throw PhysicsError("world: kind heightmap but no heightmap given");
    const Heightmap& h = *o.world.terrain;
    const std::string where = "heightmap '" + h.source + "'";
    if (h.rows < 2 || h.cols < 2) throw PhysicsError(where + ": needs at least 2x2 samples");
    if (h.heights.size() != h.rows * h.cols)
      throw PhysicsError(where + ": " + std::to_string(h.heights.size()) + " heights for " + std::to_string(h.rows) +
                         "x" + std::to_string(h.cols) + " samples");
    if (!(h.size_x > 0.0) || !(h.size_y > 0.0)) throw PhysicsError(where + ": footprint must be positive");
    for (std::size_t i = 0; i < h.heights.size(); ++i)
      if (!std::isfinite(h.heights[i])) throw PhysicsError(where + ": height " + std::to_string(i) + " is not finite");
  }
  const auto bad_arena = [](const ArenaSize& a) { return a.contacts < 1 || a.constraints < 1; };
  if (bad_arena(o.max_arena) || o.max_arena.constraints > kMaxArenaConstraints)
    throw PhysicsError("physics option max_arena: contacts and constraints must be in [1, " +
                       std::to_string(kMaxArenaConstraints) + "] (constraints), got " +
                       std::to_string(o.max_arena.contacts) + " contacts, " + std::to_string(o.max_arena.constraints) +
                       " constraints");
  if (o.arena && (bad_arena(*o.arena) || o.arena->contacts > o.max_arena.contacts ||
                  o.arena->constraints > o.max_arena.constraints))
    throw PhysicsError("physics option arena: contacts and constraints must be >= 1 and within max_arena, got " +
                       std::to_string(o.arena->contacts) + " contacts, " + std::to_string(o.arena->constraints) +
                       " constraints");
}

// MuJoCo hfield data are normalised to [0, 1]; elevation = data * size[2] above the geom.
void fill_hfield(mjModel& m, const Heightmap& h) {
  const int id = mj_name2id(&m, mjOBJ_HFIELD, kTerrainName);
  if (id < 0) throw PhysicsError("internal: terrain hfield missing from the compiled model");
  const auto [lo, hi] = std::minmax_element(h.heights.begin(), h.heights.end());
  const double range = static_cast<double>(*hi - *lo);
  float* data = m.hfield_data + m.hfield_adr[id];
  for (std::size_t i = 0; i < h.heights.size(); ++i)
    data[i] = range > 0.0 ? static_cast<float>((static_cast<double>(h.heights[i] - *lo)) / range) : 0.0f;
}

void fill_terrain_tiles(mjModel& m, const Heightmap& h) {
  for (const TerrainTile& t : plan_terrain_tiles(h)) {
    const int id = mj_name2id(&m, mjOBJ_HFIELD, t.name.c_str());
    if (id < 0) throw PhysicsError("internal: terrain tile '" + t.name + "' missing from the compiled model");
    fill_terrain_tile(h, t, m.hfield_data + m.hfield_adr[id]);
  }
}

}  // namespace

std::vector<std::string> mesh_warnings(const description::RobotModel& robot) {
  const BodyPlan plan = plan_bodies(robot, BuildOptions{});
  const std::vector<MeshAsset> meshes = collect_meshes(plan);
  std::vector<std::string> out;
  auto check = [&](const PlannedGeom& g) {
    const description::Geometry& geo = g.geometry;
    if (geo.type != description::GeometryType::Mesh) return;
    const MeshAsset* asset = nullptr;
    for (const MeshAsset& m : meshes) {
      if (m.path == geo.mesh_path && m.scale.x == geo.mesh_scale.x && m.scale.y == geo.mesh_scale.y &&
          m.scale.z == geo.mesh_scale.z) {
        asset = &m;
      }
    }
    if (geo.mesh_path.empty() || asset == nullptr || !asset->error.empty()) out.push_back(left_out_mesh_warning(g, asset));
  };
  for (const PlannedGeom& g : plan.world_geoms) check(g);
  for (const PlannedBody& b : plan.bodies)
    for (const PlannedGeom& g : b.geoms) check(g);
  return out;
}

PhysicsModel::PhysicsModel() : impl_(std::make_unique<Impl>()) {}
PhysicsModel::~PhysicsModel() = default;

std::shared_ptr<const PhysicsModel> PhysicsModel::build(const description::RobotModel& robot,
                                                        const BuildOptions& options) {
  validate_options(options);
  detail::install_wheel_terrain_contact();
  StageTimer timer;
  StageTime mjcf_time, compile_time;
  const std::string who = "robot '" + robot.name + "' (" + robot.source + ")";
  BodyPlan plan = plan_bodies(robot, options);
  std::vector<MeshAsset> meshes = collect_meshes(plan, &options.world);
  // The arena is sized from the compiled model, so the compiler gets a small one (its own
  // mj_makeData allocates and zeroes it) and the model its real size afterwards. 20 rows keep
  // MuJoCo's stack formula above its floor, so that its model-dependent term can be read back.
  const ArenaSize compile_arena{1, 20};

  std::set<std::string> skip;
  std::vector<std::string> compile_warnings;
  mjModel* m = nullptr;
  MjcfDocument doc;
  for (;;) {
    doc = write_mjcf(robot.name, plan, meshes, options, skip, compile_arena);
    std::string error;
    mjcf_time += timer.lap();
    m = compile(doc.xml, meshes, error);
    compile_time += timer.lap();
    if (m != nullptr) break;
    const std::string object = error_object(error);
    auto bad = std::find_if(meshes.begin(), meshes.end(), [&](const MeshAsset& a) { return a.name == object; });
    if (bad == meshes.end() || skip.count(object))
      throw PhysicsError(who + ": MuJoCo rejected the generated model: " + one_line(error));
    // A mesh MuJoCo cannot compile (e.g. a flat visual mesh with no volume): leave its geoms
    // out, say so, and compile again.
    skip.insert(object);
    bad->error = one_line(error);
    compile_warnings.push_back("mesh '" + bad->path + "': MuJoCo cannot compile it (" + bad->error + ")");
  }

  std::shared_ptr<PhysicsModel> pm(new PhysicsModel());
  pm->impl_->model = m;
  const long side = static_cast<long>(compile_arena.constraints) + m->nv;
  pm->impl_->stack_residual = static_cast<long>(m->nstack) - 5 * side * side;
  // Listed collision pairs (StepCost::listed_pairs) only when they are exactly what MuJoCo's
  // filters let touch, with the parameters it would give them; else its broad phase.
  if (m->opt.collision == mjCOL_PAIR) {
    if (const std::string why = check_listed_pairs(*m); !why.empty()) {
      m->opt.collision = mjCOL_DYNAMIC;
      const std::string slot = " collision=\"predefined\"";
      doc.xml.replace(doc.xml.find(slot), slot.size(), " collision=\"dynamic\"");
      compile_warnings.push_back("the listed collision pairs are not MuJoCo's (" + why +
                                 "): MuJoCo's broad phase finds the contacts instead (the same physics, slower)");
    }
  }
  pm->arena_ = estimate_arena(*m);
  if (options.arena) {
    pm->arena_.size = *options.arena;
    pm->arena_.from_options = true;
  }
  pm->arena_.size.contacts = std::min(pm->arena_.size.contacts, options.max_arena.contacts);
  pm->arena_.size.constraints = std::min(pm->arena_.size.constraints, options.max_arena.constraints);
  set_arena(*m, pm->arena_.size, pm->impl_->stack_residual);
  const std::string placeholder = mjcf_size_element(compile_arena);
  doc.xml.replace(doc.xml.find(placeholder), placeholder.size(), mjcf_size_element(pm->arena_.size));
  pm->robot_name_ = robot.name;
  pm->root_link_ = robot.root_link;
  pm->options_ = options;
  pm->mjcf_ = std::move(doc.xml);
  pm->fixed_to_world_ = plan.fixed_to_world;
  pm->dropped_joints_ = plan.dropped_joints;
  pm->warnings_ = plan.warnings;
  pm->warnings_.insert(pm->warnings_.end(), compile_warnings.begin(), compile_warnings.end());
  pm->warnings_.insert(pm->warnings_.end(), doc.warnings.begin(), doc.warnings.end());
  if (options.world.kind == WorldSpec::Kind::Heightmap) {
    fill_hfield(*m, *options.world.terrain);
    if (options.render_terrain) fill_terrain_tiles(*m, *options.world.terrain);
  }

  // Joint table: every 1-DOF MuJoCo joint of the robot and of the other robots (actuated world
  // models), in MuJoCo order (the passive models' joints are the world's, as its free objects'
  // are).
  std::set<std::string> one_dof, passive;
  for (const PlannedBody& b : plan.bodies)
    for (const PlannedJoint& j : b.joints)
      if (j.one_dof_urdf) one_dof.insert(j.name);
  for (const BodyPlan& p : plan.passive)
    for (const PlannedBody& b : p.bodies)
      for (const PlannedJoint& j : b.joints) {
        if (p.robot_bit == 0) passive.insert(j.name);
        else if (j.one_dof_urdf) one_dof.insert(j.name);
      }
  for (int j = 0; j < m->njnt; ++j) {
    if (m->jnt_type[j] != mjJNT_HINGE && m->jnt_type[j] != mjJNT_SLIDE) continue;
    if (passive.count(mj_id2name(m, mjOBJ_JOINT, j))) continue;
    JointInfo info;
    info.name = mj_id2name(m, mjOBJ_JOINT, j);
    info.prismatic = m->jnt_type[j] == mjJNT_SLIDE;
    info.urdf_one_dof = one_dof.count(info.name) > 0;
    info.limited = m->jnt_limited[j] != 0;
    info.lower = m->jnt_range[2 * j];
    info.upper = m->jnt_range[2 * j + 1];
    info.mj_joint = j;
    info.qpos_adr = m->jnt_qposadr[j];
    info.dof_adr = m->jnt_dofadr[j];
    info.damping = m->dof_damping[info.dof_adr];
    info.frictionloss = m->dof_frictionloss[info.dof_adr];
    for (int a = 0; a < m->nu; ++a)
      if (m->actuator_trnid[2 * a] == j && m->actuator_trntype[a] == mjTRN_JOINT) {
        info.actuator = a;
        info.actuated = true;
        if (m->actuator_forcelimited[a]) info.effort_limit = m->actuator_forcerange[2 * a + 1];
      }
    pm->joints_.push_back(std::move(info));
  }
  // Link table: the robot's links, then the other robots' ("<model>::<link>").
  const auto add_links = [&](const BodyPlan& p) {
    for (const LinkFrame& f : p.link_frames) {
      LinkInfo info;
      info.name = f.link;
      info.body = f.body < 0 ? 0 : mj_name2id(m, mjOBJ_BODY, p.bodies[f.body].name.c_str());
      info.X_BL = f.X_BL;
      if (f.body >= 0 && info.body < 0) throw PhysicsError("internal: body '" + p.bodies[f.body].name + "' not compiled");
      pm->links_.push_back(std::move(info));
    }
  };
  add_links(plan);
  for (const BodyPlan& p : plan.passive)
    if (p.robot_bit != 0) add_links(p);
  // Wheels: the robot's, then the other robots' (their links and joints "<model>::<name>").
  const auto add_wheels = [&](const BodyPlan& p, const description::RobotModel& description, const std::string& prefix) {
    for (const PlannedBody& b : p.bodies)
      for (const PlannedGeom& g : b.geoms) {
        const int geom = g.wheel ? mj_name2id(m, mjOBJ_GEOM, g.name.c_str()) : -1;
        if (geom < 0) continue;
        // A narrow wheel is an ellipsoid (radius, radius, half width), a wide one a cylinder (radius, half width).
        const bool cylinder = m->geom_type[geom] == mjGEOM_CYLINDER;
        if (!cylinder && !(g.narrow_wheel && m->geom_type[geom] == mjGEOM_ELLIPSOID)) continue;
        const description::Link* link = description.link(g.link.substr(prefix.size()));
        const auto joint = link != nullptr ? pm->joint_index(prefix + link->parent_joint) : std::nullopt;
        if (!joint) continue;
        const double radius = m->geom_size[3 * geom], width = 2.0 * m->geom_size[3 * geom + (cylinder ? 1 : 2)];
        pm->wheels_.push_back({g.link, *joint, geom, m->geom_bodyid[geom], radius, width, width <= radius});
      }
    for (const WheelCandidate& c : identify_wheels(description))
      if (!c.wheel) pm->not_wheels_.push_back(describe(WheelCandidate{prefix + c.link, prefix + c.joint, false, 0.0, 0.0, c.reason}));
  };
  add_wheels(plan, robot, "");
  for (std::size_t i = 0; i < plan.passive.size() && i < options.world.models.size(); ++i)
    if (plan.passive[i].robot_bit != 0) add_wheels(plan.passive[i], *options.world.models[i].robot, options.world.models[i].name + "::");
  // The passive models' primitive shapes (their bodies' collision geoms, and those welded to the world).
  const auto add_shape = [&](int geom) {
    if (geom < 0) return;
    PassiveShape shape;
    const double* sz = m->geom_size + 3 * geom;
    switch (m->geom_type[geom]) {
      case mjGEOM_BOX: shape.kind = PassiveShape::Kind::Box; shape.size = {2 * sz[0], 2 * sz[1], 2 * sz[2]}; break;
      case mjGEOM_CYLINDER: shape.kind = PassiveShape::Kind::Cylinder; shape.size = {2 * sz[0], 2 * sz[0], 2 * sz[1]}; break;
      case mjGEOM_SPHERE: shape.kind = PassiveShape::Kind::Sphere; shape.size = {2 * sz[0], 2 * sz[0], 2 * sz[0]}; break;
      default: return;
    }
    shape.body = m->geom_bodyid[geom];
    const char* name = mj_id2name(m, mjOBJ_BODY, shape.body);
    shape.body_name = shape.body == 0 || name == nullptr ? "world" : name;
    const double* pos = m->geom_pos + 3 * geom;
    const double* quat = m->geom_quat + 4 * geom;
    shape.X_BG = {{pos[0], pos[1], pos[2]}, {quat[0], quat[1], quat[2], quat[3]}};
    pm->passive_shapes_.push_back(std::move(shape));
  };
  for (const BodyPlan& p : plan.passive) {
    if (p.robot_bit != 0) continue;  // another robot: drawn from its description, not as an object
    for (const PlannedGeom& g : p.world_geoms)
      if (!g.visual) add_shape(mj_name2id(m, mjOBJ_GEOM, g.name.c_str()));
    for (const PlannedBody& b : p.bodies)
      for (const PlannedGeom& g : b.geoms)
        if (!g.visual) add_shape(mj_name2id(m, mjOBJ_GEOM, g.name.c_str()));
  }
  std::vector<std::string> gravity_off = plan.gravity_off_links;
  for (const BodyPlan& p : plan.passive) gravity_off.insert(gravity_off.end(), p.gravity_off_links.begin(), p.gravity_off_links.end());
  for (const std::string& link : gravity_off) {
    const int body = mj_name2id(m, mjOBJ_BODY, link.c_str());
    if (body <= 0) continue;
    pm->gravity_off_links_.push_back(link);
    pm->gravity_off_bodies_.push_back(body);
  }
  if (plan.differential) {
    DifferentialInfo d;
    d.plugin = plan.differential->plugin;
    d.joint_a = *pm->joint_index(plan.differential->joint_a);
    d.joint_b = *pm->joint_index(plan.differential->joint_b);
    d.force_constant = plan.differential->force_constant;
    d.active = options.differential == DifferentialMode::PluginLaw;
    pm->differential_ = d;
  }
  // Laser retro-reflectivity per compiled geom: the planned geoms' (robot, other robots, passive
  // models) and the world objects'; 0 for the rest (ground, terrain).
  pm->geom_laser_retro_.assign(static_cast<std::size_t>(m->ngeom), 0.0f);
  const auto set_retro = [&](const std::string& name, double retro) {
    const int g = retro != 0.0 ? mj_name2id(m, mjOBJ_GEOM, name.c_str()) : -1;
    if (g >= 0) pm->geom_laser_retro_[static_cast<std::size_t>(g)] = static_cast<float>(retro);
  };
  const auto plan_retro = [&](const BodyPlan& p) {
    for (const PlannedGeom& g : p.world_geoms) set_retro(g.name, g.laser_retro);
    for (const PlannedBody& b : p.bodies)
      for (const PlannedGeom& g : b.geoms) set_retro(g.name, g.laser_retro);
  };
  plan_retro(plan);
  for (const BodyPlan& p : plan.passive) plan_retro(p);
  for (const WorldBox& b : options.world.boxes) set_retro("box:" + b.name, b.laser_retro);
  compile_time += timer.lap();
  pm->build_times_.mjcf = mjcf_time;
  pm->build_times_.compile = compile_time;
  return pm;
}

int PhysicsModel::listed_pairs() const {
  const mjModel* m = impl_->model;
  return m->opt.collision == mjCOL_PAIR ? m->npair : 0;
}

std::optional<std::size_t> PhysicsModel::joint_index(std::string_view name) const {
  for (std::size_t i = 0; i < joints_.size(); ++i)
    if (joints_[i].name == name) return i;
  return std::nullopt;
}

std::optional<std::size_t> PhysicsModel::link_index(std::string_view name) const {
  for (std::size_t i = 0; i < links_.size(); ++i)
    if (links_[i].name == name) return i;
  return std::nullopt;
}

int PhysicsModel::body_count() const { return impl_->model->nbody; }
int PhysicsModel::dof_count() const { return impl_->model->nv; }
int PhysicsModel::geom_count() const { return impl_->model->ngeom; }

std::string_view PhysicsModel::geom_name(int geom) const {
  if (geom < 0 || geom >= impl_->model->ngeom) return {};
  const char* n = mj_id2name(impl_->model, mjOBJ_GEOM, geom);
  return n != nullptr ? std::string_view(n) : std::string_view();
}

double PhysicsModel::geom_laser_retro(int geom) const {
  return geom < 0 || static_cast<std::size_t>(geom) >= geom_laser_retro_.size() ? 0.0
                                                                                : geom_laser_retro_[static_cast<std::size_t>(geom)];
}

int PhysicsModel::geom_body(int geom) const {
  return geom < 0 || geom >= impl_->model->ngeom ? -1 : impl_->model->geom_bodyid[geom];
}

std::string PhysicsModel::body_name(int body) const {
  if (body <= 0 || body >= impl_->model->nbody) return "world";
  const char* n = mj_id2name(impl_->model, mjOBJ_BODY, body);
  return n != nullptr ? n : "body" + std::to_string(body);
}

int PhysicsModel::body_index(const std::string& name) const {
  return mj_name2id(impl_->model, mjOBJ_BODY, name.c_str());
}

}  // namespace mechsim::physics
