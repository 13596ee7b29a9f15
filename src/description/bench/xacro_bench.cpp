// Expanding the PR2 description (ROS's Python xacro takes ~760 ms for it).
#include <benchmark/benchmark.h>

#include <filesystem>

#include "description/xacro/xacro.hpp"

namespace {
namespace fs = std::filesystem;

void BM_ExpandPr2(benchmark::State& state) {
  const fs::path shared(MECHSIM_SHARED_DIR);
  const fs::path input = shared / "robots" / "pr2_description" / "robots" / "pr2.urdf.xacro";
  if (!fs::exists(input)) {
    state.SkipWithError("shared data missing (MECHSIM_SHARED_DIR)");
    return;
  }
  mechsim::description::XacroOptions options;
  options.packages["pr2_description"] = (shared / "robots" / "pr2_description").string();
  std::size_t bytes = 0;
  for (auto _ : state) {
    const std::string out = mechsim::description::expand_xacro_file(input.string(), options);
    bytes = out.size();
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["output_bytes"] = static_cast<double>(bytes);
}
BENCHMARK(BM_ExpandPr2)->Unit(benchmark::kMillisecond);

void BM_ExpandCc8(benchmark::State& state) {
  const fs::path shared(MECHSIM_SHARED_DIR);
  const fs::path input = shared / "robots" / "cc8_description" / "urdf" / "cc8.xacro";
  if (!fs::exists(input)) {
    state.SkipWithError("shared data missing (MECHSIM_SHARED_DIR)");
    return;
  }
  mechsim::description::XacroOptions options;
  options.packages["cc8_description"] = (shared / "robots" / "cc8_description").string();
  for (auto _ : state) {
    const std::string out = mechsim::description::expand_xacro_file(input.string(), options);
    benchmark::DoNotOptimize(out.data());
  }
}
BENCHMARK(BM_ExpandCc8)->Unit(benchmark::kMillisecond);

}  // namespace

// main() comes from the other benchmark file of this program (robot_load_bench.cpp has BENCHMARK_MAIN).

