#include "physics/egl_context.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "physics/render_error.hpp"

namespace mechsim::physics {

namespace {

constexpr const char* kInstallHint =
    "; cameras need EGL with Mesa's software renderer (Debian: libegl1 libegl-mesa0 libgl1-mesa-dri) "
    "or a GPU driver with EGL";

// libEGL is opened at run time, not linked: a machine without it still runs everything but
// cameras.
struct EglApi {
  void* lib = nullptr;
  PFNEGLGETPROCADDRESSPROC get_proc = nullptr;
  PFNEGLGETERRORPROC get_error = nullptr;
  PFNEGLGETPLATFORMDISPLAYEXTPROC get_platform_display = nullptr;
  PFNEGLQUERYDEVICESEXTPROC query_devices = nullptr;
  PFNEGLQUERYDEVICESTRINGEXTPROC query_device_string = nullptr;
  PFNEGLINITIALIZEPROC initialize = nullptr;
  PFNEGLBINDAPIPROC bind_api = nullptr;
  PFNEGLCHOOSECONFIGPROC choose_config = nullptr;
  PFNEGLCREATECONTEXTPROC create_context = nullptr;
  PFNEGLDESTROYCONTEXTPROC destroy_context = nullptr;
  PFNEGLMAKECURRENTPROC make_current = nullptr;
  PFNEGLQUERYSTRINGPROC query_string = nullptr;
};

// The library and its entry points are the same for every context of the process; resolving them
// again per context costs microseconds and keeps no process-wide mutable state of ours.
EglApi load_api() {
  EglApi api;
  api.lib = dlopen("libEGL.so.1", RTLD_NOW | RTLD_LOCAL);
  if (api.lib == nullptr) throw RenderUnavailable(std::string("cannot load libEGL.so.1 (") + dlerror() + ")" + kInstallHint);
  api.get_proc = reinterpret_cast<PFNEGLGETPROCADDRESSPROC>(dlsym(api.lib, "eglGetProcAddress"));
  if (api.get_proc == nullptr) throw RenderUnavailable(std::string("libEGL.so.1 has no eglGetProcAddress") + kInstallHint);
  auto get = [&](const char* name) {
    void* f = dlsym(api.lib, name);
    if (f == nullptr) f = reinterpret_cast<void*>(api.get_proc(name));
    return f;
  };
  api.get_error = reinterpret_cast<PFNEGLGETERRORPROC>(get("eglGetError"));
  api.get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(get("eglGetPlatformDisplayEXT"));
  api.query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(get("eglQueryDevicesEXT"));
  api.query_device_string = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(get("eglQueryDeviceStringEXT"));
  api.initialize = reinterpret_cast<PFNEGLINITIALIZEPROC>(get("eglInitialize"));
  api.bind_api = reinterpret_cast<PFNEGLBINDAPIPROC>(get("eglBindAPI"));
  api.choose_config = reinterpret_cast<PFNEGLCHOOSECONFIGPROC>(get("eglChooseConfig"));
  api.create_context = reinterpret_cast<PFNEGLCREATECONTEXTPROC>(get("eglCreateContext"));
  api.destroy_context = reinterpret_cast<PFNEGLDESTROYCONTEXTPROC>(get("eglDestroyContext"));
  api.make_current = reinterpret_cast<PFNEGLMAKECURRENTPROC>(get("eglMakeCurrent"));
  api.query_string = reinterpret_cast<PFNEGLQUERYSTRINGPROC>(get("eglQueryString"));
  if (!api.get_error || !api.get_platform_display || !api.initialize || !api.bind_api || !api.choose_config ||
      !api.create_context || !api.destroy_context || !api.make_current || !api.query_string)
    throw RenderUnavailable(std::string("libEGL.so.1 lacks EGL 1.4 functions or EGL_EXT_platform_base") + kInstallHint);
  return api;
}

std::string hex(EGLint code) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%04x", static_cast<unsigned>(code));
  return buf;
}

struct Display {
  EGLDisplay display = EGL_NO_DISPLAY;
  std::string platform;
  bool gpu = false;
};

constexpr int kMaxDevices = 16;

std::vector<EglDeviceInfo> list_devices(const EglApi& api, std::vector<EGLDeviceEXT>* handles = nullptr) {
  std::vector<EglDeviceInfo> out;
  if (api.query_devices == nullptr) return out;
  EGLDeviceEXT devices[kMaxDevices];
  EGLint n = 0;
  if (api.query_devices(kMaxDevices, devices, &n) != EGL_TRUE) return out;
  for (EGLint i = 0; i < n; ++i) {
    EglDeviceInfo info;
    info.index = i;
    const auto text = [&](EGLint name) {
      const char* s = api.query_device_string != nullptr ? api.query_device_string(devices[i], name) : nullptr;
      return s != nullptr ? std::string(s) : std::string();
    };
    info.extensions = text(EGL_EXTENSIONS);
    info.software = info.extensions.find("EGL_MESA_device_software") != std::string::npos;
    if (info.extensions.find("EGL_EXT_device_drm_render_node") != std::string::npos) info.node = text(EGL_DRM_RENDER_NODE_FILE_EXT);
    if (info.node.empty() && info.extensions.find("EGL_EXT_device_drm") != std::string::npos) info.node = text(EGL_DRM_DEVICE_FILE_EXT);
    out.push_back(std::move(info));
    if (handles != nullptr) handles->push_back(devices[i]);
  }
  return out;
}

bool cpu_chosen() {
  const char* env = std::getenv("MECHSIM_RENDER_DEVICE");
  return env != nullptr && std::string(env) == "cpu";
}

// A GPU of the device platform first (unless `cpu_only`), then the surfaceless platform
// (llvmpipe), then a software device of the device platform (an EGL with devices but no
// surfaceless platform).
Display open_display(const EglApi& api, std::string& tried, bool cpu_only) {
  EGLint major = 0, minor = 0;
  const auto version = [&] { return "EGL " + std::to_string(major) + "." + std::to_string(minor); };
  std::vector<EGLDeviceEXT> handles;
  const std::vector<EglDeviceInfo> devices = list_devices(api, &handles);
  const auto device_display = [&](std::size_t i) -> Display {
    EGLDisplay d = api.get_platform_display(EGL_PLATFORM_DEVICE_EXT, handles[i], nullptr);
    if (d == EGL_NO_DISPLAY || api.initialize(d, &major, &minor) != EGL_TRUE) {
      tried += (tried.empty() ? "" : "; ") + std::string("device ") + std::to_string(i) + ": EGL error " + hex(api.get_error());
      return {};
    }
    const EglDeviceInfo& info = devices[i];
    return {d, version() + " device " + std::to_string(i) + (info.node.empty() ? "" : " (" + info.node + ")"), !info.software};
  };
  if (!cpu_only) {
    for (std::size_t i = 0; i < devices.size(); ++i)
      if (!devices[i].software)
        if (Display d = device_display(i); d.display != EGL_NO_DISPLAY) return d;
  }
  EGLDisplay d = api.get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (d != EGL_NO_DISPLAY && api.initialize(d, &major, &minor) == EGL_TRUE) return {d, version() + " surfaceless", false};
  tried += (tried.empty() ? "" : "; ") + std::string("surfaceless platform: EGL error ") + hex(api.get_error());
  for (std::size_t i = 0; i < devices.size(); ++i)
    if (devices[i].software)
      if (Display dd = device_display(i); dd.display != EGL_NO_DISPLAY) return dd;
  if (devices.empty()) tried += "; device platform: no devices";
  return {};
}

// A desktop OpenGL context on `disp` (made, not current); "" or what failed.
std::string make_context(const EglApi& api, const Display& disp, EGLContext& ctx) {
  if (api.bind_api(EGL_OPENGL_API) != EGL_TRUE)
    return "EGL display offers no desktop OpenGL (EGL error " + hex(api.get_error()) + ")";
  const EGLint attributes[] = {EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8,
                               EGL_DEPTH_SIZE, 24, EGL_STENCIL_SIZE, 8, EGL_COLOR_BUFFER_TYPE, EGL_RGB_BUFFER,
                               EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint count = 0;
  if (api.choose_config(disp.display, attributes, &config, 1, &count) != EGL_TRUE || count < 1)
    return "EGL has no 8-bit RGBA + 24-bit depth OpenGL configuration (EGL error " + hex(api.get_error()) + ")";
  ctx = api.create_context(disp.display, config, EGL_NO_CONTEXT, nullptr);
  if (ctx == EGL_NO_CONTEXT) return "eglCreateContext failed (EGL error " + hex(api.get_error()) + ")";
  return "";
}

}  // namespace

struct EglState {
  EglApi api;
};

EglContext::EglContext() {
  // The API table lives as long as the context: keep it beside the handles.
  static_assert(sizeof(void*) == sizeof(EGLDisplay));
  const EglApi api = load_api();
  std::string tried, fallback;
  Display disp = open_display(api, tried, cpu_chosen());
  if (disp.display == EGL_NO_DISPLAY) throw RenderUnavailable("no EGL display (" + tried + ")" + kInstallHint);
  EGLContext ctx = EGL_NO_CONTEXT;
  std::string failed = make_context(api, disp, ctx);
  if (!failed.empty() && disp.gpu) {
    // A GPU whose driver offers no usable OpenGL context: the CPU renders instead, and the
    // description says why.
    fallback = "; the GPU (" + disp.platform + ") failed: " + failed;
    tried = disp.platform + ": " + failed;
    disp = open_display(api, tried, true);
    if (disp.display == EGL_NO_DISPLAY) throw RenderUnavailable("no EGL display (" + tried + ")" + kInstallHint);
    failed = make_context(api, disp, ctx);
  }
  if (!failed.empty()) throw RenderUnavailable(failed + kInstallHint);
  display_ = disp.display;
  context_ = ctx;
  api_ = std::make_unique<EglState>(EglState{api});
  make_current();
  using GetString = const unsigned char* (*)(unsigned);
  auto get_string = reinterpret_cast<GetString>(api.get_proc("glGetString"));
  auto text = [&](unsigned name) {
    const unsigned char* s = get_string != nullptr ? get_string(name) : nullptr;
    return s != nullptr ? std::string(reinterpret_cast<const char*>(s)) : std::string();
  };
  const std::string renderer = text(0x1F01 /* GL_RENDERER */), version = text(0x1F02 /* GL_VERSION */);
  if (version.empty()) throw RenderUnavailable("the EGL context answers no OpenGL version" + std::string(kInstallHint));
  description_ = disp.platform + ": " + renderer + ", OpenGL " + version + fallback;
  // A hardware device whose driver still renders in software (Mesa's fallbacks) is the CPU.
  on_gpu_ = disp.gpu && renderer.find("llvmpipe") == std::string::npos && renderer.find("softpipe") == std::string::npos;
  // MuJoCo's renderer needs OpenGL 1.5 with framebuffer objects; its own check would exit().
  const int major = version[0] - '0', minor = version.size() > 2 ? version[2] - '0' : 0;
  if (major < 1 || (major == 1 && minor < 5) || major > 9)
    throw RenderUnavailable("OpenGL " + version + " is older than MuJoCo's renderer needs (1.5)");
}

EglContext::~EglContext() {
  if (api_ == nullptr) return;
  const EglApi& api = api_->api;
  api.make_current(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  api.destroy_context(display_, context_);
  // The display is left initialised: EGL displays are per process, other renderers may use it.
}

std::vector<EglDeviceInfo> egl_devices() {
  try {
    return list_devices(load_api());
  } catch (const RenderUnavailable&) {
    return {};
  }
}

void* EglContext::proc(const char* name) const { return reinterpret_cast<void*>(api_->api.get_proc(name)); }

void EglContext::make_current() const {
  const EglApi& api = api_->api;
  if (api.make_current(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_) != EGL_TRUE)
    throw RenderUnavailable("eglMakeCurrent failed (EGL error " + hex(api.get_error()) + ")");
}

}  // namespace mechsim::physics
