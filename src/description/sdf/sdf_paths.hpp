#pragma once
// Private to description/sdf and the SDF module (description/sdformat): where model://, file://
// and package:// URIs of an SDF file lead, and mechsim's own versions of Gazebo's most used
// library models for <include>s that find no other.

#include <string>
#include <vector>

#include "description/package_path.hpp"
#include "description/sdf/sdf_model.hpp"

namespace mechsim::description::sdf_detail {

struct SdfSearch {
  std::vector<std::string> model_dirs;     // roots of model://<name>/..., in order
  std::vector<std::string> resource_dirs;  // GAZEBO_RESOURCE_PATH (file://media/... in Gazebo worlds)
  PackageMap packages;
};

SdfSearch make_search(const SdfOptions& options);

// The file a mesh or heightmap URI names, written in `from_file` (relative paths resolve against
// its folder); empty when it cannot be found.
std::string resolve_uri(const std::string& uri, const std::string& from_file, const SdfSearch& search);

// A temporary folder holding mechsim's own versions of Gazebo library models worlds name most
// (`ground_plane`, `sun`, `checkerboard_plane`, `asphalt_plane`: model.config and model.sdf
// each) for the parser's model:// search, after every other model path; removed on destruction.
class BuiltinModels {
 public:
  BuiltinModels();
  ~BuiltinModels();
  BuiltinModels(const BuiltinModels&) = delete;
  BuiltinModels& operator=(const BuiltinModels&) = delete;
  const std::string& dir() const { return dir_; }

 private:
  std::string dir_;
};

}  // namespace mechsim::description::sdf_detail
