#include "sensors/pr2_fingertip_pressure.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/transform.hpp"

namespace mechsim::sensors {

namespace {

struct Element {
  double centre[3];  // mm, left fingertip frame
  double half1[3];   // mm, half of one side
  double half2[3];   // mm, half of the other side; half1 x half2 points out of the pad
  double units_per_newton;
};

// The fingertip_pressure package's sensor geometry (left fingertip; the right one is the same
// turned half a turn about x): 0 back, 1-6 edges and corners, 7-21 the front array (5 rows of 3).
constexpr Element kElements[kFingertipPressureElements] = {
    {{25.30, -4.00, 0.00}, {0.00, 0.00, -10.00}, {-2.80, 0.00, 0.00}, 600},
    {{12.50, -9.80, -11.50}, {12.00, 0.00, 0.00}, {0.00, -3.00, 0.00}, 400},
    {{27.75, -10.30, -9.25}, {-3.25, 0.00, -2.25}, {0.00, 2.50, 0.00}, 600},
    {{31.00, -10.30, -3.50}, {0.00, 0.00, -3.50}, {0.00, 2.50, 0.00}, 600},
    {{31.00, -10.30, 3.50}, {0.00, 0.00, 3.50}, {0.00, -2.50, 0.00}, 600},
    {{27.75, -10.30, 9.25}, {-3.25, 0.00, 2.25}, {0.00, -2.50, 0.00}, 600},
    {{12.50, -9.80, 11.50}, {12.00, 0.00, 0.00}, {0.00, 3.00, 0.00}, 400},
    {{26.50, -15.00, 5.60}, {0.00, 0.00, 2.80}, {-3.00, 0.00, 0.00}, 1600},
    {{26.50, -15.00, 0.00}, {0.00, 0.00, 2.80}, {-3.00, 0.00, 0.00}, 1600},
    {{26.50, -15.00, -5.60}, {0.00, 0.00, 2.80}, {-3.00, 0.00, 0.00}, 1600},
    {{20.50, -15.00, 5.60}, {0.00, 0.00, 2.80}, {-3.00, 0.00, 0.00}, 1600},
    {{20.50, -15.00, 0.00}, {0.00, 0.00, 2.80}, {-3.00, 0.00, 0.00}, 1600},
    {{20.50, -15.00, -5.60}, {0.00, 0.00, 2.80}, {-3.00, 0.00, 0.00}, 1600},
    {{14.50, -15.00, 5.60}, {0.00, 0.00, 2.80}, {-3.00, 0.00, 0.00}, 1600},
    {{14.50, -15.00, 0.00}, {0.00, 0.00, 2.80}, {-3.00, 0.00, 0.00}, 1600},
    {{14.50, -15.00, -5.60}, {0.00, 0.00, 2.80}, {-3.00, 0.00, 0.00}, 1600},
    {{8.50, -15.00, 5.60}, {0.00, 0.00, 2.80}, {-3.00, 0.00, 0.00}, 1600},
    {{8.50, -15.00, 0.00}, {0.00, 0.00, 2.80}, {-3.00, 0.00, 0.00}, 1600},
    {{8.50, -15.00, -5.60}, {0.00, 0.00, 2.80}, {-3.00, 0.00, 0.00}, 1600},
    {{2.50, -15.00, 5.60}, {0.00, 0.00, 2.80}, {-3.00, 0.00, 0.00}, 1600},
    {{2.50, -15.00, 0.00}, {0.00, 0.00, 2.80}, {-3.00, 0.00, 0.00}, 1600},
    {{2.50, -15.00, -5.60}, {0.00, 0.00, 2.80}, {-3.00, 0.00, 0.00}, 1600},
};

double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// A table vector (mm) in metres in the finger's frame.
Vec3 to_finger(const double v[3], Fingertip finger) {
  const double s = finger == Fingertip::Left ? 1.0 : -1.0;
  return {v[0] * 1e-3, s * v[1] * 1e-3, s * v[2] * 1e-3};
}

struct Rect {
  Vec3 centre, u, w, normal;  // u, w unit along the sides; normal unit, out of the pad
  double half_u = 0.0, half_w = 0.0;
};

Rect rect(int k, Fingertip finger) {
  const Element& e = kElements[k];
  Rect r;
  r.centre = to_finger(e.centre, finger);
  const Vec3 h1 = to_finger(e.half1, finger), h2 = to_finger(e.half2, finger);
  r.half_u = std::sqrt(dot(h1, h1));
  r.half_w = std::sqrt(dot(h2, h2));
  r.u = {h1.x / r.half_u, h1.y / r.half_u, h1.z / r.half_u};
  r.w = {h2.x / r.half_w, h2.y / r.half_w, h2.z / r.half_w};
  r.normal = {r.u.y * r.w.z - r.u.z * r.w.y, r.u.z * r.w.x - r.u.x * r.w.z, r.u.x * r.w.y - r.u.y * r.w.x};
  return r;
}

// Distance (m) from p to the rectangle.
double distance(const Rect& r, const Vec3& p) {
  const Vec3 d{p.x - r.centre.x, p.y - r.centre.y, p.z - r.centre.z};
  const double a = std::max(std::abs(dot(d, r.u)) - r.half_u, 0.0);
  const double b = std::max(std::abs(dot(d, r.w)) - r.half_w, 0.0);
  const double n = dot(d, r.normal);
  return std::sqrt(a * a + b * b + n * n);
}

}  // namespace

Vec3 fingertip_element_centre(int k, Fingertip finger) { return rect(k, finger).centre; }
Vec3 fingertip_element_normal(int k, Fingertip finger) { return rect(k, finger).normal; }

std::array<double, kFingertipPressureElements> fingertip_pad_forces(const ContactsReading& contacts, Fingertip finger) {
  std::array<Rect, kFingertipPressureElements> rects;
  for (int k = 0; k < kFingertipPressureElements; ++k) rects[static_cast<std::size_t>(k)] = rect(k, finger);
  std::array<double, kFingertipPressureElements> newtons{};
  // Contact points come in the world frame; the pads are in the fingertip link's.
  const Pose X_LW = physics::inverse(contacts.X_WL);
  const std::size_t states = std::min(contacts.count, contacts.states.size());
  for (std::size_t s = 0; s < states; ++s) {
    const ContactState& c = contacts.states[s];
    const std::size_t points = std::min(c.contact_positions.size(), c.wrenches.size());
    for (std::size_t i = 0; i < points; ++i) {
      const Vec3 r = physics::rotate(X_LW.orientation, c.contact_positions[i]);
      const Vec3 p_L{r.x + X_LW.position.x, r.y + X_LW.position.y, r.z + X_LW.position.z};
      int nearest = -1;
      double best = kPressureElementReach;
      for (int k = 0; k < kFingertipPressureElements; ++k) {
        const double d = distance(rects[static_cast<std::size_t>(k)], p_L);
        if (d <= best) {
          best = d;
          nearest = k;
        }
      }
      if (nearest < 0) continue;
      // The force on the fingertip pushes the pad inwards: against its outward normal.
      const auto k = static_cast<std::size_t>(nearest);
      const double pressing = -dot(c.wrenches[i].force, rects[k].normal);
      if (pressing > 0.0) newtons[k] += pressing;
    }
  }
  return newtons;
}

std::array<std::int16_t, kFingertipPressureElements> fingertip_pressure(const ContactsReading& contacts,
                                                                         Fingertip finger) {
  const std::array<double, kFingertipPressureElements> newtons = fingertip_pad_forces(contacts, finger);
  std::array<std::int16_t, kFingertipPressureElements> out{};
  for (std::size_t k = 0; k < out.size(); ++k) {
    const double units = newtons[k] * kElements[k].units_per_newton;
    const double v = std::clamp(std::round(units), 0.0, static_cast<double>(std::numeric_limits<std::int16_t>::max()));
    out[k] = static_cast<std::int16_t>(v);
  }
  return out;
}

}  // namespace mechsim::sensors
