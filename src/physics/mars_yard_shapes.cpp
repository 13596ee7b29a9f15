#include "physics/mars_yard_shapes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mechsim::physics::detail {

GradientNoise::GradientNoise(std::mt19937_64& rng, double wavelength, double size_x,
                             double size_y)
    : wavelength_(wavelength), x0_(-0.5 * size_x), y0_(-0.5 * size_y) {
  nx_ = static_cast<std::size_t>(std::ceil(size_x / wavelength)) + 2;
  ny_ = static_cast<std::size_t>(std::ceil(size_y / wavelength)) + 2;
  gradients_.resize(nx_ * ny_);
  for (auto& g : gradients_) {
    const double a = uniform(rng, 0.0, 2.0 * std::numbers::pi);
    g = {std::cos(a), std::sin(a)};
  }
}

namespace {

// Quintic fade: continuous curvature, so slopes have no creases at lattice lines.
double fade(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

}  // namespace

double GradientNoise::operator()(double x, double y) const {
  const double u = std::clamp((x - x0_) / wavelength_, 0.0, static_cast<double>(nx_ - 2));
  const double v = std::clamp((y - y0_) / wavelength_, 0.0, static_cast<double>(ny_ - 2));
  const auto i = std::min(static_cast<std::size_t>(u), nx_ - 2);
  const auto j = std::min(static_cast<std::size_t>(v), ny_ - 2);
  const double fx = u - static_cast<double>(i), fy = v - static_cast<double>(j);
  auto dot = [&](std::size_t di, std::size_t dj) {
    const auto& g = gradients_[(j + dj) * nx_ + (i + di)];
    return g[0] * (fx - static_cast<double>(di)) + g[1] * (fy - static_cast<double>(dj));
  };
  const double sx = fade(fx), sy = fade(fy);
  const double south = dot(0, 0) + (dot(1, 0) - dot(0, 0)) * sx;
  const double north = dot(0, 1) + (dot(1, 1) - dot(0, 1)) * sx;
  return south + (north - south) * sy;
}

GradientNoise::Columns GradientNoise::columns(const std::vector<double>& xs) const {
  Columns c;
  c.i.resize(xs.size());
  c.fx.resize(xs.size());
  c.sx.resize(xs.size());
  for (std::size_t k = 0; k < xs.size(); ++k) {
    const double u = std::clamp((xs[k] - x0_) / wavelength_, 0.0, static_cast<double>(nx_ - 2));
    c.i[k] = std::min(static_cast<std::size_t>(u), nx_ - 2);
    c.fx[k] = u - static_cast<double>(c.i[k]);
    c.sx[k] = fade(c.fx[k]);
  }
  return c;
}

void GradientNoise::add_row(const Columns& c, double y, double amplitude, double* acc) const {
  // Exactly operator()'s arithmetic, with the y terms taken out of the loop.
  const double v = std::clamp((y - y0_) / wavelength_, 0.0, static_cast<double>(ny_ - 2));
  const auto j = std::min(static_cast<std::size_t>(v), ny_ - 2);
  const double fy = v - static_cast<double>(j), sy = fade(fy);
  const double fy0 = fy - 0.0, fy1 = fy - 1.0;
  const std::array<double, 2>* south_row = gradients_.data() + j * nx_;
  const std::array<double, 2>* north_row = south_row + nx_;
  for (std::size_t k = 0; k < c.i.size(); ++k) {
    const std::size_t i = c.i[k];
    const double fx0 = c.fx[k] - 0.0, fx1 = c.fx[k] - 1.0, sx = c.sx[k];
    const double d00 = south_row[i][0] * fx0 + south_row[i][1] * fy0;
    const double d10 = south_row[i + 1][0] * fx1 + south_row[i + 1][1] * fy0;
    const double d01 = north_row[i][0] * fx0 + north_row[i][1] * fy1;
    const double d11 = north_row[i + 1][0] * fx1 + north_row[i + 1][1] * fy1;
    const double south = d00 + (d10 - d00) * sx;
    const double north = d01 + (d11 - d01) * sx;
    acc[k] += amplitude * (south + (north - south) * sy);
  }
}

FractalNoise::FractalNoise(std::mt19937_64& rng, double longest, double shortest, double hurst,
                           double size_x, double size_y) {
  for (double w = longest; w >= shortest * 0.999; w *= 0.5) {
    octaves_.emplace_back(rng, w, size_x, size_y);
    amplitudes_.push_back(std::pow(w, hurst));
  }
}

double FractalNoise::operator()(double x, double y) const {
  double z = 0.0;
  for (std::size_t k = 0; k < octaves_.size(); ++k) z += amplitudes_[k] * octaves_[k](x, y);
  return z;
}

FractalNoise::Columns FractalNoise::columns(const std::vector<double>& xs) const {
  Columns c;
  for (const GradientNoise& o : octaves_) c.push_back(o.columns(xs));
  return c;
}

void FractalNoise::row(const Columns& columns, double y, std::vector<double>& out) const {
  // Octave by octave over the row: each sample still sums its octaves in operator()'s order.
  std::fill(out.begin(), out.end(), 0.0);
  for (std::size_t k = 0; k < octaves_.size(); ++k) octaves_[k].add_row(columns[k], y, amplitudes_[k], out.data());
}

PolylineHit closest_on_polyline(const std::vector<std::array<double, 2>>& line, double x,
                                double y) {
  PolylineHit best{INFINITY, 0.0};
  double arc = 0.0;
  for (std::size_t k = 0; k + 1 < line.size(); ++k) {
    const double ax = line[k][0], ay = line[k][1];
    const double dx = line[k + 1][0] - ax, dy = line[k + 1][1] - ay;
    const double len2 = dx * dx + dy * dy;
    const double t = len2 > 0.0 ? std::clamp(((x - ax) * dx + (y - ay) * dy) / len2, 0.0, 1.0) : 0.0;
    const double d = std::hypot(x - (ax + t * dx), y - (ay + t * dy));
    const double len = std::sqrt(len2);
    if (d < best.distance) best = {d, arc + t * len};
    arc += len;
  }
  return best;
}

PolylineNearest::PolylineNearest(const std::vector<std::array<double, 2>>& line) {
  double arc = 0.0;
  for (std::size_t k = 0; k + 1 < line.size(); ++k) {
    Segment g;
    g.ax = line[k][0];
    g.ay = line[k][1];
    g.dx = line[k + 1][0] - g.ax;
    g.dy = line[k + 1][1] - g.ay;
    g.len2 = g.dx * g.dx + g.dy * g.dy;
    g.len = std::sqrt(g.len2);
    g.arc = arc;
    g.x_lo = std::min(line[k][0], line[k + 1][0]);
    g.x_hi = std::max(line[k][0], line[k + 1][0]);
    g.y_lo = std::min(line[k][1], line[k + 1][1]);
    g.y_hi = std::max(line[k][1], line[k + 1][1]);
    segments_.push_back(g);
    arc += g.len;
  }
}

PolylineHit PolylineNearest::operator()(double x, double y) const {
  PolylineHit best{INFINITY, 0.0};
  for (const Segment& g : segments_) {
    // The distance to the segment is at least that to its bounding box; a segment that cannot
    // come strictly closer (closest_on_polyline keeps the first of equals) is skipped. The slack
    // covers the rounding of this bound.
    const double bx = std::max({0.0, g.x_lo - x, x - g.x_hi}), by = std::max({0.0, g.y_lo - y, y - g.y_hi});
    if (bx * bx + by * by > best.distance * best.distance * (1.0 + 1e-9)) continue;
    const double t = g.len2 > 0.0 ? std::clamp(((x - g.ax) * g.dx + (y - g.ay) * g.dy) / g.len2, 0.0, 1.0) : 0.0;
    const double d = std::hypot(x - (g.ax + t * g.dx), y - (g.ay + t * g.dy));
    if (d < best.distance) best = {d, g.arc + t * g.len};
  }
  return best;
}

double polyline_length(const std::vector<std::array<double, 2>>& line) {
  double arc = 0.0;
  for (std::size_t k = 0; k + 1 < line.size(); ++k) {
    arc += std::hypot(line[k + 1][0] - line[k][0], line[k + 1][1] - line[k][1]);
  }
  return arc;
}

double polyline_y_at(const std::vector<std::array<double, 2>>& line, double x) {
  for (std::size_t k = 0; k + 1 < line.size(); ++k) {
    if (x <= line[k + 1][0]) {
      const double t = std::clamp((x - line[k][0]) / (line[k + 1][0] - line[k][0]), 0.0, 1.0);
      return line[k][1] + t * (line[k + 1][1] - line[k][1]);
    }
  }
  return line.back()[1];
}

double channel_profile(const Channel& channel, double d, double arc, double length,
                       double taper_start, double taper_end) {
  const double half_top = 0.5 * channel.top_width, half_floor = 0.5 * channel.floor_width;
  if (d >= half_top) return 0.0;
  const double across = 1.0 - smoothstep((d - half_floor) / (half_top - half_floor));
  double along = 1.0;
  if (taper_start > 0.0) along = std::min(along, smoothstep(arc / taper_start));
  if (taper_end > 0.0) along = std::min(along, smoothstep((length - arc) / taper_end));
  return -channel.depth * across * along;
}

double crater_profile(const Crater& c, double r) {
  if (r < c.radius) {
    const double t = r / c.radius;
    return -c.depth + (c.depth + c.rim_height) * t * t;
  }
  if (r >= crater_reach(c)) return 0.0;
  // Ejecta apron: the rim falls off outside, reaching ~0 at two radii.
  const double t = (r - c.radius) / (0.4 * c.radius);
  return c.rim_height * std::exp(-t * t);
}

double mound_profile(const Mound& m, double r) {
  if (r >= m.radius) return 0.0;
  // Slope rises linearly over the summit cap (t < a), stays constant down the flank and
  // fades over the foot (t > 1 - b); heights integrate it. Peak slope = 1.38 height/radius.
  constexpr double a = 0.25, b = 0.3, total = 1.0 - 0.5 * a - 0.5 * b;
  const double t = r / m.radius;
  double f;
  if (t > 1.0 - b) {
    f = (1.0 - t) * (1.0 - t) / (2.0 * b);
  } else if (t > a) {
    f = 0.5 * b + (1.0 - b - t);
  } else {
    f = 0.5 * b + (1.0 - b - a) + (a * a - t * t) / (2.0 * a);
  }
  double z = m.height * f / total;
  if (m.caldera_radius > 0.0 && r < m.caldera_radius) {
    const double c = r / m.caldera_radius;
    z -= m.caldera_depth * (1.0 - c * c);
  }
  return z;
}

double rock_profile(const Rock& rock, double x, double y) {
  const double c = std::cos(rock.yaw), s = std::sin(rock.yaw);
  const double u = ((x - rock.x) * c + (y - rock.y) * s) / (0.5 * rock.length);
  const double v = (-(x - rock.x) * s + (y - rock.y) * c) / (0.5 * rock.width);
  const double q = u * u + v * v;
  return q < 1.0 ? rock.height * std::sqrt(1.0 - q) : 0.0;
}

double dune_profile(const DuneField& f, double x, double y) {
  const double c = std::cos(f.wind_yaw), s = std::sin(f.wind_yaw);
  const double u = (x - f.x) * c + (y - f.y) * s;    // downwind
  const double v = -(x - f.x) * s + (y - f.y) * c;   // across the wind
  const double hu = 0.5 * f.length, hv = 0.5 * f.width;
  if (std::abs(u) >= hu || std::abs(v) >= hv) return 0.0;
  // Gentle stoss slope over 65 % of the wavelength, lee face near the angle of repose.
  constexpr double kStoss = 0.65;
  const double sinuous = 0.12 * f.wavelength * std::sin(2.0 * std::numbers::pi * v / (2.3 * f.wavelength));
  double p = (u + hu + sinuous) / f.wavelength;
  p -= std::floor(p);
  const double z = p < kStoss ? 0.5 * (1.0 - std::cos(std::numbers::pi * p / kStoss))
                              : 0.5 * (1.0 + std::cos(std::numbers::pi * (p - kStoss) / (1.0 - kStoss)));
  const double edge = std::min({(hu - std::abs(u)) / 1.0, (hv - std::abs(v)) / 1.0});
  return f.height * z * smoothstep(edge);
}

}  // namespace mechsim::physics::detail
