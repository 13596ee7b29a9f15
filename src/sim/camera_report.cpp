#include "sim/camera_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "physics/image_png.hpp"

namespace mechsim::sim {

namespace {

constexpr int kTileWidth = 320;  // contact sheet: each frame shrunk to about this width

std::string time_label(double t) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2fs", t);
  return b;
}

// Depth as grey on a log scale over the kept range [lo, hi]: lo white, hi dark grey, nothing black.
std::vector<std::uint8_t> depth_picture(const sensors::CameraImage& im, double lo, double hi) {
  std::vector<std::uint8_t> out(im.depth.size() * 3, 0);
  lo = std::max(lo, 1e-3);
  const double span = std::log(std::max(hi, 2 * lo) / lo);
  for (std::size_t k = 0; k < im.depth.size(); ++k) {
    const float z = im.depth[k];
    if (!std::isfinite(z) || z <= 0.0f) continue;
    const double g = std::clamp(255.0 - 215.0 * std::log(z / lo) / span, 40.0, 255.0);
    out[3 * k] = out[3 * k + 1] = out[3 * k + 2] = static_cast<std::uint8_t>(g);
  }
  return out;
}

}  // namespace

CameraReport::CameraReport(const Simulation& sim, const Scenario& scenario, const std::string& dir) : dir_(dir) {
  if (dir_.empty()) return;
  const sensors::SensorSet& set = sim.sensors();
  for (std::size_t i = 0; i < set.size(); ++i)
    if (set.sensor(i).renders()) cameras_.push_back(i);
  times_ = scenario.camera_picture_times;
  std::sort(times_.begin(), times_.end());
  if (cameras_.empty()) times_.clear();
  seen_.assign(set.size(), 0);
  for (const std::size_t i : cameras_) seen_[i] = set.reading(i).count;
  requested_at_.assign(set.size(), -1.0);
  rows_.resize(times_.size());
}

void CameraReport::before_step(Simulation& sim) {
  const double next = sim.time() + sim.period();
  while (next_request_ < times_.size() && next + 1e-9 >= times_[next_request_]) {
    for (const std::size_t i : cameras_) {
      sim.sensors().request(i);
      requested_at_[i] = times_[next_request_];
    }
    ++next_request_;
  }
}

void CameraReport::observe(const Simulation& sim) {
  for (const std::size_t i : cameras_) {
    const sensors::SensorReading& r = sim.sensors().reading(i);
    if (r.count == seen_[i]) continue;
    seen_[i] = r.count;
    if (requested_at_[i] < 0.0) continue;
    save(sim, i, requested_at_[i]);
    requested_at_[i] = -1.0;
  }
}

void CameraReport::save(const Simulation& sim, std::size_t i, double picture_time) {
  const auto& reading = std::get<sensors::CameraReading>(sim.sensors().reading(i).value);
  const std::string name = sim.sensors().spec(i).name;
  if (!reading.error.empty()) {
    std::string warning = name;
    warning.append(": ").append(reading.error);
    if (std::find(warnings_.begin(), warnings_.end(), warning) == warnings_.end()) warnings_.push_back(warning);
    return;
  }
  const auto row = static_cast<std::size_t>(std::find(times_.begin(), times_.end(), picture_time) - times_.begin());
  std::filesystem::create_directories(std::filesystem::path(dir_) / "cameras");
  const auto& spec = std::get<description::CameraSpec>(sim.sensors().spec(i).details);
  for (std::size_t k = 0; k < reading.images.size(); ++k) {
    const sensors::CameraImage& im = reading.images[k];
    const int w = im.info.width, h = im.info.height;
    std::string base = "cameras/";
    base.append(name);
    if (reading.images.size() > 1) base.append("_").append(im.name.empty() ? std::to_string(k) : im.name);
    base.append("_").append(time_label(picture_time));
    try {
      physics::save_rgb_png(std::filesystem::path(dir_) / (base + ".png"), w, h, im.rgb);
      files_.push_back(base + ".png");
      if (!im.depth.empty()) {
        physics::save_rgb_png(std::filesystem::path(dir_) / (base + "_depth.png"), w, h,
                              depth_picture(im, spec.point_cloud_cutoff, spec.point_cloud_cutoff_max));
        files_.push_back(base + "_depth.png");
      }
    } catch (const std::exception& e) {
      warnings_.push_back(e.what());
    }
    // The sheet's tile: every step-th pixel.
    const int step = std::max(1, (w + kTileWidth - 1) / kTileWidth);
    Tile t;
    t.width = w / step;
    t.height = h / step;
    t.rgb.resize(static_cast<std::size_t>(t.width) * t.height * 3);
    for (int y = 0; y < t.height; ++y)
      for (int x = 0; x < t.width; ++x)
        for (int c = 0; c < 3; ++c)
          t.rgb[(static_cast<std::size_t>(y) * t.width + x) * 3 + c] =
              im.rgb[(static_cast<std::size_t>(y * step) * w + x * step) * 3 + c];
    if (row < rows_.size()) rows_[row].push_back(std::move(t));
  }
}

void CameraReport::write(ScenarioResult& result) {
  int width = 0, height = 0;
  constexpr int kGap = 4;
  for (const auto& row : rows_) {
    int w = 0, h = 0;
    for (const Tile& t : row) {
      w += t.width + kGap;
      h = std::max(h, t.height);
    }
    width = std::max(width, w);
    if (h > 0) height += h + kGap;
  }
  if (width > 0 && height > 0) {
    std::vector<std::uint8_t> sheet(static_cast<std::size_t>(width) * height * 3, 255);
    int y0 = 0;
    for (const auto& row : rows_) {
      int x0 = 0, h = 0;
      for (const Tile& t : row) {
        for (int y = 0; y < t.height; ++y)
          std::copy_n(&t.rgb[static_cast<std::size_t>(y) * t.width * 3], t.width * 3,
                      &sheet[(static_cast<std::size_t>(y0 + y) * width + x0) * 3]);
        x0 += t.width + kGap;
        h = std::max(h, t.height);
      }
      if (h > 0) y0 += h + kGap;
    }
    try {
      physics::save_rgb_png(std::filesystem::path(dir_) / "camera_sheet.png", width, height, sheet);
      files_.push_back("camera_sheet.png");
    } catch (const std::exception& e) {
      warnings_.push_back(e.what());
    }
  }
  result.files.insert(result.files.end(), files_.begin(), files_.end());
  result.warnings.insert(result.warnings.end(), warnings_.begin(), warnings_.end());
}

}  // namespace mechsim::sim
