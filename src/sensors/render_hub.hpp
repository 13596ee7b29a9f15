#pragma once
// The renderer the camera sensors of one SensorSet share: made on first use (so a simulation
// whose cameras nobody consumes never opens an OpenGL context), its scene updated once per
// instant however many cameras sample then (DESIGN.md: cameras at the same instant share the
// scene update), and each distinct view rendered once per instant: two sensors asking for the
// same view at one instant (a ZED2's raw and rectified images, share_camera_renders()) get one
// frame. A machine without a working EGL gets error() and no renderer; the cameras then report
// the error and everything else runs on.
//
// Threads: the simulation's loop thread (the renderer's OpenGL context is bound to it).

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "physics/physics.hpp"
#include "physics/physics_model.hpp"
#include "physics/renderer.hpp"

namespace mechsim::sensors {

// Builds the model the renderer draws (the physics model plus the terrain's render tiles): made
// only when a camera first renders, because render-only geoms in the physics model slow every
// step (the CC8 on the Mars Yard: 76-86 us a step without them, 437-529 us with).
using RenderModelFactory = std::function<std::shared_ptr<const physics::PhysicsModel>()>;

// Where the cameras' time goes, summed since the hub was made (benchmarks, `mechsim bench`): the
// scene update per instant, the renderer's stages per render (physics::RenderStats), and the
// camera sensors' own passes per image. Wall and process CPU time each.
struct CameraStages {
  physics::StageTime scene;     // positions into the renderer's scene, once per instant
  physics::StageTime prep, draw, read, convert;  // per render (physics::RenderStats)
  physics::StageTime resample;  // an image from its render: a copy, or the distortion's resampling
  physics::StageTime noise;     // Gaussian image noise
  physics::StageTime points;    // depth image and organised points from the render's depth
  long instants = 0, renders = 0, images = 0;
  long geoms = 0, terrain_tiles = 0, terrain_cells = 0;  // drawn, summed over the renders
};

class RenderHub {
 public:
  // `render_model` empty: the renderer draws `model` itself.
  RenderHub(std::shared_ptr<const physics::PhysicsModel> model, physics::RenderSettings settings,
            RenderModelFactory render_model = {});
  ~RenderHub();
  RenderHub(const RenderHub&) = delete;
  RenderHub& operator=(const RenderHub&) = delete;

  // A new instant: the next frame() copies the physics again and renders anew.
  void next_instant() {
    fresh_ = false;
    used_ = 0;
  }
  // `view` rendered from the scene of `physics` now (RGB, and depth when `depth`): rendered on the
  // first request for this view at this instant, the same frame for later ones (a frame with
  // depth serves a request without). Valid until next_instant(). nullptr when no context can be
  // made (error()). Frames are kept and reused across instants: no allocation once warm.
  const physics::Frame* frame(const physics::Physics& physics, const physics::CameraView& view, bool depth);

  // The simulation's physics was rebuilt (a robot spawned or deleted): the renderer is made anew
  // over `model` (through `render_model` when given) at the next frame.
  void set_model(std::shared_ptr<const physics::PhysicsModel> model, RenderModelFactory render_model) {
    model_ = std::move(model);
    render_model_ = std::move(render_model);
    renderer_.reset();
    fresh_ = false;
  }

  const std::string& error() const { return error_; }
  long scene_updates() const { return updates_; }
  long renders() const { return renders_; }
  const CameraStages& stages() const { return stages_; }
  CameraStages& stages() { return stages_; }  // the camera sensors add their passes

 private:
  std::shared_ptr<const physics::PhysicsModel> model_;
  physics::RenderSettings settings_;
  RenderModelFactory render_model_;
  struct Slot {
    physics::CameraView view;
    bool depth = false;
    physics::Frame frame;
  };
  // The renderer with the scene of `physics` now; nullptr when no context can be made.
  physics::Renderer* scene(const physics::Physics& physics);

  std::unique_ptr<physics::Renderer> renderer_;
  std::string error_;
  bool fresh_ = false;
  long updates_ = 0, renders_ = 0;
  CameraStages stages_;
  std::vector<std::unique_ptr<Slot>> slots_;  // the first used_ hold this instant's frames
  std::size_t used_ = 0;
};

}  // namespace mechsim::sensors
