#include "sim/soil_fit_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "control/params.hpp"
#include "sim/gnuplot.hpp"
#include "sim/scenario.hpp"
#include "sim/soil_config.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;
using control::Params;

[[noreturn]] void fail(const Params& at, const std::string& what) {
  const std::string where = at.location().empty() ? at.path() : at.location() + ": " + at.path();
  throw ScenarioError(where + ": " + what);
}

void only(const Params& node, std::initializer_list<const char*> keys) {
  for (const std::string& k : node.keys()) {
    bool known = false;
    std::string list;
    for (const char* key : keys) known = known || k == key, list += (list.empty() ? "" : ", ") + std::string(key);
    if (!known) fail(node.child(k), "unknown key '" + k + "' (expected one of: " + list + ")");
  }
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  for (char c : line) {
    if (c == '\t' || c == ',' || c == ' ' || c == '\r') {
      if (!cell.empty()) out.push_back(cell);
      cell.clear();
    } else {
      cell += c;
    }
  }
  if (!cell.empty()) out.push_back(cell);
  return out;
}

// The named columns of a test file, as numbers. Throws ScenarioError naming the file and line.
std::vector<std::vector<double>> read_columns(const fs::path& path, const std::vector<std::string>& names) {
  std::ifstream in(path);
  if (!in) throw ScenarioError("test file '" + path.string() + "' cannot be read");
  std::vector<int> index;
  std::vector<std::vector<double>> out(names.size());
  int line_no = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_no;
    const std::string where = path.string() + ":" + std::to_string(line_no);
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    const std::vector<std::string> cells = split(line);
    if (index.empty()) {
      for (const std::string& name : names) {
        const auto it = std::find(cells.begin(), cells.end(), name);
        if (it == cells.end()) throw ScenarioError(where + ": no column '" + name + "' (columns: " + line + ")");
        index.push_back(static_cast<int>(it - cells.begin()));
      }
      continue;
    }
    for (std::size_t k = 0; k < names.size(); ++k) {
      const std::size_t col = static_cast<std::size_t>(index[k]);
      if (col >= cells.size()) throw ScenarioError(where + ": too few columns");
      char* end = nullptr;
      const double v = std::strtod(cells[col].c_str(), &end);
      if (end == cells[col].c_str() || *end != '\0' || !std::isfinite(v))
        throw ScenarioError(where + ": '" + cells[col] + "' in column '" + names[k] + "' is not a number");
      out[k].push_back(v);
    }
  }
  if (index.empty()) throw ScenarioError("test file '" + path.string() + "' has no column names");
  if (out.front().empty()) throw ScenarioError("test file '" + path.string() + "' has no samples");
  return out;
}

std::vector<fs::path> files_of(const Params& entry, const fs::path& base) {
  const Params files = entry.child("files");
  std::vector<std::string> names;
  try {
    names = files.is_list() ? files.as<std::vector<std::string>>() : std::vector<std::string>{files.as<std::string>()};
  } catch (const std::exception&) {
    fail(files, "expected a file or a list of files");
  }
  if (names.empty()) fail(files, "no files");
  std::vector<fs::path> out;
  for (const std::string& n : names) out.push_back(fs::path(n).is_absolute() ? fs::path(n) : base / n);
  return out;
}

double positive(const Params& node, const char* key) {
  const double v = node.get<double>(key);
  if (!std::isfinite(v) || !(v > 0.0)) fail(node.child(key), "must be > 0");
  return v;
}

std::string num(double v, const char* format = "%.4g") {
  char text[64];
  std::snprintf(text, sizeof text, format, v);
  return text;
}

}  // namespace

SoilFitSpec read_soil_fit_spec(const std::string& path) {
  if (!fs::exists(path)) throw ScenarioError(path + ": no such file");
  Params root;
  try {
    root = Params::from_yaml_file(path);
  } catch (const std::exception& e) {
    throw ScenarioError(e.what());
  }
  if (!root.is_map()) throw ScenarioError(path + ": expected a map (name, base, model, plates, ...)");
  const fs::path base = fs::absolute(path).parent_path();
  SoilFitSpec spec;
  spec.file = path;
  try {
    only(root, {"name", "base", "model", "method", "values", "plates", "plates_columns", "shear", "shear_columns"});
    spec.name = root.get<std::string>("name", fs::path(path).stem().string());
    spec.base = root.get<std::string>("base", spec.base);
    if (root.has("model")) {
      const auto model = physics::find_model(root.get<std::string>("model"));
      if (!model) fail(root.child("model"), "expected wong_reece or ding");
      spec.model = *model;
    }
    const std::string method = root.get<std::string>("method", "two_stage");
    if (method == "direct") spec.method = physics::PlateFitMethod::Direct;
    else if (method != "two_stage") fail(root.child("method"), "expected two_stage or direct");
    try {
      spec.start = soil_by_name(spec.base, base);
    } catch (const std::exception& e) {
      fail(root.child("base"), e.what());
    }
    if (auto values = root.find("values")) {
      spec.start = read_soil_over(*values, spec.start);
      spec.given = values->keys();
    }
    std::string z_col = "z_m", p_col = "pressure_Pa", f_col;
    if (auto cols = root.find("plates_columns")) {
      only(*cols, {"z", "p", "force"});
      z_col = cols->get<std::string>("z", z_col);
      if (cols->has("force")) f_col = cols->get<std::string>("force"), p_col.clear();
      if (cols->has("p")) p_col = cols->get<std::string>("p"), f_col.clear();
    }
    const Params plates = root.child("plates");
    if (!plates.is_list() || plates.size() == 0) fail(plates, "expected a list of plate sizes with their test files");
    for (const Params& entry : plates.items()) {
      only(entry, {"diameter", "width", "length", "files"});
      double b = 0.0, area = 0.0;
      if (entry.has("diameter") == entry.has("width")) fail(entry, "a plate is circular (diameter) or rectangular (width, length)");
      if (entry.has("diameter")) {
        const double d = positive(entry, "diameter");
        b = d / 2.0;
        area = M_PI * b * b;
      } else {
        b = positive(entry, "width");
        if (!f_col.empty() && !entry.has("length")) fail(entry, "a rectangular plate's length is needed to turn force into pressure");
        const double length = entry.has("length") ? positive(entry, "length") : b;
        if (length < b) fail(entry.child("length"), "the width is the smaller side (Bekker's b)");
        area = b * length;
      }
      for (const fs::path& file : files_of(entry, base)) {
        const std::vector<std::vector<double>> cols = read_columns(file, {z_col, f_col.empty() ? p_col : f_col});
        physics::PlateTest t;
        t.name = file.filename().string();
        t.b = b;
        t.z = cols[0];
        t.p = cols[1];
        if (!f_col.empty())
          for (double& p : t.p) p /= area;
        spec.plates.push_back(std::move(t));
      }
    }
    std::string j_col = "j_m", tau_col = "tau_Pa";
    if (auto cols = root.find("shear_columns")) {
      only(*cols, {"j", "tau"});
      j_col = cols->get<std::string>("j", j_col);
      tau_col = cols->get<std::string>("tau", tau_col);
    }
    if (auto shear = root.find("shear")) {
      if (!shear->is_list()) fail(*shear, "expected a list of normal pressures with their test files");
      for (const Params& entry : shear->items()) {
        only(entry, {"normal_pressure", "files"});
        const double sigma = entry.get<double>("normal_pressure");
        if (!std::isfinite(sigma) || sigma < 0.0) fail(entry.child("normal_pressure"), "must be >= 0 Pa");
        for (const fs::path& file : files_of(entry, base)) {
          const std::vector<std::vector<double>> cols = read_columns(file, {j_col, tau_col});
          spec.shear.push_back({file.filename().string(), sigma, cols[0], cols[1]});
        }
      }
    }
  } catch (const ScenarioError&) {
    throw;
  } catch (const std::exception& e) {
    throw ScenarioError(e.what());
  }
  return spec;
}

SoilFitOutcome run_soil_fit(const SoilFitSpec& spec, const std::string& out_dir, bool plots) {
  SoilFitOutcome out;
  out.plates = physics::fit_plates(spec.plates, spec.method);
  if (!spec.shear.empty()) out.shear = physics::fit_shear(spec.shear);
  physics::SoilParameters& soil = out.soil;
  soil = spec.start;
  soil.name = spec.name;
  soil.model = spec.model;
  soil.n = out.plates.n;
  soil.k_c = out.plates.k_c;
  soil.k_phi = out.plates.k_phi;
  if (out.shear) {
    soil.cohesion = out.shear->cohesion;
    soil.friction_angle = out.shear->friction_angle;
    soil.shear_modulus = out.shear->shear_modulus;
  }
  // What the tests did not give, and where it came from: `values`, the base, or the model's defaults.
  const auto given = [&](const char* key) { return std::find(spec.given.begin(), spec.given.end(), key) != spec.given.end(); };
  std::vector<std::string> from_values, from_base, from_defaults;
  const auto from = [&](const char* key, const char* what) { (given(key) ? from_values : from_base).push_back(what); };
  if (!out.shear) {
    from("cohesion", "cohesion");
    from("friction_angle_deg", "friction angle");
    from("shear_modulus", "shear modulus K");
  }
  from("c1", "c1");
  from("c2", "c2");
  from("bedrock_depth", "bedrock depth");
  if (soil.model == physics::WheelSoilModel::Ding)
    for (const char* key : {"rear_ratio", "n1", "n2"}) (given(key) ? from_values : from_defaults).push_back(key);
  const auto list = [](const std::vector<std::string>& v) {
    std::string text;
    for (const std::string& s : v) text += (text.empty() ? "" : ", ") + s;
    return text;
  };
  if (!from_values.empty()) out.not_from_tests.push_back(list(from_values) + " (given: values)");
  if (!from_base.empty()) out.not_from_tests.push_back(list(from_base) + " (from " + spec.start.name + ")");
  if (!from_defaults.empty()) out.not_from_tests.push_back(list(from_defaults) + " (the model's defaults)");
  std::ostringstream source;
  source << (spec.method == physics::PlateFitMethod::TwoStage ? "two-stage" : "direct") << " plate fit of " << spec.plates.size()
         << " tests, " << out.plates.sizes.size() << " plate sizes (" << fs::path(spec.file).filename().string()
         << ", mechsim soil fit): n, k_c, k_phi, rms " << num(out.plates.rms, "%.0f") << " Pa";
  if (out.shear) source << "; shear fit of " << spec.shear.size() << " tests: c, phi, K";
  for (const std::string& n : out.not_from_tests) source << "; " << n;
  soil.source = source.str();
  if (const std::string problem = physics::check_soil(soil); !problem.empty())
    throw std::invalid_argument("the fitted soil '" + soil.name + "': " + problem);

  const physics::PlateFit& f = out.plates;
  std::ostringstream s;
  s << "soil '" << soil.name << "' (" << physics::model_name(soil.model) << " model)\n";
  s << "plate tests: " << spec.plates.size() << " (" << f.samples << " samples), " << f.sizes.size() << " plate sizes, "
    << (spec.method == physics::PlateFitMethod::TwoStage ? "two_stage" : "direct") << " fit of p = (k_c / b + k_phi) z^n\n";
  s << "  n      " << num(f.n, "%.4f") << "\n  k_c    " << num(f.k_c, "%.4e") << " N/m^(n+1)\n  k_phi  " << num(f.k_phi, "%.4e")
    << " N/m^(n+2)\n";
  for (const physics::PlateFit::Size& size : f.sizes)
    s << "  b " << num(size.b, "%.4f") << " m (" << size.tests << " tests): K = " << num(size.K, "%.4e") << " N/m^(n+2), k_c / b + k_phi = "
      << num(f.k_c / size.b + f.k_phi, "%.4e") << "\n";
  if (spec.method == physics::PlateFitMethod::TwoStage)
    s << "  first stage (one K per size) rms " << num(f.stage_rms, "%.0f") << " Pa; the sizes' K off the line by " << num(f.line_rms, "%.3e")
      << " rms\n";
  s << "  residual rms " << num(f.rms, "%.0f") << " Pa, R^2 " << num(f.r2, "%.4f") << "\n";
  if (f.k_c < 0.0)
    s << "  k_c < 0: the pressure grows with the plate's size; the soil carries wheels wider than " << num(-f.k_c / f.k_phi, "%.4f")
      << " m only\n";
  if (out.shear) {
    const physics::ShearFit& sh = *out.shear;
    s << "shear tests: " << spec.shear.size() << " (" << sh.samples << " samples): c " << num(sh.cohesion, "%.1f") << " Pa, phi "
      << num(sh.friction_angle * 180.0 / M_PI, "%.2f") << " deg, K " << num(sh.shear_modulus * 1000.0, "%.3f") << " mm, rms "
      << num(sh.rms, "%.1f") << " Pa\n";
  }
  s << "not from these tests:";
  for (std::size_t i = 0; i < out.not_from_tests.size(); ++i) s << (i ? ";" : "") << " " << out.not_from_tests[i];
  s << "\n  cohesion " << num(soil.cohesion, "%.1f") << " Pa, friction angle " << num(soil.friction_angle * 180.0 / M_PI, "%.2f")
    << " deg, K " << num(soil.shear_modulus, "%.4g") << " m";
  if (soil.model == physics::WheelSoilModel::Ding) s << ", rear_ratio " << num(soil.rear_ratio) << ", n1 " << num(soil.n1) << ", n2 " << num(soil.n2);
  s << "\n";
  out.summary = s.str();
  if (out_dir.empty()) return out;

  const fs::path dir = out_dir;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw std::runtime_error("cannot create '" + dir.string() + "': " + ec.message());
  const std::string soil_file = spec.name + ".soil.yaml";
  {
    std::ofstream yaml(dir / soil_file);
    yaml << soil_yaml(soil, "soil fitted by mechsim soil fit from " + fs::path(spec.file).filename().string() + "\n" + out.summary);
    if (!yaml) throw std::runtime_error("cannot write '" + (dir / soil_file).string() + "'");
  }
  out.files.push_back(soil_file);
  {
    std::ofstream tsv(dir / "plate_fit.tsv");
    tsv << "# plate fit residuals: p_model = (k_c / b + k_phi) z^n with n " << num(f.n, "%.6g") << ", k_c " << num(f.k_c, "%.6g")
        << ", k_phi " << num(f.k_phi, "%.6g") << "\ntest\tb_m\tz_m\tp_Pa\tp_model_Pa\tresidual_Pa\n";
    for (const physics::PlateTest& t : spec.plates)
      for (std::size_t i = 0; i < t.z.size(); ++i) {
        const double model = physics::plate_pressure(f, t.b, t.z[i]);
        tsv << t.name << "\t" << num(t.b, "%.6g") << "\t" << num(t.z[i], "%.6g") << "\t" << num(t.p[i], "%.6g") << "\t" << num(model, "%.6g")
            << "\t" << num(t.p[i] - model, "%.6g") << "\n";
      }
  }
  out.files.push_back("plate_fit.tsv");
  if (out.shear) {
    std::ofstream tsv(dir / "shear_fit.tsv");
    const physics::ShearFit& sh = *out.shear;
    tsv << "test\tnormal_pressure_Pa\tj_m\ttau_Pa\ttau_model_Pa\tresidual_Pa\n";
    for (const physics::ShearTest& t : spec.shear)
      for (std::size_t i = 0; i < t.j.size(); ++i) {
        const double model = (sh.cohesion + t.normal_pressure * std::tan(sh.friction_angle)) *
                             (1.0 - std::exp(-std::max(0.0, t.j[i]) / sh.shear_modulus));
        tsv << t.name << "\t" << num(t.normal_pressure, "%.6g") << "\t" << num(t.j[i], "%.6g") << "\t" << num(t.tau[i], "%.6g") << "\t"
            << num(model, "%.6g") << "\t" << num(t.tau[i] - model, "%.6g") << "\n";
      }
    out.files.push_back("shear_fit.tsv");
  }
  if (!plots) return out;

  // plate_fit.png: pressure against sinkage per plate size with the fitted curves; the residuals;
  // the sizes' K against 1 / b with the line (two_stage) or the constants' (direct).
  const std::string data = quoted((dir / "plate_fit.tsv").string());
  std::ostringstream gp;
  gp << "set terminal pngcairo size 1000,1150 font 'DejaVu Sans,10'\nset output " << quoted((dir / "plate_fit.png").string())
     << "\nset datafile separator '\\t'\nset grid\nset key top left\n"
     << "set multiplot layout 3,1 title " << quoted("soil fit '" + soil.name + "': " + std::to_string(spec.plates.size()) + " plate tests") << " noenhanced\n";
  gp << "n = " << num(f.n, "%.8g") << "; kc = " << num(f.k_c, "%.8g") << "; kphi = " << num(f.k_phi, "%.8g") << "\n";
  gp << "set xlabel 'sinkage z (mm)'\nset ylabel 'pressure p (kPa)'\nset samples 400\nplot ";
  for (std::size_t k = 0; k < f.sizes.size(); ++k) {
    const double b = f.sizes[k].b;
    double z_max = 0.0;  // the fitted curve over the size's own data
    for (const physics::PlateTest& t : spec.plates)
      if (std::abs(t.b - b) <= 1e-6 * b)
        for (double z : t.z) z_max = std::max(z_max, z);
    const std::string label = "b " + num(b * 1000.0, "%.0f") + " mm";
    gp << (k ? ", " : "") << data << " using ($2 > " << num(b * 0.999999, "%.9g") << " && $2 < " << num(b * 1.000001, "%.9g")
       << " ? 1000 * $3 : 1/0):($4 / 1000) every ::1 with points pt 7 ps 0.3 lc " << k + 1 << " title " << quoted(label + " tests")
       << ", (x <= " << num(1000.0 * z_max, "%.6g") << " ? (kc / " << num(b, "%.9g") << " + kphi) * (x / 1000) ** n / 1000 : 1/0) with lines lw 2 lc "
       << k + 1 << " title "
       << quoted(label + " fit");
  }
  gp << "\nset ylabel 'residual (kPa)'\nplot 0 with lines lc rgb 'gray' notitle";
  for (std::size_t k = 0; k < f.sizes.size(); ++k) {
    const double b = f.sizes[k].b;
    gp << ", " << data << " using ($2 > " << num(b * 0.999999, "%.9g") << " && $2 < " << num(b * 1.000001, "%.9g")
       << " ? 1000 * $3 : 1/0):($6 / 1000) every ::1 with points pt 7 ps 0.3 lc " << k + 1 << " title "
       << quoted("b " + num(b * 1000.0, "%.0f") + " mm");
  }
  gp << "\nset xlabel '1 / b (1/m)'\nset ylabel 'K = k_c / b + k_{phi} (MN/m^{n+2})'\nset key top right\n";
  gp << "$sizes << EOD\n";
  for (const physics::PlateFit::Size& size : f.sizes) gp << num(1.0 / size.b, "%.8g") << " " << num(size.K / 1e6, "%.8g") << "\n";
  gp << "EOD\nset xrange [0:*]\nset datafile separator whitespace\nplot $sizes using 1:2 with points pt 7 ps 1.5 title "
     << quoted(spec.method == physics::PlateFitMethod::TwoStage ? "each size's K (common n)" : "each size's K")
     << ", (kc * x + kphi) / 1e6 with lines lw 2 title 'k_c / b + k_{phi}'\nunset multiplot\n";
  if (const std::string err = run_gnuplot(dir, "plate_fit", gp.str()); !err.empty()) out.warnings.push_back(err);
  else out.files.push_back("plate_fit.png");
  if (out.shear) {
    const physics::ShearFit& sh = *out.shear;
    const std::string shear_data = quoted((dir / "shear_fit.tsv").string());
    std::ostringstream g2;
    g2 << "set terminal pngcairo size 900,600 font 'DejaVu Sans,10'\nset output " << quoted((dir / "shear_fit.png").string())
       << "\nset datafile separator '\\t'\nset grid\nset key bottom right\nset xlabel 'shear displacement j (mm)'\n"
       << "set ylabel 'shear stress (kPa)'\nset title " << quoted("shear fit: c " + num(sh.cohesion, "%.0f") + " Pa, phi " +
                                                                   num(sh.friction_angle * 180.0 / M_PI, "%.1f") + " deg, K " +
                                                                   num(sh.shear_modulus * 1000.0, "%.2f") + " mm") << " noenhanced\nplot ";
    std::vector<double> sigmas;
    for (const physics::ShearTest& t : spec.shear)
      if (std::find(sigmas.begin(), sigmas.end(), t.normal_pressure) == sigmas.end()) sigmas.push_back(t.normal_pressure);
    for (std::size_t k = 0; k < sigmas.size(); ++k) {
      const double sg = sigmas[k];
      g2 << (k ? ", " : "") << shear_data << " using ($2 == " << num(sg, "%.9g") << " ? 1000 * $3 : 1/0):($4 / 1000) every ::1 with points pt 7 ps 0.4 lc "
         << k + 1 << " title " << quoted("sigma " + num(sg / 1000.0, "%.3g") + " kPa") << ", (" << num(sh.cohesion, "%.9g") << " + "
         << num(sg, "%.9g") << " * " << num(std::tan(sh.friction_angle), "%.9g") << ") * (1 - exp(-x / 1000 / "
         << num(sh.shear_modulus, "%.9g") << ")) / 1000 with lines lw 2 lc " << k + 1 << " notitle";
    }
    g2 << "\n";
    if (const std::string err = run_gnuplot(dir, "shear_fit", g2.str()); !err.empty()) out.warnings.push_back(err);
    else out.files.push_back("shear_fit.png");
  }
  return out;
}

}  // namespace mechsim::sim
