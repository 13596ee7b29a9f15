// `mechsim tune ROBOT --controllers FILE --joint J`: PID tuning by closed-loop step experiments
// in simulation; prints the metrics before and after and writes the gains back to the YAML.

#include <cstdio>
#include <iostream>
#include <memory>

#include "apps/cmd_common.hpp"
#include "apps/commands.hpp"
#include "control/params.hpp"
#include "description/robot_loader.hpp"
#include "sim/tuning.hpp"

namespace mechsim::apps {
namespace {

struct TuneArgs {
  RobotArgs robot;
  std::string controllers;
  std::string ns;
  std::vector<std::string> joints;
  double step = 0.0;
  double settle = 0.3, rise = 0.2, overshoot = 5.0;
  double observe = 1.0;
  int evaluations = 80;
  bool write = false;
  bool robust = false;
  std::string conditions;  // a conditions file (implies robust)
};

// `unit` is the joint's position unit ("rad" or "m").
std::string metrics_line(const sim::StepMetrics& m, bool velocity, const std::string& unit) {
  if (m.diverged) return "diverged";
  char buf[256];
  auto t = [](double v) { return v < 0 ? std::string("never") : std::to_string(v).substr(0, 5) + " s"; };
  const std::string step_unit = velocity ? unit + "/s" : unit;
  std::snprintf(buf, sizeof buf, "step %.3g %s: 95%% at %s, settles (2%%) at %s, overshoot %.1f %%, final error %.3g, peak effort %.3g",
                m.step, step_unit.c_str(), t(m.rise95).c_str(), t(m.settling_time).c_str(), m.overshoot,
                m.steady_state_error, m.peak_effort);
  return buf;
}

// The controllers' namespace: as given, else the YAML's single top-level map without a `type`.
std::string detect_namespace(const std::string& file, const std::string& given) {
  if (!given.empty()) return given;
  const control::Params root = control::Params::from_yaml_file(file);
  const std::vector<std::string> keys = root.keys();
  if (keys.size() == 1 && root.child(keys[0]).is_map() && !root.child(keys[0]).has("type")) return keys[0];
  return "";
}

void run(const TuneArgs& args, CommandResult& result) {
  sim::TuneSetup setup;
  setup.robot = description::load_robot(args.robot.file, load_options(args.robot)).model;
  setup.controllers_file = args.controllers;
  setup.controllers_namespace = detect_namespace(args.controllers, args.ns);
  if (args.step != 0.0) setup.step = args.step;
  setup.targets.settling_time = args.settle;
  setup.targets.rise95 = args.rise;
  setup.targets.overshoot = args.overshoot;
  setup.observe = args.observe;
  setup.max_evaluations = args.evaluations;
  setup.robust = args.robust || !args.conditions.empty();
  if (!args.conditions.empty()) setup.conditions = sim::read_tune_conditions(args.conditions);
  bool all_met = true;
  for (const std::string& joint : args.joints) {
    setup.joint = joint;
    const sim::TuneResult r = sim::tune_joint(setup);
    const description::Joint* model_joint = setup.robot.joint(joint);
    const std::string unit =
        model_joint != nullptr && model_joint->type == description::JointType::Prismatic ? "m" : "rad";
    std::cout << r.controller << " (" << r.type << ", joint " << joint << ")\n";
    if (r.plan.reversed) {
      std::cout << "  note: a step of " << -r.plan.step << " " << unit << " from " << r.start << " would leave the "
                << (r.plan.soft ? "soft limits" : "limits") << " [" << r.plan.lower << ", " << r.plan.upper
                << "]; stepping " << r.plan.step << " " << unit << " instead\n";
    }
    std::cout << "  before: p " << r.before.p << " i " << r.before.i << " d " << r.before.d << "\n          "
              << metrics_line(r.before_metrics, r.velocity, unit) << "\n"
              << "  after:  p " << r.after.p << " i " << r.after.i << " d " << r.after.d << "\n          "
              << metrics_line(r.after_metrics, r.velocity, unit) << "\n"
              << "  " << r.evaluations << " experiments; targets (";
    if (r.velocity) {
      std::cout << "95 % within " << args.rise << " s";
    } else {
      std::cout << "settling within " << args.settle << " s";
    }
    std::cout << ", overshoot under " << args.overshoot << " %) " << (r.targets_met ? "met" : "NOT met")
              << (r.conditions.empty() ? "" : " in every condition") << "\n";
    for (const sim::TuneResult::ConditionOutcome& c : r.conditions) {
      std::cout << "  condition " << c.name << ":\n    before " << (c.met_before ? "(met)     " : "(NOT met) ")
                << metrics_line(c.before, r.velocity, unit) << "\n    after  " << (c.met_after ? "(met)     " : "(NOT met) ")
                << metrics_line(c.after, r.velocity, unit) << "\n";
    }
    all_met = all_met && r.targets_met;
    if (args.write) {
      if (!sim::write_gains_in_place(args.controllers, r.controller, r.after)) {
        throw UserError("could not find a one-line 'pid: {...}' for '" + r.controller + "' in " + args.controllers);
      }
      std::cout << "  written to " << args.controllers << "\n";
    } else {
      std::cout << "  YAML: " << r.controller << ": {pid: {p: " << r.after.p << ", i: " << r.after.i << ", d: " << r.after.d
                << "}}\n";
    }
  }
  result.exit_code = all_met ? 0 : 1;
}

}  // namespace

void add_tune_command(CLI::App& app, CommandResult& result) {
  auto args = std::make_shared<TuneArgs>();
  CLI::App* cmd = app.add_subcommand("tune", "Tune a joint's PID controller by step experiments in simulation");
  add_robot_options(cmd, args->robot);
  cmd->add_option("--controllers", args->controllers, "Controller YAML")->required();
  cmd->add_option("--namespace", args->ns, "Namespace of the controllers in the YAML (default: its single top-level map)");
  cmd->add_option("--joint", args->joints, "Joint whose controller is tuned (repeatable)")->required();
  cmd->add_option("--step", args->step, "Step size (rad, m, or rad/s for velocity controllers)");
  cmd->add_option("--settle", args->settle, "Target settling time (2 %) of position controllers (s)");
  cmd->add_option("--rise", args->rise, "Target time to 95 % of velocity controllers (s)");
  cmd->add_option("--overshoot", args->overshoot, "Target maximum overshoot (%)");
  cmd->add_option("--observe", args->observe, "Time observed after the step (s); longer than the target settling time");
  cmd->add_option("--evaluations", args->evaluations, "Maximum experiments per joint");
  cmd->add_flag("--write", args->write, "Write the gains into the controller YAML (its pid line)");
  cmd->add_flag("--robust", args->robust,
                "Tune for the worst of several conditions: by default a small and a reversed step and a payload "
                "(position), or a slow, a fast and a reversed step (velocity)");
  cmd->add_option("--conditions", args->conditions,
                  "Conditions file for --robust (YAML: conditions: [{name, step_scale, world: {...}, payload: {link, mass}}])")
      ->check(CLI::ExistingFile);
  cmd->callback([args, &result] { run(*args, result); });
}

}  // namespace mechsim::apps
