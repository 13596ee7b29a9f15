// A robot on a slide, as pr2_gazebo's test_slide has the PR2 on a zero-friction slide: an SDF
// world of our own (Gazebo's ground plane and a static slide inclined 25 degrees, its surface's
// <mu>/<mu2> as written) and a test robot of our own (a sled: a base box with a mast, Gazebo's
// default friction 1 unless its <gazebo> says otherwise). Friction combines as Gazebo's ODE
// does, the smaller coefficient of the two surfaces on either side, so the sled slides down with
// a = g (sin theta - mu cos theta), mu = min(slide, sled), measured from its position along the
// slope at three instants 0.4 s apart (second difference). Tolerance: 3 % of g sin theta.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "description/urdf/urdf_parser.hpp"
#include "physics/physics.hpp"
#include "sim/world.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;

constexpr double kTheta = 25.0 * M_PI / 180.0;
constexpr double kG = 9.8;  // the SDF world's gravity (SDF's default)

std::string sled_urdf(const std::string& gazebo) {
  return R"(<robot name="sled">
  <link name="base"><inertial><mass value="4"/><inertia ixx="0.02" iyy="0.04" izz="0.05" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><box size="0.3 0.2 0.1"/></geometry></collision></link>
  <link name="mast"><inertial><origin xyz="0 0 0.15"/><mass value="0.5"/><inertia ixx="0.004" iyy="0.004" izz="0.0001" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin xyz="0 0 0.15"/><geometry><cylinder radius="0.02" length="0.2"/></geometry></collision></link>
  <joint name="mast_joint" type="fixed"><parent link="base"/><child link="mast"/><origin xyz="0 0 0.05"/></joint>
  )" + gazebo + "</robot>";
}

// The slide: an 8 m board, 0.1 m thick, its top through the origin, pitched theta about y (so it
// falls along +x), its surface as given.
std::string slide_world(const std::string& surface_xml) {
  return R"(<?xml version="1.0"?>
<sdf version="1.6"><world name="slide">
  <include><uri>model://ground_plane</uri></include>
  <model name="slide"><static>true</static><pose>0 0 3 0 )" +
         std::to_string(kTheta) + R"( 0</pose>
    <link name="board"><collision name="surface"><pose>0 0 -0.05 0 0 0</pose>
      <geometry><box><size>8 1 0.1</size></box></geometry>)" +
         surface_xml + R"(</collision></link></model>
</world></sdf>
)";
}

struct TempDir {
  fs::path path = fs::temp_directory_path() / ("mechsim_slide_" + std::to_string(::getpid()));
  TempDir() { fs::create_directories(path); }
  ~TempDir() { fs::remove_all(path); }
};

// The sled's acceleration down the slope (m/s^2).
double acceleration(const std::string& surface_xml, const std::string& sled_gazebo) {
  TempDir dir;
  const fs::path file = dir.path / "slide.world";
  std::ofstream(file) << slide_world(surface_xml);
  WorldConfig config;
  config.name = file.string();
  const World world = make_world(config);
  physics::BuildOptions options;
  options.world = world.spec;
  // On the board's upper half, 5 mm above it, pitched with it.
  const double s0 = -2.5, h = 0.055;
  options.spawn.x = s0 * std::cos(kTheta) + h * std::sin(kTheta);
  options.spawn.z = 3.0 - s0 * std::sin(kTheta) + h * std::cos(kTheta);
  options.spawn.pitch = kTheta;
  physics::Physics p(physics::PhysicsModel::build(description::parse_urdf_string(sled_urdf(sled_gazebo), "sled.urdf", {}), options));
  const auto along = [&] {  // position along the slope's downhill direction (m)
    const auto& x = p.base_pose().position;
    return x.x * std::cos(kTheta) - (x.z - 3.0) * std::sin(kTheta);
  };
  double s[3];
  for (int i = 0; i < 3; ++i) {
    while (p.time() < 0.2 + 0.4 * i - 1e-9) EXPECT_TRUE(p.step().ok());
    s[i] = along();
  }
  return (s[2] - 2.0 * s[1] + s[0]) / (0.4 * 0.4);
}

std::string surface(double mu) {
  const std::string m = std::to_string(mu);
  return "<surface><friction><ode><mu>" + m + "</mu><mu2>" + m + "</mu2></ode></friction></surface>";
}

std::string sled_mu(double mu) {
  const std::string m = std::to_string(mu);
  return "<gazebo reference=\"base\"><mu1>" + m + "</mu1><mu2>" + m + "</mu2></gazebo>";
}

double predicted(double mu) { return kG * (std::sin(kTheta) - mu * std::cos(kTheta)); }

TEST(FrictionSlide, ASledSlidesDownAZeroFrictionSlideAtGSinTheta) {
  const double a = acceleration(surface(0.0), "");
  std::printf("[ figures  ] zero-friction slide, sled mu 1: a = %.3f m/s^2 (g sin theta = %.3f)\n", a, predicted(0.0));
  EXPECT_NEAR(a, predicted(0.0), 0.03 * kG * std::sin(kTheta));
}

TEST(FrictionSlide, TheSmallerOfTheTwoSurfacesSetsTheSlidingFrictionOnEitherSide) {
  const double slide_low = acceleration(surface(0.2), "");           // slide 0.2, sled 1 (default)
  const double sled_low = acceleration(surface(1.0), sled_mu(0.2));  // slide 1, sled 0.2
  std::printf("[ figures  ] mu 0.2 on either side: a = %.3f and %.3f m/s^2 (predicted %.3f)\n", slide_low, sled_low,
              predicted(0.2));
  EXPECT_NEAR(slide_low, predicted(0.2), 0.03 * kG * std::sin(kTheta));
  EXPECT_NEAR(sled_low, predicted(0.2), 0.03 * kG * std::sin(kTheta));
  // mu 1 > tan 25 deg on both sides: the sled holds.
  EXPECT_NEAR(acceleration(surface(1.0), ""), 0.0, 0.03 * kG * std::sin(kTheta));
}

}  // namespace
}  // namespace mechsim::sim
