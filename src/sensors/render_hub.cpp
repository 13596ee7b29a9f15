#include "sensors/render_hub.hpp"

#include <stdexcept>

namespace mechsim::sensors {

RenderHub::RenderHub(std::shared_ptr<const physics::PhysicsModel> model, physics::RenderSettings settings,
                     RenderModelFactory render_model)
    : model_(std::move(model)), settings_(settings), render_model_(std::move(render_model)) {}

RenderHub::~RenderHub() = default;

physics::Renderer* RenderHub::scene(const physics::Physics& physics) {
  if (!renderer_ && error_.empty()) {
    try {
      renderer_ = std::make_unique<physics::Renderer>(render_model_ ? render_model_() : model_, settings_);
    } catch (const std::exception& e) {
      error_ = std::string("cameras cannot render: ") + e.what();
    }
  }
  if (!renderer_) return nullptr;
  if (!fresh_) {
    physics::StageTimer timer;
    renderer_->update_scene(physics);
    stages_.scene += timer.lap();
    ++stages_.instants;
    fresh_ = true;
    ++updates_;
  }
  return renderer_.get();
}

namespace {

bool same_view(const physics::CameraView& a, const physics::CameraView& b) {
  const description::Pose &p = a.X_WC, &q = b.X_WC;
  return a.width == b.width && a.height == b.height && a.fx == b.fx && a.fy == b.fy && a.cx == b.cx && a.cy == b.cy &&
         a.near == b.near && a.far == b.far && p.position.x == q.position.x && p.position.y == q.position.y &&
         p.position.z == q.position.z && p.orientation.w == q.orientation.w && p.orientation.x == q.orientation.x &&
         p.orientation.y == q.orientation.y && p.orientation.z == q.orientation.z;
}

}  // namespace

const physics::Frame* RenderHub::frame(const physics::Physics& physics, const physics::CameraView& view, bool depth) {
  physics::Renderer* renderer = scene(physics);
  if (renderer == nullptr) return nullptr;
  for (std::size_t i = 0; i < used_; ++i) {
    const Slot& s = *slots_[i];
    if ((s.depth || !depth) && same_view(s.view, view)) return &s.frame;
  }
  if (used_ == slots_.size()) slots_.push_back(std::make_unique<Slot>());
  Slot& s = *slots_[used_++];
  s.view = view;
  s.depth = depth;
  const physics::RenderStats stats = renderer->render(view, s.frame, true, depth);
  stages_.prep += stats.prep;
  stages_.draw += stats.draw;
  stages_.read += stats.read;
  stages_.convert += stats.convert;
  ++stages_.renders;
  stages_.geoms += stats.geoms;
  stages_.terrain_tiles += stats.terrain_tiles;
  stages_.terrain_cells += stats.terrain_cells;
  ++renders_;
  return &s.frame;
}

}  // namespace mechsim::sensors
