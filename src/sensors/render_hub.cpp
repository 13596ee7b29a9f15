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
    renderer_->update_scene(physics);
    fresh_ = true;
    ++updates_;
  }
  return renderer_.get();
}

}  // namespace mechsim::sensors
