#pragma once
// Offscreen rendering of one Physics instance's world with MuJoCo's renderer, on an OpenGL context
// without a window (EGL: a GPU when one is listed, else Mesa's llvmpipe on the CPU; egl_context.hpp).
// Colour and depth come from one render; depth is converted to metres along the optical axis.
//
// Cost (DESIGN.md, "Rendering without a GPU"): multisampling, shadows and reflections are off
// unless asked for; terrain is drawn from render tiles at the detail each camera's view needs
// (BuildOptions::render_terrain), so that a 0.44 M-sample yard does not cost 0.9 M triangles a
// frame.
//
// Threads: a Renderer belongs to the thread that uses it (its OpenGL context is made current at
// each call). It keeps its own MuJoCo data: update_scene() copies the instance's positions, so
// the Physics instance is only read.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "description/robot_model.hpp"
#include "physics/physics.hpp"
#include "physics/physics_model.hpp"
#include "physics/render_error.hpp"
#include "physics/stage_timer.hpp"

namespace mechsim::physics {

// A pinhole camera. Frame C is the optical frame (ROS convention): z along the view, x to the
// right of the image, y down. Intrinsics in pixels with the ROS/OpenCV convention: pixel (u, v)
// has its centre at integer coordinates, (0, 0) the top-left pixel; u = fx x/z + cx, v = fy y/z + cy.
struct CameraView {
  description::Pose X_WC;  // optical frame in the world
  int width = 0, height = 0;  // pixels, > 0
  double fx = 0.0, fy = 0.0;  // focal lengths (pixels); the renderer needs square pixels (fx == fy)
  double cx = 0.0, cy = 0.0;  // principal point (pixels)
  double near = 0.05, far = 100.0;  // clip distances along z (m), 0 < near < far
};

struct RenderSettings {
  int max_width = 640, max_height = 480;  // the largest view rendered (offscreen buffer size)
  int multisamples = 0;       // MSAA samples (0: off; 4 is MuJoCo's default, at half the speed)
  bool shadows = false;       // the sun's shadows (costs a shadow-map pass per frame)
  bool reflections = false;
  // Terrain tiles: the coarsest level whose cells still project to at most this many pixels.
  double terrain_pixels_per_cell = 8.0;
  // Colour of the ground (plane, height field) where the world gives none.
  float ground_rgb[3] = {0.62f, 0.45f, 0.33f};
  float background_rgb[3] = {0.70f, 0.78f, 0.86f};
};

// Where nothing is drawn within the view's far clip distance, depth is +infinity.
struct Frame {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // width * height * 3, rows from the top
  std::vector<float> depth;       // width * height, metres along the optical axis, rows from the top
};

// What a render cost (for benchmarks and `mechsim bench`). The stage times are wall and process
// CPU time (llvmpipe rasterises on threads of its own: its work shows in `draw`'s CPU time).
struct RenderStats {
  int geoms = 0;          // geoms drawn
  int culled = 0;         // geoms not drawn: their bounding spheres lie outside the view
  int terrain_tiles = 0;  // terrain tiles drawn (after culling)
  long terrain_cells = 0; // height field cells drawn (two triangles each)
  StageTime prep;     // choosing geoms, terrain levels, camera and lights
  StageTime draw;     // MuJoCo's renderer and the rasterisation, to the last pixel (glFinish)
  StageTime read;     // glReadPixels: colour and/or depth out of the frame buffer
  StageTime convert;  // rows top-down, RGBA to RGB, window depth to metres
};

class Renderer {
 public:
  // Throws RenderUnavailable when no OpenGL context can be made (the message says why) and
  // std::invalid_argument for impossible settings.
  Renderer(std::shared_ptr<const PhysicsModel> model, const RenderSettings& settings = {});
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  const std::string& context_description() const;  // EGL platform, GL renderer and version
  const RenderSettings& settings() const { return settings_; }

  // Mirrors the instance's state (positions of every body) into the renderer's data; every view
  // rendered after it shows that instant. `physics` must run the same model (or a model built
  // from the same robot and world, e.g. with render tiles): throws std::invalid_argument otherwise.
  void update_scene(const Physics& physics);

  // Renders the last scene through `view` into `frame` (resized; allocates only when it grows).
  // want_rgb / want_depth choose what is read back; both come from one render.
  // Throws std::invalid_argument for a view that is impossible or larger than the settings allow.
  RenderStats render(const CameraView& view, Frame& frame, bool want_rgb = true, bool want_depth = true);

  struct Impl;

 private:
  std::shared_ptr<const PhysicsModel> model_;
  RenderSettings settings_;
  std::unique_ptr<Impl> impl_;
};

// Checks a view; returns "" when it can be rendered, else what is wrong ("width must be > 0").
std::string check_view(const CameraView& view);

}  // namespace mechsim::physics
