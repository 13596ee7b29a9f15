// `mechsim ros2 ROBOT --controllers FILE`: one world and its robot on a ROS 2 domain, as gzserver
// with gazebo_ros and gazebo_ros2_control presents them to Humble and Jazzy nodes (src/ros2/README.md,
// docs/ros2.md). Built with the ROS 2 layer (MECHSIM_ROS2, Debian's Fast DDS); without it the command
// says why it is unavailable.
//
// Runs until SIGINT/SIGTERM (exit status 0), or for --duration seconds of simulated time.

#include <time.h>

#include <chrono>
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
#include "ros2/sim_node.hpp"
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
// the loop thread's CPU time (what the layer costs the tick) each give a ratio.
void bench_rtf(ros2::SimNode& node, double seconds) {
  bridge::SimBridge& bridge = node.bridge();
  // Discovery and matching settle first: 2 s at real time, publishing.
  bridge.set_real_time_factor(1.0);
  bridge.run_for(2.0, nullptr);
  bridge.set_real_time_factor(0.0);
  constexpr double kBlock = 0.5;
  double wall[2] = {0.0, 0.0}, cpu[2] = {0.0, 0.0}, all[2] = {0.0, 0.0}, sim[2] = {0.0, 0.0};
  std::string error;
  for (int k = 0; sim[1] < seconds || sim[0] < seconds; ++k) {
    // ABBA: on, off, off, on, ...: a load that drifts over the run weighs on both alike.
    const int on = (k % 4 == 0 || k % 4 == 3) ? 1 : 0;
    node.set_publishing(on == 1);
    const auto w0 = std::chrono::steady_clock::now();
    const double c0 = thread_cpu_seconds(), a0 = process_cpu_seconds(), s0 = bridge.time();
    if (!bridge.run_for(kBlock, &error)) throw UserError("the simulation failed: " + error);
    wall[on] += std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
    cpu[on] += thread_cpu_seconds() - c0;
    all[on] += process_cpu_seconds() - a0;
    sim[on] += bridge.time() - s0;
  }
  node.set_publishing(true);
  const double rtf_on = sim[1] / wall[1], rtf_off = sim[0] / wall[0];
  std::printf("mechsim ros2 --bench-rtf: %.1f s simulated with the ROS 2 layer publishing, %.1f s without, in "
              "alternating blocks of %.1f s (on, off, off, on, ...)\n",
              sim[1], sim[0], kBlock);
  std::printf("  real-time factor (wall):       %.3f publishing, %.3f without: ratio %.3f\n", rtf_on, rtf_off,
              rtf_on / rtf_off);
  std::printf("  loop thread CPU per sim second: %.4f s publishing, %.4f s without: ratio %.3f\n", cpu[1] / sim[1],
              cpu[0] / sim[0], (cpu[0] / sim[0]) / (cpu[1] / sim[1]));
  std::printf("  mechsim's CPU per sim second (every thread: loop, outbox, Fast DDS): %.4f s publishing, %.4f s without\n",
              all[1] / sim[1], all[0] / sim[0]);
  const ros2::NodeStats st = node.stats();
  std::printf("  published: %llu /clock, %llu /tf messages\n", static_cast<unsigned long long>(st.clock_messages),
              static_cast<unsigned long long>(st.tf_messages));
  std::fflush(stdout);
}

void run(const Ros2Args& args, CommandResult& result) {
  const auto distro = ros2::parse_distro(args.distro);
  if (!distro) throw UserError("--ros-distro '" + args.distro + "': humble or jazzy");
  ros2::NodeOptions options;
  options.participant = ros2::options_from_environment(*distro);
  options.clock_rate = args.clock_rate;
  options.tf_rate = args.tf_rate;
  options.publish_tf = !args.no_tf;
  options.use_stamped_vel = args.use_stamped_vel == "true";

  description::LoadedRobot loaded = description::load_robot(args.robot.file, load_options(args.robot));
  for (const std::string& w : loaded.warnings) std::cerr << "warning: " << args.robot.file << ": " << w << "\n";
  options.robot_description = loaded.urdf;
  // The controller manager's namespace: --robot-namespace, else the description's plugin's, else
  // the YAML's, else the root.
  options.robot_namespace = args.robot_namespace;
  if (options.robot_namespace.empty()) options.robot_namespace = plugin_namespace(loaded.model);
  if (options.robot_namespace.empty() && !args.controllers.empty()) {
    options.robot_namespace = yaml_namespace(args.controllers, args.yaml_ns);
  }
  if (options.robot_namespace.empty()) options.robot_namespace = "/";

  bridge::BridgeOptions bridge;
  bridge.robot = std::move(loaded.model);
  bridge.world = args.world;
  if (args.spawn.size() >= 2) {
    bridge.x = args.spawn[0];
    bridge.y = args.spawn[1];
  }
  if (args.spawn.size() >= 3) bridge.z = args.spawn[2];
  bridge.yaw = args.yaw;
  bridge.paused = args.paused;
  bridge.real_time_factor = args.real_time_factor;
  std::vector<std::string> in_yaml;
  if (!args.controllers.empty()) {
    control::Params root = control::Params::from_yaml_file(args.controllers);
    bridge.controller_params = controller_namespace(args.controllers, args.yaml_ns);
    bridge.parameter_root = root;
    for (const std::string& k : bridge.controller_params.keys()) {
      if (bridge.controller_params.child(k).is_map() && bridge.controller_params.child(k).has("type")) in_yaml.push_back(k);
    }
  }

  ros2::SimNode node(std::move(bridge), options);
  ros2::Participant& p = node.participant();
  for (const std::string& w : node.bridge().physics_warnings()) p.log("physics: " + w);
  // Controllers: --start, or the usual set of the YAML's controllers (all loaded, then the widest
  // conflict-free set started); none with --no-controllers.
  std::vector<std::string> start = args.start;
  if (!args.no_controllers && start.empty() && !in_yaml.empty()) {
    for (const std::string& name : in_yaml) {
      const bridge::BridgeResult r = node.load_controller(name);
      if (!r.ok) p.log("controller '" + name + "' not loaded: " + r.error);
    }
    start = usual_set(node.bridge().list_controllers());
  }
  auto print_banner = [&] {
    std::printf("mechsim ros2: controllers running:");
    for (const bridge::ControllerSummary& c : node.bridge().list_controllers()) {
      if (c.state == "running") std::printf(" %s", c.name.c_str());
    }
    std::printf("\n");
    std::printf("mechsim ros2: %s in world '%s' on ROS 2 domain %d (%s layout, %s); controller manager %s\n",
                node.bridge().robot().name.c_str(), args.world.c_str(), p.domain_id(), ros2::distro_name(p.distro()),
                "rmw_fastrtps_cpp and rmw_cyclonedds_cpp peers", options.robot_namespace.c_str());
    std::printf("mechsim ros2: nodes:");
    for (const std::string& n : p.node_names()) std::printf(" %s", n.c_str());
    std::printf("\n");
    for (const std::string& t : node.topic_lines()) std::printf("mechsim ros2: topic %s\n", t.c_str());
    std::fflush(stdout);
  };
  // The loop runs before the switch: a switch applies at a tick (as a spawner's does).
  if (args.bench_rtf > 0.0) {
    node.start();
    if (!args.no_controllers && !start.empty()) {
      const bridge::BridgeResult r = node.start_controllers(start);
      if (!r.ok) p.log("controllers: " + r.error);
    }
    node.stop();
    print_banner();
    bench_rtf(node, args.bench_rtf);
    return;
  }
  const StopOnSignals stop_on_signals;
  const auto wall_start = std::chrono::steady_clock::now();
  const double sim_start = node.bridge().time();
  node.start();
  if (!args.no_controllers && !start.empty()) {
    const bridge::BridgeResult r = node.start_controllers(start);
    if (!r.ok) p.log("controllers: " + r.error);
  }
  print_banner();

  while (g_stop_signal.load() == 0) {
    if (args.duration > 0.0 && node.bridge().time() - sim_start >= args.duration) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  node.stop();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  const double simulated = node.bridge().time() - sim_start;
  const ros2::NodeStats s = node.stats();
  std::printf("mechsim ros2: %.3f s simulated in %.3f s of wall time (real-time factor %.3f); %llu /clock, %llu /tf "
              "messages, %llu commands taken, %llu rejected\n",
              simulated, wall, wall > 0.0 ? simulated / wall : 0.0, static_cast<unsigned long long>(s.clock_messages),
              static_cast<unsigned long long>(s.tf_messages), static_cast<unsigned long long>(s.commands),
              static_cast<unsigned long long>(s.commands_rejected));
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
      "ros2", "Serve a world and its robot on a ROS 2 domain (Humble or Jazzy nodes; ROS_DOMAIN_ID from the environment)");
  add_robot_options(cmd, args->robot);
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
