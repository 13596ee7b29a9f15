// The PR2 fingertip pressure pads from contact points: the element under a point gets the force
// pressing into it times its units per newton; points off the pads, pulling forces and the other
// fingertip's geometry are told apart; readings clamp at int16.

#include <gtest/gtest.h>

#include <cmath>

#include "sensors/pr2_fingertip_pressure.hpp"

namespace mechsim::sensors {
namespace {

// One contact point at `p` with force `f` on the fingertip.
ContactsReading touch(const Vec3& p, const Vec3& f) {
  ContactsReading r;
  ContactState c;
  c.contact_positions.push_back(p);
  c.wrenches.push_back({f, {}});
  r.states.push_back(c);
  r.count = 1;
  return r;
}

Vec3 plus(const Vec3& a, const Vec3& b, double s = 1.0) { return {a.x + s * b.x, a.y + s * b.y, a.z + s * b.z}; }

TEST(FingertipPressure, FrontPadElementReadsTheForcePressingIntoIt) {
  for (const Fingertip finger : {Fingertip::Left, Fingertip::Right}) {
    // The middle of the front array (element 14), and its normal: the left pad faces -y, the right +y.
    const Vec3 centre = fingertip_element_centre(14, finger);
    const Vec3 n = fingertip_element_normal(14, finger);
    EXPECT_NEAR(n.y, finger == Fingertip::Left ? -1.0 : 1.0, 1e-12);
    // 2 N pushing the pad in (against its normal), the point 1 mm off the surface.
    const auto p = fingertip_pressure(touch(plus(centre, n, 0.001), plus({}, n, -2.0)), finger);
    for (int k = 0; k < kFingertipPressureElements; ++k) {
      EXPECT_EQ(p[static_cast<std::size_t>(k)], k == 14 ? 3200 : 0) << "element " << k;
    }
  }
}

TEST(FingertipPressure, TwoPointsOnOneElementAddAndTheBackCountsLess) {
  const Fingertip f = Fingertip::Left;
  ContactsReading r = touch(fingertip_element_centre(7, f), plus({}, fingertip_element_normal(7, f), -1.0));
  r.states[0].contact_positions.push_back(plus(fingertip_element_centre(7, f), {0.002, 0.0, 0.0}));
  r.states[0].wrenches.push_back({plus({}, fingertip_element_normal(7, f), -0.5), {}});
  ContactState back;
  back.contact_positions.push_back(fingertip_element_centre(0, f));
  back.wrenches.push_back({plus({}, fingertip_element_normal(0, f), -1.0), {}});
  r.states.push_back(back);
  r.count = 2;
  const auto p = fingertip_pressure(r, f);
  EXPECT_EQ(p[7], 2400);  // 1.5 N * 1600
  EXPECT_EQ(p[0], 600);   // 1 N * 600
}

TEST(FingertipPressure, OffThePadsPullingAndUnusedStatesReadNothing) {
  const Fingertip f = Fingertip::Left;
  const Vec3 centre = fingertip_element_centre(14, f);
  const Vec3 n = fingertip_element_normal(14, f);
  auto none = [](const std::array<std::int16_t, kFingertipPressureElements>& p) {
    for (const auto v : p)
      if (v != 0) return false;
    return true;
  };
  EXPECT_TRUE(none(fingertip_pressure(touch(plus(centre, n, 0.01), plus({}, n, -2.0)), f)));  // 1 cm out
  EXPECT_TRUE(none(fingertip_pressure(touch(centre, plus({}, n, 2.0)), f)));                   // pulling
  ContactsReading stale = touch(centre, plus({}, n, -2.0));
  stale.count = 0;  // the state is kept capacity, not in use
  EXPECT_TRUE(none(fingertip_pressure(stale, f)));
  // The right fingertip's front pad is on the other side: a point on the left one's misses it.
  EXPECT_TRUE(none(fingertip_pressure(touch(centre, plus({}, n, -2.0)), Fingertip::Right)));
}

TEST(FingertipPressure, ClampsAtInt16) {
  const Fingertip f = Fingertip::Right;
  const auto p = fingertip_pressure(
      touch(fingertip_element_centre(20, f), plus({}, fingertip_element_normal(20, f), -100.0)), f);
  EXPECT_EQ(p[20], 32767);
}

}  // namespace
}  // namespace mechsim::sensors
