#include "sim/tuning.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <regex>
#include <sstream>
#include <tuple>
#include <type_traits>
#include <stdexcept>

#include "control/params.hpp"
#include "control/ports.hpp"
#include "sim/scenario.hpp"
#include "sim/simulation.hpp"

namespace mechsim::sim {
namespace {

// Fraction of the target time below which a faster response no longer lowers the cost.
constexpr double kTimeMargin = 0.75;
// Final error, as a fraction of the step, below which a smaller one no longer lowers the cost.
constexpr double kErrorMargin = 0.005;
// Cost per decade the gains move from where the search starts (the YAML's gains).
constexpr double kStayWeight = 0.05;

control::Params controller_namespace(const TuneSetup& setup) {
  control::Params root = control::Params::from_yaml_file(setup.controllers_file);
  return setup.controllers_namespace.empty() ? root : root.child(setup.controllers_namespace);
}

bool is_position_type(const std::string& type) {
  return type == "effort_controllers/JointPositionController" || type == "robot_mechanism_controllers/JointPositionController";
}
bool is_velocity_type(const std::string& type) {
  return type == "effort_controllers/JointVelocityController" || type == "robot_mechanism_controllers/JointVelocityController";
}

control::PidGains read_gains(const control::Params& pid) {
  control::PidGains g;
  g.p = pid.get<double>("p");
  g.i = pid.get<double>("i", 0.0);
  g.d = pid.get<double>("d", 0.0);
  return g;
}

// Nelder-Mead over a small dimension (2 or 3): the standard reflection/expansion/contraction/
// shrink steps. Written here because the search is tiny and Debian's minimisers (GSL) would add
// a GPL dependency for forty lines.
template <std::size_t N, class F>
std::array<double, N> nelder_mead(F&& cost, std::array<double, N> start, double scale, int max_evaluations, int& evaluations) {
  std::array<std::array<double, N>, N + 1> x;
  std::array<double, N + 1> f;
  for (std::size_t k = 0; k <= N; ++k) {
    x[k] = start;
    if (k > 0) x[k][k - 1] += scale;
    f[k] = cost(x[k]);
    ++evaluations;
  }
  while (evaluations < max_evaluations) {
    std::array<std::size_t, N + 1> order;
    for (std::size_t k = 0; k <= N; ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return f[a] < f[b]; });
    const std::size_t best = order[0], worst = order[N], second = order[N - 1];
    if (std::abs(f[worst] - f[best]) < 1e-4 * (1.0 + std::abs(f[best]))) break;
    std::array<double, N> centroid{};
    for (std::size_t k = 0; k <= N; ++k) {
      if (k == worst) continue;
      for (std::size_t d = 0; d < N; ++d) centroid[d] += x[k][d] / static_cast<double>(N);
    }
    auto along = [&](double t) {
      std::array<double, N> p;
      for (std::size_t d = 0; d < N; ++d) p[d] = centroid[d] + t * (x[worst][d] - centroid[d]);
      return p;
    };
    const auto reflected = along(-1.0);
    const double fr = cost(reflected);
    ++evaluations;
    if (fr < f[best]) {
      const auto expanded = along(-2.0);
      const double fe = cost(expanded);
      ++evaluations;
      if (fe < fr) {
        x[worst] = expanded, f[worst] = fe;
      } else {
        x[worst] = reflected, f[worst] = fr;
      }
    } else if (fr < f[second]) {
      x[worst] = reflected, f[worst] = fr;
    } else {
      const auto contracted = along(fr < f[worst] ? -0.5 : 0.5);
      const double fc = cost(contracted);
      ++evaluations;
      if (fc < std::min(fr, f[worst])) {
        x[worst] = contracted, f[worst] = fc;
      } else {
        for (std::size_t k = 0; k <= N; ++k) {
          if (k == best) continue;
          for (std::size_t d = 0; d < N; ++d) x[k][d] = x[best][d] + 0.5 * (x[k][d] - x[best][d]);
          f[k] = cost(x[k]);
          ++evaluations;
        }
      }
    }
  }
  std::size_t best = 0;
  for (std::size_t k = 1; k <= N; ++k) {
    if (f[k] < f[best]) best = k;
  }
  return x[best];
}

// The robot with every controller of the namespace that loads, the tuned one (with `gains`)
// winning its joint; not yet run.
std::unique_ptr<Simulation> make_experiment(const TuneSetup& setup, const std::string& controller, bool velocity,
                                            const control::PidGains& gains) {
  control::Params ns = controller_namespace(setup);
  ns.set(controller + "/pid/p", gains.p);
  ns.set(controller + "/pid/i", gains.i);
  ns.set(controller + "/pid/d", gains.d);
  SimulationOptions options;
  options.spawn.z = setup.spawn_z;
  World world = make_world(setup.world);
  if (velocity && setup.velocity_on_stand) {
    world.spec.gravity = 0.0;
    options.spawn.z = 1.0;
  }
  auto sim = std::make_unique<Simulation>(setup.robot, world, ns, options);
  std::vector<std::string> start{controller};
  for (const std::string& name : ns.keys()) {
    if (name == controller || !ns.child(name).is_map() || !ns.child(name).has("type")) continue;
    if (sim->load_controller(name)) start.push_back(name);
  }
  if (control::ControlResult r = sim->load_controller(controller); !r) {
    throw std::runtime_error("could not load controller '" + controller + "': " + r.error);
  }
  // The tuned controller first: it wins its joint over group controllers.
  sim->controllers().switch_controllers(start, {}, control::SwitchStrictness::SkipConflicts);
  return sim;
}

std::size_t simulated_joint(const Simulation& sim, const std::string& joint) {
  const auto index = sim.physics().model().joint_index(joint);
  if (!index) throw std::runtime_error("joint '" + joint + "' is not simulated");
  return *index;
}

std::string format_number(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

// Where a position-controlled joint rests after `settle_before` under `gains` (rad or m).
double resting_position(const TuneSetup& setup, const std::string& controller, const control::PidGains& gains) {
  const std::unique_ptr<Simulation> sim = make_experiment(setup, controller, false, gains);
  const std::size_t joint = simulated_joint(*sim, setup.joint);
  sim->run_for(setup.settle_before);  // a diverging hold still has a last position to start from
  const double q = sim->physics().position(joint);
  return std::isfinite(q) ? q : 0.0;
}

bool meets(const StepMetrics& m, const TuneTargets& tg, bool velocity) {
  return !m.diverged && m.overshoot <= tg.overshoot &&
         (velocity ? (m.rise95 >= 0 && m.rise95 <= tg.rise95) : (m.settling_time >= 0 && m.settling_time <= tg.settling_time));
}

// The setup of one robust condition: the step scaled (position steps planned again in the
// joint's range), its world, its payload.
TuneSetup condition_setup(const TuneSetup& nominal, const TuneCondition& c, bool velocity, double start) {
  TuneSetup v = nominal;
  v.conditions.clear();
  v.robust = false;
  const double step = nominal.step.value_or(velocity ? 2.0 : 0.5) * c.step_scale;
  if (!velocity) {
    const description::Joint* joint = nominal.robot.joint(nominal.joint);
    try {
      v.step = plan_position_step(*joint, start, step).step;
    } catch (const std::runtime_error& e) {
      throw std::runtime_error("condition '" + c.name + "': " + e.what());
    }
  } else {
    v.step = step;
  }
  if (c.world) v.world = *c.world;
  if (!c.payload_link.empty()) {
    auto link = std::find_if(v.robot.links.begin(), v.robot.links.end(),
                             [&](const description::Link& l) { return l.name == c.payload_link; });
    if (link == v.robot.links.end()) {
      throw std::runtime_error("condition '" + c.name + "': no link '" + c.payload_link + "' in robot '" + v.robot.name + "'");
    }
    if (!link->inertial) link->inertial = description::Inertial{};
    link->inertial->mass += c.payload_mass;  // a point mass at the centre of mass
  }
  return v;
}

}  // namespace

TuneResult::StepPlanInfo plan_position_step(const description::Joint& joint, double start, double step) {
  TuneResult::StepPlanInfo plan;
  plan.step = step;
  const bool bounded = joint.type == description::JointType::Revolute || joint.type == description::JointType::Prismatic;
  if (!bounded || !joint.limits) return plan;
  plan.limited = true;
  plan.soft = joint.safety.has_value();
  plan.lower = plan.soft ? joint.safety->soft_lower_limit : joint.limits->lower;
  plan.upper = plan.soft ? joint.safety->soft_upper_limit : joint.limits->upper;
  auto inside = [&](double target) { return target >= plan.lower && target <= plan.upper; };
  if (inside(start + step)) return plan;
  if (inside(start - step)) {
    plan.step = -step;
    plan.reversed = true;
    return plan;
  }
  throw std::runtime_error("joint '" + joint.name + "': a step of " + format_number(step) + " from " + format_number(start) +
                           " leaves its " + (plan.soft ? "soft limits" : "limits") + " [" + format_number(plan.lower) + ", " +
                           format_number(plan.upper) + "] in both directions (targets " + format_number(start + step) +
                           " and " + format_number(start - step) + "); give a smaller --step");
}

StepMetrics measure_step(const TuneSetup& setup, const std::string& controller, bool velocity,
                         const control::PidGains& gains) {
  const std::unique_ptr<Simulation> experiment = make_experiment(setup, controller, velocity, gains);
  Simulation& sim = *experiment;
  const std::size_t joint = simulated_joint(sim, setup.joint);
  auto value = [&] { return velocity ? sim.physics().velocity(joint) : sim.physics().position(joint); };
  StepMetrics m;
  m.step = setup.step.value_or(velocity ? 2.0 : 0.5);
  if (!sim.run_for(setup.settle_before)) {
    m.diverged = true;
    return m;
  }
  const double y0 = value();
  auto* port = dynamic_cast<control::ScalarCommandPort*>(sim.controllers().controller(controller)->port("command"));
  if (port == nullptr) throw std::runtime_error("controller '" + controller + "' has no command port");
  const double target = velocity ? m.step : y0 + m.step;
  port->write(target);

  const double t0 = sim.time();
  double peak = 0.0, last_outside = 0.0;
  bool outside_ever = false;
  const auto ticks = static_cast<long>(std::lround(setup.observe / sim.period()));
  for (long k = 0; k < ticks; ++k) {
    if (!sim.step()) {
      m.diverged = true;
      return m;
    }
    const double t = sim.time() - t0;
    const double normalised = velocity ? value() / m.step : (value() - y0) / m.step;
    if (!std::isfinite(normalised)) {
      m.diverged = true;
      return m;
    }
    if (m.rise95 < 0.0 && normalised >= 0.95) m.rise95 = t;
    peak = std::max(peak, normalised);
    if (std::abs(normalised - 1.0) > 0.02) {
      last_outside = t;
      outside_ever = true;
    }
    m.peak_effort = std::max(m.peak_effort, std::abs(sim.physics().actuator_effort(joint)));
  }
  m.overshoot = std::max(0.0, peak - 1.0) * 100.0;
  m.steady_state_error = target - value();
  const bool settled_at_end = std::abs((velocity ? value() / m.step : (value() - y0) / m.step) - 1.0) <= 0.02;
  m.settling_time = settled_at_end ? (outside_ever ? last_outside : 0.0) : -1.0;
  return m;
}

TuneResult tune_joint(const TuneSetup& requested) {
  TuneSetup setup = requested;  // its step becomes the planned one
  const control::Params ns = controller_namespace(setup);
  TuneResult result;
  for (const std::string& name : ns.keys()) {
    const control::Params c = ns.child(name);
    if (!c.is_map() || c.get<std::string>("joint", "") != setup.joint) continue;
    const std::string type = c.get<std::string>("type", "");
    if (!is_position_type(type) && !is_velocity_type(type)) continue;
    result.controller = name;
    result.type = type;
    result.velocity = is_velocity_type(type);
    result.before = read_gains(c.child("pid"));
  }
  if (result.controller.empty()) {
    throw std::runtime_error("no PID position or velocity controller for joint '" + setup.joint + "' in " +
                             setup.controllers_file + (setup.controllers_namespace.empty() ? "" : " under '" + setup.controllers_namespace + "'"));
  }
  if (!result.velocity) {
    // The step must stay in the joint's range from where the joint rests (a step into a limit
    // never settles, and would be reported as a controller that misses its targets).
    const description::Joint* joint = setup.robot.joint(setup.joint);
    if (joint == nullptr) throw std::runtime_error("joint '" + setup.joint + "' is not in robot '" + setup.robot.name + "'");
    result.start = resting_position(setup, result.controller, result.before);
    result.plan = plan_position_step(*joint, result.start, setup.step.value_or(0.5));
    setup.step = result.plan.step;
  } else {
    result.plan.step = setup.step.value_or(2.0);
  }
  result.before_metrics = measure_step(setup, result.controller, result.velocity, result.before);
  // The experiments a set of gains is judged by: the nominal one, and each robust condition.
  std::vector<TuneSetup> variants{setup};
  std::vector<std::string> names{"nominal"};
  if (setup.robust) {
    const std::vector<TuneCondition> conditions =
        setup.conditions.empty() ? default_robust_conditions(setup.robot, setup.joint, result.velocity) : setup.conditions;
    for (const TuneCondition& c : conditions) {
      variants.push_back(condition_setup(setup, c, result.velocity, result.start));
      // A scaled position step planned back the other way (it left the range) says so.
      const bool turned = (*variants.back().step > 0) != (*setup.step * c.step_scale > 0);
      names.push_back(turned ? c.name + " (taken the other way: it leaves the range)" : c.name);
    }
  }

  const TuneTargets& tg = setup.targets;
  // Where the search starts: the YAML's gains, raised to at least p 10 (weak gains give a flat
  // cost landscape), d 0.1 sqrt(p) and i 0.1 p (velocity: i p).
  control::PidGains start = result.before;
  start.p = std::max(result.before.p, 10.0);
  if (result.velocity) {
    start.i = std::max(result.before.i, start.p);
    start.d = 0.0;
  } else {
    start.d = std::max(result.before.d, 0.1 * std::sqrt(start.p));
    start.i = std::max(result.before.i, 0.1 * start.p);
  }
  // Decades away from the start, summed over the searched gains.
  auto distance_from_start = [&](const control::PidGains& g) {
    double decades = std::abs(std::log10(g.p / start.p)) + std::abs(std::log10(g.i / start.i));
    if (!result.velocity) decades += std::abs(std::log10(g.d / start.d));
    return decades;
  };
  // The cost of a response, without the distance from the start.
  auto response_cost = [&](const StepMetrics& m) {
    if (m.diverged) return 1e6;
    const double horizon = setup.observe;
    double c = 0.0;
    // Being faster than three quarters of the target earns nothing: past that margin the search
    // stays near the YAML's gains instead of taking ever stiffer ones (which only shave
    // milliseconds off an effort-saturated step and make the loop touchy elsewhere in the
    // workspace), or ever softer ones (which meet a step but hold poorly against the loads of a
    // moving robot).
    if (result.velocity) {
      c += std::max(m.rise95 < 0 ? 2.0 * horizon : m.rise95, kTimeMargin * tg.rise95) / tg.rise95;
    } else {
      c += std::max(m.settling_time < 0 ? 2.0 * horizon : m.settling_time, kTimeMargin * tg.settling_time) / tg.settling_time;
    }
    c += 10.0 * std::max(0.0, m.overshoot - tg.overshoot) / tg.overshoot;
    // A final error costs as much as missing the time target by several times: a velocity loop
    // that settles off its set point is useless for driving.
    // Errors under half a percent of the step earn nothing either (same reason).
    c += std::max(0.0, std::abs(m.steady_state_error / m.step) - kErrorMargin) * 100.0;
    return c;
  };
  auto cost_of = [&](const StepMetrics& m, const control::PidGains& g) {
    const double c = response_cost(m);
    return c >= 1e6 ? c : c + kStayWeight * distance_from_start(g);  // among equals, the smallest change
  };
  auto gains_of = [&](const auto& x) {
    control::PidGains g = result.before;
    g.p = std::exp(x[0]);
    if constexpr (std::tuple_size_v<std::decay_t<decltype(x)>> == 2) {
      g.i = std::exp(x[1]);  // velocity: PI
      g.d = 0.0;
    } else {
      g.d = std::exp(x[1]);  // position: PID
      g.i = std::exp(x[2]);
    }
    return g;
  };
  auto clamp_log = [](double v) { return std::log(std::clamp(v, 1e-3, 1e5)); };
  // The worst condition's cost (one experiment when not robust).
  auto worst_cost = [&](const control::PidGains& g) {
    double worst = 0.0;
    for (const TuneSetup& v : variants) {
      worst = std::max(worst, cost_of(measure_step(v, result.controller, result.velocity, g), g));
      if (worst >= 1e6) break;  // diverged: no need to run the rest
    }
    return worst;
  };
  int evaluations = 1;
  control::PidGains best;
  if (result.velocity) {
    auto cost = [&](const std::array<double, 2>& x) { return worst_cost(gains_of(x)); };
    const auto x = nelder_mead<2>(cost, {clamp_log(start.p), clamp_log(start.i)}, 1.0,
                                  setup.max_evaluations, evaluations);
    best = gains_of(x);
  } else {
    auto cost = [&](const std::array<double, 3>& x) { return worst_cost(gains_of(x)); };
    const auto x = nelder_mead<3>(cost, {clamp_log(start.p), clamp_log(start.d), clamp_log(start.i)},
                                  1.0, setup.max_evaluations, evaluations);
    best = gains_of(x);
  }
  // Round to 3 significant digits: shipped YAML should be readable.
  auto round3 = [](double v) {
    if (v == 0.0) return 0.0;
    const double scale = std::pow(10.0, 2 - std::floor(std::log10(std::abs(v))));
    return std::round(v * scale) / scale;
  };
  best.p = round3(best.p);
  best.i = round3(best.i);
  best.d = round3(best.d);
  // The YAML's gains stay when the search found no better response in any condition: the search
  // starts from raised gains, and a tuner should not move gains that already do the job.
  auto worst_response = [&](const control::PidGains& g) {
    double worst = 0.0;
    for (const TuneSetup& v : variants) worst = std::max(worst, response_cost(measure_step(v, result.controller, result.velocity, g)));
    return worst;
  };
  if (worst_response(result.before) <= worst_response(best)) best = result.before;
  result.after = best;
  result.after_metrics = measure_step(setup, result.controller, result.velocity, best);
  result.evaluations = evaluations + 1;
  result.targets_met = meets(result.after_metrics, tg, result.velocity);
  if (setup.robust) {
    for (std::size_t i = 0; i < variants.size(); ++i) {
      TuneResult::ConditionOutcome o;
      o.name = names[i];
      o.before = i == 0 ? result.before_metrics : measure_step(variants[i], result.controller, result.velocity, result.before);
      o.after = i == 0 ? result.after_metrics : measure_step(variants[i], result.controller, result.velocity, best);
      o.met_before = meets(o.before, tg, result.velocity);
      o.met_after = meets(o.after, tg, result.velocity);
      result.targets_met = result.targets_met && o.met_after;
      result.conditions.push_back(std::move(o));
    }
  }
  return result;
}

std::vector<TuneCondition> default_robust_conditions(const description::RobotModel& robot, const std::string& joint,
                                                     bool velocity) {
  if (velocity) return {{"slow step (0.25x)", 0.25, {}, "", 0.0}, {"fast step (2x)", 2.0, {}, "", 0.0},
                        {"reversed step", -1.0, {}, "", 0.0}};
  std::vector<TuneCondition> c{{"small step (0.2x)", 0.2, {}, "", 0.0}, {"reversed step", -1.0, {}, "", 0.0}};
  const description::Joint* j = robot.joint(joint);
  const description::Link* moved = j != nullptr ? robot.link(j->child_link) : nullptr;
  if (moved != nullptr && moved->inertial && moved->inertial->mass > 0.0) {
    const double mass = 0.5 * moved->inertial->mass;
    std::ostringstream name;
    name << "payload " << mass << " kg on " << moved->name;
    c.push_back({name.str(), 1.0, {}, moved->name, mass});
  }
  return c;
}

std::vector<TuneCondition> read_tune_conditions(const std::string& file) {
  const control::Params root = control::Params::from_yaml_file(file);
  auto fail = [&](const control::Params& at, const std::string& what) -> void {
    const std::string where = at.location().empty() ? file : at.location();
    throw std::runtime_error(where + ": " + at.path() + ": " + what);
  };
  const std::optional<control::Params> list = root.find("conditions");
  if (!list || !list->is_list() || list->size() == 0) fail(list ? *list : root, "expected a non-empty list 'conditions'");
  const std::filesystem::path base = std::filesystem::path(file).parent_path();
  std::vector<TuneCondition> out;
  for (const control::Params& item : list->items()) {
    if (!item.is_map()) fail(item, "expected a map (name, step_scale, world, payload)");
    for (const std::string& k : item.keys()) {
      if (k != "name" && k != "step_scale" && k != "world" && k != "payload")
        fail(item.child(k), "unknown key '" + k + "' (expected one of: name, step_scale, world, payload)");
    }
    TuneCondition c;
    c.step_scale = item.get<double>("step_scale", 1.0);
    if (!std::isfinite(c.step_scale) || c.step_scale == 0.0) fail(item.child("step_scale"), "expected a finite, non-zero scale");
    std::ostringstream made;
    if (c.step_scale != 1.0) made << "step x" << c.step_scale;
    if (auto world = item.find("world")) {
      if (!world->is_map()) fail(*world, "expected a map of a scenario's world keys (name, slope_deg, soil, seed, ...)");
      c.world = read_world_config(*world, base);
      made << (made.tellp() > 0 ? ", " : "") << "world " << c.world->name;
    }
    if (auto payload = item.find("payload")) {
      c.payload_link = payload->get<std::string>("link");
      c.payload_mass = payload->get<double>("mass");
      if (!std::isfinite(c.payload_mass) || c.payload_mass <= 0.0) fail(payload->child("mass"), "expected a mass > 0 (kg)");
      made << (made.tellp() > 0 ? ", " : "") << "payload " << c.payload_mass << " kg on " << c.payload_link;
    }
    c.name = item.get<std::string>("name", made.str().empty() ? "nominal again" : made.str());
    out.push_back(std::move(c));
  }
  return out;
}

bool write_gains_in_place(const std::string& file, const std::string& controller, const control::PidGains& gains) {
  std::ifstream in(file);
  if (!in) return false;
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  in.close();
  // Find "<indent>controller:" then, deeper indented, "pid: {...}".
  const std::regex header("^(\\s*)" + std::regex_replace(controller, std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)") + ":\\s*$");
  static const std::regex pid_line(R"(^(\s*)pid:\s*\{(.*)\}\s*$)");
  for (std::size_t k = 0; k < lines.size(); ++k) {
    std::smatch h;
    if (!std::regex_match(lines[k], h, header)) continue;
    const std::size_t indent = h[1].length();
    for (std::size_t j = k + 1; j < lines.size(); ++j) {
      const std::string& l = lines[j];
      const std::size_t first = l.find_first_not_of(' ');
      if (first == std::string::npos || l[first] == '#') continue;
      if (first <= indent) break;
      std::smatch m;
      if (!std::regex_match(l, m, pid_line)) continue;
      // Keep every other key of the map (i_clamp, antiwindup, ...).
      std::string rest;
      std::stringstream fields(m[2].str());
      for (std::string field; std::getline(fields, field, ',');) {
        const std::string key = field.substr(field.find_first_not_of(' '), field.find(':') - field.find_first_not_of(' '));
        if (key != "p" && key != "i" && key != "d") rest += "," + field;
      }
      std::ostringstream out;
      out << m[1].str() << "pid: {p: " << gains.p << ", i: " << gains.i << ", d: " << gains.d << rest << "}";
      lines[j] = out.str();
      std::ofstream o(file);
      for (const std::string& line : lines) o << line << '\n';
      return true;
    }
  }
  return false;
}

}  // namespace mechsim::sim
