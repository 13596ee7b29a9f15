#include "sim/external_forces.hpp"

#include <algorithm>

#include "physics/physics.hpp"

namespace mechsim::sim {

ForceWindow force_window(double now, double period, double start_time, double duration) {
  ForceWindow w;
  w.start = std::max(now, start_time);
  if (duration < 0.0) w.end = -1.0;
  else if (duration == 0.0) w.end = w.start;  // active at no time
  else w.end = w.start + std::max(duration, period);
  return w;
}

std::size_t ExternalForces::clear_wrenches(std::size_t link) {
  return std::erase_if(wrenches_, [link](const TimedWrench& w) { return w.wrench.link == link; });
}

std::size_t ExternalForces::clear_efforts(std::size_t joint) {
  return std::erase_if(efforts_, [joint](const TimedEffort& e) { return e.joint == joint; });
}

void ExternalForces::apply(physics::Physics& physics, double t) {
  physics.clear_external_forces();
  for (const TimedWrench& w : wrenches_) {
    if (w.window.active_at(t)) physics.add_link_wrench(w.wrench.link, w.wrench.force_W, w.wrench.torque_W, w.wrench.offset_W);
  }
  for (const TimedEffort& e : efforts_) {
    if (e.window.active_at(t)) physics.add_joint_effort(e.joint, e.effort);
  }
  std::erase_if(wrenches_, [t](const TimedWrench& w) { return w.window.over_at(t); });
  std::erase_if(efforts_, [t](const TimedEffort& e) { return e.window.over_at(t); });
  in_physics_ = !empty();
}

}  // namespace mechsim::sim
