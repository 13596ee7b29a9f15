// The scenario's `checks:` list (scenario.hpp, Check): one reader per kind, every key checked.
#include <cmath>
#include <string>

#include "sim/scenario_read.hpp"

namespace mechsim::sim::scenario_read {

Check read_check(const Params& c) {
  Check check;
  const std::vector<std::string> keys = c.keys();
  if (keys.size() != 1) {
    fail(c, "a check is a map with one key (reach, final_pose, final_heading, direction, upright, odometry, distance, trajectory, gripper, joint, tracking, laser_range, imu_tilt)");
  }
  const std::string& kind = keys.front();
  const Params p = c.child(kind);
  check.text = kind;
  if (p.is_map()) check.robot = p.get<std::string>("robot", "");
  if (kind == "reach") {
    check.kind = Check::Kind::Reach;
    only_keys(p, {"x", "y", "within", "by"});
    check.x = p.get<double>("x");
    check.y = p.get<double>("y");
    check.within = p.get<double>("within");
    check.by = p.get<double>("by");
  } else if (kind == "final_pose") {
    check.kind = Check::Kind::FinalPose;
    only_keys(p, {"robot", "x", "y", "within", "lateral_within"});
    check.x = p.get<double>("x");
    check.y = p.get<double>("y");
    check.within = p.get<double>("within");
    if (p.has("lateral_within")) check.lateral_within = p.get<double>("lateral_within");
  } else if (kind == "final_heading") {
    check.kind = Check::Kind::FinalHeading;
    only_keys(p, {"robot", "yaw_deg", "within_deg"});
    check.yaw = p.get<double>("yaw_deg") * kDeg;
    check.within_angle = p.get<double>("within_deg") * kDeg;
  } else if (kind == "direction") {
    check.kind = Check::Kind::Direction;
    only_keys(p, {"deg", "within_deg"});
    check.yaw = p.get<double>("deg") * kDeg;
    check.within_angle = p.get<double>("within_deg") * kDeg;
  } else if (kind == "upright") {
    check.kind = Check::Kind::Upright;
    only_keys(p, {"max_tilt_deg"});
    check.max_tilt = p.get<double>("max_tilt_deg") * kDeg;
  } else if (kind == "odometry") {
    check.kind = Check::Kind::Odometry;
    only_keys(p, {"robot", "max_error_fraction", "max_yaw_error_fraction"});
    if (p.has("max_error_fraction")) check.max_error_fraction = p.get<double>("max_error_fraction");
    if (p.has("max_yaw_error_fraction")) check.max_yaw_error_fraction = p.get<double>("max_yaw_error_fraction");
    if (!check.max_error_fraction && !check.max_yaw_error_fraction) fail(p, "needs max_error_fraction and/or max_yaw_error_fraction");
  } else if (kind == "distance") {
    check.kind = Check::Kind::Distance;
    only_keys(p, {"robot", "min", "max"});
    check.min_distance = p.get<double>("min", 0.0);
    check.max_distance = p.get<double>("max", 1e300);
  } else if (kind == "trajectory" || kind == "gripper") {
    const bool trajectory = kind == "trajectory";
    check.kind = trajectory ? Check::Kind::Trajectory : Check::Kind::Gripper;
    if (trajectory) {
      only_keys(p, {"controller", "goal", "max_rms_error", "max_error", "result"});
    } else {
      only_keys(p, {"controller", "goal", "reached", "stalled", "by", "position", "within", "effort", "effort_within"});
    }
    check.controller = p.get<std::string>("controller");
    if (p.has("goal")) {
      const int goal = p.get<int>("goal");
      if (goal < 1) fail(p.child("goal"), "is the 1-based index of the controller's goal in the timeline");
      check.goal = static_cast<std::size_t>(goal);
    }
    auto positive = [&](const char* key) {
      const double v = p.get<double>(key);
      if (!(v >= 0.0) || !std::isfinite(v)) fail(p.child(key), "must be >= 0");
      return v;
    };
    if (trajectory) {
      if (p.has("max_rms_error")) check.max_rms_error = positive("max_rms_error");
      if (p.has("max_error")) check.max_abs_error = positive("max_error");
      if (p.has("result")) {
        const std::string r = p.get<std::string>("result");
        using Code = control::TrajectoryResultCode;
        for (Code code : {Code::Successful, Code::InvalidGoal, Code::InvalidJoints, Code::OldHeaderTimestamp,
                          Code::PathToleranceViolated, Code::GoalToleranceViolated}) {
          if (r == control::result_code_name(code)) check.result = code;
        }
        if (!check.result) {
          fail(p.child("result"), "unknown result code '" + r +
                                      "' (SUCCESSFUL, INVALID_GOAL, INVALID_JOINTS, OLD_HEADER_TIMESTAMP, "
                                      "PATH_TOLERANCE_VIOLATED, GOAL_TOLERANCE_VIOLATED)");
        }
      }
      if (!check.max_rms_error && !check.max_abs_error && !check.result) fail(p, "needs max_rms_error, max_error and/or result");
    } else {
      if (p.has("reached")) check.reached = p.get<bool>("reached");
      if (p.has("stalled")) check.stalled = p.get<bool>("stalled");
      if (p.has("by")) check.finished_by = positive("by");
      if (p.has("position")) {
        check.position = p.get<double>("position");
        check.within = positive("within");
      } else if (p.has("within")) {
        fail(p.child("within"), "goes with position");
      }
      if (p.has("effort")) {
        check.effort = p.get<double>("effort");
        check.effort_within = positive("effort_within");
      } else if (p.has("effort_within")) {
        fail(p.child("effort_within"), "goes with effort");
      }
      if (!check.reached && !check.stalled && !check.finished_by && !check.position && !check.effort) {
        fail(p, "needs reached, stalled, by, position and/or effort");
      }
    }
  } else if (kind == "joint") {
    check.kind = Check::Kind::Joint;
    only_keys(p, {"name", "at", "position", "within"});
    check.joint = p.get<std::string>("name");
    if (p.has("at")) {
      check.at = p.get<double>("at");
      if (!(*check.at >= 0.0) || !std::isfinite(*check.at)) fail(p.child("at"), "must be >= 0 s");
    }
    check.position = finite(p, "position", 0.0);
    if (!p.has("position")) fail(p, "needs position (and within)");
    check.within = p.get<double>("within");
    if (!(check.within >= 0.0)) fail(p.child("within"), "must be >= 0");
  } else if (kind == "tracking") {
    check.kind = Check::Kind::Tracking;
    only_keys(p, {"controller", "max_error", "after"});
    check.controller = p.get<std::string>("controller");
    check.max_abs_error = p.get<double>("max_error");
    if (!(*check.max_abs_error >= 0.0) || !std::isfinite(*check.max_abs_error)) fail(p.child("max_error"), "must be >= 0");
    if (p.has("after")) {
      check.at = p.get<double>("after");
      if (!(*check.at >= 0.0) || !std::isfinite(*check.at)) fail(p.child("after"), "must be >= 0 s");
    }
  } else if (kind == "laser_range" || kind == "imu_tilt") {
    const bool laser = kind == "laser_range";
    check.kind = laser ? Check::Kind::LaserRange : Check::Kind::ImuTilt;
    if (laser) only_keys(p, {"sensor", "angle_deg", "range", "within", "at"});
    else only_keys(p, {"sensor", "tilt_deg", "within_deg", "at"});
    check.sensor = p.get<std::string>("sensor");
    if (p.has("at")) {
      check.at = p.get<double>("at");
      if (!(*check.at >= 0.0) || !std::isfinite(*check.at)) fail(p.child("at"), "must be >= 0 s");
    }
    if (laser) {
      check.angle = finite(p, "angle_deg", 0.0) * kDeg;
      const std::string range = scalar_text(p.child("range"));
      check.range = range == "inf" ? HUGE_VAL : p.get<double>("range");
      if (!(check.range > 0.0)) fail(p.child("range"), "must be > 0 m, or inf");
      check.within = p.get<double>("within");
      if (!(check.within >= 0.0)) fail(p.child("within"), "must be >= 0 m");
    } else {
      check.tilt = p.get<double>("tilt_deg") * kDeg;
      check.within_angle = p.get<double>("within_deg") * kDeg;
      if (!(check.within_angle >= 0.0)) fail(p.child("within_deg"), "must be >= 0 deg");
    }
  } else if (kind == "slip") {
    check.kind = Check::Kind::Slip;
    only_keys(p, {"wheel", "from", "to", "min_mean", "max_mean"});
    check.wheel = p.get<std::string>("wheel", "");
    check.from = finite(p, "from", 0.0);
    check.to = finite(p, "to", 1e300);
    if (!(check.from >= 0.0 && check.to > check.from)) fail(p, "needs 0 <= from < to (s)");
    if (p.has("min_mean")) check.min_mean = finite(p, "min_mean", 0.0);
    if (p.has("max_mean")) check.max_mean = finite(p, "max_mean", 0.0);
    if (!check.min_mean && !check.max_mean) fail(p, "needs min_mean and/or max_mean");
  } else {
    fail(c, "unknown check '" + kind + "' (reach, final_pose, final_heading, direction, upright, odometry, distance, trajectory, gripper, joint, tracking, laser_range, imu_tilt, slip)");
  }
  return check;
}

}  // namespace mechsim::sim::scenario_read
