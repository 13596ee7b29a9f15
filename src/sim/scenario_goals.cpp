#include "sim/scenario_goals.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace mechsim::sim {
namespace {

template <class P>
P* port_of(control::Controller* c, control::PortKind kind) {
  if (c == nullptr) return nullptr;
  for (control::Port* p : c->ports()) {
    if (p->kind() == kind) return dynamic_cast<P*>(p);
  }
  return nullptr;
}

[[noreturn]] void event_error(const TimelineEvent& e, const std::string& what) {
  char at[32];
  std::snprintf(at, sizeof at, "%g", e.at);
  throw ScenarioError(e.location + ": timeline event at t=" + at + " s, controller '" + e.controller + "': " + what);
}

// `all` entries first, expanded to every joint, so that entries naming a joint refine them
// (a 0 keeps what was there, as control_msgs' convention has it).
std::vector<control::JointTolerance> resolve_tolerances(const std::vector<control::JointTolerance>& in,
                                                        const std::vector<std::string>& joints,
                                                        const TimelineEvent& e, const char* what) {
  std::vector<control::JointTolerance> out;
  for (const control::JointTolerance& t : in) {
    if (t.name != "all") continue;
    for (const std::string& j : joints) out.push_back({j, t.position, t.velocity, t.acceleration});
  }
  for (const control::JointTolerance& t : in) {
    if (t.name == "all") continue;
    if (std::find(joints.begin(), joints.end(), t.name) == joints.end()) {
      event_error(e, std::string("trajectory/") + what + ": the controller has no joint '" + t.name + "'");
    }
    out.push_back(t);
  }
  return out;
}

std::string status_name(const std::optional<control::GoalStatus>& s) {
  return s ? control::goal_status_name(*s) : "UNKNOWN";
}

std::string fmt(const char* format, double a, double b = 0.0, double c = 0.0) {
  char buf[160];
  std::snprintf(buf, sizeof buf, format, a, b, c);
  return buf;
}

}  // namespace

ScenarioGoals::ScenarioGoals(const Scenario& s, control::ControllerManager& manager) {
  for (const TimelineEvent& e : s.timeline) {
    if (e.kind != TimelineEvent::Kind::Trajectory && e.kind != TimelineEvent::Kind::Gripper) continue;
    control::Controller* c = manager.controller(e.controller);
    if (c == nullptr) event_error(e, "no such controller is loaded");
    if (e.kind == TimelineEvent::Kind::Trajectory) {
      TrajectoryGoal g;
      g.event = &e;
      g.port = port_of<control::TrajectoryGoalPort>(c, control::PortKind::TrajectoryGoal);
      g.state = port_of<const control::StatePort<control::JointTrajectoryControllerState>>(
          c, control::PortKind::JointTrajectoryState);
      if (g.port == nullptr || g.state == nullptr) {
        event_error(e, "is not a trajectory controller (no FollowJointTrajectory action and state)");
      }
      const std::vector<std::string>& joints = g.port->joint_names();
      g.goal = e.trajectory;
      if (g.goal.trajectory.joint_names.empty()) g.goal.trajectory.joint_names = joints;
      for (const std::string& j : g.goal.trajectory.joint_names) {
        if (std::find(joints.begin(), joints.end(), j) == joints.end()) event_error(e, "trajectory/joints: the controller has no joint '" + j + "'");
      }
      const std::size_t n = g.goal.trajectory.joint_names.size();
      for (std::size_t k = 0; k < g.goal.trajectory.points.size(); ++k) {
        if (g.goal.trajectory.points[k].positions.size() != n) {
          event_error(e, "trajectory/points[" + std::to_string(k) + "]/positions has " +
                             std::to_string(g.goal.trajectory.points[k].positions.size()) + " values for " +
                             std::to_string(n) + " joints");
        }
      }
      g.goal.goal_tolerance = resolve_tolerances(e.trajectory.goal_tolerance, joints, e, "goal_tolerance");
      g.goal.path_tolerance = resolve_tolerances(e.trajectory.path_tolerance, joints, e, "path_tolerance");
      TrajectoryGoalOutcome out;
      out.controller = e.controller;
      out.index = 1 + static_cast<std::size_t>(std::count_if(trajectory_outcomes_.begin(), trajectory_outcomes_.end(),
                                                             [&](const auto& o) { return o.controller == e.controller; }));
      out.status = "not_sent";
      out.joints = joints;
      out.rms.assign(joints.size(), 0.0);
      out.max.assign(joints.size(), 0.0);
      g.sum_sq.assign(joints.size(), 0.0);
      trajectory_.push_back(std::move(g));
      trajectory_outcomes_.push_back(std::move(out));
      if (std::find(trajectory_controllers_.begin(), trajectory_controllers_.end(), e.controller) == trajectory_controllers_.end()) {
        trajectory_controllers_.push_back(e.controller);
      }
    } else {
      GripperGoal g;
      g.event = &e;
      g.port = port_of<control::GripperGoalPort>(c, control::PortKind::GripperGoal);
      if (g.port == nullptr) event_error(e, "is not a gripper controller (no GripperCommand action)");
      GripperGoalOutcome out;
      out.controller = e.controller;
      out.index = 1 + static_cast<std::size_t>(std::count_if(gripper_outcomes_.begin(), gripper_outcomes_.end(),
                                                             [&](const auto& o) { return o.controller == e.controller; }));
      out.command = e.gripper;
      out.status = "not_sent";
      gripper_.push_back(g);
      gripper_outcomes_.push_back(out);
    }
  }
  for (const Check& c : s.checks) {
    if (c.kind == Check::Kind::Trajectory || c.kind == Check::Kind::Gripper) find(c);
  }
}

std::size_t ScenarioGoals::find(const Check& c) const {
  const bool trajectory = c.kind == Check::Kind::Trajectory;
  std::vector<std::size_t> of_controller;
  if (trajectory) {
    for (std::size_t k = 0; k < trajectory_outcomes_.size(); ++k) {
      if (trajectory_outcomes_[k].controller == c.controller) of_controller.push_back(k);
    }
  } else {
    for (std::size_t k = 0; k < gripper_outcomes_.size(); ++k) {
      if (gripper_outcomes_[k].controller == c.controller) of_controller.push_back(k);
    }
  }
  const std::string what = trajectory ? "trajectory" : "gripper";
  if (of_controller.empty()) {
    throw ScenarioError("checks: " + what + " check: the timeline sends no " + what + " goal to controller '" + c.controller + "'");
  }
  if (c.goal > of_controller.size()) {
    throw ScenarioError("checks: " + what + " check: goal " + std::to_string(c.goal) + " of controller '" + c.controller +
                        "', but the timeline sends it " + std::to_string(of_controller.size()));
  }
  return c.goal == 0 ? of_controller.back() : of_controller[c.goal - 1];
}

void ScenarioGoals::submit(const TimelineEvent& e, double t) {
  for (std::size_t k = 0; k < trajectory_.size(); ++k) {
    if (trajectory_[k].event != &e) continue;
    TrajectoryGoal& g = trajectory_[k];
    TrajectoryGoalOutcome& out = trajectory_outcomes_[k];
    const control::GoalSubmission sub = g.port->submit(g.goal);
    g.id = sub.id;
    g.seen = g.state->sequence();
    out.sent_at = t;
    out.accepted = sub.accepted;
    if (!sub.accepted) {
      out.status = control::goal_status_name(control::GoalStatus::Rejected);
      out.finished = true;
      out.finished_at = t;
      out.result = sub.result;
    } else {
      out.status = control::goal_status_name(control::GoalStatus::Pending);
    }
    return;
  }
  for (std::size_t k = 0; k < gripper_.size(); ++k) {
    if (gripper_[k].event != &e) continue;
    GripperGoal& g = gripper_[k];
    GripperGoalOutcome& out = gripper_outcomes_[k];
    const control::GripperSubmission sub = g.port->submit(e.gripper);
    g.id = sub.id;
    out.sent_at = t;
    out.accepted = sub.accepted;
    out.error = sub.error;
    out.status = control::goal_status_name(sub.accepted ? control::GoalStatus::Pending : control::GoalStatus::Rejected);
    out.finished = !sub.accepted;
    return;
  }
}

void ScenarioGoals::poll(double t) {
  for (std::size_t k = 0; k < trajectory_.size(); ++k) {
    TrajectoryGoal& g = trajectory_[k];
    TrajectoryGoalOutcome& out = trajectory_outcomes_[k];
    if (g.id == 0 || out.finished) continue;
    const auto status = g.port->status(g.id);
    out.status = status_name(status);
    if (status == control::GoalStatus::Active && g.state->sequence() != g.seen) {
      g.seen = g.state->sequence();
      const control::JointTrajectoryControllerState s = g.state->read();
      const std::size_t n = std::min({s.desired.positions.size(), s.actual.positions.size(), g.sum_sq.size()});
      for (std::size_t j = 0; j < n; ++j) {
        const double e = s.desired.positions[j] - s.actual.positions[j];
        g.sum_sq[j] += e * e;
        out.max[j] = std::max(out.max[j], std::abs(e));
      }
      ++out.samples;
      for (std::size_t j = 0; j < g.sum_sq.size(); ++j) out.rms[j] = std::sqrt(g.sum_sq[j] / static_cast<double>(out.samples));
    }
    if (status && control::goal_finished(*status)) {
      out.finished = true;
      out.finished_at = t;
      if (auto r = g.port->result(g.id)) out.result = *r;
    }
  }
  for (std::size_t k = 0; k < gripper_.size(); ++k) {
    GripperGoal& g = gripper_[k];
    GripperGoalOutcome& out = gripper_outcomes_[k];
    if (g.id == 0 || out.finished) continue;
    const auto status = g.port->status(g.id);
    out.status = status_name(status);
    if (status && control::goal_finished(*status)) {
      out.finished = true;
      out.finished_after = t - out.sent_at;
      if (auto r = g.port->result(g.id)) out.result = *r;
    }
  }
}

CheckOutcome ScenarioGoals::judge(const Check& c) const {
  CheckOutcome out;
  out.name = c.text;
  out.passed = true;
  std::string& d = out.detail;
  if (c.kind == Check::Kind::Trajectory) {
    const TrajectoryGoalOutcome& g = trajectory_outcomes_[find(c)];
    d = g.controller + " trajectory goal " + std::to_string(g.index) + " (sent at " + fmt("%.3f s", g.sent_at) + ", " + g.status + ")";
    if (c.max_rms_error || c.max_abs_error) {
      std::size_t worst_rms = 0, worst_max = 0;
      for (std::size_t j = 0; j < g.rms.size(); ++j) {
        if (g.rms[j] > g.rms[worst_rms]) worst_rms = j;
        if (g.max[j] > g.max[worst_max]) worst_max = j;
      }
      if (g.samples == 0) {
        out.passed = false;
        d += ": no state sample while the goal was active";
      } else {
        if (c.max_rms_error) {
          out.passed = out.passed && g.rms[worst_rms] <= *c.max_rms_error;
          d += ": RMS error " + fmt("%.5f", g.rms[worst_rms]) + " (" + g.joints[worst_rms] + ", worst of " +
               std::to_string(g.joints.size()) + " joints, " + std::to_string(g.samples) + " samples), limit " +
               fmt("%.5f", *c.max_rms_error);
        }
        if (c.max_abs_error) {
          out.passed = out.passed && g.max[worst_max] <= *c.max_abs_error;
          d += "; max error " + fmt("%.5f", g.max[worst_max]) + " (" + g.joints[worst_max] + "), limit " +
               fmt("%.5f", *c.max_abs_error);
        }
      }
    }
    if (c.result) {
      const std::string wanted = control::result_code_name(*c.result);
      if (!g.finished) {
        out.passed = false;
        d += "; result: none (still " + g.status + " at the end), wanted " + wanted;
      } else {
        out.passed = out.passed && g.result.error_code == *c.result;
        d += "; result " + std::string(control::result_code_name(g.result.error_code)) +
             (g.result.error_string.empty() ? "" : " (" + g.result.error_string + ")") + ", wanted " + wanted;
      }
    }
    return out;
  }
  const GripperGoalOutcome& g = gripper_outcomes_[find(c)];
  d = g.controller + " gripper goal " + std::to_string(g.index) + " (" + fmt("%.3f m, max_effort %.3g N", g.command.position, g.command.max_effort) +
      ", sent at " + fmt("%.3f s", g.sent_at) + "): " + g.status;
  if (!g.accepted) d += " (" + g.error + ")";
  if (!g.finished) {
    out.passed = false;
    d += ", not finished at the end";
    return out;
  }
  d += fmt(" after %.3f s, gap %.4f m, effort %.4f N", g.finished_after, g.result.position, g.result.effort);
  d += std::string(", reached ") + (g.result.reached_goal ? "yes" : "no") + ", stalled " + (g.result.stalled ? "yes" : "no");
  if (c.reached) {
    out.passed = out.passed && g.accepted && g.result.reached_goal == *c.reached;
    d += std::string("; wanted reached ") + (*c.reached ? "yes" : "no");
  }
  if (c.stalled) {
    out.passed = out.passed && g.accepted && g.result.stalled == *c.stalled;
    d += std::string("; wanted stalled ") + (*c.stalled ? "yes" : "no");
  }
  if (c.finished_by) {
    out.passed = out.passed && g.accepted && g.finished_after <= *c.finished_by;
    d += fmt("; wanted finished within %.3f s", *c.finished_by);
  }
  if (c.position) {
    out.passed = out.passed && g.accepted && std::abs(g.result.position - *c.position) <= c.within;
    d += fmt("; wanted gap %.4f +- %.4f m", *c.position, c.within);
  }
  if (c.effort) {
    out.passed = out.passed && g.accepted && std::abs(g.result.effort - *c.effort) <= c.effort_within;
    d += fmt("; wanted effort %.4f +- %.4f", *c.effort, c.effort_within);
  }
  return out;
}

}  // namespace mechsim::sim
