#pragma once
// The PR2's fingertip pressure pads (pr2_msgs/PressureState on /pressure/<side>_gripper_motor),
// made from the fingertips' contact sensors as pr2_gazebo did (its contact-to-pressure
// translator fed by the fingertip bumpers): each fingertip has 22 sensing elements — one on the
// back, six around the edges, a 3 x 5 array on the front — whose rectangles in the fingertip
// link's frame are those of the fingertip_pressure package's sensor geometry. A contact point
// adds the force pressing into the element it lies on (within kPressureElementReach of its
// rectangle; the nearest element when several are) times the element's force_per_unit (raw
// units per newton: 1600 front array, 600 back and corners, 400 sides; the package's viewer
// divides by it to show newtons), clamped to int16.
// Compiles as C++17 too (the ROS layer calls it).

#include <array>
#include <cstdint>

#include "sensors/sensor_output.hpp"

namespace mechsim::sensors {

inline constexpr int kFingertipPressureElements = 22;
// How far (m) a contact point may lie from an element's rectangle (in-plane and along its normal)
// and still count for it: the physics' collision shape is the fingertip mesh, not the pads.
inline constexpr double kPressureElementReach = 0.004;

enum class Fingertip { Left, Right };  // the gripper's l_finger_tip / r_finger_tip

// The force (N) pressing into each of one fingertip's 22 elements, from its contact sensor's
// reading: its points (world frame) taken into the fingertip link's frame by the reading's X_WL,
// its forces in the fingertip's own body frame (the link's: a fingertip is a body). MuJoCo reports one to four points per touching pair, so an object loads
// the elements under those points only (as Gazebo's point contacts did), not its whole patch.
std::array<double, kFingertipPressureElements> fingertip_pad_forces(const ContactsReading& contacts, Fingertip finger);

// The 22 raw readings: fingertip_pad_forces times each element's units per newton, rounded and
// clamped to [0, 32767] (an element saturates at 20.5 N on the front array).
std::array<std::int16_t, kFingertipPressureElements> fingertip_pressure(const ContactsReading& contacts,
                                                                         Fingertip finger);

// Element k's centre (m) and outward normal in the fingertip link frame (for tests and displays).
Vec3 fingertip_element_centre(int k, Fingertip finger);
Vec3 fingertip_element_normal(int k, Fingertip finger);

}  // namespace mechsim::sensors
