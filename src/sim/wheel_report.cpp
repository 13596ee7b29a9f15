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
  wheels_ = sim.physics().soil_wheels();
  if (active_) {
    not_wheels_ = sim.physics().model().not_wheels();
    for (const std::string& note : sim.physics().soil_wheel_notes()) not_wheels_.push_back(note);
  }
  const auto index = [&](const std::string& link) {
    const auto it = std::find_if(wheels_.begin(), wheels_.end(), [&](const physics::SoilWheelInfo& w) { return w.link == link; });
    return it == wheels_.end() ? -1 : static_cast<int>(it - wheels_.begin());
  };
  for (const Check& c : scenario.checks) {
    int wheel = -1;
    if (c.kind == Check::Kind::Slip && !c.wheel.empty()) {
      wheel = index(c.wheel);
      if (wheel < 0 && active_)
        throw ScenarioError(scenario.file + ": checks: slip check: '" + c.wheel + "' is not a soil wheel of the robot");
    }
    check_wheel_.push_back(wheel);
  }
  if (scenario.steady_states && active_) {
    steady_wheel_ = scenario.steady_states->wheel.empty() ? (wheels_.empty() ? -1 : 0) : index(scenario.steady_states->wheel);
    if (steady_wheel_ < 0)
      throw ScenarioError(scenario.file + ": steady_states: " +
                          (scenario.steady_states->wheel.empty() ? std::string("the robot has no soil wheel")
                                                                 : "'" + scenario.steady_states->wheel + "' is not a soil wheel of the robot"));
    steady_.resize(scenario.steady_states->windows.size());
  }
  windows_.resize(scenario.checks.size());
  figures_.resize(wheels_.size());
  record_every_ = std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::llround(1.0 / (scenario.record_rate * scenario.period))));
  if (!active_ || dir.empty()) return;
  csv_.open(fs::path(dir) / "wheels.csv");
  csv_ << "time";
  for (const physics::SoilWheelInfo& w : wheels_) {
    const std::string& l = w.link;
    csv_ << "," << l << "_slip," << l << "_slip_angle_deg," << l << "_sinkage_mm," << l << "_normal_N," << l << "_traction_N,"
         << l << "_lateral_N," << l << "_torque_Nm," << l << "_rut_mm";
  }
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
      if (!wheels[i].contact || !wheels[i].moving || (check_wheel_[k] >= 0 && static_cast<std::size_t>(check_wheel_[k]) != i)) continue;
      windows_[k].sum += wheels[i].slip;
      ++windows_[k].samples;
    }
  }
  for (std::size_t i = 0; i < wheels.size() && i < figures_.size(); ++i) {
    if (!wheels[i].contact) continue;
    if (wheels[i].moving) {
      figures_[i].slip_sum += wheels[i].slip;
      ++figures_[i].moving;
    }
    figures_[i].traction_sum += wheels[i].traction;
    figures_[i].max_sinkage = std::max(figures_[i].max_sinkage, wheels[i].sinkage);
    figures_[i].sinkage_sum += wheels[i].sinkage;
    figures_[i].rut_sum += wheels[i].rut_depth;
    ++figures_[i].samples;
  }
  if (steady_wheel_ >= 0 && static_cast<std::size_t>(steady_wheel_) < wheels.size()) {
    const physics::WheelSoilReading& w = wheels[static_cast<std::size_t>(steady_wheel_)];
    for (std::size_t k = 0; k < steady_.size(); ++k) {
      const auto& window = scenario_.steady_states->windows[k];
      if (!w.contact || t < window[0] - 1e-9 || t > window[1] + 1e-9) continue;
      Steady& s = steady_[k];
      if (w.moving) s.slip += w.slip, ++s.moving;
      s.drawbar += w.traction;
      s.load += w.normal_force;
      s.torque += w.torque;
      s.sinkage += w.sinkage;
      ++s.samples;
    }
  }
  if (!csv_.is_open() || sim.ticks() % record_every_ != 0) return;
  char row[256];
  std::snprintf(row, sizeof row, "%.4f", t);
  csv_ << row;
  for (const physics::WheelSoilReading& w : wheels) {
    // Slip and slip angle are undefined at rest: blank, not 0.
    char slip[32] = "", angle[32] = "";
    if (w.moving) std::snprintf(slip, sizeof slip, "%.5f", w.slip);
    if (w.sliding) std::snprintf(angle, sizeof angle, "%.4f", w.slip_angle * 180.0 / M_PI);
    std::snprintf(row, sizeof row, ",%s,%s,%.4f,%.4f,%.4f,%.4f,%.5f,%.4f", slip, angle, 1000.0 * w.sinkage, w.normal_force,
                  w.traction, w.lateral_force, w.torque, 1000.0 * w.rut_depth);
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
                  active_ ? "no wheel was in the soil and moving then" : "no soil (world.soil) in this scenario");
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
  result.not_wheels = not_wheels_;
  for (std::size_t i = 0; i < figures_.size(); ++i) {
    WheelOutcome w;
    const physics::SoilWheelInfo& info = wheels_[i];
    w.link = info.link;
    w.radius = info.shape.radius;
    w.width = info.shape.width;
    w.narrow = info.narrow;
    w.grouser_height = info.shape.grouser_height;
    w.grouser_count = info.shape.grouser_count;
    w.origin = info.origin;
    const double n = static_cast<double>(std::max(1L, figures_[i].samples));
    w.mean_slip = figures_[i].slip_sum / static_cast<double>(std::max(1L, figures_[i].moving));
    w.mean_traction = figures_[i].traction_sum / n;
    w.max_sinkage = figures_[i].max_sinkage;
    w.mean_sinkage = figures_[i].sinkage_sum / n;
    w.mean_rut_depth = figures_[i].rut_sum / n;
    w.time_in_soil = static_cast<double>(figures_[i].samples) * scenario_.period;
    result.wheels.push_back(w);
  }
  write_steady_states(result, plots);
  if (!csv_.is_open()) return;
  csv_.close();
  result.files.push_back("wheels.csv");
  if (!plots) return;
  const fs::path dir = dir_;
  const std::string csv = quoted((dir / "wheels.csv").string());
  std::ostringstream gp;
  gp << "set terminal pngcairo size 1100,1000 font 'DejaVu Sans,10'\nset output " << quoted((dir / "wheels.png").string())
     << "\nset datafile separator ','\nset datafile missing ''\nset grid\nset key outside right top\nset xlabel 'time (s)'\n"
     << "set multiplot layout 3,1 title " << quoted(scenario_.name + ": wheels in " + scenario_.world.soil->name) << " noenhanced\n";
  const auto panel = [&](const char* label, int column) {
    gp << "set ylabel " << quoted(label) << "\nplot ";
    for (std::size_t i = 0; i < wheels_.size(); ++i) {
      gp << (i ? ", " : "") << csv << " using 1:" << 2 + 8 * static_cast<int>(i) + column << " with lines title "
         << quoted(wheels_[i].link) << " noenhanced";
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

void WheelReport::write_steady_states(ScenarioResult& result, bool plots) {
  if (steady_wheel_ < 0) return;
  const physics::SoilWheelInfo& wheel = wheels_[static_cast<std::size_t>(steady_wheel_)];
  result.steady_state_wheel = wheel.link;
  for (std::size_t k = 0; k < steady_.size(); ++k) {
    const Steady& s = steady_[k];
    SteadyStateRow row;
    row.from = scenario_.steady_states->windows[k][0];
    row.to = scenario_.steady_states->windows[k][1];
    row.samples = s.samples;
    if (s.samples > 0) {
      const double n = static_cast<double>(s.samples);
      row.slip = s.moving > 0 ? s.slip / static_cast<double>(s.moving) : std::nan("");
      row.drawbar = s.drawbar / n;
      row.load = s.load / n;
      row.torque = s.torque / n;
      row.sinkage = s.sinkage / n;
    }
    result.steady_states.push_back(row);
  }
  if (dir_.empty()) return;
  const fs::path dir = dir_;
  {
    std::ofstream csv(dir / "steady_states.csv");
    csv << "from_s,to_s,slip,drawbar_N,load_N,dp_per_w,torque_Nm,torque_per_wr,sinkage_mm,samples\n";
    char line[256];
    for (const SteadyStateRow& r : result.steady_states) {
      if (r.samples == 0) continue;
      const double w = r.load > 0.0 ? r.load : std::nan("");
      std::snprintf(line, sizeof line, "%.3f,%.3f,%.5f,%.5f,%.4f,%.5f,%.6f,%.5f,%.4f,%ld\n", r.from, r.to, r.slip, r.drawbar, r.load,
                    r.drawbar / w, r.torque, -r.torque / (w * wheel.shape.radius), 1000.0 * r.sinkage, r.samples);
      csv << line;
    }
  }
  result.files.push_back("steady_states.csv");
  if (!plots) return;
  const std::string csv = quoted((dir / "steady_states.csv").string());
  char title[512];
  std::snprintf(title, sizeof title, "%s: %s (r %.3g m, b %.3g m) in %s (%s), steady states", scenario_.name.c_str(), wheel.link.c_str(),
                wheel.shape.radius, wheel.shape.width, scenario_.world.soil->name.c_str(), physics::model_name(scenario_.world.soil->model));
  std::ostringstream gp;
  gp << "set terminal pngcairo size 900,1000 font 'DejaVu Sans,10'\nset output " << quoted((dir / "steady_states.png").string())
     << "\nset datafile separator ','\nset grid\nunset key\nset xlabel 'slip'\nset xrange [*:*]\n"
     << "set multiplot layout 3,1 title " << quoted(title) << " noenhanced\n"
     << "set ylabel 'drawbar pull / load, DP/W'\nplot 0 with lines lc rgb 'gray', " << csv
     << " using 3:6 every ::1 with linespoints pt 7 lw 2\n"
     << "set ylabel 'torque / (W r)'\nplot " << csv << " using 3:8 every ::1 with linespoints pt 7 lw 2\n"
     << "set ylabel 'sinkage (mm)'\nplot " << csv << " using 3:9 every ::1 with linespoints pt 7 lw 2\n"
     << "unset multiplot\n";
  if (const std::string err = run_gnuplot(dir, "steady_states", gp.str()); !err.empty()) {
    result.warnings.push_back(err);
  } else {
    result.files.push_back("steady_states.png");
  }
}

}  // namespace mechsim::sim
