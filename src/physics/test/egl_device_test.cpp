// Which device the offscreen renderer's EGL context renders on: a GPU when EGL lists one (its
// device platform, EGL_EXT_device_enumeration), else the CPU (Mesa's llvmpipe), and the CPU
// whatever is there when MECHSIM_RENDER_DEVICE=cpu. The GPU test runs only where a GPU and its EGL
// driver are; elsewhere it skips saying what it found.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "physics/egl_context.hpp"
#include "physics/renderer.hpp"
#include "physics/transform.hpp"
#include "physics_test_util.hpp"

namespace mechsim::physics {
namespace {

// GPU device files the kernel offers (NVIDIA's, DRM render nodes): evidence of a GPU that does not
// come from EGL.
std::vector<std::string> gpu_device_files() {
  std::vector<std::string> out;
  std::error_code ec;
  if (std::filesystem::exists("/dev/nvidia0", ec)) out.push_back("/dev/nvidia0");
  for (const auto& e : std::filesystem::directory_iterator("/dev/dri", ec))
    if (e.path().filename().string().rfind("renderD", 0) == 0) out.push_back(e.path().string());
  return out;
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

// Where EGL lists a hardware device, the context is made on it and draws there (its renderer is
// not llvmpipe), and a renderer on it draws a box where the pinhole model puts it.
TEST(EglDevice, PicksTheGpuWhenOneIsPresent) {
  const std::vector<EglDeviceInfo> devices = egl_devices();
  std::vector<std::string> hardware;
  for (const auto& d : devices)
    if (!d.software) hardware.push_back("device " + std::to_string(d.index) + (d.node.empty() ? "" : " " + d.node));
  const std::vector<std::string> files = gpu_device_files();
  if (hardware.empty()) {
    if (files.empty())
      GTEST_SKIP() << "no GPU on this machine: EGL lists " << devices.size()
                   << " device(s), all software, and there is no /dev/nvidia0 or /dev/dri/renderD*";
    GTEST_SKIP() << "GPU device files (" << join(files) << ") but EGL lists no hardware device among its "
                 << devices.size() << ": the GPU's EGL driver (e.g. NVIDIA's libEGL_nvidia, Mesa's for DRM) is not installed";
  }
  EglContext ctx;
  EXPECT_TRUE(ctx.on_gpu()) << "EGL lists " << join(hardware) << " yet the context is " << ctx.description();
  EXPECT_NE(ctx.description().find(" device "), std::string::npos) << ctx.description();
  EXPECT_EQ(ctx.description().find("llvmpipe"), std::string::npos) << ctx.description();
  std::printf("rendering on: %s\n", ctx.description().c_str());

  // A renderer on it draws: a 1 m cube 3 m ahead fills the image's centre, at 2.5 m depth.
  BuildOptions o;
  o.world.ground_plane = false;
  o.world.gravity = 0.0;
  WorldBox b;
  b.name = "cube";
  b.pose.position = {3.0, 0.0, 1.0};
  b.size = {1.0, 1.0, 1.0};
  o.world.boxes.push_back(b);
  o.spawn.x = -100.0;
  auto model = test::build(test::box_urdf(), o);
  RenderSettings s;
  s.max_width = 64;
  s.max_height = 48;
  Renderer r(model, s);
  EXPECT_EQ(r.context_description().find("llvmpipe"), std::string::npos) << r.context_description();
  Physics p(model);
  r.update_scene(p);
  CameraView v;
  v.X_WC = {{0.0, 0.0, 1.0}, quat_from_rpy(-1.5707963267948966, 0.0, -1.5707963267948966)};
  v.width = 64;
  v.height = 48;
  v.fx = v.fy = 32.0;
  v.cx = 31.5;
  v.cy = 23.5;
  Frame f;
  r.render(v, f);
  EXPECT_NEAR(f.depth[24 * 64 + 32], 2.5, 0.01);
}

// MECHSIM_RENDER_DEVICE=cpu: the CPU (llvmpipe) whatever the machine has. In a fresh process,
// because EGL initialises its displays once.
TEST(EglDevice, CpuChosenRendersOnTheCpu) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        setenv("MECHSIM_RENDER_DEVICE", "cpu", 1);
        try {
          EglContext ctx;
          std::fprintf(stderr, "context: %s (on_gpu %d)\n", ctx.description().c_str(), ctx.on_gpu() ? 1 : 0);
          std::exit(ctx.on_gpu() ? 1 : 0);
        } catch (const RenderUnavailable& e) {
          std::fprintf(stderr, "unavailable: %s\n", e.what());
          std::exit(2);
        }
      },
      ::testing::ExitedWithCode(0), "context: .*llvmpipe.*on_gpu 0");
}

}  // namespace
}  // namespace mechsim::physics
