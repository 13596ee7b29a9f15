#pragma once
// A scenario report's replay/ folder (sim/replay_recorder.hpp) as `mechsim view` finds it: is it
// whole and of the format this build reads, and which files does the page load from it.

#include <filesystem>
#include <string>
#include <vector>

namespace mechsim::web {

struct ReplayFolder {
  bool ok = false;
  std::string error;               // why not, naming the folder or file (empty when ok)
  std::filesystem::path report;    // the report folder
  std::string scenario;            // from the manifest (when readable)
  // Files the page reads, relative to the report folder ("replay/manifest.json", "path.png"):
  // the manifest, robot, world, poses, terrain, meshes, plots and their axes. Only when ok.
  std::vector<std::string> files;
};

// Never throws for bad input: a missing folder, a report without replay/ (replay_rate: 0 or an
// older mechsim), a manifest that is not JSON or of another format version, a missing or
// truncated file each give ok = false and a message saying what and where.
ReplayFolder check_replay_folder(const std::filesystem::path& report);

}  // namespace mechsim::web
