// `mechsim render SCENARIO --at T`: one frame of every camera at T, at the size a scenario's
// camera_overrides asks for; a robot without cameras and a time past the run are errors.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <unistd.h>

#include "run_process.hpp"

namespace mechsim::apps::test {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

const fs::path kSource = MECHSIM_SOURCE_DIR;

ProcessResult mechsim(std::vector<std::string> args, double timeout = 300.0) {
  args.insert(args.begin(), MECHSIM_EXE);
  return run_process(args, timeout);
}

// Width and height from a PNG's IHDR chunk; {0, 0} when the file is no PNG.
std::pair<std::uint32_t, std::uint32_t> png_size(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  unsigned char h[24] = {};
  if (!in.read(reinterpret_cast<char*>(h), sizeof h) || h[1] != 'P' || h[2] != 'N' || h[3] != 'G') return {0, 0};
  auto be = [&](int at) {
    return (std::uint32_t{h[at]} << 24) | (std::uint32_t{h[at + 1]} << 16) | (std::uint32_t{h[at + 2]} << 8) | h[at + 3];
  };
  return {be(16), be(20)};
}

class RenderCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mechsim_render_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(dir_);
  }
  // The CC8 with its ZED2 on flat ground, every camera at 320 pixels wide and 2 Hz.
  fs::path scenario(const std::string& extra = "") {
    const fs::path cc8 = kSource / "robots/cc8";
    const fs::path file = dir_ / "zed2_small.yaml";
    std::ofstream(file) << "name: zed2_small\n"
                        << "robot: {description: " << (cc8 / "urdf/cc8.urdf.xacro").string() << ", packages: {mechsim_cc8: "
                        << cc8.string() << "}}\n"
                        << "world: {name: empty}\n"
                        << "controllers: {file: " << (cc8 / "config/controllers.yaml").string()
                        << ", namespace: cc8, start: [joint_state_controller]}\n"
                        << "duration: 1\n"
                        << "camera_overrides: {all: {width: 320, rate: 2}}\n"
                        << extra;
    return file;
  }
  fs::path dir_;
};

TEST_F(RenderCli, WritesOneFrameOfEveryCameraAtTheOverriddenSize) {
  const fs::path out = dir_ / "frames";
  const ProcessResult r = mechsim({"render", scenario().string(), "--at", "0.25", "-o", out.string()});
  ASSERT_TRUE(r.started);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  std::vector<fs::path> frames;
  for (const auto& e : fs::directory_iterator(out / "cameras")) {
    if (e.path().extension() == ".png") frames.push_back(e.path());
  }
  // The ZED2 set: left and right raw, left and right rectified, the depth camera's colour and depth.
  EXPECT_GE(frames.size(), 4u) << r.out;
  for (const fs::path& f : frames) {
    EXPECT_THAT(f.filename().string(), HasSubstr("0.25")) << "the frame's time in its name";
    const auto [w, h] = png_size(f);
    EXPECT_EQ(w, 320u) << f;
    EXPECT_EQ(h, 180u) << f;  // 1280x720 scaled, the aspect ratio kept
    EXPECT_THAT(r.out, HasSubstr(f.filename().string()));
  }
  EXPECT_TRUE(fs::exists(out / "camera_sheet.png"));
}

TEST_F(RenderCli, AnUnknownCameraInTheOverridesIsAnErrorNamingTheScenarioLine) {
  const fs::path bad = dir_ / "bad_name.yaml";
  {
    std::ifstream in(scenario());
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    text.replace(text.find("all:"), 4, "zed9:");
    std::ofstream(bad) << text;
  }
  const ProcessResult r = mechsim({"render", bad.string(), "--at", "0.1", "-o", (dir_ / "none").string()});
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_THAT(r.err, HasSubstr("camera override 'zed9': the robot has no camera sensor of that name"));
  EXPECT_THAT(r.err, HasSubstr("bad_name.yaml:"));
}

TEST_F(RenderCli, ARobotWithoutCamerasIsAnError) {
  const fs::path file = dir_ / "turntable.yaml";
  std::ofstream(file) << "name: turntable\nrobot: {description: " << (kSource / "robots/testbots/urdf/turntable.urdf").string()
                      << "}\nworld: {name: empty}\nduration: 1\n";
  const ProcessResult r = mechsim({"render", file.string(), "--at", "0.1", "-o", (dir_ / "t").string()});
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_THAT(r.err, HasSubstr("no camera frame was written"));
}

}  // namespace
}  // namespace mechsim::apps::test
