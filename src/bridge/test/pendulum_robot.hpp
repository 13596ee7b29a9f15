#pragma once
// The ROS unit tests' small robot: sim/test/pendulum_urdf.hpp's pendulum with its bob level (it
// swings under gravity about y).
#include <string>

#include "../../sim/test/pendulum_urdf.hpp"

namespace mechsim::bridge::test {

inline std::string pendulum_urdf(int reduction) { return mechsim::test::pendulum_urdf(reduction, true); }

}  // namespace mechsim::bridge::test
