#pragma once
// Seeded random inputs for the ROS API abuse test (pr2_abuse_test.cpp): doubles that break
// arithmetic (NaN, infinities, 1e300, denormals), names that are unknown, empty or absurd, and
// joint trajectories with wrong joints, wrong lengths, non-monotonic or unnormalised times and
// empty point lists. Everything comes from one std::mt19937_64, so a seed reproduces a run.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <ros/duration.h>
#include <trajectory_msgs/JointTrajectory.h>

namespace mechsim::ros::test {

class AbuseInputs {
 public:
  explicit AbuseInputs(std::uint64_t seed) : rng_(seed) {}

  std::mt19937_64& rng() { return rng_; }
  bool chance(double p) { return std::uniform_real_distribution<double>(0.0, 1.0)(rng_) < p; }
  int below(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
  template <class T>
  const T& pick(const std::vector<T>& v) {
    return v[static_cast<std::size_t>(below(static_cast<int>(v.size())))];
  }

  // Half of the time a plain value in [-typical, typical]; otherwise one that breaks arithmetic.
  double nasty(double typical) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    switch (below(16)) {
      case 0: return std::numeric_limits<double>::quiet_NaN();
      case 1: return -std::numeric_limits<double>::quiet_NaN();
      case 2: return inf;
      case 3: return -inf;
      case 4: return 1e300;
      case 5: return -1e300;
      case 6: return std::numeric_limits<double>::max();
      case 7: return std::numeric_limits<double>::denorm_min();
      default: return uniform(-typical, typical);
    }
  }
  bool is_sane(double v, double typical) const { return std::abs(v) <= typical; }

  // An unknown, empty or absurd controller/joint/model name.
  std::string bad_name() {
    switch (below(7)) {
      case 0: return "";
      case 1: return "no_such_" + std::to_string(below(1000));
      case 2: return std::string(2000 + below(3000), 'x');
      case 3: return "../../etc/passwd";
      case 4: return "/pr2/r_arm_controller";
      case 5: return "name with spaces\n\t";
      default: return std::string("\xff\xfe") + "::" + std::to_string(below(100));
    }
  }

  // A duration with a random (possibly negative, huge or unnormalised) sec/nsec pair.
  ::ros::Duration bad_duration() {
    ::ros::Duration d;
    switch (below(5)) {
      case 0: d.sec = -below(10) - 1; d.nsec = 0; break;
      case 1: d.sec = std::numeric_limits<std::int32_t>::max(); d.nsec = 999999999; break;
      case 2: d.sec = below(3); d.nsec = -below(1000000000); break;
      case 3: d.sec = 0; d.nsec = 0; break;
      default: d.sec = below(3); d.nsec = 1500000000; break;  // nsec over a second
    }
    return d;
  }

  // A trajectory for `joints` that is often wrong. `sane` receives whether it is well formed
  // (known joints, each once, lengths right, finite values, times increasing from > 0).
  trajectory_msgs::JointTrajectory trajectory(const std::vector<std::string>& joints,
                                              const std::vector<double>& centre, double spread, bool* sane) {
    trajectory_msgs::JointTrajectory t;
    bool ok = true;
    t.joint_names = joints;
    switch (below(8)) {
      case 0: t.joint_names[static_cast<std::size_t>(below(static_cast<int>(joints.size())))] = bad_name(); ok = false; break;
      case 1: t.joint_names.pop_back(); ok = joints.size() == 1 ? false : ok; break;  // a subset: allowed by some
      case 2: t.joint_names.push_back(joints.front()); ok = false; break;                // a joint twice
      case 3: t.joint_names.clear(); ok = false; break;
      default: break;
    }
    if (t.joint_names.size() != joints.size()) ok = false;  // keep "sane" to the plain full set
    const int points = below(6) == 0 ? 0 : 1 + below(4);
    if (points == 0) ok = false;
    double time = 0.0;
    for (int k = 0; k < points; ++k) {
      trajectory_msgs::JointTrajectoryPoint p;
      std::size_t n = t.joint_names.size();
      if (chance(0.1)) {
        n = static_cast<std::size_t>(below(static_cast<int>(joints.size()) + 3));
        ok = ok && n == t.joint_names.size();
      }
      for (std::size_t j = 0; j < n; ++j) {
        const double c = j < centre.size() ? centre[j] : 0.0;
        double v = c + uniform(-spread, spread);
        if (chance(0.08)) {
          v = nasty(1.0);
          ok = ok && std::isfinite(v) && std::abs(v) < 10.0;
        }
        p.positions.push_back(v);
      }
      if (chance(0.3)) {
        p.velocities.assign(chance(0.2) ? n + 1 : n, chance(0.1) ? nasty(1.0) : 0.0);
        ok = ok && p.velocities.size() == n && std::isfinite(p.velocities.front()) && std::abs(p.velocities.front()) < 10.0;
      }
      if (chance(0.12)) {
        p.time_from_start = bad_duration();
        ok = false;
      } else {
        time += chance(0.1) ? -0.3 : uniform(0.2, 1.0);  // sometimes going back in time
        p.time_from_start = ::ros::Duration(std::max(time, 0.0));
        if (time <= 0.0) ok = false;
      }
      t.points.push_back(p);
    }
    for (std::size_t k = 1; k < t.points.size(); ++k) {
      if (t.points[k].time_from_start <= t.points[k - 1].time_from_start) ok = false;
    }
    *sane = ok;
    return t;
  }

 private:
  std::mt19937_64 rng_;
};

}  // namespace mechsim::ros::test
