#pragma once
// Reading URDF documents into a RobotModel: urdfdom for links and joints, tinyxml2 for what
// urdfdom ignores (transmissions in the ros_control and PR2 formats, gazebo extensions), then
// validation (description/urdf/validation.hpp).

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "description/package_path.hpp"
#include "description/robot_model.hpp"

namespace mechsim::description {

// Bad input in a description. what() names the file, line where known, the link/joint/element
// and what is wrong; `problems` lists every problem found when there were several.
class DescriptionError : public std::runtime_error {
 public:
  explicit DescriptionError(const std::string& message, std::vector<std::string> problems = {})
      : std::runtime_error(message), problems_(std::move(problems)) {}
  const std::vector<std::string>& problems() const { return problems_; }

 private:
  std::vector<std::string> problems_;
};

struct UrdfOptions {
  // Physical-plausibility problems (mass, inertia, limits) become warnings instead of errors,
  // for descriptions a user cannot fix. Structural problems stay errors.
  bool lenient = false;
  PackageMap packages;  // for package:// mesh URIs
};

// Parses and validates. Throws DescriptionError. Warnings (and, when lenient, downgraded
// errors) are appended to `warnings` when given.
RobotModel parse_urdf_string(std::string_view xml, const std::string& source_name,
                             const UrdfOptions& options, std::vector<std::string>* warnings = nullptr);
RobotModel parse_urdf_file(const std::string& path, const UrdfOptions& options,
                           std::vector<std::string>* warnings = nullptr);

}  // namespace mechsim::description
