// `mechsim ros2 ROBOT --controllers FILE`: one world and its robot on a ROS 2 domain, as gzserver
// with gazebo_ros and gazebo_ros2_control presents them to Humble and Jazzy nodes (src/ros2/README.md,
// docs/ros2.md). Built with the ROS 2 layer (MECHSIM_ROS2, Debian's Fast DDS); without it the command
// says why it is unavailable.
//
// Runs until SIGINT/SIGTERM (exit status 0), or for --duration seconds of simulated time.

#include <time.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <optional>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "apps/cmd_common.hpp"
#include "apps/commands.hpp"
#include "apps/stop_on_signals.hpp"

#ifdef MECHSIM_HAS_ROS2
#include "bridge/sim_bridge.hpp"
#include "description/robot_loader.hpp"
#include "ros2/world_node.hpp"
#include "sim/controller_set.hpp"
#endif

namespace mechsim::apps {
namespace {

struct Ros2Args {
  RobotArgs robot;
  std::string controllers, yaml_ns;
  std::vector<std::string> start;
  bool no_controllers = false;
  std::string world = "empty";
  std::vector<double> spawn;  // x y [z]
  double yaw = 0.0;
  double real_time_factor = 1.0;
  std::string distro = "jazzy";
  double clock_rate = 0.0;
  double tf_rate = 20.0;
  bool no_tf = false;
  std::string robot_namespace;
  std::string use_stamped_vel = "true";
  double duration = 0.0;
  bool paused = false;
  double bench_rtf = 0.0;  // s of simulated time with publishing on (and as many off)
};

#ifdef MECHSIM_HAS_ROS2

// The description's controller manager namespace: gazebo_ros_control's <robotNamespace> (ROS 1
// descriptions); "" when it has none.
std::string plugin_namespace(const description::RobotModel& robot) {
  for (const auto& plugin : robot.plugins) {
    if (plugin.filename.find("gazebo_ros_control") != std::string::npos) {
      if (auto it = plugin.parameters.find("robotNamespace"); it != plugin.parameters.end() && !it->second.empty()) {
        return it->second;
      }
    }
  }
  return "";
}

// The namespace the controllers' YAML puts them in: --namespace, or the file's single top-level
// map when that is not itself a controller (the `pr2:` of mechsim's PR2 YAML); "" for the root.
std::string yaml_namespace(const std::string& file, const std::string& ns) {
  if (!ns.empty()) return ns;
  const control::Params root = control::Params::from_yaml_file(file);
  const std::vector<std::string> keys = root.keys();
  if (keys.size() == 1 && root.child(keys[0]).is_map() && !root.child(keys[0]).has("type")) return keys[0];
  return "";
}

// Without --start: the robot's usual set, as `mechsim bench` picks it (sim::widest_conflict_free).
std::vector<std::string> usual_set(const std::vector<bridge::ControllerSummary>& loaded) {
  std::vector<control::ControllerInfo> infos;
  for (const bridge::ControllerSummary& c : loaded) {
    control::ControllerInfo& i = infos.emplace_back();
    i.name = c.name;
    i.type = c.type;
    for (const bridge::ClaimedResources& claim : c.claims) i.claims.push_back({control::HardwareInterface::Effort, claim.resources});
  }
  return sim::widest_conflict_free(infos);
}

double cpu_seconds(clockid_t clock) {
  timespec t{};
  clock_gettime(clock, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}
double thread_cpu_seconds() { return cpu_seconds(CLOCK_THREAD_CPUTIME_ID); }
double process_cpu_seconds() { return cpu_seconds(CLOCK_PROCESS_CPUTIME_ID); }

// --bench-rtf: the real-time factor (as fast as it goes) with the ROS 2 layer publishing and
// without, in one run: blocks of 0.5 s of simulated time alternate (ABBA), publishing on and off, so that
// both see the same states and the same load of the machine; wall time (what a user gets) and
// the loop thread's CPU time (what the layer costs the tick) each give a ratio. The blocks switch
// in the world's loop thread, after a tick (WorldNode's tick hook).
void bench_rtf(ros2::WorldNode& node, double seconds) {
  bridge::World& world = node.world();
  bridge::PhysicsProperties physics = world.physics_properties();
  // Discovery and matching settle first: 2 s at real time, publishing.
  std::this_thread::sleep_for(std::chrono::seconds(2));
  physics.max_update_rate = 0.0;
  world.set_physics_properties(physics);
  constexpr double kBlock = 0.5;
  struct Bench {
    double wall[2] = {0.0, 0.0}, cpu[2] = {0.0, 0.0}, all[2] = {0.0, 0.0}, sim[2] = {0.0, 0.0};
    int k = -1, on = 1;
    double s0 = 0.0, c0 = 0.0, a0 = 0.0;
    std::chrono::steady_clock::time_point w0;
    std::atomic<bool> done{false};
  };
  auto b = std::make_shared<Bench>();
  node.set_tick_hook([b, seconds, &node](double t) {
    if (b->done.load()) return;
    if (b->k >= 0 && t - b->s0 < kBlock) return;
    const auto now = std::chrono::steady_clock::now();
    const double c = thread_cpu_seconds(), a = process_cpu_seconds();
    if (b->k >= 0) {
      b->wall[b->on] += std::chrono::duration<double>(now - b->w0).count();
      b->cpu[b->on] += c - b->c0;
      b->all[b->on] += a - b->a0;
      b->sim[b->on] += t - b->s0;
      if (b->sim[0] >= seconds && b->sim[1] >= seconds) {
        node.set_publishing(true);
        b->done.store(true);
        return;
      }
    }
    ++b->k;
    // ABBA: on, off, off, on, ...: a load that drifts over the run weighs on both alike.
    b->on = (b->k % 4 == 0 || b->k % 4 == 3) ? 1 : 0;
    node.set_publishing(b->on == 1);
    b->w0 = std::chrono::steady_clock::now();
    b->s0 = t;
    b->c0 = thread_cpu_seconds();
    b->a0 = process_cpu_seconds();
  });
  while (!b->done.load() && g_stop_signal.load() == 0) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  node.set_tick_hook({});
  const double* sim = b->sim;
  const double rtf_on = sim[1] / b->wall[1], rtf_off = sim[0] / b->wall[0];
  std::printf("mechsim ros2 --bench-rtf: %.1f s simulated with the ROS 2 layer publishing, %.1f s without, in "
              "alternating blocks of %.1f s (on, off, off, on, ...)\n",
              sim[1], sim[0], kBlock);
  std::printf("  real-time factor (wall):       %.3f publishing, %.3f without: ratio %.3f\n", rtf_on, rtf_off,
              rtf_on / rtf_off);
  std::printf("  loop thread CPU per sim second: %.4f s publishing, %.4f s without: ratio %.3f\n", b->cpu[1] / sim[1],
              b->cpu[0] / sim[0], (b->cpu[0] / sim[0]) / (b->cpu[1] / sim[1]));
  std::printf("  mechsim's CPU per sim second (every thread: loop, outbox, Fast DDS): %.4f s publishing, %.4f s without\n",
              b->all[1] / sim[1], b->all[0] / sim[0]);
  std::printf("  published: %llu /clock messages\n", static_cast<unsigned long long>(node.clock_messages()));
  std::fflush(stdout);
}

void run(const Ros2Args& args, CommandResult& result) {
  const auto distro = ros2::parse_distro(args.distro);
  if (!distro) throw UserError("--ros-distro '" + args.distro + "': humble or jazzy");
  ros2::WorldNodeOptions options;
  options.participant = ros2::options_from_environment(*distro);
  options.clock_rate = args.clock_rate;
  options.world.world = args.world;
  options.world.paused = args.paused;
  options.world.real_time_factor = args.real_time_factor;
  options.node.tf_rate = args.tf_rate;
  options.node.publish_tf = !args.no_tf;
  options.node.use_stamped_vel = args.use_stamped_vel == "true";

  // The command line's robot, as a launch file's robot_state_publisher and spawn_entity.py would
  // bring it (none: an empty gzserver that /spawn_entity fills).
  std::optional<ros2::CommandLineRobot> robot;
  std::vector<std::string> in_yaml;
  if (!args.robot.file.empty()) {
    description::LoadedRobot loaded = description::load_robot(args.robot.file, load_options(args.robot));
    for (const std::string& w : loaded.warnings) std::cerr << "warning: " << args.robot.file << ": " << w << "\n";
    ros2::CommandLineRobot r;
    r.urdf = loaded.urdf;
    // The controller manager's namespace: --robot-namespace, else the description's plugin's, else
    // the YAML's, else the root.
    r.robot_namespace = args.robot_namespace;
    if (r.robot_namespace.empty()) r.robot_namespace = plugin_namespace(loaded.model);
    if (r.robot_namespace.empty() && !args.controllers.empty()) r.robot_namespace = yaml_namespace(args.controllers, args.yaml_ns);
    if (r.robot_namespace.empty()) r.robot_namespace = "/";
    r.robot = std::move(loaded.model);
    if (args.spawn.size() >= 2) {
      r.pose.position.x = args.spawn[0];
      r.pose.position.y = args.spawn[1];
    }
    if (args.spawn.size() >= 3) r.pose.position.z = args.spawn[2];
    r.pose.orientation = {std::cos(args.yaw / 2.0), 0.0, 0.0, std::sin(args.yaw / 2.0)};
    if (!args.controllers.empty()) {
      control::Params root = control::Params::from_yaml_file(args.controllers);
      r.controller_params = controller_namespace(args.controllers, args.yaml_ns);
      r.parameter_root = root;
      for (const std::string& k : r.controller_params.keys()) {
        if (r.controller_params.child(k).is_map() && r.controller_params.child(k).has("type")) in_yaml.push_back(k);
      }
    }
    robot = std::move(r);
  }

  ros2::WorldNode node(options);
  ros2::Participant& p = node.participant();
  node.start();
  std::string robot_name, robot_ns = "/";
  ros2::SimNode* model = nullptr;
  if (robot) {
    robot_name = robot->robot.name;
    robot_ns = robot->robot_namespace;
    const bridge::BridgeResult r = node.spawn_robot(std::move(*robot));
    if (!r.ok) throw UserError("the robot could not be spawned: " + r.error);
    model = node.model_node(robot_name);
    if (model == nullptr) throw UserError("the robot '" + robot_name + "' is not in the world after its spawn");
    for (const std::string& w : model->bridge().physics_warnings()) p.log("physics: " + w);
    // Controllers: --start, or the usual set of the YAML's controllers (all loaded, then the widest
    // conflict-free set started); none with --no-controllers. A switch applies at a tick (as a
    // spawner's does): the world runs.
    std::vector<std::string> start = args.start;
    if (!args.no_controllers && start.empty() && !in_yaml.empty()) {
      for (const std::string& name : in_yaml) {
        const bridge::BridgeResult lr = model->load_controller(name);
        if (!lr.ok) p.log("controller '" + name + "' not loaded: " + lr.error);
      }
      start = usual_set(model->bridge().list_controllers());
    }
    if (!args.no_controllers && !start.empty()) {
      const bridge::BridgeResult sr = model->start_controllers(start);
      if (!sr.ok) p.log("controllers: " + sr.error);
    }
  }
  std::printf("mechsim ros2: controllers running:");
  if (model != nullptr)
    for (const bridge::ControllerSummary& c : model->bridge().list_controllers())
      if (c.state == "running") std::printf(" %s", c.name.c_str());
  std::printf("\n");
  std::printf("mechsim ros2: %s in world '%s' on ROS 2 domain %d (%s layout, %s); controller manager %s\n",
              robot_name.empty() ? "no robot" : robot_name.c_str(), args.world.c_str(), p.domain_id(),
              ros2::distro_name(p.distro()), "rmw_fastrtps_cpp and rmw_cyclonedds_cpp peers", robot_ns.c_str());
  std::printf("mechsim ros2: topic /clock (rosgraph_msgs/msg/Clock, %s of sim time)\n",
              args.clock_rate > 0.0 ? (std::to_string(args.clock_rate) + " Hz").c_str() : "every tick");
  std::printf("mechsim ros2: topic /pause_physics, /unpause_physics, /reset_simulation, /reset_world, /spawn_entity, "
              "/delete_entity, /get_model_list, /get_entity_state, /set_entity_state (gazebo_ros services, "
              "rmw_fastrtps and rmw_cyclonedds clients)\n");
  for (const std::string& t : node.node_lines()) std::printf("mechsim ros2: topic %s\n", t.c_str());
  std::printf("mechsim ros2: nodes:");
  for (const std::string& n : p.node_names()) std::printf(" %s", n.c_str());
  std::printf("\n");
  std::fflush(stdout);
  if (args.bench_rtf > 0.0) {
    bench_rtf(node, args.bench_rtf);
    return;
  }
  const StopOnSignals stop_on_signals;
  const auto wall_start = std::chrono::steady_clock::now();
  const double sim_start = node.world().time();
  while (g_stop_signal.load() == 0) {
    if (args.duration > 0.0 && node.world().time() - sim_start >= args.duration) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  const double simulated = node.world().time() - sim_start;
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  ros2::NodeStats s;
  if (ros2::SimNode* m = robot_name.empty() ? nullptr : node.model_node(robot_name)) s = m->stats();
  std::printf("mechsim ros2: %.3f s simulated in %.3f s of wall time (real-time factor %.3f); %llu /clock, %llu /tf "
              "messages, %llu commands taken, %llu rejected\n",
              simulated, wall, wall > 0.0 ? simulated / wall : 0.0, static_cast<unsigned long long>(node.clock_messages()),
              static_cast<unsigned long long>(s.tf_messages), static_cast<unsigned long long>(s.commands),
              static_cast<unsigned long long>(s.commands_rejected));
  const ros2::ActionStats a = node.action_stats();
  if (a.accepted + a.rejected > 0) {
    std::printf("mechsim ros2: action goals: %llu accepted, %llu rejected; %llu succeeded, %llu canceled, %llu aborted; "
                "results: %llu sent, %llu dropped (client gone), %zu requests waiting; %zu goals held\n",
                static_cast<unsigned long long>(a.accepted), static_cast<unsigned long long>(a.rejected),
                static_cast<unsigned long long>(a.succeeded), static_cast<unsigned long long>(a.canceled),
                static_cast<unsigned long long>(a.aborted), static_cast<unsigned long long>(a.results_sent),
                static_cast<unsigned long long>(a.results_dropped), a.results_waiting, a.goals_held);
  }
  std::fflush(stdout);
  node.stop();
  result.exit_code = 0;
}

#else

void run(const Ros2Args&, CommandResult&) {
  throw UserError(
      "this mechsim was built without its ROS 2 layer: it needs eProsima Fast DDS (Debian's libfastrtps-dev and "
      "libfastcdr-dev). Install them with `scripts/install-deps.sh --with-ros` and build again (CMake option "
      "MECHSIM_ROS2=AUTO, the default, picks them up)");
}

#endif

}  // namespace

void add_ros2_command(CLI::App& app, CommandResult& result) {
  auto args = std::make_shared<Ros2Args>();
  CLI::App* cmd = app.add_subcommand(
      "ros2", "Serve a world (and a robot, if given) on a ROS 2 domain (Humble or Jazzy nodes; ROS_DOMAIN_ID from the environment)");
  add_robot_options(cmd, args->robot);
  // No robot: an empty gzserver, filled through /spawn_entity.
  cmd->get_option("file")->required(false);
  cmd->add_option("--controllers", args->controllers, "Controller YAML (ros_control or mechsim form)");
  cmd->add_option("--namespace", args->yaml_ns, "Namespace of the controllers in the YAML");
  cmd->add_option("--start", args->start,
                  "Controllers to load and start (default: every controller of the YAML loaded, the widest "
                  "conflict-free set started, as `mechsim bench`)");
  cmd->add_flag("--no-controllers", args->no_controllers, "Start no controller");
  cmd->add_option("--world", args->world, "empty, mars_yard_2024 or a heightmap file");
  cmd->add_option("--spawn", args->spawn, "Spawn position X Y [Z] (m)")->expected(2, 3);
  cmd->add_option("--yaw", args->yaw, "Spawn yaw (rad)");
  cmd->add_option("--real-time-factor", args->real_time_factor,
                  "Simulated time runs this many times as fast as wall time (default 1; 0: as fast as it goes)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--ros-distro", args->distro,
                  "humble or jazzy (default): the graph message's layout and Jazzy's type hashes")
      ->check(CLI::IsMember({"humble", "jazzy"}));
  cmd->add_option("--clock-rate", args->clock_rate, "Hz of simulated time of /clock (default 0: every tick)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--tf-rate", args->tf_rate, "Hz of simulated time of /tf (default 20, robot_state_publisher's)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--no-tf", args->no_tf, "No robot_state_publisher (/tf, /tf_static, /robot_description): run your own");
  cmd->add_option("--robot-namespace", args->robot_namespace,
                  "Namespace of the controller manager and controllers (default: the description's gazebo_ros_control "
                  "<robotNamespace>, else the YAML's namespace, else /)");
  cmd->add_option("--use-stamped-vel", args->use_stamped_vel,
                  "Humble: diff_drive_controller's use_stamped_vel default (true: TwistStamped on ~/cmd_vel; false: "
                  "Twist on ~/cmd_vel_unstamped); a controller's own parameter wins")
      ->check(CLI::IsMember({"true", "false"}));
  cmd->add_option("--duration", args->duration, "Stop after this many seconds of simulated time (default: run until "
                                                 "SIGINT/SIGTERM)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--paused", args->paused, "Start paused");
  cmd->add_option("--bench-rtf", args->bench_rtf,
                  "Measure what publishing costs: run as fast as possible for this many seconds of simulated time "
                  "with the ROS 2 layer publishing and as many without, in alternating blocks, and print both "
                  "real-time factors and their ratio (subscribe peers first: a topic without subscribers costs little)")
      ->check(CLI::NonNegativeNumber);
  cmd->callback([args, &result] { run(*args, result); });
}

}  // namespace mechsim::apps
