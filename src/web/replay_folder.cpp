#include "web/replay_folder.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "sim/replay_recorder.hpp"

namespace mechsim::web {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct Invalid {
  std::string message;
};

// The member `key` of `object` in `file`, of the JSON type `check` accepts.
template <class Check>
const json& member(const json& object, const std::string& key, const std::string& file, Check check, const char* what) {
  auto it = object.find(key);
  if (it == object.end()) throw Invalid{file + ": no \"" + key + "\""};
  if (!check(*it)) throw Invalid{file + ": \"" + key + "\" is not " + what};
  return *it;
}

json read_json(const fs::path& file, const std::string& name) {
  std::ifstream in(file);
  if (!in) throw Invalid{name + ": missing (" + file.string() + ")"};
  std::stringstream text;
  text << in.rdbuf();
  json j = json::parse(text.str(), nullptr, false);
  if (j.is_discarded() || !j.is_object()) throw Invalid{name + ": not a JSON object (" + file.string() + ")"};
  return j;
}

void need_file(const fs::path& report, const std::string& relative, std::vector<std::string>& files) {
  const fs::path normal = fs::path(relative).lexically_normal();
  if (normal.empty() || normal.is_absolute() || *normal.begin() == "..") {
    throw Invalid{"replay/manifest.json: file '" + relative + "' points outside the report folder"};
  }
  std::error_code ec;
  if (!fs::is_regular_file(report / relative, ec)) throw Invalid{relative + ": missing (" + (report / relative).string() + ")"};
  files.push_back(fs::path(relative).lexically_normal().generic_string());
}

std::uintmax_t size_of(const fs::path& file) {
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(file, ec);
  return ec ? 0 : size;
}

void check(const fs::path& report, ReplayFolder& out) {
  std::error_code ec;
  if (!fs::is_directory(report, ec)) throw Invalid{report.string() + ": no such report folder"};
  if (!fs::is_directory(report / "replay", ec)) {
    if (fs::exists(report / "summary.json", ec)) {
      throw Invalid{report.string() + ": the report has no replay/ folder (written with replay_rate: 0, or by a mechsim "
                                      "without replays): run the scenario again to record one"};
    }
    throw Invalid{report.string() + ": not a scenario report (no summary.json, no replay/)"};
  }
  if (!fs::exists(report / "replay" / "manifest.json", ec)) {
    throw Invalid{"replay/manifest.json: missing in " + report.string() +
                  " (the run did not finish writing its report, or the folder was copied in part)"};
  }
  const std::string mname = "replay/manifest.json";
  const json manifest = read_json(report / "replay" / "manifest.json", mname);
  const json& format = member(manifest, "format", mname, [](const json& v) { return v.is_string(); }, "a string");
  if (format.get<std::string>() != sim::kReplayFormatName) {
    throw Invalid{mname + ": format '" + format.get<std::string>() + "', expected '" + sim::kReplayFormatName + "'"};
  }
  const json& version = member(manifest, "version", mname, [](const json& v) { return v.is_number_integer(); }, "an integer");
  if (version.get<int>() != sim::kReplayFormatVersion) {
    throw Invalid{mname + ": replay format version " + std::to_string(version.get<int>()) + ", this mechsim reads version " +
                  std::to_string(sim::kReplayFormatVersion) + " (run the scenario again with this mechsim)"};
  }
  if (auto s = manifest.find("scenario"); s != manifest.end() && s->is_string()) out.scenario = s->get<std::string>();
  std::vector<std::string> files;
  files.push_back(mname);
  const auto is_string = [](const json& v) { return v.is_string(); };
  const std::string robot = "replay/" + member(manifest, "robot_file", mname, is_string, "a string").get<std::string>();
  const std::string world = "replay/" + member(manifest, "world_file", mname, is_string, "a string").get<std::string>();
  need_file(report, robot, files);
  need_file(report, world, files);
  const json& poses = member(manifest, "poses", mname, [](const json& v) { return v.is_object(); }, "an object");
  const std::string poses_file = "replay/" + member(poses, "file", mname + " poses", is_string, "a string").get<std::string>();
  const auto is_count = [](const json& v) { return v.is_number_unsigned(); };
  const std::uint64_t stride = member(poses, "stride", mname + " poses", is_count, "a count").get<std::uint64_t>();
  const std::uint64_t frames = member(manifest, "frames", mname, is_count, "a count").get<std::uint64_t>();
  const std::size_t links = member(manifest, "links", mname, [](const json& v) { return v.is_array(); }, "a list").size();
  // The world's free objects follow the links in each frame (absent in replays that have none).
  std::size_t objects = 0;
  if (manifest.contains("objects")) {
    objects = member(manifest, "objects", mname, [](const json& v) { return v.is_array(); }, "a list").size();
  }
  if (stride != 1 + 7 * (links + objects)) {
    throw Invalid{mname + ": poses stride " + std::to_string(stride) + " does not fit " + std::to_string(links) + " links and " +
                  std::to_string(objects) + " objects"};
  }
  if (frames == 0) throw Invalid{mname + ": no frames recorded"};
  need_file(report, poses_file, files);
  const std::uintmax_t expected = frames * stride * sizeof(float);
  if (const std::uintmax_t size = size_of(report / poses_file); size != expected) {
    throw Invalid{poses_file + ": " + std::to_string(size) + " bytes, the manifest's " + std::to_string(frames) + " frames need " +
                  std::to_string(expected) + " (truncated or from another run)"};
  }
  const json robot_json = read_json(report / robot, robot);
  for (const json& link : member(robot_json, "links", robot, [](const json& v) { return v.is_array(); }, "a list")) {
    for (const json& visual : link.value("visuals", json::array())) {
      if (visual.value("type", "") == "mesh") {
        const std::string mesh = "replay/" + visual.value("file", "");
        if (std::find(files.begin(), files.end(), mesh) == files.end()) need_file(report, mesh, files);
      }
    }
  }
  const json world_json = read_json(report / world, world);
  if (auto field = world_json.find("heightfield"); field != world_json.end() && field->is_object()) {
    const std::string terrain = "replay/" + field->value("file", "");
    need_file(report, terrain, files);
    const std::uintmax_t cells = field->value("rows", std::uintmax_t{0}) * field->value("cols", std::uintmax_t{0});
    if (size_of(report / terrain) != cells * sizeof(float)) {
      throw Invalid{terrain + ": " + std::to_string(size_of(report / terrain)) + " bytes, world.json's grid needs " +
                    std::to_string(cells * sizeof(float))};
    }
  }
  if (auto odometry = manifest.find("odometry"); odometry != manifest.end() && odometry->is_object()) {
    need_file(report, "replay/" + odometry->value("file", ""), files);
  }
  for (const json& laser : manifest.value("lasers", json::array())) {
    if (laser.contains("file") && laser["file"].is_string()) need_file(report, "replay/" + laser["file"].get<std::string>(), files);
  }
  for (const json& plot : manifest.value("plots", json::array())) {
    for (const char* key : {"file", "axes"}) {
      if (plot.contains(key) && plot[key].is_string()) need_file(report, "replay/" + plot[key].get<std::string>(), files);
    }
  }
  out.files = std::move(files);
}

}  // namespace

ReplayFolder check_replay_folder(const fs::path& report) {
  ReplayFolder out;
  out.report = report;
  try {
    check(report, out);
    out.ok = true;
  } catch (const Invalid& e) {
    out.error = e.message;
    out.files.clear();
  } catch (const std::exception& e) {  // a JSON value of an unexpected type
    out.error = "replay/manifest.json in " + report.string() + ": " + e.what();
    out.files.clear();
  }
  return out;
}

}  // namespace mechsim::web
