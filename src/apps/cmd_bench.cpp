// `mechsim bench ROBOT --controllers FILE`: start-up (each stage from the description to the first
// tick, and peak memory), then the speed of the full tick (transmissions, controller manager,
// safety limits, sensors, physics) against the bare physics step of the same model, and the
// real-time factor, on one core.
//
// --sensors none | usual | cameras: without the robot's sensors, with them as a run without
// consumers has them (lasers, IMUs, contacts; cameras render only when asked), or with its cameras
// rendering at their rates too (all of them, or those named by --camera; --camera-width W sets
// their size as camera_overrides {all: {width: W}} would). Rendering runs on threads of its own
// (llvmpipe), so the full tick is also given in process CPU and wall-clock time, the real-time
// factor in wall time, and the cameras' stage budget (sensors/render_hub.hpp) per simulated second.
//
// The two are timed on the same states: alternating blocks of kBlock full ticks and kBlock bare
// steps, so that the bare step never runs for long on commands the controllers no longer
// update. (Timed one after the other, 5 s of bare steps on the last efforts let a CC8 on the Mars
// Yard drive off, fall into the canyon and bounce on no ground at all: 1.7 contacts a step
// against 8 in the full ticks that followed, which made the tick look 150 % dearer than the step.)

#include <sys/resource.h>

#include <algorithm>
#include <ctime>
#include <cstdio>
#include <iostream>
#include <memory>

#include "apps/cmd_common.hpp"
#include "apps/commands.hpp"
#include "control/params.hpp"
#include "description/camera_override.hpp"
#include "description/robot_loader.hpp"
#include "sim/controller_set.hpp"
#include "sim/simulation.hpp"
#include "sim/soil_config.hpp"

namespace mechsim::apps {
namespace {

struct BenchArgs {
  RobotArgs robot;
  std::vector<std::string> start;
  std::string controllers, ns, world = "empty";
  double seconds = 5.0;
  double spawn_z = 0.02;
  std::vector<double> spawn_xy;  // empty: the Mars Yard's start pad, the origin elsewhere
  std::string soil;              // a named soil (physics/soil.hpp); empty: rigid ground
  std::string integrator = physics::integrator_name(physics::BuildOptions{}.integrator);
  std::string sensors = "usual";      // none, usual or cameras
  std::vector<std::string> cameras;   // with --sensors cameras: these (empty: all)
  int camera_width = 0;               // > 0: every camera that wide (aspect kept)
  std::vector<std::string> step_cost;  // which of physics::StepCost's ways are on (empty: all)
  bool compare_step_cost = false;       // also time the step as before (StepCost::before())
};

using physics::StageTime;

constexpr long kBlock = 50;  // ticks (and bare steps) per timed block: 50 ms of simulated time

// Peak resident memory of this process so far (MB).
double peak_memory_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;  // ru_maxrss: kB on Linux
}

struct BenchStartup {
  StageTime description, world, controllers, first_tick, total;
};

void print_startup(const sim::Simulation& sim, const BenchStartup& b) {
  const sim::Simulation::StartupTimes& t = sim.startup_times();
  const physics::ArenaEstimate& a = sim.physics().model().arena();
  StageTime controllers = t.mechanism;
  controllers += b.controllers;
  std::printf("start-up (description -> first tick):  wall ms   CPU ms\n");
  const auto row = [](const char* stage, const StageTime& s, const std::string& what) {
    std::printf("  %-12s %8.1f %8.1f  %s\n", stage, s.wall_ms, s.cpu_ms, what.c_str());
  };
  row("description", b.description, "(xacro, URDF)");
  row("world", b.world, "(terrain: generated or read)");
  row("MJCF", t.mjcf, "(body plan, meshes, MJCF)");
  row("compile", t.compile, "(MuJoCo compiler, arena estimate)");
  row("data", t.data, "(MuJoCo data: arena of " + std::to_string(a.size.contacts) + " contacts, " +
                          std::to_string(a.size.constraints) + " constraint rows)");
  row("controllers", controllers, "(mechanism, controller manager; controllers loaded and started)");
  row("sensors", t.sensors, "(the robot's sensors set up and sampled once; cameras render only when asked)");
  row("first tick", b.first_tick, "");
  row("total", b.total, "");
  std::printf("peak memory at the first tick: %.1f MB (getrusage maxrss)\n", peak_memory_mb());
  if (a.from_options) {
    std::printf("arena: %d contacts, %d constraint rows (given)\n", a.size.contacts, a.size.constraints);
  } else {
    std::printf("arena: %d contacts, %d constraint rows: %d geom pairs can touch, %d of them a geom resting on the "
                "ground; %d contacts (%d rows) and %d rows of limits, equalities and friction loss estimated, a quarter "
                "more\n",
                a.size.contacts, a.size.constraints, a.candidate_pairs, a.support_geoms, a.contacts, a.contact_rows,
                a.other_rows);
  }
}

// --step-cost: the named ways of physics::StepCost on, the others off ("none": all off).
physics::StepCost step_cost_of(const std::vector<std::string>& names) {
  if (names.empty()) return {};
  physics::StepCost c = physics::StepCost::before();
  for (const std::string& n : names) {
    if (n == "pairs") c.listed_pairs = true;
    else if (n == "sparse") c.sparse_jacobian = true;
    else if (n == "tree-forces") c.tree_external_forces = true;
    else if (n != "none") throw UserError("--step-cost: unknown '" + n + "' (pairs, sparse, tree-forces or none)");
  }
  return c;
}

// Loads `start` (or, with `usual_set`, every controller, then keeps the widest conflict-free
// set) and starts them; the names started.
std::vector<std::string> start_controllers(sim::Simulation& sim, const std::vector<std::string>& start, bool usual_set,
                                           bool quiet) {
  // Load everything asked for; start what does not conflict first come first served.
  std::vector<std::string> loaded;
  for (const std::string& name : start) {
    if (control::ControlResult r = sim.load_controller(name); r) {
      loaded.push_back(name);
    } else if (!quiet) {
      std::cerr << "warning: " << r.error << "\n";
    }
  }
  // Without --start: the robot's usual set (sim::widest_conflict_free), not every controller of
  // the YAML, so that the figures are those of the configuration its scenarios run.
  if (usual_set) loaded = sim::widest_conflict_free(sim.controllers().list_controllers());
  const control::SwitchResult s = sim.controllers().switch_controllers(loaded, {}, control::SwitchStrictness::SkipConflicts);
  if (!quiet)
    for (const std::string& skipped : s.skipped) std::cerr << "warning: " << skipped << "\n";
  return s.starting;
}

void run(const BenchArgs& args) {
  BenchStartup startup;
  physics::StageTimer total, timer;
  description::RobotModel robot = description::load_robot(args.robot.file, load_options(args.robot)).model;
  const bool with_cameras = args.sensors == "cameras";
  if ((!args.cameras.empty() || args.camera_width > 0) && !with_cameras)
    throw UserError("--camera and --camera-width need --sensors cameras");
  if (with_cameras && args.camera_width > 0) {
    description::CameraOverride o;
    o.width = args.camera_width;
    o.origin = "--camera-width";
    try {
      description::apply_camera_overrides(robot, {{"all", o}});
    } catch (const std::exception& e) {
      throw UserError(std::string("--camera-width: ") + e.what());
    }
  }
  startup.description = timer.lap();
  control::Params params;
  std::vector<std::string> start = args.start;
  const bool usual_set = start.empty();
  if (!args.controllers.empty()) {
    params = controller_namespace(args.controllers, args.ns);
    if (usual_set) {
      for (const std::string& k : params.keys()) {
        if (params.child(k).is_map() && params.child(k).has("type")) start.push_back(k);
      }
    }
  }
  sim::WorldConfig world_config;
  world_config.name = args.world;
  if (!args.soil.empty()) {
    try {
      world_config.soil = sim::soil_by_name(args.soil);
    } catch (const std::exception& e) {
      throw UserError(std::string("--soil: ") + e.what());
    }
  }
  sim::SimulationOptions options;
  options.spawn.z = args.spawn_z;
  options.sensors = args.sensors != "none";
  // On a height field the robot stands on the ground fitted under it, as a scenario puts it.
  options.settle_on_ground = args.world != "empty";
  options.integrator = *physics::parse_integrator(args.integrator);  // checked by CLI11
  options.step_cost = step_cost_of(args.step_cost);
  startup.controllers = timer.lap();  // the controllers' YAML
  const sim::World world = sim::make_world(world_config);
  startup.world = timer.lap();
  if (args.spawn_xy.size() == 2) {
    options.spawn.x = args.spawn_xy[0];
    options.spawn.y = args.spawn_xy[1];
  } else if (world.mars_yard) {  // where its scenarios start: (0, 0) is the canyon's edge
    options.spawn.x = world.mars_yard->start.x;
    options.spawn.y = world.mars_yard->start.y;
    options.spawn.yaw = world.mars_yard->start.yaw;
  }
  // The same robot with the step as mechsim computed it before (physics::StepCost::before()),
  // timed in the same run, before the measured one is built so that its start-up stays its own.
  std::unique_ptr<sim::Simulation> before;
  if (args.compare_step_cost) {
    sim::SimulationOptions o = options;
    o.step_cost = physics::StepCost::before();
    before = std::make_unique<sim::Simulation>(robot, world, params, o);
    start_controllers(*before, start, usual_set, true);
    if (const sim::TickResult r = before->step(); !r) throw UserError("the first tick (step as before) failed: " + r.error);
    timer.restart();
  }
  sim::Simulation sim(std::move(robot), world, params, options);
  timer.restart();  // its stages: Simulation::startup_times()
  const std::vector<std::string> starting = start_controllers(sim, start, usual_set, false);
  std::printf("controllers running (%s):", usual_set ? "default: the widest conflict-free set" : "--start");
  for (const std::string& name : starting) std::printf(" %s", name.c_str());
  std::printf("\n");
  startup.controllers += timer.lap();
  std::vector<std::size_t> cameras;  // sensor indices rendering
  if (with_cameras) {
    sensors::SensorSet& set = sim.sensors();
    std::vector<std::string> unknown = args.cameras;
    for (std::size_t i = 0; i < set.size(); ++i) {
      if (!set.sensor(i).renders()) continue;
      const std::string& name = set.spec(i).name;
      const auto named = std::find(unknown.begin(), unknown.end(), name);
      if (!args.cameras.empty() && named == unknown.end()) continue;
      if (named != unknown.end()) unknown.erase(named);
      set.set_enabled(i, true);
      cameras.push_back(i);
    }
    if (!unknown.empty()) throw UserError("--camera " + unknown.front() + ": no camera sensor of the robot has that name");
    if (cameras.empty()) throw UserError("--sensors cameras: the robot has no camera sensor simulated here");
  }
  const sim::TickResult first = sim.step();
  startup.first_tick = timer.lap();
  startup.total = total.lap();
  if (!first) throw UserError("the first tick failed: " + first.error);
  print_startup(sim, startup);
  sim.run_for(0.2);
  if (before) before->run_for(0.2);

  const auto ticks = static_cast<long>(args.seconds / sim.period());
  // CPU time of this thread: on a shared machine wall time measures the neighbours too.
  auto cpu_now = [] {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
  };
  auto time_it = [&](long n, auto&& body) {
    const double t0 = cpu_now();
    for (long k = 0; k < n; ++k) body();
    return cpu_now() - t0;
  };
  double bare = 0.0, full = 0.0, bare_before = 0.0, full_before = 0.0;
  physics::StageTime full_process;  // the full ticks in wall-clock and process CPU time
  const sensors::CameraStages stages0 =
      sim.sensors().render_hub() != nullptr ? sim.sensors().render_hub()->stages() : sensors::CameraStages{};
  for (long done = 0; done < ticks; done += kBlock) {
    const long n = std::min(kBlock, ticks - done);
    physics::StageTimer process;
    full += time_it(n, [&] { sim.step(); });
    full_process += process.lap();
    bare += time_it(n, [&] { sim.physics().step(); });
    if (!before) continue;
    full_before += time_it(n, [&] { before->step(); });
    bare_before += time_it(n, [&] { before->physics().step(); });
  }
  const double bare_rate = static_cast<double>(ticks) / bare, full_rate = static_cast<double>(ticks) / full;
  std::printf("robot %s, %zu controllers running, %ld steps of %.4g s, %s integrator\n", sim.robot().name.c_str(),
              starting.size(), ticks, sim.period(), physics::integrator_name(options.integrator));
  const physics::StepCost& c = options.step_cost;
  std::printf("step cost: listed pairs %s (%d pairs), sparse Jacobian %s, tree forces %s\n", c.listed_pairs ? "on" : "off",
              sim.physics().model().listed_pairs(), c.sparse_jacobian ? "on" : "off", c.tree_external_forces ? "on" : "off");
  std::printf("spawned at (%.3g, %.3g) in %s%s%s; full ticks and bare steps alternate in blocks of %ld\n",
              sim.options().spawn.x, sim.options().spawn.y, args.world.c_str(), args.soil.empty() ? "" : ", soil ",
              args.soil.c_str(), kBlock);
  std::printf("bare physics step: %10.0f steps/s (%.2f us)\n", bare_rate, 1e6 / bare_rate);
  std::printf("full tick:         %10.0f steps/s (%.2f us)\n", full_rate, 1e6 / full_rate);
  std::printf("tick overhead:     %+.1f %% over the bare step\n", 100.0 * (bare_rate / full_rate - 1.0));
  std::printf("real-time factor:  %.2f (full tick, as fast as possible, one core)\n", full_rate * sim.period());
  if (before) {
    const double per_bare = 1e6 * bare_before / static_cast<double>(ticks), per_full = 1e6 * full_before / static_cast<double>(ticks);
    std::printf("step as before (physics::StepCost::before(), timed in the same blocks):\n");
    std::printf("  bare physics step: %10.0f steps/s (%.2f us)\n", 1e6 / per_bare, per_bare);
    std::printf("  full tick:         %10.0f steps/s (%.2f us)\n", 1e6 / per_full, per_full);
    std::printf("full tick now / bare step before: %.3f; bare step now / before: %.3f; full tick now / before: %.3f\n",
                full / bare_before, bare / bare_before, full / full_before);
  }
  std::printf("(thread CPU time; wall time is longer when other processes share the core)\n");
  const double per_tick = 1e3 / static_cast<double>(ticks);  // ms -> us per tick
  std::printf("sensors: %s%s\n", args.sensors.c_str(),
              args.sensors == "none" ? " (SimulationOptions::sensors off)"
              : with_cameras        ? ""
                                    : " (cameras render only when asked: none here)");
  std::printf("full tick, process: %.2f us CPU (all threads), %.2f us wall: real-time factor %.2f (wall)\n",
              full_process.cpu_ms * per_tick, full_process.wall_ms * per_tick,
              full_process.wall_ms > 0.0 ? static_cast<double>(ticks) * sim.period() * 1e3 / full_process.wall_ms : 0.0);
  if (with_cameras && sim.sensors().render_hub() != nullptr) {
    const sensors::RenderHub& hub = *sim.sensors().render_hub();
    if (!hub.error().empty()) std::cerr << "warning: cameras: " << hub.error() << "\n";
    const sensors::CameraStages& st = hub.stages();
    const double sim_s = static_cast<double>(ticks) * sim.period();
    std::printf("cameras (%zu):", cameras.size());
    for (const std::size_t i : cameras) std::printf(" %s", sim.sensors().spec(i).name.c_str());
    std::printf("\n  %.1f instants, %.1f renders, %.1f images per simulated second\n",
                static_cast<double>(st.instants - stages0.instants) / sim_s,
                static_cast<double>(st.renders - stages0.renders) / sim_s,
                static_cast<double>(st.images - stages0.images) / sim_s);
    std::printf("  stage budget, ms per simulated second (wall, process CPU):\n");
    const auto stage = [&](const char* name, physics::StageTime sensors::CameraStages::*m, const char* what) {
      std::printf("  %-9s %8.1f %8.1f  %s\n", name, ((st.*m).wall_ms - (stages0.*m).wall_ms) / sim_s,
                  ((st.*m).cpu_ms - (stages0.*m).cpu_ms) / sim_s, what);
    };
    stage("scene", &sensors::CameraStages::scene, "(positions into the renderer's scene)");
    stage("prep", &sensors::CameraStages::prep, "(geoms, terrain levels, camera, lights)");
    stage("draw", &sensors::CameraStages::draw, "(the render: MuJoCo's renderer and rasterisation to glFinish)");
    stage("read", &sensors::CameraStages::read, "(glReadPixels)");
    stage("convert", &sensors::CameraStages::convert, "(rows top-down, RGBA to RGB, depth to metres)");
    stage("resample", &sensors::CameraStages::resample, "(copy, or the distortion's resampling)");
    stage("noise", &sensors::CameraStages::noise, "(Gaussian image noise)");
    stage("points", &sensors::CameraStages::points, "(depth image and organised points)");
  }
  const physics::ArenaUse use = sim.physics().arena_use();
  std::printf("arena use: at most %d contacts, %d constraint rows in a step (arena %d, %d; grew %d times)\n",
              use.peak.contacts, use.peak.constraints, use.size.contacts, use.size.constraints, use.growths);
  for (const std::string& w : sim.physics_warnings()) std::cerr << "warning: " << w << "\n";
  std::printf("peak memory: %.1f MB (getrusage maxrss)\n", peak_memory_mb());
}

}  // namespace

void add_bench_command(CLI::App& app, CommandResult& /*result*/) {
  auto args = std::make_shared<BenchArgs>();
  CLI::App* cmd = app.add_subcommand("bench", "Speed of the full tick against the bare physics step, and the real-time factor");
  add_robot_options(cmd, args->robot);
  cmd->add_option("--controllers", args->controllers, "Controller YAML (all its controllers are loaded)");
  cmd->add_option("--namespace", args->ns, "Namespace of the controllers in the YAML");
  cmd->add_option("--start", args->start, "Controllers to start (default: the widest conflict-free set of the namespace's controllers, e.g. the CC8's rover drive)");
  cmd->add_option("--world", args->world, "empty, mars_yard_2024 or a heightmap file");
  cmd->add_option("--seconds", args->seconds, "Simulated seconds per measurement");
  cmd->add_option("--soil", args->soil, "Wheels on this soil instead of rigid ground: a named soil (mechsim world soils lists them) or a soil file (.yaml, mechsim soil fit)");
  cmd->add_option("--spawn", args->spawn_xy, "Spawn position X Y (m; default: the Mars Yard's start pad, else the origin)")
      ->expected(2);
  cmd->add_option("--integrator", args->integrator, "MuJoCo integrator: euler (default), implicit or rk4")
      ->check(CLI::IsMember({"implicit", "euler", "rk4"}));
  cmd->add_option("--sensors", args->sensors,
                  "none, usual (default: lasers, IMUs, contacts; cameras render only when asked) or cameras (and the cameras rendering at their rates)")
      ->check(CLI::IsMember({"none", "usual", "cameras"}));
  cmd->add_option("--camera", args->cameras, "With --sensors cameras: only these camera sensors (default: all)");
  cmd->add_option("--camera-width", args->camera_width, "With --sensors cameras: every camera this wide (pixels, aspect kept)")
      ->check(CLI::Range(1, 8192));
  cmd->add_option("--step-cost", args->step_cost,
                  "Which of the cheaper ways to the same MuJoCo step are on (physics::StepCost): pairs, sparse, "
                  "tree-forces, or none (default: all)")
      ->delimiter(',');
  cmd->add_flag("--compare-step-cost", args->compare_step_cost,
                "Also time the same robot with the step as before (every StepCost way off), in the same blocks");
  cmd->callback([args] { run(*args); });
}

}  // namespace mechsim::apps
