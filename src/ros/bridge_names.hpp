#pragma once
// The ROS 1 binding maps its messages onto the bridge layer (src/bridge: the Gazebo world and
// controller-manager API that both ROS bindings share); its names are used unqualified here.
#include "bridge/sim_bridge.hpp"

namespace mechsim::ros {
using namespace ::mechsim::bridge;  // NOLINT(google-build-using-namespace)
}  // namespace mechsim::ros
