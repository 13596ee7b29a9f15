#include "ros/head_pointing.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "physics/transform.hpp"
#include "ros/tf_publisher.hpp"

namespace mechsim::ros {

namespace {

using description::Vec3;

bool movable(const description::Joint& j) {
  return j.type == description::JointType::Revolute || j.type == description::JointType::Continuous ||
         j.type == description::JointType::Prismatic;
}

Vec3 normalized(const Vec3& v) {
  const double n = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
  return n > 0.0 ? Vec3{v.x / n, v.y / n, v.z / n} : v;
}

double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

}  // namespace

HeadPointing::HeadPointing(const description::RobotModel& robot, const std::string& pan_link,
                           const std::string& pointing_frame)
    : tip_(pointing_frame) {
  const description::Link* pan = robot.link(pan_link);
  if (pan == nullptr) throw std::runtime_error("the robot has no pan link '" + pan_link + "'");
  const description::Joint* pan_joint = pan->parent_joint.empty() ? nullptr : robot.joint(pan->parent_joint);
  if (pan_joint == nullptr) throw std::runtime_error("the pan link '" + pan_link + "' has no parent link");
  root_ = pan_joint->parent_link;
  // Up from the tip to the root.
  std::string at = pointing_frame;
  if (robot.link(at) == nullptr) throw std::runtime_error("the robot has no link '" + pointing_frame + "' (the pointing frame)");
  while (at != root_) {
    const description::Link* link = robot.link(at);
    const description::Joint* j = link->parent_joint.empty() ? nullptr : robot.joint(link->parent_joint);
    if (j == nullptr) {
      throw std::runtime_error("no chain from '" + root_ + "' to the pointing frame '" + pointing_frame + "'");
    }
    chain_.insert(chain_.begin(), j);
    at = j->parent_link;
  }
  for (std::size_t i = 0; i < chain_.size(); ++i) {
    if (!movable(*chain_[i])) continue;
    movable_.push_back(static_cast<int>(i));
    names_.push_back(chain_[i]->name);
  }
}

description::Pose HeadPointing::frame_in_root(const std::vector<double>& q) const {
  description::Pose X;
  std::size_t k = 0;
  for (std::size_t i = 0; i < chain_.size(); ++i) {
    const bool moves = k < movable_.size() && movable_[k] == static_cast<int>(i);
    X = physics::compose(X, joint_transform(*chain_[i], moves && k < q.size() ? q[k] : 0.0));
    if (moves) ++k;
  }
  return X;
}

double HeadPointing::pointing_error(const std::vector<double>& q, const Vec3& axis, const Vec3& target) const {
  const description::Pose X = frame_in_root(q);
  const Vec3 pointing = normalized(physics::rotate(X.orientation, axis));
  const Vec3 to_target = normalized({target.x - X.position.x, target.y - X.position.y, target.z - X.position.z});
  return std::acos(std::clamp(dot(pointing, to_target), -1.0, 1.0));
}

std::vector<double> HeadPointing::solve(const Vec3& axis, const Vec3& target) const {
  const std::size_t n = names_.size();
  std::vector<double> q(n, 0.0);
  const auto clamp_to_limits = [&](std::vector<double>& v) {
    for (std::size_t k = 0; k < n; ++k) {
      const description::Joint& j = *chain_[static_cast<std::size_t>(movable_[k])];
      if (j.type != description::JointType::Continuous && j.limits && j.limits->lower < j.limits->upper)
        v[k] = std::clamp(v[k], j.limits->lower, j.limits->upper);
    }
  };
  // e(q): the direction to the target less the pointing direction (both unit, root frame).
  const auto residual = [&](const std::vector<double>& v) {
    const description::Pose X = frame_in_root(v);
    const Vec3 p = normalized(physics::rotate(X.orientation, axis));
    const Vec3 t = normalized({target.x - X.position.x, target.y - X.position.y, target.z - X.position.z});
    return std::vector<double>{t.x - p.x, t.y - p.y, t.z - p.z};
  };
  for (int iteration = 0; iteration < 200 && n > 0; ++iteration) {
    const std::vector<double> e = residual(q);
    if (std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]) < 1e-9) break;
    // Numeric Jacobian (3 x n), then (J^T J + lambda I) dq = -J^T e.
    std::vector<double> J(3 * n);
    for (std::size_t k = 0; k < n; ++k) {
      std::vector<double> qk = q;
      qk[k] += 1e-6;
      const std::vector<double> ek = residual(qk);
      for (int r = 0; r < 3; ++r) J[static_cast<std::size_t>(r) * n + k] = (ek[static_cast<std::size_t>(r)] - e[static_cast<std::size_t>(r)]) / 1e-6;
    }
    std::vector<double> A(n * n, 0.0), b(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = 0; j < n; ++j)
        for (int r = 0; r < 3; ++r) A[i * n + j] += J[static_cast<std::size_t>(r) * n + i] * J[static_cast<std::size_t>(r) * n + j];
      A[i * n + i] += 1e-6;
      for (int r = 0; r < 3; ++r) b[i] -= J[static_cast<std::size_t>(r) * n + i] * e[static_cast<std::size_t>(r)];
    }
    // Gaussian elimination with partial pivoting (n is the chain's joint count: 2 on the PR2).
    for (std::size_t c = 0; c < n; ++c) {
      std::size_t pivot = c;
      for (std::size_t r = c + 1; r < n; ++r)
        if (std::abs(A[r * n + c]) > std::abs(A[pivot * n + c])) pivot = r;
      for (std::size_t k = 0; k < n; ++k) std::swap(A[c * n + k], A[pivot * n + k]);
      std::swap(b[c], b[pivot]);
      for (std::size_t r = c + 1; r < n; ++r) {
        const double f = A[r * n + c] / A[c * n + c];
        for (std::size_t k = c; k < n; ++k) A[r * n + k] -= f * A[c * n + k];
        b[r] -= f * b[c];
      }
    }
    std::vector<double> dq(n);
    for (std::size_t c = n; c-- > 0;) {
      double s = b[c];
      for (std::size_t k = c + 1; k < n; ++k) s -= A[c * n + k] * dq[k];
      dq[c] = s / A[c * n + c];
    }
    double step = 0.0;
    std::vector<double> next = q;
    for (std::size_t k = 0; k < n; ++k) {
      next[k] += std::clamp(dq[k], -0.5, 0.5);  // small steps: the residual is far from linear
      step = std::max(step, std::abs(dq[k]));
    }
    clamp_to_limits(next);
    q = next;
    if (step < 1e-10) break;
  }
  clamp_to_limits(q);
  return q;
}

}  // namespace mechsim::ros
