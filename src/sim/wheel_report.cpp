#include "sim/wheel_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "sim/gnuplot.hpp"

namespace mechsim::sim {

namespace fs = std::filesystem;

WheelReport::WheelReport(const Simulation& sim, const Scenario& scenario, const std::string& dir)
    : scenario_(scenario), dir_(dir), active_(sim.physics().soil().has_value()) {
  for (const physics::WheelInfo& w : sim.physics().model().wheels()) links_.push_back(w.link);
  for (const Check& c : scenario.checks) {
    int wheel = -1;
    if (c.kind == Check::Kind::Slip && !c.wheel.empty()) {
      const auto it = std::find(links_.begin(), links_.end(), c.wheel);
      if (it == links_.end()) throw ScenarioError(scenario.file + ": checks: slip check: the robot has no wheel '" + c.wheel + "'");
      wheel = static_cast<int>(it - links_.begin());
    }
    check_wheel_.push_back(wheel);
  }
  windows_.resize(scenario.checks.size());
  figures_.resize(links_.size());
  record_every_ = std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::llround(1.0 / (scenario.record_rate * scenario.period))));
  if (!active_ || dir.empty()) return;
  csv_.open(fs::path(dir) / "wheels.csv");
  csv_ << "time";
  for (const std::string& l : links_)
    csv_ << "," << l << "_slip," << l << "_slip_angle_deg," << l << "_sinkage_mm," << l << "_normal_N," << l << "_traction_N,"
         << l << "_lateral_N," << l << "_torque_Nm," << l << "_rut_mm";
  csv_ << "\n";
}

void WheelReport::observe(const Simulation& sim) {
  if (!active_) return;
  const std::vector<physics::WheelSoilReading>& wheels = sim.physics().wheel_soil();
  const double t = sim.time();
  for (std::size_t k = 0; k < windows_.size(); ++k) {
    const Check& c = scenario_.checks[k];
    if (c.kind != Check::Kind::Slip || t < c.from - 1e-9 || t > c.to + 1e-9) continue;
    for (std::size_t i = 0; i < wheels.size(); ++i) {
      if (!wheels[i].contact || (check_wheel_[k] >= 0 && static_cast<std::size_t>(check_wheel_[k]) != i)) continue;
      windows_[k].sum += wheels[i].slip;
      ++windows_[k].samples;
    }
  }
  for (std::size_t i = 0; i < wheels.size() && i < figures_.size(); ++i) {
    if (!wheels[i].contact) continue;
    figures_[i].slip_sum += wheels[i].slip;
    figures_[i].traction_sum += wheels[i].traction;
    figures_[i].max_sinkage = std::max(figures_[i].max_sinkage, wheels[i].sinkage);
    figures_[i].sinkage_sum += wheels[i].sinkage;
    figures_[i].rut_sum += wheels[i].rut_depth;
    ++figures_[i].samples;
  }
  if (!csv_.is_open() || sim.ticks() % record_every_ != 0) return;
  char row[256];
  std::snprintf(row, sizeof row, "%.4f", t);
  csv_ << row;
  for (const physics::WheelSoilReading& w : wheels) {
    std::snprintf(row, sizeof row, ",%.5f,%.4f,%.4f,%.4f,%.4f,%.4f,%.5f,%.4f", w.slip, w.slip_angle * 180.0 / M_PI,
                  1000.0 * w.sinkage, w.normal_force, w.traction, w.lateral_force, w.torque, 1000.0 * w.rut_depth);
    csv_ << row;
  }
  csv_ << "\n";
}

CheckOutcome WheelReport::judge(const Check& c) const {
  CheckOutcome out;
  out.name = c.text;
  const std::size_t k = static_cast<std::size_t>(&c - scenario_.checks.data());
  const std::string which = c.wheel.empty() ? "every wheel" : c.wheel;
  char buf[512];
  if (!active_ || k >= windows_.size() || windows_[k].samples == 0) {
    std::snprintf(buf, sizeof buf, "mean slip of %s in [%.2f, %.3g] s: %s", which.c_str(), c.from, c.to,
                  active_ ? "no wheel was in the soil then" : "no soil (world.soil) in this scenario");
    out.detail = buf;
    return out;
  }
  const double mean = windows_[k].sum / static_cast<double>(windows_[k].samples);
  out.passed = (!c.min_mean || mean >= *c.min_mean) && (!c.max_mean || mean <= *c.max_mean);
  char lo[32] = "-", hi[32] = "-";
  if (c.min_mean) std::snprintf(lo, sizeof lo, "%.3g", *c.min_mean);
  if (c.max_mean) std::snprintf(hi, sizeof hi, "%.3g", *c.max_mean);
  std::snprintf(buf, sizeof buf, "mean slip of %s in [%.2f, %.3g] s: %.4f (bounds [%s, %s])", which.c_str(), c.from, c.to, mean, lo, hi);
  out.detail = buf;
  return out;
}

void WheelReport::write(ScenarioResult& result, bool plots) {
  if (!active_) return;
  for (std::size_t i = 0; i < figures_.size(); ++i) {
    WheelOutcome w;
    w.link = links_[i];
    const double n = static_cast<double>(std::max(1L, figures_[i].samples));
    w.mean_slip = figures_[i].slip_sum / n;
    w.mean_traction = figures_[i].traction_sum / n;
    w.max_sinkage = figures_[i].max_sinkage;
    w.mean_sinkage = figures_[i].sinkage_sum / n;
    w.mean_rut_depth = figures_[i].rut_sum / n;
    w.time_in_soil = static_cast<double>(figures_[i].samples) * scenario_.period;
    result.wheels.push_back(w);
  }
  if (!csv_.is_open()) return;
  csv_.close();
  result.files.push_back("wheels.csv");
  if (!plots) return;
  const fs::path dir = dir_;
  const std::string csv = quoted((dir / "wheels.csv").string());
  std::ostringstream gp;
  gp << "set terminal pngcairo size 1100,1000 font 'DejaVu Sans,10'\nset output " << quoted((dir / "wheels.png").string())
     << "\nset datafile separator ','\nset grid\nset key outside right top\nset xlabel 'time (s)'\n"
     << "set multiplot layout 3,1 title " << quoted(scenario_.name + ": wheels in " + scenario_.world.soil->name) << " noenhanced\n";
  const auto panel = [&](const char* label, int column) {
    gp << "set ylabel " << quoted(label) << "\nplot ";
    for (std::size_t i = 0; i < links_.size(); ++i) {
      gp << (i ? ", " : "") << csv << " using 1:" << 2 + 8 * static_cast<int>(i) + column << " with lines title "
         << quoted(links_[i]) << " noenhanced";
    }
    gp << "\n";
  };
  panel("slip", 0);
  panel("sinkage (mm)", 2);
  panel("traction (N)", 4);
  gp << "unset multiplot\n";
  if (const std::string err = run_gnuplot(dir, "wheels", gp.str()); !err.empty()) {
    result.warnings.push_back(err);
  } else {
    result.files.push_back("wheels.png");
  }
}

}  // namespace mechsim::sim
