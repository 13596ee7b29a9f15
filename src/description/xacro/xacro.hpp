#pragma once
// mechsim's xacro: expands xacro documents with the semantics of ROS Noetic's xacro
// (in-order processing). Drop-in for `xacro FILE name:=value ...`.

#include <map>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace mechsim::description {

struct XacroOptions {
  std::map<std::string, std::string> args;      // name:=value mappings from the command line
  std::map<std::string, std::string> packages;  // --package NAME=DIR, searched before ROS_PACKAGE_PATH
  // Where xacro's warnings and xacro.message() output go; nullptr: std::cerr.
  std::ostream* diagnostics = nullptr;
};

// An expansion failure. what() is the full message: the problem as xacro words it (possibly
// several lines, e.g. "when evaluating expression '...'"), then "  at FILE:LINE" (the innermost
// node being expanded), then the macro/include stack, innermost first:
// "  in macro 'x' (defined at FILE:LINE) called from FILE:LINE" and
// "  in file FILE included from FILE:LINE".
class XacroError : public std::runtime_error {
 public:
  // Xacro: an expansion error (xacro's XacroException); Parse: malformed XML (expat's ParseError).
  enum class Kind { Xacro, Parse };
  explicit XacroError(const std::string& message, Kind kind = Kind::Xacro)
      : std::runtime_error(message), kind_(kind) {}
  Kind kind() const { return kind_; }

 private:
  Kind kind_;
};

// Expands the file at `path`; returns the output document exactly as `xacro path -o OUT` writes
// it (XML declaration, generated-file banner, 2-space indentation). Throws XacroError.
std::string expand_xacro_file(const std::string& path, const XacroOptions& options);

// Expands a document held in memory; `source_name` names it in messages and in the banner, and
// relative includes resolve from the current working directory. Throws XacroError.
std::string expand_xacro_string(std::string_view document, const std::string& source_name,
                                const XacroOptions& options);

}  // namespace mechsim::description
