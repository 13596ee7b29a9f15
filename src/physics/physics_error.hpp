#pragma once
// Bad input found while building or loading a physics model (names the element and cause).

#include <stdexcept>
#include <string>

namespace mechsim::physics {

class PhysicsError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace mechsim::physics
