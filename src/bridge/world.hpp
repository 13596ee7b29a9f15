#pragma once
// World: a Gazebo world as gazebo_ros' gzserver serves it, with gazebo_ros_api_plugin's semantics
// (spawn and delete, model and link states in reference frames, properties, forces, physics
// properties, pause, step, reset), in plain C++ for the ROS bindings: each binding maps its own
// messages onto these calls and keeps no world semantics of its own.
//
// Models. The world's own (an SDF world's models, or the ground plane of mechsim's worlds) and
// the models spawned into it. The world is a simulation with no robot of its own (its loop thread,
// its clock, its physics); every spawned model is another robot of it (SimBridge's other-robot
// constructor): its own controller manager, ports, model plugins and sensors in the one physics
// (they collide). A spawn during a run takes the model in between two ticks: the models already
// there go on undisturbed; a delete stops and unloads the model's controllers first.
//
// Names as gazebo_ros takes them: a model by its name, a link as "model::link" (a link name alone
// is taken when a model has it), a joint as "joint" or "model::joint". A reference frame "" or
// "world" ("map" too) is the world; a model's frame is its root link's. States relative to a frame
// R: pose X_RE, twist (v_E - v_R, w_E - w_R) expressed in R, as gazebo_ros computes them. Every
// refusal answers ok = false with why, and leaves the simulation as it was.
//
// Threads: the calls below may come from any thread; they run one at a time. Everything that
// reads or changes the physics runs in the loop thread between ticks. The binding's hooks
// (WorldBinding) run in the calling thread (model hooks) or the loop thread (ticked, idle).

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "bridge/sim_bridge.hpp"

namespace mechsim::bridge {

struct WorldOptions {
  std::string world = "empty";  // mechsim world name, heightmap, or an SDF .world file
  bool paused = false;
  double real_time_factor = 1.0;  // 0: as fast as possible
  double period = 0.001;          // s
  bool lenient = true;            // description problems Gazebo tolerates are warnings
};

// A model of the world, as a binding sees it.
struct ModelInfo {
  std::string name;
  // The ROS namespace of its controller manager and plugins ("/" the root): gazebo_ros_control's
  // <robotNamespace>, else the spawn's robot_namespace.
  std::string robot_namespace = "/";
  bool pr2 = false;                 // the PR2's gazebo plugin: pr2_controller_manager's services
  bool controller_manager = false;  // gazebo_ros_control's plugin (or the PR2's): a controller manager
};

struct SpawnRequest {
  std::string name;
  std::string xml;              // URDF, or SDF holding one <model>
  std::string robot_namespace;  // "" or "/": the root
  description::Pose pose;       // X_RM: the model frame in reference_frame
  std::string reference_frame;  // "" or "world": the world; else any entity of the world
  // gazebo_ros (ROS 2)'s factory: an empty name takes the description's own (<robot name>,
  // <model name>); ROS 1's spawn_model refuses it.
  bool name_from_description = false;
  // A description parsed already (a command line's robot, its packages resolved as it was
  // loaded): used instead of `xml`.
  std::optional<description::RobotModel> model;
};

// gazebo_msgs/GetModelProperties' content.
struct ModelProperties {
  std::string parent_model_name, canonical_body_name;
  std::vector<std::string> body_names, geom_names, joint_names, child_model_names;
  bool is_static = false;
};

// gazebo_msgs/GetPhysicsProperties' content (what mechsim has of it).
struct PhysicsProperties {
  double time_step = 0.001;       // s
  double max_update_rate = 1000;  // steps per wall second (0: as fast as possible)
  description::Vec3 gravity{0.0, 0.0, -9.81};  // m/s^2
  bool paused = false;
};

// A light of the world (an SDF world's <light>s; mechsim's own worlds have Gazebo's `sun`):
// gazebo_msgs/GetLightProperties' and SetLightProperties' content. Gazebo's light API reads and
// changes these; mechsim's cameras are not lit by them (its renderer has its own lighting).
struct LightProperties {
  std::string name;
  std::string type = "directional";  // point, directional, spot
  bool cast_shadows = true;
  std::array<double, 4> diffuse{0.8, 0.8, 0.8, 1.0}, specular{0.2, 0.2, 0.2, 1.0};  // RGBA
  double attenuation_constant = 0.9, attenuation_linear = 0.01, attenuation_quadratic = 0.001;
  description::Vec3 direction{-0.5, 0.1, -0.9};
  description::Pose pose;  // X_WL
};

// One named entity's state (model_states, link_states: world frame).
struct NamedState {
  std::string name;
  EntityState state;
};

// What a binding does when models come and go and the world ticks. Default: nothing.
class WorldBinding {
 public:
  virtual ~WorldBinding() = default;
  // Before a model's simulation is built: what the binding's middleware holds for it (controller
  // parameters from a parameter server) goes into `options`.
  virtual void prepare_model(const ModelInfo&, BridgeOptions&) {}
  // The model is in the world (ticking, paused or not): its outputs on. Throwing refuses the spawn
  // (the model leaves again).
  virtual void model_added(const ModelInfo&, SimBridge&) {}
  // The model is about to leave: its outputs off, its controllers stopped and unloaded (topics
  // first). The world then stops whatever is still running and takes it out of the physics.
  virtual void model_removing(const ModelInfo&, SimBridge&) {}
  // The model is out of the physics; its bridge goes next (what the binding holds of it may go).
  virtual void model_removed(const ModelInfo&) {}
  // Loop thread: after each tick (time: s), and while paused about every millisecond.
  virtual void ticked(double) {}
  virtual void idle(double) {}
  // Messages the world has for its user (what is not simulated, a diverged simulation).
  virtual void warn(const std::string&) {}
  virtual void info(const std::string&) {}
};

class World {
 public:
  // Builds the world once for its checks and what it lists; throws std::runtime_error naming the
  // world or file when it cannot be built.
  explicit World(WorldOptions options);
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  // Starts the world's simulation and its loop thread; `binding` (kept, may be null) hears of
  // models and ticks. Throws std::runtime_error when the simulation cannot be built.
  void start(WorldBinding* binding);
  // Stops the loop thread; every model goes with the world (model_removed runs for each; their
  // controllers are not unloaded one by one).
  void stop();

  const std::string& name() const { return world_name_; }

  // ---- models
  // Status: gazebo_ros' words on success ("SpawnModel: Successfully spawned entity").
  BridgeResult spawn(const SpawnRequest& request, std::string* status);
  BridgeResult remove(const std::string& model, std::string* status);
  std::vector<std::string> model_names() const;  // the world's own first, then spawned ones in order
  std::vector<ModelInfo> spawned_models() const;

  // ---- time
  double time() const;  // s
  bool paused() const;
  void set_paused(bool paused);
  // `steps` ticks while paused; returns once they ran. At most kMaxSteps per call.
  static constexpr std::uint64_t kMaxSteps = 100000;
  BridgeResult step(std::uint64_t steps);
  // Both put every model back at its spawn pose and restart its running controllers; time goes on
  // (sim/simulation.hpp says why).
  void reset();
  double measured_real_time_factor() const;

  // ---- states and properties (Gazebo's model API)
  BridgeResult model_state(const std::string& model, const std::string& relative_to, EntityState& out) const;
  BridgeResult link_state(const std::string& link, const std::string& reference_frame, EntityState& out) const;
  // `state` in reference_frame; sets a model's root (a moving world model's frame). A link other
  // than a root is moved by its joints: refused.
  BridgeResult set_model_state(const std::string& model, const std::string& reference_frame, const EntityState& state);
  BridgeResult set_link_state(const std::string& link, const std::string& reference_frame, const EntityState& state);
  BridgeResult model_properties(const std::string& model, ModelProperties& out) const;
  BridgeResult joint_properties(const std::string& joint, JointPropertiesData& out) const;
  BridgeResult link_properties(const std::string& link, LinkPropertiesData& out) const;
  PhysicsProperties physics_properties() const;
  // time_step must be the world's period (mechsim's tick); max_update_rate >= 0; gravity finite.
  BridgeResult set_physics_properties(const PhysicsProperties& properties);
  BridgeResult set_model_configuration(const std::string& model, const std::vector<std::string>& joints,
                                       const std::vector<double>& positions);
  // Force (N) and torque (N m) in reference_frame's axes, the force acting at reference_point (m,
  // from the body's centre of mass, in reference_frame's axes), from `start` (s, sim time; past:
  // now) for `duration` s (< 0: no end).
  BridgeResult apply_body_wrench(const std::string& body, const std::string& reference_frame,
                                 const description::Vec3& force, const description::Vec3& torque,
                                 const description::Vec3& reference_point, double start, double duration);
  BridgeResult apply_joint_effort(const std::string& joint, double effort, double start, double duration);
  BridgeResult clear_body_wrenches(const std::string& body);
  BridgeResult clear_joint_forces(const std::string& joint);
  // gazebo_msgs/SetJointProperties (damping, hiStop, loStop of the joint's first axis) and
  // SetLinkProperties (mass, centre of mass, inertia; gravity_mode as it is).
  BridgeResult set_joint_properties(const std::string& joint, const JointPropertyChange& change);
  BridgeResult set_link_properties(const std::string& link, const LinkPropertiesData& properties);

  // ---- lights
  std::vector<std::string> light_names() const;
  BridgeResult light_properties(const std::string& light, LightProperties& out) const;
  // Sets every field but name and type.
  BridgeResult set_light_properties(const LightProperties& properties);
  BridgeResult delete_light(const std::string& light);

  // ---- loop thread (inside WorldBinding::ticked): every model's root / every link, world frame.
  // Gazebo's order: the world's own models, then the spawned ones.
  void model_states_now(std::vector<NamedState>& out);
  void link_states_now(std::vector<NamedState>& out);

 private:
  // What a request names (resolve()): the world, one of its own models, a spawned model (its
  // root), or one of a spawned model's links.
  struct Entity {
    enum class Kind { World, WorldModel, Model, ModelLink };
    Kind kind = Kind::World;
    std::string link;             // ModelLink: the URDF link
    std::size_t model = 0;        // WorldModel: index into world_models_
    SimBridge* bridge = nullptr;  // Model, ModelLink: the spawned model's
  };
  struct Model {
    ModelInfo info;
    std::unique_ptr<SimBridge> bridge;
  };

  void loop();
  // Brings a model in (spawn, the world's own robots at start): its namespace and checks, the
  // binding's hooks; "" when it is in, else why not. `bridge.robot.name` is its name.
  std::string admit(BridgeOptions& bridge, const description::Pose& X_WM, const std::string& robot_namespace);
  bool resolve(const std::string& name, Entity& out, std::string* status) const;
  bool entity_state(const Entity& e, EntityState& out, std::string* status) const;
  BridgeResult set_root(const Entity& target, const std::string& frame, const EntityState& given);
  const Model* find(const std::string& name) const;
  // A joint of a spawned model ("model::joint", or "joint": the first model that has it).
  SimBridge* joint_owner(const std::string& scoped, std::string& joint, std::string* status) const;

  WorldOptions options_;
  std::string world_name_;
  // The world's own models, by name (an SDF world's; the ground plane of mechsim's worlds), and
  // where the SDF puts them. The first sdf_model_count_ are an SDF world's (the physics has them).
  std::vector<std::string> world_models_;
  std::vector<description::Pose> world_model_poses_;
  std::size_t sdf_model_count_ = 0;
  description::Vec3 gravity_{0.0, 0.0, -9.81};  // m/s^2
  std::vector<std::string> not_simulated_, world_warnings_;
  std::vector<WorldRobot> world_robots_;  // the world's models that are robots (start() brings them in)
  std::vector<LightProperties> lights_;   // under mutex_

  WorldBinding* binding_ = nullptr;
  mutable std::mutex mutex_;  // one call at a time; guards the models' lifetimes
  std::unique_ptr<SimBridge> world_;  // the world's simulation (no robot of its own), from start()
  // In spawn order. Changed under mutex_ and, since the loop thread reads it, models_mutex_.
  std::vector<Model> models_;
  mutable std::mutex models_mutex_;
  std::vector<std::vector<EntityState>> link_scratch_;  // loop thread
  std::vector<EntityState> world_scratch_;              // loop thread

  std::thread loop_thread_;
  std::atomic<bool> stop_{false};
  std::string divergence_;  // loop thread: the last one reported
};

}  // namespace mechsim::bridge
