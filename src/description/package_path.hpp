#pragma once
// Finding ROS packages by name, as `$(find pkg)` and `package://pkg/...` need: first the explicit
// NAME=DIR map (the CLI's --package), then every directory under ROS_PACKAGE_PATH holding a
// package.xml whose <name> is NAME (or, lacking one, a directory so named).

#include <map>
#include <optional>
#include <string>

namespace mechsim::description {

using PackageMap = std::map<std::string, std::string>;

// The package's directory, or nullopt when it cannot be found.
std::optional<std::string> find_package(const std::string& name, const PackageMap& explicit_packages);

// Resolves `package://pkg/rel` and `file://abs` URIs and plain paths (relative ones against
// `base_dir`). Returns nullopt when the package is unknown.
std::optional<std::string> resolve_uri(const std::string& uri, const PackageMap& explicit_packages,
                                       const std::string& base_dir);

}  // namespace mechsim::description
