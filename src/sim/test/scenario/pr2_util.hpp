#pragma once
// Helpers of the PR2 scenario tests: the real PR2 (reference expansion of pr2_description, read in
// place from the shared data folder) under its default controller set
// (robots/pr2/config/controllers.yaml).

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "control/controller.hpp"
#include "sim/simulation.hpp"

namespace mechsim::sim {

// The integrator the PR2 tests run under unless MECHSIM_PR2_INTEGRATOR says otherwise.
inline const physics::Integrator kPr2DefaultIntegrator = physics::BuildOptions{}.integrator;
// kPr2DefaultIntegrator, or the environment variable MECHSIM_PR2_INTEGRATOR (implicit | euler |
// rk4) to run the PR2 acceptance figures under another integrator; throws naming a bad value.
physics::Integrator pr2_test_integrator();

// The shared data folder holds the PR2 reference description.
bool pr2_shared_data_present();

// The PR2 on `world` (the empty world when default) with the `pr2` namespace of
// robots/pr2/config/controllers.yaml, spawned 1 cm above the ground, `start` loaded and started.
std::unique_ptr<Simulation> make_pr2_simulation(const std::vector<std::string>& start, const World* world = nullptr);

// The controller `name` as type T; throws naming the controller when absent or of another type.
template <class T>
T& pr2_controller(Simulation& sim, const std::string& name) {
  auto* c = dynamic_cast<T*>(sim.controllers().controller(name));
  if (c == nullptr) throw std::runtime_error("controller '" + name + "' is not loaded or not of the expected type");
  return *c;
}

// Physics joint index of `joint`; throws naming the joint when the physics has none.
std::size_t pr2_physics_joint(const Simulation& sim, const std::string& joint);

}  // namespace mechsim::sim
