#pragma once
// SimBridge's state (C++20; bridge/*.cpp only): shared by sim_bridge.cpp and model_api.cpp.

#include <functional>
#include <map>
#include <mutex>
#include <memory>
#include <string>
#include <vector>

#include "live/live_stream.hpp"
#include "bridge/mechanism_statistics.hpp"
#include "bridge/sim_bridge.hpp"
#include "sim/simulation.hpp"

namespace mechsim::bridge {

struct SimBridge::Impl {
  explicit Impl(BridgeOptions o) : options(std::move(o)) {}
  // Runs `command` in the loop thread between ticks and waits for it (model_api.cpp).
  BridgeResult in_loop(const std::function<BridgeResult(sim::Simulation&)>& command) const;
  // Loop thread: the physics indices below looked up again when the world's physics was rebuilt
  // (a robot spawned or deleted) since they were.
  void refresh();
  void reapply_overrides();  // loop thread, from refresh()
  BridgeOptions options;
  control::Params params;
  std::optional<Ros2ControlSummary> ros2;  // ros2_control robots
  std::unique_ptr<sim::Simulation> owned;  // the first robot's simulation (it ticks the world)
  sim::Simulation* simulation = nullptr;   // this robot's: owned, or an other robot of host's world
  Impl* host = nullptr;                    // an other robot's: the bridge of the world's first robot
  std::uint64_t generation = 0;            // physics_generation() the indices below are of
  bool resolved = false;
  std::vector<int> physics_joint;  // per description joint; -1 when the physics has none
  std::shared_ptr<MechanismStatistics> statistics;  // PR2 controller manager outputs; null: off
  std::vector<std::string> link_names;  // description links the physics has (fixed at the spawn)
  std::vector<std::size_t> link_index;  // their physics links
  // Per World::sdf_model_frames: the physics body carrying the model, -1 for a static one.
  std::vector<int> world_model_body;
  // set_joint_properties / set_link_properties, by joint and link name: applied again by refresh()
  // when the physics is built again.
  std::mutex overrides_mutex;
  std::map<std::string, JointPropertyChange> joint_overrides;
  std::map<std::string, LinkPropertiesData> link_overrides;
  // After `simulation`: its observer refers to the stream, which goes first (after the ticks).
  std::unique_ptr<live::LiveStream> live;
};

}  // namespace mechsim::bridge
