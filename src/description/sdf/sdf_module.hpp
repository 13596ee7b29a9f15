#pragma once
// Private to description: the seam between the description library and libmechsim_sdformat.so,
// the module that reads SDF with libsdformat (description/sdformat/).
//
// Why a module: libsdformat 12 and ignition-math 6 compile dozens of std::regex objects in their
// static initialisers, 28 ms of CPU at every start of every program that links them (measured:
// an empty program linked against them, 33 ms against 1.2 ms), whether or not it ever reads SDF.
// `mechsim xacro`, `mechsim check`, the test programs and every other start paid it. The module
// is loaded (dlopen) at the first SDF read instead; its code and libsdformat are unchanged.
//
// Both sides are built from this tree by the same compiler in the same build, so the interface is
// plain C++ (the description types by reference). Only the entry point is exported.

#include <string>
#include <vector>

#include "description/sdf/sdf_model.hpp"

namespace mechsim::description::sdf_detail {

constexpr int kSdfModuleVersion = 1;
constexpr const char* kSdfModuleFile = "libmechsim_sdformat.so";
constexpr const char* kSdfModuleEntry = "mechsim_sdformat_module";

// Each call returns "" and fills `out`, or returns the message of the SdfError it met (other
// exceptions, e.g. std::bad_alloc, pass through).
struct SdfModuleApi {
  int version = kSdfModuleVersion;
  std::string (*parse_model)(const std::string& xml, const std::string& source, const SdfOptions& options,
                             SdfModel& out) = nullptr;
  std::string (*load_world)(const std::string& path, const SdfOptions& options, SdfWorld& out) = nullptr;
};

using SdfModuleEntry = const SdfModuleApi* (*)();

// The first of `files` that is this build's SDF module, loaded; else no api and an error naming
// each file and why it was passed over (absent, not loadable, not the module). The description
// library calls it once per process (sdf_load.cpp); tests call it directly.
struct SdfModuleLoad {
  const SdfModuleApi* api = nullptr;
  std::string error;
};
SdfModuleLoad load_sdf_module(const std::vector<std::string>& files);

}  // namespace mechsim::description::sdf_detail
