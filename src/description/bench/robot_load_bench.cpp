// Loading the PR2: expanding pr2.urdf.xacro and parsing/validating the result (load_robot), and
// parsing the reference pr2.urdf alone. Target: under 25 ms for the whole load on one core.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "description/robot_loader.hpp"
#include "description/urdf/urdf_parser.hpp"
#include "description/xacro/xacro.hpp"

namespace mechsim::description {
namespace {

namespace fs = std::filesystem;

const fs::path kShared = MECHSIM_SHARED_DIR;
const fs::path kPr2Package = kShared / "robots" / "pr2_description";

std::string read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void BM_LoadPr2Xacro(benchmark::State& state) {
  const fs::path xacro = kPr2Package / "robots" / "pr2.urdf.xacro";
  if (!fs::exists(xacro)) {
    state.SkipWithError("no shared data (pr2_description)");
    return;
  }
  LoadOptions options;
  options.packages["pr2_description"] = kPr2Package.string();
  options.lenient = true;  // the PR2's two placeholder sensor inertias
  for (auto _ : state) {
    LoadedRobot robot = load_robot(xacro.string(), options);
    benchmark::DoNotOptimize(robot.model.links.data());
  }
}
BENCHMARK(BM_LoadPr2Xacro)->Unit(benchmark::kMillisecond);

void BM_ExpandPr2Xacro(benchmark::State& state) {
  const fs::path xacro = kPr2Package / "robots" / "pr2.urdf.xacro";
  if (!fs::exists(xacro)) {
    state.SkipWithError("no shared data (pr2_description)");
    return;
  }
  XacroOptions options;
  options.packages["pr2_description"] = kPr2Package.string();
  for (auto _ : state) {
    std::string urdf = expand_xacro_file(xacro.string(), options);
    benchmark::DoNotOptimize(urdf.data());
  }
}
BENCHMARK(BM_ExpandPr2Xacro)->Unit(benchmark::kMillisecond);

void BM_ParsePr2Urdf(benchmark::State& state) {
  const fs::path urdf = kShared / "robots" / "reference" / "pr2.urdf";
  if (!fs::exists(urdf)) {
    state.SkipWithError("no shared data (reference/pr2.urdf)");
    return;
  }
  const std::string text = read(urdf);
  UrdfOptions options;
  options.packages["pr2_description"] = kPr2Package.string();
  options.lenient = true;
  for (auto _ : state) {
    RobotModel model = parse_urdf_string(text, urdf.string(), options);
    benchmark::DoNotOptimize(model.links.data());
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * text.size()));
}
BENCHMARK(BM_ParsePr2Urdf)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace mechsim::description

BENCHMARK_MAIN();
