#pragma once
// Internal to the URDF reader (urdf_*.cpp): the tinyxml2 passes that run before and beside
// urdfdom. Not part of the public API.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <tinyxml2.h>

#include "description/robot_model.hpp"
#include "description/urdf/validation.hpp"

namespace mechsim::description::detail {

// A number as URDF writes it (optional leading '+', surrounding blanks); nullopt when the text is
// not one whole number. "nan"/"inf" parse (they are reported as not finite, not as not numbers).
std::optional<double> parse_number(std::string_view text);

// Whitespace-separated numbers; nullopt when any piece is not a number.
std::optional<std::vector<double>> parse_numbers(std::string_view text);

// "true"/"false"/"1"/"0" (any case); nullopt otherwise.
std::optional<bool> parse_bool(std::string_view text);

// The element's 'value' attribute when it has one, else its trimmed text.
std::string value_text(const tinyxml2::XMLElement& e);

// The element with its attributes, trimmed text and children, keeping line numbers.
XmlNode to_xml_node(const tinyxml2::XMLElement& element);

// Records the problems of one document, each prefixed "SOURCE:LINE: ".
class Problems {
 public:
  explicit Problems(std::string source) : source_(std::move(source)) {}
  void error(int line, const std::string& message);
  void warning(int line, const std::string& message);
  const std::string& source() const { return source_; }
  ValidationReport& report() { return report_; }

  // Checks of an element's attributes. `what` names the owner ("joint 'j1'"). They record an
  // error and return nullopt when the attribute is required but missing, is not a number (or
  // the wrong count of numbers), or is not finite.
  std::optional<std::string> text_attribute(const tinyxml2::XMLElement& e, const char* attr,
                                            const std::string& what, bool required);
  std::optional<double> number_attribute(const tinyxml2::XMLElement& e, const char* attr,
                                         const std::string& what, bool required);
  std::optional<std::vector<double>> numbers_attribute(const tinyxml2::XMLElement& e,
                                                       const char* attr, std::size_t count,
                                                       const std::string& what, bool required);
  // value_text as a number (for <mu1>0.2</mu1>, <mu1 value="0.2"/> and the like).
  std::optional<double> number_text(const tinyxml2::XMLElement& e, const std::string& what);

 private:
  std::string source_;
  ValidationReport report_;
};

// Checks what urdfdom would reject or misreport (missing attributes, unknown joint types,
// non-numbers, non-finite values) and fills `skeleton` with the links and joints (names, lines,
// joint types and parent/child) in document order, for the structural checks that must pass
// before urdfdom builds its tree.
void precheck_urdf(const tinyxml2::XMLElement& robot, Problems& problems, RobotModel& skeleton);

// <transmission> elements in the ros_control and the PR2 formats.
void read_transmissions(const tinyxml2::XMLElement& robot, Problems& problems, RobotModel& model);

// <gazebo> elements: per-link and per-joint properties, plugins (also those inside sensors).
void read_gazebo(const tinyxml2::XMLElement& robot, Problems& problems, RobotModel& model);

// <ros2_control> tags (description/ros2_control.hpp): their structure, then (on the built model,
// after the references are checked) their joints, interfaces, mimic relations and sensors
// against the robot. check_ros2_control also sets the URDF mimic of a joint that Humble's
// <param name="mimic"> makes a follower (mechsim's physics makes mimic joints constraints).
void read_ros2_control(const tinyxml2::XMLElement& robot, Problems& problems, RobotModel& model);
void check_ros2_control(RobotModel& model, Problems& problems);

}  // namespace mechsim::description::detail
