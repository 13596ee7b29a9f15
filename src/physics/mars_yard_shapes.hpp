#pragma once
// Internal to the Mars Yard generator: random draws that are identical on every standard
// library (std::uniform_real_distribution is not), fractal gradient noise, and the height
// profiles of the landforms. Heights are relative to the surrounding ground (m).

#include <array>
#include <cstdint>
#include <random>
#include <vector>

#include "physics/mars_yard.hpp"

namespace mechsim::physics::detail {

// Uniform in [lo, hi) from the top 53 bits of one draw.
inline double uniform(std::mt19937_64& rng, double lo, double hi) {
  return lo + (hi - lo) * static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

inline double smoothstep(double t) {
  t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
  return t * t * (3.0 - 2.0 * t);
}

// One octave of 2-D gradient (Perlin-style) noise over a rectangle, with random unit
// gradients on a square lattice of `wavelength` (m). Values roughly in [-0.7, 0.7].
class GradientNoise {
 public:
  GradientNoise(std::mt19937_64& rng, double wavelength, double size_x, double size_y);
  double operator()(double x, double y) const;

  // What operator() computes from x alone, for a row of sample points: evaluating a grid row
  // by row gives the same values bit for bit at a fraction of the cost.
  struct Columns {
    std::vector<std::size_t> i;  // lattice cell
    std::vector<double> fx, sx;  // position in the cell and its fade
  };
  Columns columns(const std::vector<double>& xs) const;
  // acc[c] += amplitude * operator()(xs[c], y) for the xs of `columns`.
  void add_row(const Columns& columns, double y, double amplitude, double* acc) const;

 private:
  double wavelength_, x0_, y0_;
  std::size_t nx_, ny_;
  std::vector<std::array<double, 2>> gradients_;
};

// Sum of octaves from `longest` down to `shortest` wavelength (halving), amplitude
// proportional to wavelength^hurst (m per metre of wavelength at 1 m).
class FractalNoise {
 public:
  FractalNoise(std::mt19937_64& rng, double longest, double shortest, double hurst,
               double size_x, double size_y);
  double operator()(double x, double y) const;

  // out[c] = operator()(xs[c], y), bit for bit, row by row (GradientNoise::Columns).
  using Columns = std::vector<GradientNoise::Columns>;
  Columns columns(const std::vector<double>& xs) const;
  void row(const Columns& columns, double y, std::vector<double>& out) const;

 private:
  std::vector<GradientNoise> octaves_;
  std::vector<double> amplitudes_;
};

// Distance (m) from (x, y) to a polyline and the arc length (m) of the closest point.
struct PolylineHit {
  double distance = 0.0;
  double arc = 0.0;
};
PolylineHit closest_on_polyline(const std::vector<std::array<double, 2>>& line, double x, double y);

// closest_on_polyline for many points: the same hits bit for bit, skipping the segments whose
// bounding box is already farther than the best distance found.
class PolylineNearest {
 public:
  explicit PolylineNearest(const std::vector<std::array<double, 2>>& line);
  PolylineHit operator()(double x, double y) const;

 private:
  struct Segment {
    double ax, ay, dx, dy, len2, len, arc;  // arc: length of the segments before it
    double x_lo, x_hi, y_lo, y_hi;
  };
  std::vector<Segment> segments_;
};
double polyline_length(const std::vector<std::array<double, 2>>& line);
// y (m) of a polyline running west to east at x, continued flat beyond its ends.
double polyline_y_at(const std::vector<std::array<double, 2>>& line, double x);

// Height change (m, <= 0) of a channel at distance d from its centre line, arc `arc` of
// `length`; tapered over `taper_start`/`taper_end` metres at the ends (0: no taper).
double channel_profile(const Channel& channel, double d, double arc, double length,
                       double taper_start, double taper_end);

double crater_profile(const Crater& crater, double r);   // r: distance from the centre (m)
double mound_profile(const Mound& mound, double r);
double rock_profile(const Rock& rock, double x, double y);  // world x, y (m)
double dune_profile(const DuneField& dunes, double x, double y);

// Radius (m) beyond which a crater's profile is zero.
inline double crater_reach(const Crater& c) { return 2.0 * c.radius; }

}  // namespace mechsim::physics::detail
