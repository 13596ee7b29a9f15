#include "physics/renderer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <GL/gl.h>

#include "physics/egl_context.hpp"
#include "physics/mjcf_writer.hpp"
#include "physics/mujoco_internal.hpp"
#include "physics/physics_data.hpp"
#include "physics/render_terrain.hpp"
#include "physics/terrain_tiles.hpp"
#include "physics/transform.hpp"

namespace mechsim::physics {

namespace {

// Gazebo's default sun (direction -0.5 0.1 -0.9, diffuse 0.8, specular 0.2) over an ambient of
// 0.4, carried by MuJoCo's headlight (ambient only): images lit as a Gazebo world's default.
constexpr float kSunDirection[3] = {-0.5f, 0.1f, -0.9f};
constexpr float kSunDiffuse = 0.8f, kSunSpecular = 0.2f, kAmbient = 0.4f;

// Meshes with more vertices than this are tested vertex by vertex when their box reaches into a
// view.
constexpr int kVertexCullMin = 2000;

bool is_ground(const mjModel* m, int geom, int terrain_geom, int ground_geom) {
  return geom == terrain_geom || geom == ground_geom || (geom >= 0 && m->geom_group[geom] == kTileGroup);
}

}  // namespace

std::string check_view(const CameraView& v) {
  if (v.width <= 0 || v.height <= 0)
    return "image size " + std::to_string(v.width) + " x " + std::to_string(v.height) + ": width and height must be > 0";
  if (!(v.fx > 0.0) || !(v.fy > 0.0) || !std::isfinite(v.fx) || !std::isfinite(v.fy))
    return "focal lengths must be finite and > 0 (fx " + std::to_string(v.fx) + ", fy " + std::to_string(v.fy) + ")";
  if (std::abs(v.fx - v.fy) > 1e-6 * v.fx) return "the renderer needs square pixels (fx == fy)";
  if (!std::isfinite(v.cx) || !std::isfinite(v.cy)) return "principal point must be finite";
  if (!(v.near > 0.0) || !(v.far > v.near) || !std::isfinite(v.far))
    return "clip distances must satisfy 0 < near < far < inf (near " + std::to_string(v.near) + ", far " +
           std::to_string(v.far) + ")";
  return "";
}

// The OpenGL calls mechsim makes itself, around MuJoCo's renderer (entry points of the context's
// driver: nothing links libGL).
struct GlCalls {
  void (*finish)() = nullptr;
  void (*pixel_store)(GLenum, GLint) = nullptr;
  void (*read_buffer)(GLenum) = nullptr;
  void (*bind_framebuffer)(GLenum, GLuint) = nullptr;
  void (*read_pixels)(GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, void*) = nullptr;
  bool complete() const { return finish && pixel_store && read_buffer && bind_framebuffer && read_pixels; }
};

struct Renderer::Impl {
  EglContext egl;
  GlCalls gl;
  const mjModel* m = nullptr;
  mjData* d = nullptr;
  mjvScene scn{};
  mjvOption opt{};
  mjvCamera cam{};
  mjvPerturb pert{};
  mjrContext con{};
  std::vector<mjvGeom> geoms;  // the scene of the last update_scene(), every geom
  // Per mesh: the box its vertices span in the geom's frame (a mesh geom's frame is its mesh's).
  // Tighter than the bounding sphere: a camera on a rover sees none of the rover's 60 000-face
  // rockers below and behind it, whose spheres still reach into its view.
  std::vector<std::array<float, 6>> mesh_box;
  int nlight = 0;
  std::array<mjvLight, mjMAXLIGHT> lights{};
  int terrain_geom = -1, ground_geom = -1;
  TerrainLod lod;
  bool scene_ready = false;
  std::vector<std::uint8_t> scratch_rgba;  // colour as the frame buffer holds it, rows from the bottom
  std::vector<float> scratch_depth;        // window depth, rows from the bottom

  ~Impl() {
    try {
      egl.make_current();
    } catch (const RenderUnavailable&) {
      // The context is going anyway; freeing GL objects of a lost context is harmless.
    }
    mjr_freeContext(&con);
    mjv_freeScene(&scn);
    if (d != nullptr) mj_deleteData(d);
  }
};

Renderer::Renderer(std::shared_ptr<const PhysicsModel> model, const RenderSettings& settings)
    : model_(std::move(model)), settings_(settings) {
  if (settings_.max_width <= 0 || settings_.max_height <= 0 || settings_.max_width > 8192 || settings_.max_height > 8192)
    throw std::invalid_argument("render settings: the largest view must be 1..8192 pixels each way (got " +
                                std::to_string(settings_.max_width) + " x " + std::to_string(settings_.max_height) + ")");
  if (settings_.multisamples < 0 || settings_.multisamples > 16)
    throw std::invalid_argument("render settings: multisamples must be 0..16");
  if (!(settings_.terrain_pixels_per_cell > 0.0))
    throw std::invalid_argument("render settings: terrain_pixels_per_cell must be > 0");
  impl_ = std::make_unique<Impl>();
  Impl& r = *impl_;
  const auto load = [&](auto& f, const char* name) { f = reinterpret_cast<std::remove_reference_t<decltype(f)>>(r.egl.proc(name)); };
  load(r.gl.finish, "glFinish");
  load(r.gl.pixel_store, "glPixelStorei");
  load(r.gl.read_buffer, "glReadBuffer");
  load(r.gl.bind_framebuffer, "glBindFramebuffer");
  load(r.gl.read_pixels, "glReadPixels");
  if (!r.gl.complete()) throw RenderUnavailable("the OpenGL driver lacks glReadPixels, glFinish or framebuffer objects");
  r.m = model_->impl().model;
  r.d = mj_makeData(r.m);
  // MuJoCo sizes the offscreen buffer from the model's visual options: a shallow copy carries
  // ours without touching the shared model.
  mjModel sized = *r.m;
  sized.vis.global.offwidth = settings_.max_width;
  sized.vis.global.offheight = settings_.max_height;
  sized.vis.quality.offsamples = settings_.multisamples;
  sized.vis.quality.shadowsize = settings_.shadows ? 4096 : 1024;
  mjr_defaultContext(&r.con);
  mjr_makeContext(&sized, &r.con, mjFONTSCALE_50);
  if (r.con.offWidth < settings_.max_width || r.con.offHeight < settings_.max_height)
    throw RenderUnavailable("the OpenGL context offers an offscreen buffer of " + std::to_string(r.con.offWidth) +
                            " x " + std::to_string(r.con.offHeight) + " pixels only");
  mjr_setBuffer(mjFB_OFFSCREEN, &r.con);
  mjv_defaultScene(&r.scn);
  mjv_makeScene(r.m, &r.scn, r.m->ngeom + 64);
  mjv_defaultOption(&r.opt);
  std::fill(std::begin(r.opt.flags), std::end(r.opt.flags), mjtByte{0});
  r.opt.flags[mjVIS_STATIC] = 1;
  std::fill(std::begin(r.opt.geomgroup), std::end(r.opt.geomgroup), mjtByte{0});
  std::fill(std::begin(r.opt.sitegroup), std::end(r.opt.sitegroup), mjtByte{0});
  r.opt.geomgroup[1] = 1;  // robot visuals
  r.opt.geomgroup[2] = 1;  // ground, terrain, world boxes
  r.lod = TerrainLod(r.m);
  r.mesh_box.resize(static_cast<std::size_t>(r.m->nmesh));
  for (int i = 0; i < r.m->nmesh; ++i) {
    std::array<float, 6>& b = r.mesh_box[static_cast<std::size_t>(i)];
    b = {0, 0, 0, 0, 0, 0};
    const float* v = r.m->mesh_vert + 3 * r.m->mesh_vertadr[i];
    for (int k = 0; k < r.m->mesh_vertnum[i]; ++k)
      for (int a = 0; a < 3; ++a) {
        b[static_cast<std::size_t>(a)] = k == 0 ? v[3 * k + a] : std::min(b[static_cast<std::size_t>(a)], v[3 * k + a]);
        b[static_cast<std::size_t>(3 + a)] = k == 0 ? v[3 * k + a] : std::max(b[static_cast<std::size_t>(3 + a)], v[3 * k + a]);
      }
  }
  r.opt.geomgroup[kTileGroup] = r.lod.empty() ? 0 : 1;
  r.terrain_geom = mj_name2id(r.m, mjOBJ_GEOM, kTerrainName);
  r.ground_geom = mj_name2id(r.m, mjOBJ_GEOM, kGroundName);
  mjv_defaultFreeCamera(r.m, &r.cam);
  mjv_defaultPerturb(&r.pert);
}

Renderer::~Renderer() = default;

const std::string& Renderer::context_description() const { return impl_->egl.description(); }

void Renderer::update_scene(const Physics& physics) {
  Impl& r = *impl_;
  const mjData& src = *physics.data().d;
  const mjModel* pm = physics.model().impl().model;
  if (pm->nq != r.m->nq || pm->nbody != r.m->nbody)
    throw std::invalid_argument("renderer: the simulation runs another model (" + std::to_string(pm->nbody) +
                                " bodies, renderer " + std::to_string(r.m->nbody) + ")");
  std::memcpy(r.d->qpos, src.qpos, sizeof(mjtNum) * static_cast<std::size_t>(r.m->nq));
  r.d->time = src.time;
  mj_kinematics(r.m, r.d);
  mj_camlight(r.m, r.d);
  mjv_updateScene(r.m, r.d, &r.opt, &r.pert, &r.cam, mjCAT_ALL, &r.scn);
  r.geoms.assign(r.scn.geoms, r.scn.geoms + r.scn.ngeom);
  r.nlight = r.scn.nlight;
  std::copy(r.scn.lights, r.scn.lights + r.scn.nlight, r.lights.begin());
  r.scene_ready = true;
}

RenderStats Renderer::render(const CameraView& view, Frame& frame, bool want_rgb, bool want_depth) {
  Impl& r = *impl_;
  if (const std::string bad = check_view(view); !bad.empty()) throw std::invalid_argument("camera view: " + bad);
  if (view.width > settings_.max_width || view.height > settings_.max_height)
    throw std::invalid_argument("camera view: " + std::to_string(view.width) + " x " + std::to_string(view.height) +
                                " is larger than the renderer's " + std::to_string(settings_.max_width) + " x " +
                                std::to_string(settings_.max_height));
  if (!r.scene_ready) throw std::logic_error("renderer: render() before update_scene()");
  StageTimer timer;
  r.egl.make_current();

  const description::Vec3 y_axis = rotate(view.X_WC.orientation, {0.0, 1.0, 0.0});
  const description::Vec3 z_axis = rotate(view.X_WC.orientation, {0.0, 0.0, 1.0});
  const double n = view.near, f = view.far;
  RenderStats stats;
  const std::vector<int> levels = r.lod.choose(view, settings_.terrain_pixels_per_cell, stats);

  // This view's geoms: ground colour, the terrain at the chosen levels (the collision height field
  // only when there are no render tiles), none whose bounding sphere lies outside the frustum
  // (Mesa transforms and clips every vertex it is given on the CPU: the CC8's meshes alone are
  // 330 000 triangles, and a camera sees a few of its links at most).
  const ViewFrustum frustum(view);
  int k = 0;
  for (const mjvGeom& g : r.geoms) {
    if (g.modelrbound > 0.0f && frustum.outside_sphere(g.pos, g.modelrbound)) {
      ++stats.culled;
      continue;
    }
    const int id = g.objtype == mjOBJ_GEOM ? g.objid : -1;
    if (g.type == mjGEOM_MESH && g.dataid >= 0 && g.dataid < r.m->nmesh) {
      // MuJoCo draws a mesh's vertices as they are in the geom's frame (its size is not a scale).
      const std::array<float, 6>& b = r.mesh_box[static_cast<std::size_t>(g.dataid)];
      const int nvert = r.m->mesh_vertnum[g.dataid];
      // The box first; a large mesh whose box reaches into the view, vertex by vertex (a rover's
      // rocker: 60 000 faces drawn for nothing; the test costs a fraction of drawing them).
      if (frustum.outside_oriented_box(g.pos, g.mat, b.data(), b.data() + 3) ||
          (nvert > kVertexCullMin && frustum.outside_points(g.pos, g.mat, r.m->mesh_vert + 3 * r.m->mesh_vertadr[g.dataid], nvert))) {
        ++stats.culled;
        continue;
      }
    }
    if (id >= 0 && !r.lod.empty()) {
      if (id == r.terrain_geom) continue;
      if (r.m->geom_group[id] == kTileGroup && !r.lod.drawn(id, levels)) continue;
    }
    mjvGeom& out = r.scn.geoms[k++];
    out = g;
    if (id >= 0 && is_ground(r.m, id, r.terrain_geom, r.ground_geom) && r.m->geom_rgba[4 * id] == 0.5f &&
        r.m->geom_rgba[4 * id + 1] == 0.5f && r.m->geom_rgba[4 * id + 2] == 0.5f)
      std::copy(settings_.ground_rgb, settings_.ground_rgb + 3, out.rgba);
  }
  r.scn.ngeom = k;
  stats.geoms = k;

  // Camera: MuJoCo looks along `forward` with `up` up; the optical frame has z forward, y down.
  for (mjvGLCamera& c : r.scn.camera) {
    c.pos[0] = static_cast<float>(view.X_WC.position.x);
    c.pos[1] = static_cast<float>(view.X_WC.position.y);
    c.pos[2] = static_cast<float>(view.X_WC.position.z);
    c.forward[0] = static_cast<float>(z_axis.x);
    c.forward[1] = static_cast<float>(z_axis.y);
    c.forward[2] = static_cast<float>(z_axis.z);
    c.up[0] = static_cast<float>(-y_axis.x);
    c.up[1] = static_cast<float>(-y_axis.y);
    c.up[2] = static_cast<float>(-y_axis.z);
    // Frustum from the intrinsics: the image spans u in [-0.5, w - 0.5], v in [-0.5, h - 0.5].
    c.frustum_near = static_cast<float>(n);
    c.frustum_far = static_cast<float>(f);
    c.frustum_top = static_cast<float>(n * (view.cy + 0.5) / view.fy);
    c.frustum_bottom = static_cast<float>(-n * (view.height - 0.5 - view.cy) / view.fy);
    c.frustum_center = static_cast<float>(n * ((view.width - 1) / 2.0 - view.cx) / view.fx);
  }
  r.scn.stereo = mjSTEREO_NONE;
  r.scn.enabletransform = 0;

  // Lights: the model's, the headlight as ambient only, and the sun.
  int nl = 0;
  for (int i = 0; i < r.nlight && nl < mjMAXLIGHT - 1; ++i) {
    mjvLight l = r.lights[static_cast<std::size_t>(i)];
    if (l.headlight) {
      std::fill(l.ambient, l.ambient + 3, kAmbient);
      std::fill(l.diffuse, l.diffuse + 3, 0.0f);
      std::fill(l.specular, l.specular + 3, 0.0f);
    }
    l.castshadow = settings_.shadows ? l.castshadow : 0;
    r.scn.lights[nl++] = l;
  }
  mjvLight sun{};
  const float norm = std::sqrt(kSunDirection[0] * kSunDirection[0] + kSunDirection[1] * kSunDirection[1] +
                               kSunDirection[2] * kSunDirection[2]);
  for (int i = 0; i < 3; ++i) {
    sun.dir[i] = kSunDirection[i] / norm;
    sun.pos[i] = static_cast<float>(-50.0 * kSunDirection[i] / norm) + r.scn.camera[0].pos[i];
    sun.diffuse[i] = kSunDiffuse;
    sun.specular[i] = kSunSpecular;
  }
  sun.attenuation[0] = 1.0f;
  sun.cutoff = 180.0f;
  sun.directional = 1;
  sun.castshadow = settings_.shadows ? 1 : 0;
  r.scn.lights[nl++] = sun;
  r.scn.nlight = nl;

  std::fill(std::begin(r.scn.flags), std::end(r.scn.flags), mjtByte{0});
  r.scn.flags[mjRND_SHADOW] = settings_.shadows ? 1 : 0;
  r.scn.flags[mjRND_REFLECTION] = settings_.reflections ? 1 : 0;
  // Back faces stay: the terrain tiles' side walls close the cracks between levels of detail
  // from either side.
  r.scn.flags[mjRND_CULL_FACE] = 0;

  const mjrRect viewport{0, 0, view.width, view.height};
  mjr_setBuffer(mjFB_OFFSCREEN, &r.con);
  stats.prep = timer.lap();
  mjr_render(viewport, &r.scn, &r.con);
  // To the last pixel: llvmpipe rasterises on its own threads, and glReadPixels would wait here.
  r.gl.finish();
  stats.draw = timer.lap();

  const std::size_t w = static_cast<std::size_t>(view.width), h = static_cast<std::size_t>(view.height);
  frame.width = view.width;
  frame.height = view.height;
  frame.rgb.resize(want_rgb ? w * h * 3 : 0);
  frame.depth.resize(want_depth ? w * h : 0);
  // Depth is read whenever colour is: MuJoCo clears to black whatever the clear colour, and the
  // background (window depth 1) gets the sky's colour here.
  r.scratch_depth.resize(w * h);
  if (settings_.multisamples > 0) {
    // MuJoCo resolves the samples into its second frame buffer first.
    r.scratch_rgba.resize(want_rgb ? w * h * 3 : 0);
    mjr_readPixels(want_rgb ? r.scratch_rgba.data() : nullptr, r.scratch_depth.data(), viewport, &r.con);
  } else {
    // RGBA and float depth are what the frame buffer holds: Mesa copies them out without a
    // conversion pass of its own (GL_RGB costs a repack per pixel).
    r.gl.bind_framebuffer(GL_READ_FRAMEBUFFER, r.con.offFBO);
    r.gl.read_buffer(GL_COLOR_ATTACHMENT0);
    r.gl.pixel_store(GL_PACK_ALIGNMENT, 1);
    if (want_rgb) {
      r.scratch_rgba.resize(w * h * 4);
      r.gl.read_pixels(0, 0, view.width, view.height, GL_RGBA, GL_UNSIGNED_BYTE, r.scratch_rgba.data());
    }
    r.gl.read_pixels(0, 0, view.width, view.height, GL_DEPTH_COMPONENT, GL_FLOAT, r.scratch_depth.data());
  }
  stats.read = timer.lap();

  // OpenGL's rows run from the bottom; images' from the top. One pass per buffer.
  if (want_rgb) {
    std::uint8_t sky[3];
    for (int i = 0; i < 3; ++i) sky[i] = static_cast<std::uint8_t>(std::lround(255.0f * std::clamp(settings_.background_rgb[i], 0.0f, 1.0f)));
    const std::size_t in_px = settings_.multisamples > 0 ? 3 : 4;
    for (std::size_t y = 0; y < h; ++y) {
      const std::size_t row = (h - 1 - y) * w;
      const std::uint8_t* src = r.scratch_rgba.data() + row * in_px;
      const float* d = r.scratch_depth.data() + row;
      std::uint8_t* dst = frame.rgb.data() + y * w * 3;
      for (std::size_t x = 0; x < w; ++x) {
        const bool background = d[x] >= 1.0f;
        dst[3 * x] = background ? sky[0] : src[in_px * x];
        dst[3 * x + 1] = background ? sky[1] : src[in_px * x + 1];
        dst[3 * x + 2] = background ? sky[2] : src[in_px * x + 2];
      }
    }
  }
  if (want_depth) {
    // Window depth d in [0, 1] of a perspective projection: z = n f / (f - d (f - n)); the far
    // plane (nothing drawn) is +infinity.
    const double fn = f * n, span = f - n;
    constexpr float kInf = std::numeric_limits<float>::infinity();
    for (std::size_t y = 0; y < h; ++y) {
      const float* src = r.scratch_depth.data() + (h - 1 - y) * w;
      float* dst = frame.depth.data() + y * w;
      for (std::size_t x = 0; x < w; ++x) {
        const float d = src[x];
        dst[x] = d >= 1.0f ? kInf : static_cast<float>(fn / (f - static_cast<double>(d) * span));
      }
    }
  }
  stats.convert = timer.lap();
  return stats;
}

}  // namespace mechsim::physics
