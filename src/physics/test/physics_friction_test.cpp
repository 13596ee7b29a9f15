// Friction as Gazebo's ODE combines two surfaces' (contact_defaults.hpp): each contact takes the
// smaller coefficient of its two geoms, whichever side has it: a robot link against a world
// object, against the ground plane (Gazebo's ground_plane: mu 100, mu2 50), and against another
// link. A box sliding at 2 m/s stops after v^2 / (2 mu g); tolerance 10 % (soft contacts).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "physics_test_util.hpp"

namespace mechsim::physics {
namespace {

using ::testing::HasSubstr;

constexpr double kG = 9.81;

std::string box_with_mu(double mu) {
  return test::box_urdf().substr(0, test::box_urdf().rfind("</robot>")) + "<gazebo reference=\"box\"><mu1>" +
         std::to_string(mu) + "</mu1><mu2>" + std::to_string(mu) + "</mu2></gazebo></robot>";
}

// The distance the box slides on a floor, from 2 m/s.
double slide_distance(const std::string& urdf, BuildOptions o) {
  o.spawn.z = 0.05;
  Physics p(test::build(urdf, o));
  for (int i = 0; i < 200; ++i) EXPECT_TRUE(p.step().ok());  // settle
  const double x0 = p.base_pose().position.x;
  p.set_base_twist({{2.0, 0.0, 0.0}, {0.0, 0.0, 0.0}});
  while (p.time() < 3.0) EXPECT_TRUE(p.step().ok());
  return p.base_pose().position.x - x0;
}

// A fixed 8 x 8 m plate whose top is z = 0, with the given surface, as the only floor.
BuildOptions on_plate(std::optional<double> mu, std::optional<double> mu2) {
  BuildOptions o;
  o.world.ground_plane = false;
  WorldBox plate;
  plate.name = "plate";
  plate.size = {8.0, 8.0, 0.1};
  plate.pose.position = {0.0, 0.0, -0.05};
  plate.mu = mu;
  plate.mu2 = mu2;
  o.world.boxes = {plate};
  return o;
}

TEST(PhysicsFriction, TheSmallerCoefficientOfTheTwoSurfacesDecidesOnEitherSide) {
  struct Case {
    double robot, plate;
  };
  for (const Case c : {Case{0.5, 0.2}, Case{0.2, 0.5}, Case{0.35, 0.35}}) {
    const double mu = std::min(c.robot, c.plate);
    const double expected = 4.0 / (2.0 * mu * kG);
    EXPECT_NEAR(slide_distance(box_with_mu(c.robot), on_plate(c.plate, c.plate)), expected, 0.1 * expected)
        << "robot mu " << c.robot << ", plate mu " << c.plate;
  }
}

// A surface with mu along fdir1 and mu2 across it is one coefficient in MuJoCo 2.2.2: their mean;
// a coefficient left out is Gazebo's default, 1.
TEST(PhysicsFriction, AnisotropicSurfacesAreTheirMeanAndAMissingCoefficientIsOne) {
  const double expected = 4.0 / (2.0 * 0.3 * kG);  // plate (0.4, 0.2) -> 0.3
  EXPECT_NEAR(slide_distance(box_with_mu(1.0), on_plate(0.4, 0.2)), expected, 0.1 * expected);
  const double half = 4.0 / (2.0 * 0.6 * kG);  // plate mu 0.2, mu2 left out (1) -> 0.6
  EXPECT_NEAR(slide_distance(box_with_mu(1.0), on_plate(0.2, std::nullopt)), half, 0.1 * half);
  const auto model = test::build(test::box_urdf().substr(0, test::box_urdf().rfind("</robot>")) +
                                 "<gazebo reference=\"box\"><mu1>0.4</mu1><mu2>0.2</mu2></gazebo></robot>");
  ASSERT_EQ(model->warnings().size(), 1u);
  EXPECT_THAT(model->warnings()[0], HasSubstr("link 'box': anisotropic friction mu1=0.4"));
  EXPECT_THAT(model->warnings()[0], HasSubstr("approximated by their mean 0.3"));
}

// The ground plane is Gazebo's ground_plane: mu 100, mu2 50, so a link's own friction decides
// against it (the 0.2 box slides as on any surface of 0.2 or more), and the ground's 75 caps a link
// of more.
TEST(PhysicsFriction, TheGroundPlaneIsGazebosGroundPlane) {
  const double expected = 4.0 / (2.0 * 0.2 * kG);
  EXPECT_NEAR(slide_distance(box_with_mu(0.2), BuildOptions{}), expected, 0.1 * expected);
  const auto model = test::build(box_with_mu(500.0));
  EXPECT_THAT(model->mjcf(), HasSubstr("name=\"ground\" type=\"plane\" size=\"0 0 1\" contype=\"1\" conaffinity=\"1\" "
                                       "group=\"2\" priority=\"1\" friction=\"75 "));
  EXPECT_THAT(model->mjcf(), HasSubstr("priority=\"0\" friction=\"500 "));
}

// A box on a plank inclined 25 degrees slides down with a = g (sin theta - mu cos theta), mu the
// smaller coefficient of box and plank (zero: g sin theta), measured from its position along the
// slope at three instants 0.4 s apart; within 3 % of g sin theta.
double slope_acceleration(double box_mu, double plank_mu) {
  const double theta = 25.0 * M_PI / 180.0;
  BuildOptions o;
  o.world.ground_plane = false;
  WorldBox plank;
  plank.name = "plank";
  plank.size = {8.0, 1.0, 0.1};
  // Its top through (0, 0, 3): the centre 5 cm below along the plank's normal.
  plank.pose.position = {-0.05 * std::sin(theta), 0.0, 3.0 - 0.05 * std::cos(theta)};
  plank.pose.orientation = {std::cos(theta / 2), 0.0, std::sin(theta / 2), 0.0};
  plank.mu = plank_mu;
  plank.mu2 = plank_mu;
  o.world.boxes = {plank};
  const double s0 = -2.5, h = 0.051;
  o.spawn.x = s0 * std::cos(theta) + h * std::sin(theta);
  o.spawn.z = 3.0 - s0 * std::sin(theta) + h * std::cos(theta);
  o.spawn.pitch = theta;
  Physics p(test::build(box_with_mu(box_mu), o));
  double s[3];
  for (int i = 0; i < 3; ++i) {
    while (p.time() < 0.2 + 0.4 * i - 1e-9) EXPECT_TRUE(p.step().ok());
    const auto& x = p.base_pose().position;
    s[i] = x.x * std::cos(theta) - (x.z - 3.0) * std::sin(theta);
  }
  return (s[2] - 2.0 * s[1] + s[0]) / (0.4 * 0.4);
}

TEST(PhysicsFriction, ABoxSlidesDownASlopeAsTheSmallerCoefficientPredicts) {
  const double theta = 25.0 * M_PI / 180.0, g_sin = kG * std::sin(theta);
  const auto predicted = [&](double mu) { return kG * (std::sin(theta) - mu * std::cos(theta)); };
  const double frictionless = slope_acceleration(1.0, 0.0), plank_low = slope_acceleration(1.0, 0.2),
               box_low = slope_acceleration(0.2, 1.0), both_high = slope_acceleration(1.0, 1.0);
  std::printf("[ figures  ] 25 deg slope: a = %.4f (mu 0; predicted %.4f), %.4f and %.4f (mu 0.2 on either side; %.4f), "
              "%.4f (mu 1)\n",
              frictionless, predicted(0.0), plank_low, box_low, predicted(0.2), both_high);
  EXPECT_NEAR(frictionless, predicted(0.0), 0.03 * g_sin);
  EXPECT_NEAR(plank_low, predicted(0.2), 0.03 * g_sin);
  EXPECT_NEAR(box_low, predicted(0.2), 0.03 * g_sin);
  EXPECT_NEAR(both_high, 0.0, 0.03 * g_sin);  // mu 1 > tan 25 deg: it holds
}

}  // namespace
}  // namespace mechsim::physics
