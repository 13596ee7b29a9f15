#pragma once
// Params from an XML element: how a Gazebo model plugin's <plugin> element becomes the parameters
// of the controller that simulates it (DESIGN.md, "Gazebo plugins in a description"). Each child
// element is a key: one with text only is a plain scalar (converted on demand, like a YAML plain
// scalar: "0.5" reads as a number, "true" as a boolean), one with child elements a map of them;
// an empty element (<hasPID/>) is an empty scalar. A repeated child keeps its first occurrence,
// as sdformat's GetElement does. Attributes are not parameters. Every node keeps its line, so
// that errors read "parameter /<root>/<key>: ... (file:line)".

#include <string>

#include "control/params.hpp"
#include "description/robot_model.hpp"

namespace mechsim::control {

// The tree's root is a map holding one key, `root_name`; the result is that key's node (path
// "/<root_name>", the element's line). `source` is the file named in messages.
Params params_from_xml(const description::XmlNode& element, const std::string& source, const std::string& root_name);

}  // namespace mechsim::control
