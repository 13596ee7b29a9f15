#pragma once
// Private to src/physics: an OpenGL context without a window, for MuJoCo's offscreen renderer.
// EGL's surfaceless platform (Mesa: llvmpipe on the CPU, or a GPU's render node when the machine
// has one), else EGL's device platform (a GPU whose driver offers it, e.g. NVIDIA's).

#include <memory>
#include <string>

namespace mechsim::physics {

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
  // "EGL 1.5 surfaceless: llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5 (Compatibility Profile) Mesa 22.3.6"
  const std::string& description() const { return description_; }
  // An OpenGL entry point of the context's driver (null when it has none).
  void* proc(const char* name) const;

 private:
  std::unique_ptr<EglState> api_;
  void* display_ = nullptr;
  void* context_ = nullptr;
  std::string description_;
};

}  // namespace mechsim::physics
