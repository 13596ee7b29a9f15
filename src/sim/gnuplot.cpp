#include "sim/gnuplot.hpp"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace mechsim::sim {

namespace fs = std::filesystem;

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string run_gnuplot(const fs::path& dir, const std::string& name, const std::string& script) {
  const fs::path script_path = dir / (name + ".gp");
  const fs::path log_path = dir / (name + ".gnuplot.log");
  {
    std::ofstream out(script_path);
    out << script;
  }
  const std::string command = "gnuplot " + quoted(script_path.string()) + " > " + quoted(log_path.string()) + " 2>&1";
  const int status = std::system(command.c_str());
  std::error_code ec;
  if (status == 0) {
    fs::remove(script_path, ec);
    fs::remove(log_path, ec);
    return {};
  }
  std::ifstream log(log_path);
  std::stringstream text;
  text << log.rdbuf();
  return "gnuplot failed for " + name + ".png (is gnuplot installed?): " + text.str().substr(0, 400);
}

void write_terrain(const physics::Heightmap& map, const fs::path& file, double& z_min, double& z_max) {
  std::ofstream out(file);
  // At most ~400 samples a side: enough for a picture.
  const std::size_t step = std::max<std::size_t>(1, std::max(map.rows, map.cols) / 400);
  z_min = 1e300;
  z_max = -1e300;
  for (std::size_t r = 0; r < map.rows; r += step) {
    for (std::size_t c = 0; c < map.cols; c += step) {
      const double x = -map.size_x / 2 + static_cast<double>(c) * map.cell_x();
      const double y = -map.size_y / 2 + static_cast<double>(r) * map.cell_y();
      const double z = map.at(r, c);
      z_min = std::min(z_min, z);
      z_max = std::max(z_max, z);
      out << x << ',' << y << ',' << z << '\n';
    }
    out << '\n';
  }
}

std::string axes_record(const std::filesystem::path& file, bool first) {
  return "set print " + quoted(file.string()) + (first ? "" : " append") +
         "\nprint sprintf('{\"px\":[%g,%g,%g,%g],\"x\":[%g,%g],\"y\":[%g,%g]}', GPVAL_TERM_XMIN, GPVAL_TERM_XMAX, "
         "GPVAL_TERM_YMIN, GPVAL_TERM_YMAX, GPVAL_X_MIN, GPVAL_X_MAX, GPVAL_Y_MIN, GPVAL_Y_MAX)\nunset print\n";
}

}  // namespace mechsim::sim
