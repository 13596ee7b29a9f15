#pragma once
// The renderer the camera sensors of one SensorSet share: made on first use (so a simulation
// whose cameras nobody consumes never opens an OpenGL context), its scene updated once per
// instant however many cameras sample then (DESIGN.md: cameras at the same instant share the
// scene update). A machine without a working EGL gets error() and no renderer; the cameras then
// report the error and everything else runs on.
//
// Threads: the simulation's loop thread (the renderer's OpenGL context is bound to it).

#include <functional>
#include <memory>
#include <string>

#include "physics/physics.hpp"
#include "physics/physics_model.hpp"
#include "physics/renderer.hpp"

namespace mechsim::sensors {

// Builds the model the renderer draws (the physics model plus the terrain's render tiles): made
// only when a camera first renders, because render-only geoms in the physics model slow every
// step (the CC8 on the Mars Yard: 76-86 us a step without them, 437-529 us with).
using RenderModelFactory = std::function<std::shared_ptr<const physics::PhysicsModel>()>;

class RenderHub {
 public:
  // `render_model` empty: the renderer draws `model` itself.
  RenderHub(std::shared_ptr<const physics::PhysicsModel> model, physics::RenderSettings settings,
            RenderModelFactory render_model = {});
  ~RenderHub();
  RenderHub(const RenderHub&) = delete;
  RenderHub& operator=(const RenderHub&) = delete;

  // A new instant: the next scene() copies the physics again.
  void next_instant() { fresh_ = false; }
  // The renderer with the scene of `physics` now; nullptr when no context can be made (error()).
  physics::Renderer* scene(const physics::Physics& physics);

  const std::string& error() const { return error_; }
  long scene_updates() const { return updates_; }
  long renders() const { return renders_; }
  void count_render() { ++renders_; }

 private:
  std::shared_ptr<const physics::PhysicsModel> model_;
  physics::RenderSettings settings_;
  RenderModelFactory render_model_;
  std::unique_ptr<physics::Renderer> renderer_;
  std::string error_;
  bool fresh_ = false;
  long updates_ = 0, renders_ = 0;
};

}  // namespace mechsim::sensors
