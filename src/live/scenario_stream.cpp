#include "live/scenario_stream.hpp"

#include "description/robot_loader.hpp"

namespace mechsim::live {

std::string scenario_urdf(const sim::Scenario& scenario) {
  description::LoadOptions load;
  load.xacro_args = scenario.xacro_args;
  load.packages = scenario.packages;
  load.lenient = scenario.lenient;
  try {
    return description::load_robot(scenario.description, load).urdf;
  } catch (const std::exception& e) {
    throw sim::ScenarioError(scenario.file + ": robot: " + e.what());
  }
}

std::vector<std::array<double, 2>> scenario_waypoints(const sim::Scenario& scenario) {
  std::vector<std::array<double, 2>> points;
  for (const sim::TimelineEvent& e : scenario.timeline) {
    if (e.kind == sim::TimelineEvent::Kind::Route) points.insert(points.end(), e.route.waypoints.begin(), e.route.waypoints.end());
  }
  return points;
}

}  // namespace mechsim::live
