// Camera sensors against analytic geometry: a box in front of a depth camera (its face's corners
// where CameraInfo's P projects them, depth of the fronto-parallel face, points on the face),
// stereo disparity against the baseline in P, lens distortion, seeded image noise, rendering only
// for consumers with one scene update per instant, and a machine without EGL.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include "physics/transform.hpp"
#include "sensor_test_util.hpp"
#include "sensors/sensor_set.hpp"

namespace mechsim::sensors {
namespace {

using description::Pose;
using description::Vec3;
using ::testing::HasSubstr;

constexpr double kPi = 3.14159265358979323846;
constexpr double kFace = 2.1;  // x of the target's front face; the camera sits at x = 0.1

std::string camera_block(const std::string& type, const std::string& lenses, const std::string& plugin) {
  return R"(<gazebo reference="laser_link"><sensor type=")" + type + R"(" name="cam"><update_rate>10</update_rate>)" +
         lenses + plugin + "</sensor></gazebo>";
}

std::string lens(const std::string& name = "", const std::string& extra = "", const std::string& pose = "") {
  return "<camera" + (name.empty() ? std::string() : " name=\"" + name + "\"") + ">" + pose +
         "<horizontal_fov>1.2</horizontal_fov><image><width>320</width><height>240</height></image>"
         "<clip><near>0.05</near><far>20</far></clip>" + extra + "</camera>";
}

const char* kKinect = R"(<plugin name="k" filename="libgazebo_ros_openni_kinect.so"><cameraName>kinect</cameraName>
  <frameName>kinect_optical</frameName><Cx>166.5</Cx><Cy>117.5</Cy><CxPrime>166.5</CxPrime>
  <pointCloudCutoff>0.3</pointCloudCutoff><pointCloudCutoffMax>10</pointCloudCutoffMax></plugin>)";

struct Rig {
  description::RobotModel robot;
  std::shared_ptr<const physics::PhysicsModel> model;
  std::unique_ptr<physics::Physics> physics;
  // A 0.5 x 0.8 x 0.6 m box whose front face is at x = kFace, centred on the camera's axis.
  explicit Rig(const std::string& gazebo, double box_y = 0.0) : robot(test::parse(test::robot_urdf(gazebo))) {
    physics::BuildOptions o;
    o.world.ground_plane = false;
    o.world.gravity = 0.0;
    physics::WorldBox target;
    target.name = "target";
    target.pose.position = {kFace + 0.25, box_y, 0.5};
    target.size = {0.5, 0.8, 0.6};
    o.world.boxes.push_back(target);
    model = test::build(robot, 0.0, o);
    physics = std::make_unique<physics::Physics>(model);
  }
  // The optical frame of the camera on laser_link (SDF camera: +x forward; optical: z forward).
  Pose X_WC(Vec3 offset = {0, 0, 0}) const {
    const Pose X_WL = physics->link_pose(*model->link_index("laser_link"));
    return physics::compose(X_WL, {offset, physics::quat_from_rpy(-kPi / 2, 0.0, -kPi / 2)});
  }
};

const CameraReading& sample(SensorSet& set, const physics::Physics& p) {
  set.set_enabled(0, true);
  set.sample_all(p, 0.0);
  const auto& r = std::get<CameraReading>(set.reading(0).value);
  EXPECT_EQ(r.error, "");
  return r;
}

// (u, v) of a world point through P (and the optical frame X_WC).
std::array<double, 2> project(const CameraInfo& info, const Pose& X_WC, Vec3 p_W) {
  const Vec3 d{p_W.x - X_WC.position.x, p_W.y - X_WC.position.y, p_W.z - X_WC.position.z};
  const Vec3 p = physics::rotate(physics::quat_conjugate(X_WC.orientation), d);
  const auto& P = info.P;
  const double w = P[8] * p.x + P[9] * p.y + P[10] * p.z + P[11];
  return {(P[0] * p.x + P[1] * p.y + P[2] * p.z + P[3]) / w, (P[4] * p.x + P[5] * p.y + P[6] * p.z + P[7]) / w};
}

// First and last columns (rows) holding a finite depth, over the whole image.
struct Extent {
  int u0 = 1 << 30, u1 = -1, v0 = 1 << 30, v1 = -1;
};
Extent finite_extent(const CameraImage& im) {
  Extent e;
  for (int v = 0; v < im.info.height; ++v)
    for (int u = 0; u < im.info.width; ++u)
      if (std::isfinite(im.depth[static_cast<std::size_t>(v * im.info.width + u)])) {
        e.u0 = std::min(e.u0, u);
        e.u1 = std::max(e.u1, u);
        e.v0 = std::min(e.v0, v);
        e.v1 = std::max(e.v1, v);
      }
  return e;
}

TEST(CameraSensor, BoxFaceCornersProjectThroughCameraInfoP) {
  Rig rig(camera_block("depth", lens(), kKinect));
  SensorSet set(rig.robot.sensors, rig.model, 1);
  const CameraImage& im = sample(set, *rig.physics).images.at(0);
  ASSERT_EQ(im.info.width, 320);
  ASSERT_EQ(im.depth.size(), 320u * 240u);
  const double f = 320 / (2 * std::tan(0.6));
  EXPECT_NEAR(im.info.K[0], f, 1e-9);
  EXPECT_DOUBLE_EQ(im.info.K[2], 166.5);
  EXPECT_DOUBLE_EQ(im.info.P[3], 0.0);
  // The face's corners (y +-0.4, z 0.5 +-0.3 at x = kFace): pixel centres inside the projected
  // rectangle are covered, so the extremes sit within 1 px of the projections.
  const Pose X_WC = rig.X_WC();
  const auto a = project(im.info, X_WC, {kFace, 0.4, 0.8});   // top left in the image
  const auto b = project(im.info, X_WC, {kFace, -0.4, 0.2});  // bottom right
  const Extent e = finite_extent(im);
  EXPECT_NEAR(e.u0, a[0], 1.0);
  EXPECT_NEAR(e.v0, a[1], 1.0);
  EXPECT_NEAR(e.u1, b[0], 1.0);
  EXPECT_NEAR(e.v1, b[1], 1.0);
  RecordProperty("corner_error_px", std::to_string(std::max({std::abs(e.u0 - a[0]), std::abs(e.v0 - a[1]),
                                                            std::abs(e.u1 - b[0]), std::abs(e.v1 - b[1])})));
}

TEST(CameraSensor, DepthOfTheFrontoParallelFaceAndPointsOnIt) {
  Rig rig(camera_block("depth", lens(), kKinect));
  SensorSet set(rig.robot.sensors, rig.model, 1);
  const CameraImage& im = sample(set, *rig.physics).images.at(0);
  const Pose X_WC = rig.X_WC();
  const double Z = kFace - X_WC.position.x;
  double worst_depth = 0.0, worst_point = 0.0;
  int n = 0;
  for (std::size_t k = 0; k < im.depth.size(); ++k) {
    if (!std::isfinite(im.depth[k])) {
      EXPECT_TRUE(std::isnan(im.points[3 * k + 2]));
      continue;
    }
    ++n;
    worst_depth = std::max(worst_depth, std::abs(im.depth[k] - Z) / Z);
    const Vec3 p_C{im.points[3 * k], im.points[3 * k + 1], im.points[3 * k + 2]};
    const Vec3 p_W = physics::compose(X_WC, {p_C, {1, 0, 0, 0}}).position;
    // Distance to the face (a rectangle at x = kFace).
    const double dy = std::max(0.0, std::abs(p_W.y) - 0.4), dz = std::max(0.0, std::abs(p_W.z - 0.5) - 0.3);
    worst_point = std::max(worst_point, std::sqrt((p_W.x - kFace) * (p_W.x - kFace) + dy * dy + dz * dz));
  }
  EXPECT_GT(n, 5000);
  EXPECT_LT(worst_depth, 0.01);
  EXPECT_LT(worst_point, 0.01);
  RecordProperty("depth_rel_error", std::to_string(worst_depth));
  RecordProperty("point_error_m", std::to_string(worst_point));
}

// A multicamera pair 0.12 m apart: the right camera's P carries -f * baseline, and the box's
// edge moves by f b / Z between the images.
TEST(CameraSensor, StereoDisparityMatchesTheBaselineInP) {
  const std::string lenses = lens("left", "", "<pose>0 0.06 0 0 0 0</pose>") + lens("right", "", "<pose>0 -0.06 0 0 0 0</pose>");
  const std::string plugin = R"(<plugin name="s" filename="libgazebo_ros_multicamera.so"><cameraName>stereo</cameraName>
    <hackBaseline>0.12</hackBaseline><frameName>stereo_optical</frameName></plugin>)";
  Rig rig(camera_block("multicamera", lenses, plugin), -0.3);  // box edge at y = 0.1
  SensorSet set(rig.robot.sensors, rig.model, 1);
  const CameraReading& r = sample(set, *rig.physics);
  ASSERT_EQ(r.images.size(), 2u);
  const CameraInfo& right = r.images[1].info;
  const double f = right.P[0];
  EXPECT_DOUBLE_EQ(r.images[0].info.P[3], 0.0);
  EXPECT_NEAR(-right.P[3] / f, 0.12, 1e-12);
  // The box's left edge on the middle row: the first column showing the box's colour.
  auto edge = [](const CameraImage& im) {
    const int v = im.info.height / 2;
    const auto* row = &im.rgb[static_cast<std::size_t>(v * im.info.width) * 3];
    const int sky = row[0];
    for (int u = 0; u < im.info.width; ++u)
      if (std::abs(row[3 * u] - sky) > 20) return u;
    return -1;
  };
  const int ul = edge(r.images[0]), ur = edge(r.images[1]);
  const double Z = kFace - rig.X_WC().position.x;
  EXPECT_NEAR(ul - ur, f * 0.12 / Z, 1.0) << ul << " " << ur;
  RecordProperty("disparity_px", std::to_string(ul - ur));
  RecordProperty("expected_px", std::to_string(f * 0.12 / Z));
}

// Barrel distortion (k1 < 0) pulls the box's edge (at x = -0.5 in normalised coordinates) towards
// the centre by x (1 + k1 x^2); Gazebo's crop (the default) then scales the image about its middle
// by 1 / (1 + k1 r^2) of a corner (r^2 = 0.5 in texture units).
TEST(CameraSensor, DistortionMovesTheEdgeAsPlumbBob) {
  const std::string dist = "<distortion><k1>-0.25</k1><center>0.5 0.5</center></distortion>";
  Rig plain(camera_block("camera", lens(), R"(<plugin name="c" filename="libgazebo_ros_camera.so"/>)"), 0.6);
  Rig bent(camera_block("camera", lens("", dist),
                        R"(<plugin name="c" filename="libgazebo_ros_camera.so"><borderCrop>false</borderCrop></plugin>)"),
           0.6);
  Rig cropped(camera_block("camera", lens("", dist), R"(<plugin name="c" filename="libgazebo_ros_camera.so"/>)"), 0.6);
  SensorSet a(plain.robot.sensors, plain.model, 1), b(bent.robot.sensors, bent.model, 1),
      c(cropped.robot.sensors, cropped.model, 1);
  const CameraImage& ia = sample(a, *plain.physics).images.at(0);
  const CameraImage& ib = sample(b, *bent.physics).images.at(0);
  const CameraImage& ic = sample(c, *cropped.physics).images.at(0);
  const double f = ia.info.K[0], cx = ia.info.K[2], cy = ia.info.K[5];
  auto edge = [&](const CameraImage& im) {
    const int v = static_cast<int>(std::lround(cy));
    const auto* row = &im.rgb[static_cast<std::size_t>(v * im.info.width) * 3];
    for (int u = 0; u < im.info.width; ++u)
      if (std::abs(row[3 * u] - row[0]) > 20) return u;
    return -1;
  };
  const double xu = (edge(ia) - cx) / f;
  const double expected = cx + f * xu * (1 - 0.25 * xu * xu);
  EXPECT_NEAR(edge(ib), expected, 1.0);
  EXPECT_GT(std::abs(edge(ib) - edge(ia)), 2);  // the distortion is visible at all
  const double scale = 1.0 - 0.25 * 0.5;
  EXPECT_NEAR(edge(ic), cx + (expected - cx) / scale, 1.0);
}

TEST(CameraSensor, NoiseIsSeededWithTheConfiguredDeviation) {
  const std::string noisy = "<noise><type>gaussian</type><mean>0</mean><stddev>0.02</stddev></noise>";
  const std::string gz = camera_block("camera", lens("", noisy), "");
  Rig rig(gz), quiet_rig(camera_block("camera", lens(), ""));
  SensorSet s1(rig.robot.sensors, rig.model, 7), s2(rig.robot.sensors, rig.model, 7), q(quiet_rig.robot.sensors, quiet_rig.model, 7);
  const auto one = sample(s1, *rig.physics).images.at(0).rgb;
  const auto two = sample(s2, *rig.physics).images.at(0).rgb;
  const auto clean = sample(q, *quiet_rig.physics).images.at(0).rgb;
  EXPECT_EQ(one, two);  // same seed: the same image
  double sum = 0, sum2 = 0;
  for (std::size_t k = 0; k < one.size(); ++k) {
    const double d = static_cast<double>(one[k]) - clean[k];
    sum += d;
    sum2 += d * d;
  }
  const double n = static_cast<double>(one.size());
  const double sd = std::sqrt(sum2 / n - (sum / n) * (sum / n));
  EXPECT_NEAR(sd, 0.02 * 255, 0.1 * 0.02 * 255);  // rounding to levels adds 1/12 level^2
  EXPECT_NEAR(sum / n, 0.0, 0.1);
}

// Cameras render only when enabled; two cameras due at one instant share one scene update.
TEST(CameraSensor, RendersOnlyForConsumersAndSharesTheScene) {
  const std::string two = camera_block("camera", lens(), "") +
                          R"(<gazebo reference="head"><sensor type="camera" name="cam2"><update_rate>5</update_rate>)" + lens() +
                          "</sensor></gazebo>";
  Rig rig(two);
  SensorSet set(rig.robot.sensors, rig.model, 1);
  ASSERT_NE(set.render_hub(), nullptr);
  EXPECT_FALSE(set.enabled(0));
  set.sample_all(*rig.physics, 0.0);
  EXPECT_EQ(set.reading(0).count, 0u);
  EXPECT_EQ(set.render_hub()->scene_updates(), 0);  // no consumer: no context, no render
  set.set_enabled(0, true);
  set.set_enabled(1, true);
  for (int k = 0; k <= 10; ++k) set.sample_due(*rig.physics, k * 0.1);  // 0 .. 1 s
  EXPECT_EQ(set.reading(0).count, 11u);  // 10 Hz
  EXPECT_EQ(set.reading(1).count, 6u);   // 5 Hz
  EXPECT_EQ(set.render_hub()->renders(), 17);
  EXPECT_EQ(set.render_hub()->scene_updates(), 11);  // one per instant, shared at 0, 0.2, ...
}

// A machine whose EGL is broken: the camera reports why, the IMU next to it samples on. In a
// fresh process, because EGL reads its vendors once.
TEST(CameraSensor, BrokenEglStopsOnlyTheCameras) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        setenv("__EGL_VENDOR_LIBRARY_FILENAMES", "/nonexistent/mechsim_no_such_vendor.json", 1);
        Rig rig(camera_block("camera", lens(), "") + R"(<gazebo reference="head"><sensor type="imu" name="imu"/></gazebo>)");
        SensorSet set(rig.robot.sensors, rig.model, 1);
        set.set_enabled(0, true);
        set.sample_all(*rig.physics, 0.0);
        const auto& r = std::get<CameraReading>(set.reading(0).value);
        const bool imu = std::holds_alternative<ImuReading>(set.reading(1).value) && set.reading(1).count == 1;
        std::fprintf(stderr, "error: %s imu: %d\n", r.error.c_str(), imu ? 1 : 0);
        std::exit(r.images.at(0).rgb.empty() && imu ? 3 : 0);
      },
      ::testing::ExitedWithCode(3), "error: cameras cannot render: .*EGL.* imu: 1");
}

// The ZED2's pattern: a raw camera with distortion and a rectified depth camera at one place, with
// principal points a few pixels apart. They share one render per instant; the raw image, resampled
// from the rectified render, shows the box's edge where the raw camera alone shows it.
std::string raw_and_rect(int raw_width, const std::string& raw_rate = "10") {
  const std::string dist = "<distortion><k1>-0.25</k1><center>0.5 0.5</center></distortion>";
  const std::string raw = R"(<sensor type="camera" name="raw"><update_rate>)" + raw_rate + "</update_rate>" +
                          "<camera><horizontal_fov>1.2</horizontal_fov><image><width>" + std::to_string(raw_width) +
                          "</width><height>240</height></image><clip><near>0.05</near><far>20</far></clip>" + dist +
                          R"(</camera><plugin name="c" filename="libgazebo_ros_camera.so"><Cx>155.5</Cx><Cy>118.5</Cy></plugin></sensor>)";
  const std::string rect = R"(<sensor type="depth" name="rect"><update_rate>10</update_rate>)" + lens() + kKinect + "</sensor>";
  return R"(<gazebo reference="laser_link">)" + raw + rect + "</gazebo>";
}

int edge_column(const CameraImage& im) {
  const int v = static_cast<int>(std::lround(im.info.K[5]));
  const auto* row = &im.rgb[static_cast<std::size_t>(v * im.info.width) * 3];
  for (int u = 0; u < im.info.width; ++u)
    if (std::abs(row[3 * u] - row[0]) > 20) return u;
  return -1;
}

TEST(CameraSensor, RawAndRectifiedImagesShareOneRender) {
  Rig both(raw_and_rect(320), 0.6);
  SensorSet set(both.robot.sensors, both.model, 1);
  ASSERT_EQ(set.size(), 2u);
  set.set_enabled(0, true);
  set.set_enabled(1, true);
  set.sample_all(*both.physics, 0.0);
  EXPECT_EQ(set.render_hub()->renders(), 1);
  const auto& raw = std::get<CameraReading>(set.reading(0).value);
  const auto& rect = std::get<CameraReading>(set.reading(1).value);
  ASSERT_EQ(raw.error, "");
  ASSERT_EQ(rect.error, "");
  EXPECT_DOUBLE_EQ(raw.images.at(0).info.K[2], 155.5);  // each keeps its own intrinsics
  EXPECT_DOUBLE_EQ(rect.images.at(0).info.K[2], 166.5);
  EXPECT_FALSE(rect.images.at(0).depth.empty());

  // The raw camera alone renders through its own intrinsics.
  const std::string alone = raw_and_rect(320);
  Rig solo(alone.substr(0, alone.find(R"(<sensor type="depth")")) + "</gazebo>", 0.6);
  SensorSet one(solo.robot.sensors, solo.model, 1);
  ASSERT_EQ(one.size(), 1u);
  const CameraImage& reference = sample(one, *solo.physics).images.at(0);
  const int shared_edge = edge_column(raw.images.at(0)), own_edge = edge_column(reference);
  ASSERT_GT(own_edge, 0);
  EXPECT_NEAR(shared_edge, own_edge, 1);
  // And sharing is what makes the difference: the rectified camera sees the edge elsewhere.
  EXPECT_GT(std::abs(edge_column(rect.images.at(0)) - own_edge), 2);
}

TEST(CameraSensor, CamerasOfOtherSizesOrRatesRenderApart) {
  for (const auto& [width, rate] : {std::pair{256, "10"}, std::pair{320, "5"}}) {
    Rig rig(raw_and_rect(width, rate));
    SensorSet set(rig.robot.sensors, rig.model, 1);
    set.set_enabled(0, true);
    set.set_enabled(1, true);
    set.sample_all(*rig.physics, 0.0);
    EXPECT_EQ(set.render_hub()->renders(), 2) << width << " px at " << rate << " Hz";
  }
}

TEST(CameraSensor, OpticalFrameAndCameraInfoOfThePlugin) {
  Rig rig(camera_block("camera", lens(), R"(<plugin name="c" filename="libgazebo_ros_camera.so"><focalLength>250</focalLength>
    <hackBaseline>0.07</hackBaseline><distortionK1>0.1</distortionK1></plugin>)"));
  SensorSet set(rig.robot.sensors, rig.model, 1);
  const CameraInfo& info = sample(set, *rig.physics).images.at(0).info;
  EXPECT_EQ(info.distortion_model, "plumb_bob");
  EXPECT_DOUBLE_EQ(info.D[0], 0.1);
  EXPECT_DOUBLE_EQ(info.K[0], 250.0);
  EXPECT_DOUBLE_EQ(info.K[2], 160.5);  // (w + 1) / 2, gazebo_ros_camera_utils' default
  EXPECT_DOUBLE_EQ(info.K[5], 120.5);
  EXPECT_DOUBLE_EQ(info.P[3], -250.0 * 0.07);
}

}  // namespace
}  // namespace mechsim::sensors
