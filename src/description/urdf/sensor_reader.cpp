#include "description/urdf/sensor_reader.hpp"

#include <sstream>

#include "description/urdf/urdf_parser.hpp"
#include "description/urdf/urdf_sensors.hpp"

namespace mechsim::description {

namespace {

void shift_lines(XmlNode& node, int offset) {
  node.line += offset;
  for (XmlNode& c : node.children) shift_lines(c, offset);
}

[[noreturn]] void fail(const std::vector<std::string>& errors) {
  std::ostringstream msg;
  for (std::size_t i = 0; i < errors.size(); ++i) msg << (i ? "\n" : "") << errors[i];
  throw DescriptionError(msg.str(), errors);
}

}  // namespace

std::vector<SensorSpec> read_sensor_blocks(std::string_view xml, const RobotModel& robot, const std::string& source,
                                           int first_line, std::vector<std::string>* warnings) {
  // A wrapper root lets the text hold several <gazebo> elements; it adds no line.
  const std::string wrapped = "<sensors>" + std::string(xml) + "</sensors>";
  tinyxml2::XMLDocument doc;
  const int offset = first_line > 0 ? first_line - 1 : 0;
  if (doc.Parse(wrapped.data(), wrapped.size()) != tinyxml2::XML_SUCCESS) {
    fail({location(source, doc.ErrorLineNum() + offset) + "malformed XML in the sensor block: " +
          (doc.ErrorStr() != nullptr ? std::string(doc.ErrorStr()) : std::string("?"))});
  }
  detail::Problems problems(source);
  std::vector<SensorSpec> out;
  int gazebo_elements = 0;
  for (const tinyxml2::XMLElement* g = doc.RootElement()->FirstChildElement(); g != nullptr; g = g->NextSiblingElement()) {
    XmlNode node = detail::to_xml_node(*g);
    shift_lines(node, offset);
    if (node.name != "gazebo") {
      problems.error(node.line, "expected <gazebo reference=\"LINK\"> elements holding <sensor>s, found <" + node.name + ">");
      continue;
    }
    ++gazebo_elements;
    const std::string reference = node.attribute("reference").value_or("");
    for (const XmlNode& c : node.children) {
      if (c.name == "sensor") {
        detail::read_sensor(c, reference, robot, problems, out);
      } else if (c.name == "plugin") {
        if (!detail::read_sensor_plugin(c, robot, problems, out))
          problems.error(c.line, "plugin '" + c.attribute("filename").value_or("") + "' is not a sensor plugin");
      } else {
        problems.error(c.line, "<" + c.name + "> in a sensor block: only <sensor> and sensor <plugin>s belong here");
      }
    }
  }
  if (gazebo_elements == 0 && problems.report().errors.empty())
    problems.error(first_line, "the sensor block holds no <gazebo> element");
  for (const SensorSpec& s : out)
    for (const SensorSpec& t : robot.sensors)
      if (s.name == t.name) problems.error(s.line, "sensor '" + s.name + "': the robot already has a sensor so named (" + t.where() + ")");
  if (!problems.report().ok()) fail(problems.report().errors);
  if (warnings != nullptr)
    warnings->insert(warnings->end(), problems.report().warnings.begin(), problems.report().warnings.end());
  return out;
}

}  // namespace mechsim::description
