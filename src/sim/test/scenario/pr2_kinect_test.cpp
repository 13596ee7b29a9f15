// The PR2 SE's Kinect (pr2_description's kinect_prosilica_camera on the head: depth sensors
// head_mount_ir_sensor and head_mount_rgb_sensor, gazebo_ros_openni_kinect, 640x480, 57 deg)
// in a whole simulation of the shared pr2_se description: facing a wall 2.5 m ahead, every pixel
// sees it, the depth at the image centre is the distance along the optical axis to the wall, and
// every point of the cloud, taken to the world through the link's pose, the sensor's <pose> and
// the optical frame's turn, lies on the wall.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>
#include <variant>

#include "description/urdf/urdf_parser.hpp"
#include "physics/transform.hpp"
#include "scenario_util.hpp"
#include "sim/simulation.hpp"
#include "sim/world.hpp"

namespace mechsim::sim {
namespace {

namespace fs = std::filesystem;

TEST(Pr2SeKinect, DepthAndPointsOfAWallAheadAreWhereTheWallIs) {
  const fs::path shared = MECHSIM_SHARED_DIR;
  const fs::path urdf = shared / "robots/reference/pr2_se.urdf";
  if (!fs::exists(urdf)) GTEST_SKIP() << "shared data absent: " << urdf;
  description::UrdfOptions urdf_options;
  urdf_options.lenient = true;  // two sensor mounts break the inertia triangle inequality
  urdf_options.packages["pr2_description"] = (shared / "robots/pr2_description").string();
  description::RobotModel pr2se = description::parse_urdf_file(urdf.string(), urdf_options);

  constexpr double kWallX = 2.5;  // the wall's face: the plane x = 2.5 m, 4 m wide and high
  World world = make_world({});
  physics::WorldBox wall;
  wall.name = "wall";
  wall.size = {1.0, 4.0, 4.0};
  wall.pose.position = {kWallX + 0.5, 0.0, 1.2};
  world.spec.boxes.push_back(wall);
  SimulationOptions options;
  options.spawn.z = 0.01;
  Simulation sim(std::move(pr2se), world, control::Params{}, options);

  for (const char* name : {"head_mount_rgb_sensor", "head_mount_ir_sensor"}) {
    SCOPED_TRACE(name);
    const auto index = sim.sensors().find(name);
    ASSERT_TRUE(index) << "no sensor " << name;
    const description::SensorSpec& spec = sim.sensors().spec(*index);
    const std::uint64_t before = sim.sensors().reading(*index).count;
    sim.sensors().request(*index);
    for (int i = 0; i < 100 && sim.sensors().reading(*index).count == before; ++i) sim.step();
    ASSERT_GT(sim.sensors().reading(*index).count, before) << "not sampled";
    const auto& reading = std::get<sensors::CameraReading>(sim.sensors().reading(*index).value);
    ASSERT_TRUE(reading.error.empty()) << reading.error;
    ASSERT_EQ(reading.images.size(), 1u);
    const sensors::CameraImage& image = reading.images[0];
    const auto w = static_cast<std::size_t>(image.info.width), h = static_cast<std::size_t>(image.info.height);
    ASSERT_EQ(w, 640u);
    ASSERT_EQ(h, 480u);
    ASSERT_EQ(image.depth.size(), w * h);
    ASSERT_EQ(image.points.size(), 3 * w * h);

    // World <- optical: the link (as the physics has it now, the state the sample saw), the
    // sensor's <pose>, the optical frame (z forward, x right, y down).
    const description::Pose X_WL = link_pose(sim, spec.link);
    description::Pose X_SO;
    X_SO.orientation = physics::quat_from_rpy(-M_PI / 2, 0.0, -M_PI / 2);
    const description::Pose X_WO = physics::compose(physics::compose(X_WL, spec.pose), X_SO);
    const description::Vec3 axis = physics::rotate(X_WO.orientation, {0.0, 0.0, 1.0});
    const double expected_centre = (kWallX - X_WO.position.x) / axis.x;

    std::size_t seen = 0;
    double worst = 0.0;
    for (std::size_t i = 0; i < w * h; ++i) {
      if (!std::isfinite(image.depth[i])) continue;
      ++seen;
      const description::Vec3 p_O{image.points[3 * i], image.points[3 * i + 1], image.points[3 * i + 2]};
      const description::Vec3 r = physics::rotate(X_WO.orientation, p_O);
      worst = std::max(worst, std::abs(X_WO.position.x + r.x - kWallX));
    }
    // The centre of the image: the four pixels around (cx, cy) straddle the optical axis.
    const std::size_t u = w / 2, v = h / 2;
    const double centre = (image.depth[v * w + u] + image.depth[v * w + u - 1] + image.depth[(v - 1) * w + u] +
                           image.depth[(v - 1) * w + u - 1]) / 4.0;
    std::printf("[ figures  ] %s: optical origin (%.3f, %.3f, %.3f) m, %zu of %zu pixels see the wall, centre depth "
                "%.4f m (along the axis to the wall %.4f m, %.3f %%), points off the wall by at most %.2f mm\n",
                name, X_WO.position.x, X_WO.position.y, X_WO.position.z, seen, w * h, centre, expected_centre,
                100.0 * (centre - expected_centre) / expected_centre, 1e3 * worst);
    EXPECT_EQ(seen, w * h) << "the wall fills the view";
    EXPECT_NEAR(centre, expected_centre, 0.01 * expected_centre);
    EXPECT_LT(worst, 0.01);
  }
}

}  // namespace
}  // namespace mechsim::sim
