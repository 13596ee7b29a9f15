#include "batch/sweep_plots.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include "batch/point_result.hpp"
#include "sim/gnuplot.hpp"

namespace mechsim::batch {
namespace {

namespace fs = std::filesystem;
using sim::quoted;

// An axis's values as numbers: the value itself, or its position among the distinct values when
// any is not a number.
struct NumericAxis {
  std::vector<double> x;             // per point
  std::vector<std::string> labels;   // distinct values, when categorical
  bool discrete = false;
  double step = 1.0;                 // smallest gap between distinct values (discrete)
};

NumericAxis numeric_axis(const Plan& plan, std::size_t a) {
  NumericAxis out;
  out.discrete = plan.axes[a].kind == "list" || plan.axes[a].kind == "grid";
  bool numbers = true;
  for (const Point& p : plan.points) {
    char* end = nullptr;
    const std::string& v = p.values[a];
    const double x = std::strtod(v.c_str(), &end);
    numbers = numbers && end != v.c_str() && *end == '\0' && std::isfinite(x);
    out.x.push_back(x);
  }
  if (!numbers) {
    for (std::size_t i = 0; i < plan.points.size(); ++i) {
      const std::string& v = plan.points[i].values[a];
      auto it = std::find(out.labels.begin(), out.labels.end(), v);
      if (it == out.labels.end()) it = out.labels.insert(out.labels.end(), v);
      out.x[i] = static_cast<double>(it - out.labels.begin());
    }
  }
  std::vector<double> distinct = out.x;
  std::sort(distinct.begin(), distinct.end());
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  out.step = 1.0;
  for (std::size_t i = 1; i < distinct.size(); ++i) {
    out.step = i == 1 ? distinct[1] - distinct[0] : std::min(out.step, distinct[i] - distinct[i - 1]);
  }
  if (distinct.size() < 2) out.step = 1.0;
  return out;
}

std::string xtics(const NumericAxis& a, const char* which) {
  if (a.labels.empty()) return "";
  std::string s = std::string("set ") + which + "tics (";
  for (std::size_t i = 0; i < a.labels.size(); ++i) s += (i ? ", " : "") + quoted(a.labels[i]) + " " + std::to_string(i);
  return s + ")\n";
}

std::string gp_number(double v) { return std::isfinite(v) ? table_number(v) : "NaN"; }

// A repeatable spread in [-0.5, 0.5) from the point's index (no random state).
double spread(std::size_t index, std::uint64_t salt) {
  std::uint64_t x = index * 0x9e3779b97f4a7c15ULL + salt;
  x = (x ^ (x >> 31)) * 0xbf58476d1ce4e5b9ULL;
  x ^= x >> 29;
  return static_cast<double>(x >> 11) * 0x1.0p-53 - 0.5;
}

}  // namespace

std::vector<std::string> write_plots(const fs::path& dir, const Plan& plan, std::vector<std::string>& errors) {
  std::vector<std::string> written;
  if (plan.points.empty() || plan.axes.empty()) return written;
  const fs::path plots = dir / "plots";
  fs::create_directories(plots);
  std::vector<NumericAxis> axes;
  for (std::size_t a = 0; a < plan.axes.size(); ++a) axes.push_back(numeric_axis(plan, a));
  const auto axis_index = [&](const std::string& path) {
    for (std::size_t a = 0; a < plan.axes.size(); ++a) {
      if (plan.axes[a].path == path) return a;
    }
    return std::size_t{0};
  };
  const std::size_t mx = axis_index(plan.maps.empty() ? plan.axes[0].path : plan.maps[0]);
  const bool two = plan.maps.size() == 2;
  const std::size_t my = two ? axis_index(plan.maps[1]) : 0;

  // points.dat: index, outcome (0 passed, 1 failed a check, 2 did not finish, 3 missing), the
  // axes, the metrics, then the pass/fail map's spread coordinates.
  const fs::path data = plots / "points.dat";
  std::size_t passed = 0, finished = 0;
  {
    std::ofstream out(data);
    for (const Point& p : plan.points) {
      const auto r = read_point_result(point_dir(dir, p.index));
      const int outcome = !r ? 3 : r->status == PointStatus::Passed ? 0 : r->status == PointStatus::Failed ? 1 : 2;
      passed += outcome == 0 ? 1 : 0;
      finished += outcome != 3 ? 1 : 0;
      out << p.index << ' ' << outcome;
      for (const NumericAxis& a : axes) out << ' ' << gp_number(a.x[p.index]);
      for (const std::string& m : plan.metrics) {
        double v = NAN;
        if (r) {
          if (auto it = r->metrics.find(m); it != r->metrics.end()) v = it->second;
        }
        out << ' ' << gp_number(v);
      }
      const auto jitter = [&](const NumericAxis& a, std::uint64_t salt) {
        return a.x[p.index] + (a.discrete ? 0.6 * a.step * spread(p.index, salt) : 0.0);
      };
      out << ' ' << gp_number(jitter(axes[mx], 1)) << ' '
          << gp_number(two ? jitter(axes[my], 2) : static_cast<double>(p.index)) << '\n';
    }
  }
  const std::size_t first_metric = 3 + plan.axes.size();  // gnuplot column of the first metric
  const std::size_t jx = first_metric + plan.metrics.size();
  const std::string head = "set terminal pngcairo size ";
  const auto run = [&](const std::string& name, const std::string& script) {
    const std::string err = sim::run_gnuplot(plots, name, script);
    if (err.empty()) written.push_back("plots/" + name + ".png");
    else errors.push_back(err);
  };

  // The metric against each axis.
  const std::size_t n = plan.axes.size();
  const std::size_t cols = std::min<std::size_t>(n, 3), rows = (n + cols - 1) / cols;
  for (std::size_t m = 0; m < plan.metrics.size(); ++m) {
    std::ostringstream gp;
    gp << head << 480 * cols << "," << 360 * rows + 40 << " font 'DejaVu Sans,9' noenhanced\nset output "
       << quoted((plots / (plan.metrics[m] + ".png")).string()) << "\nset grid\nset key off\n"
       << "set multiplot layout " << rows << "," << cols << " title " << quoted(plan.name + ": " + plan.metrics[m] + " (green passed, red not)") << "\n";
    for (std::size_t a = 0; a < n; ++a) {
      gp << "unset xtics\nset xtics\n" << xtics(axes[a], "x") << "set xlabel " << quoted(plan.axes[a].path) << "\nset ylabel "
         << quoted(plan.metrics[m]) << "\nplot " << quoted(data.string()) << " using " << 3 + a << ":($2==0?$" << first_metric + m
         << ":NaN) with points pt 7 ps 0.8 lc rgb '#2ca02c', '' using " << 3 + a << ":($2!=0?$" << first_metric + m
         << ":NaN) with points pt 7 ps 0.8 lc rgb '#d62728'\n";
    }
    gp << "unset multiplot\n";
    run(plan.metrics[m], gp.str());
  }

  if (two && !plan.metrics.empty()) {
    // The first metric over the two map axes.
    const std::string metric = plan.metrics[0];
    std::ostringstream gp;
    const bool grid = axes[mx].discrete && axes[my].discrete;
    gp << head << "900,700 font 'DejaVu Sans,10' noenhanced\nset output " << quoted((plots / ("heatmap_" + metric + ".png")).string())
       << "\nset title " << quoted(plan.name + ": " + metric + " (mean of the points at each pair of values)")
       << "\nset xlabel " << quoted(plan.maps[0]) << "\nset ylabel " << quoted(plan.maps[1]) << "\nset cblabel " << quoted(metric)
       << "\nset palette rgb 33,13,10\n";
    // The mean per pair of values: other axes (and common random draws) put several points on one.
    std::map<std::pair<double, double>, std::pair<double, int>> cells;
    for (const Point& p : plan.points) {
      const auto r = read_point_result(point_dir(dir, p.index));
      if (!r) continue;
      const auto it = r->metrics.find(metric);
      if (it == r->metrics.end()) continue;
      auto& cell = cells[{axes[mx].x[p.index], axes[my].x[p.index]}];
      cell.first += it->second;
      ++cell.second;
    }
    std::vector<double> xs, ys;
    for (const auto& [key, cell] : cells) xs.push_back(key.first), ys.push_back(key.second);
    std::sort(xs.begin(), xs.end());
    xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
    std::sort(ys.begin(), ys.end());
    ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
    const fs::path mean_file = plots / "heatmap.dat";
    std::ofstream out(mean_file);
    if (grid) {
      // Cells by position (the values as tic labels): even cells whatever the spacing.
      for (std::size_t j = 0; j < ys.size(); ++j) {
        for (std::size_t i = 0; i < xs.size(); ++i) {
          const auto it = cells.find({xs[i], ys[j]});
          out << i << ' ' << j << ' ' << gp_number(it == cells.end() ? NAN : it->second.first / it->second.second) << '\n';
        }
        out << '\n';
      }
      const auto tics = [&](const char* which, const NumericAxis& a, const std::vector<double>& values) {
        gp << "set " << which << "tics (";
        for (std::size_t i = 0; i < values.size(); ++i) {
          gp << (i ? ", " : "") << quoted(a.labels.empty() ? table_number(values[i]) : a.labels[static_cast<std::size_t>(values[i])]) << " " << i;
        }
        gp << ")\n";
      };
      tics("x", axes[mx], xs);
      tics("y", axes[my], ys);
      gp << "set xrange [-0.5:" << static_cast<double>(xs.size()) - 0.5 << "]\nset yrange [-0.5:" << static_cast<double>(ys.size()) - 0.5
         << "]\nplot " << quoted(mean_file.string()) << " using 1:2:3 with image notitle\n";
    } else {
      for (const auto& [key, cell] : cells) {
        out << gp_number(key.first) << ' ' << gp_number(key.second) << ' ' << gp_number(cell.first / cell.second) << '\n';
      }
      gp << xtics(axes[mx], "x") << xtics(axes[my], "y") << "plot " << quoted(mean_file.string())
         << " using 1:2:3 with points pt 5 ps 2.2 lc palette z notitle\n";
    }
    out.close();
    run("heatmap_" + metric, gp.str());
  }

  std::ostringstream gp;
  gp << head << "900,700 font 'DejaVu Sans,10' noenhanced\nset output " << quoted((plots / "pass_fail.png").string()) << "\nset title "
     << quoted(plan.name + ": " + std::to_string(passed) + " of " + std::to_string(finished) + " points passed") << "\nset xlabel "
     << quoted(plan.maps.empty() ? plan.axes[0].path : plan.maps[0]) << "\nset ylabel " << quoted(two ? plan.maps[1] : "point")
     << "\nset grid\nset key outside right top\n" << xtics(axes[mx], "x") << (two ? xtics(axes[my], "y") : "") << "plot "
     << quoted(data.string()) << " using " << jx << ":($2==0?$" << jx + 1 << ":NaN) with points pt 7 ps 1.1 lc rgb '#2ca02c' title 'passed', '' using "
     << jx << ":($2==1?$" << jx + 1 << ":NaN) with points pt 9 ps 1.3 lc rgb '#ff7f0e' title 'failed a check', '' using " << jx
     << ":($2==2?$" << jx + 1 << ":NaN) with points pt 2 ps 1.4 lw 2 lc rgb '#d62728' title 'did not finish'\n";
  run("pass_fail", gp.str());
  return written;
}

}  // namespace mechsim::batch
