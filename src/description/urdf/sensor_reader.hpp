#pragma once
// Gazebo sensor blocks outside a URDF (a scenario adding a sensor to a robot whose description
// has none): the same reader as the URDF's <gazebo> elements, the same errors.

#include <string>
#include <string_view>
#include <vector>

#include "description/robot_model.hpp"
#include "description/sensor_spec.hpp"

namespace mechsim::description {

// Reads every sensor of `xml`: one or more <gazebo reference="LINK"><sensor ...>...</gazebo>
// elements (and top-level <gazebo><plugin> sensor plugins), as a URDF holds them, against the
// links and joints of `robot`. Lines are counted from `first_line` of `source` (a YAML block
// scalar starting at that line). Throws DescriptionError naming file, line and sensor for every
// problem; appends warnings when given.
std::vector<SensorSpec> read_sensor_blocks(std::string_view xml, const RobotModel& robot, const std::string& source,
                                           int first_line, std::vector<std::string>* warnings = nullptr);

}  // namespace mechsim::description
