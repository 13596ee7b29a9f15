#include "sensors/sensor_set.hpp"

#include "sensors/sensor_types.hpp"

#include <algorithm>
#include <cmath>

namespace mechsim::sensors {

namespace {

// FNV-1a: a stable hash of the sensor's name for its generator's seed.
std::uint64_t name_hash(std::string_view name) {
  std::uint64_t h = 1469598103934665603ull;
  for (const char c : name) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ull;
  }
  return h;
}

// Slack for comparing tick times (multiples of the period, with rounding) with due times.
constexpr double kTimeSlack = 1e-9;

double next_due_after(double rate, double time) {
  if (rate <= 0.0) return time;  // every tick
  return std::floor(time * rate + kTimeSlack + 1.0) / rate;
}

}  // namespace

SensorSet::SensorSet(const std::vector<description::SensorSpec>& specs,
                     std::shared_ptr<const physics::PhysicsModel> model, std::uint64_t seed,
                     RenderModelFactory render_model, std::string physics_prefix)
    : model_(std::move(model)), prefix_(std::move(physics_prefix)) {
  for (const description::SensorSpec& spec : specs) {
    if (!spec.simulated()) {
      skipped_.push_back({spec, std::get<description::UnsupportedSpec>(spec.details).reason});
      continue;
    }
    try {
      sensors_.push_back(make_sensor(spec, *model_, prefix_));
    } catch (const SensorLeftOut& e) {
      skipped_.push_back({spec, e.what(), true});
      continue;
    }
    std::seed_seq seq{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                      static_cast<std::uint32_t>(name_hash(spec.name)),
                      static_cast<std::uint32_t>(name_hash(spec.name) >> 32)};
    states_.push_back(sensors_.back()->make_state(Rng(seq)));
  }
  readings_.resize(sensors_.size());
  next_due_.assign(sensors_.size(), 0.0);
  enabled_.assign(sensors_.size(), 1);
  requested_.assign(sensors_.size(), 0);
  held_.assign(sensors_.size(), 0);
  physics::RenderSettings settings;
  settings.max_width = settings.max_height = 0;
  for (std::size_t i = 0; i < sensors_.size(); ++i) {
    if (!sensors_[i]->renders()) continue;
    enabled_[i] = 0;
    const auto [w, h] = sensors_[i]->render_size();
    settings.max_width = std::max(settings.max_width, w);
    settings.max_height = std::max(settings.max_height, h);
  }
  if (settings.max_width > 0) {
    share_camera_renders();
    hub_ = std::make_unique<RenderHub>(model_, settings, std::move(render_model));
    for (std::size_t i = 0; i < sensors_.size(); ++i)
      if (sensors_[i]->renders()) states_[i]->render = hub_.get();
  }
}

void SensorSet::share_camera_renders() {
  std::vector<CameraSensor*> cameras;
  for (const std::unique_ptr<Sensor>& s : sensors_)
    if (auto* c = dynamic_cast<CameraSensor*>(s.get())) cameras.push_back(c);
  for (CameraSensor* a : cameras)
    for (const CameraSensor* b : cameras) a->share_renders_with(*b);
}

void SensorSet::set_model(std::shared_ptr<const physics::PhysicsModel> model, RenderModelFactory render_model) {
  model_ = std::move(model);
  // The first robot's links, geoms and bodies come first in the physics and keep their indices.
  if (!prefix_.empty())
    for (const std::unique_ptr<Sensor>& s : sensors_) s->bind(*model_);
  if (hub_) hub_->set_model(model_, std::move(render_model));
}

std::optional<std::size_t> SensorSet::find(std::string_view name) const {
  for (std::size_t i = 0; i < sensors_.size(); ++i)
    if (sensors_[i]->spec().name == name) return i;
  return std::nullopt;
}

void SensorSet::take(std::size_t i, const physics::Physics& physics, double time) {
  SensorState& state = *states_[i];
  SensorReading& r = readings_[i];
  sensors_[i]->sample(physics, time, state, r.value);
  state.last_sample = time;
  r.stamp = time;
  ++r.count;
  next_due_[i] = next_due_after(sensors_[i]->spec().update_rate, time);
}

std::size_t SensorSet::sample_due(const physics::Physics& physics, double time) {
  if (hub_) hub_->next_instant();
  std::size_t sampled = 0;
  for (std::size_t i = 0; i < sensors_.size(); ++i) {
    const bool due = (enabled_[i] || held_[i]) && time + kTimeSlack >= next_due_[i];
    if (!due && !requested_[i]) continue;
    requested_[i] = 0;
    take(i, physics, time);
    ++sampled;
  }
  return sampled;
}

void SensorSet::sample_all(const physics::Physics& physics, double time) {
  if (hub_) hub_->next_instant();
  for (std::size_t i = 0; i < sensors_.size(); ++i)
    if (enabled_[i] || held_[i]) take(i, physics, time);
}

}  // namespace mechsim::sensors
