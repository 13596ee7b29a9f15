#pragma once
// Rendering cannot work on this machine (no usable EGL/OpenGL): cameras are off, everything else
// runs. The message says which step failed and what to install.

#include <stdexcept>

namespace mechsim::physics {

class RenderUnavailable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace mechsim::physics
