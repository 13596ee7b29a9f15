#pragma once
// Private to src/physics: an OpenGL context without a window, for MuJoCo's offscreen renderer.
//
// Which device: a GPU when the machine has one, else the CPU. EGL's device platform lists every
// device its vendors drive (EGL_EXT_device_enumeration): a GPU (NVIDIA's driver, or Mesa's for a
// DRM render node) comes first; a software device (Mesa's llvmpipe, EGL_MESA_device_software) is
// skipped there. Without a GPU, Mesa's surfaceless platform (llvmpipe on the CPU). Surfaceless
// alone would not do: under libglvnd it answers with Mesa, which renders on the CPU beside an
// NVIDIA GPU it cannot drive. MECHSIM_RENDER_DEVICE=cpu chooses the CPU whatever is there. A GPU
// whose driver makes no desktop OpenGL context falls back to the CPU (description() says why).

#include <memory>
#include <string>
#include <vector>

namespace mechsim::physics {

// One device of EGL's device platform.
struct EglDeviceInfo {
  int index = 0;
  bool software = false;  // EGL_MESA_device_software: a CPU renderer
  std::string node;       // its DRM render node (or device file), when EGL names one
  std::string extensions;
};

// The devices EGL lists (empty without libEGL or EGL_EXT_device_enumeration); never throws.
std::vector<EglDeviceInfo> egl_devices();

struct EglState;  // the EGL entry points (egl_context.cpp)

class EglContext {
 public:
  // Creates a desktop OpenGL context and makes it current on this thread. Throws
  // RenderUnavailable saying which EGL step failed (no EGL library/vendor, no display, no
  // OpenGL config, no context) and what to install.
  EglContext();
  ~EglContext();
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  // Makes the context current on the calling thread (another renderer may have taken it).
  void make_current() const;
  // "EGL 1.5 surfaceless: llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5 (Compatibility Profile) Mesa 22.3.6",
  // "EGL 1.5 device 0 (/dev/dri/renderD128): NVIDIA H200/PCIe/SSE2, OpenGL 4.6.0 NVIDIA 550.54.15"
  const std::string& description() const { return description_; }
  // Whether the context renders on a GPU (a hardware EGL device), not on the CPU.
  bool on_gpu() const { return on_gpu_; }
  // An OpenGL entry point of the context's driver (null when it has none).
  void* proc(const char* name) const;

 private:
  std::unique_ptr<EglState> api_;
  void* display_ = nullptr;
  void* context_ = nullptr;
  std::string description_;
  bool on_gpu_ = false;
};

}  // namespace mechsim::physics
