// Cost of the terrain work a simulation does once at start-up (generation, loading,
// statistics) and of the per-query sampling used in contact/spawn code.

#include <benchmark/benchmark.h>

#include <filesystem>

#include "physics/heightmap_io.hpp"
#include "physics/heightmap_sample.hpp"
#include "physics/mars_yard.hpp"
#include "physics/terrain_stats.hpp"

namespace mechsim::physics {
namespace {

void BM_GenerateMarsYard2024(benchmark::State& state) {
  for (auto _ : state) {
    MarsYard yard = generate_mars_yard(kMarsYardDefaultSeed);
    benchmark::DoNotOptimize(yard.heightmap.heights.data());
  }
}
BENCHMARK(BM_GenerateMarsYard2024)->Unit(benchmark::kMillisecond);

void BM_TerrainStatsMarsYard2024(benchmark::State& state) {
  const MarsYard yard = generate_mars_yard(kMarsYardDefaultSeed);
  for (auto _ : state) benchmark::DoNotOptimize(compute_terrain_stats(yard.heightmap, yard.usable));
}
BENCHMARK(BM_TerrainStatsMarsYard2024)->Unit(benchmark::kMillisecond);

void BM_LoadMarsYard2022Tiff(benchmark::State& state) {
  const auto path = std::filesystem::path(MECHSIM_SHARED_DIR) / "terrain" / "marsyard2022_heightmap.tif";
  if (!std::filesystem::exists(path)) {
    state.SkipWithError("shared terrain data absent");
    return;
  }
  for (auto _ : state) benchmark::DoNotOptimize(load_heightmap(path).heights.data());
}
BENCHMARK(BM_LoadMarsYard2022Tiff)->Unit(benchmark::kMillisecond);

void BM_HeightAndNormalAt(benchmark::State& state) {
  const MarsYard yard = generate_mars_yard(kMarsYardDefaultSeed);
  double x = -18.0, sum = 0.0;
  for (auto _ : state) {
    x = x > 18.0 ? -18.0 : x + 0.0137;
    sum += height_at(yard.heightmap, x, 0.3 * x) + normal_at(yard.heightmap, x, 0.3 * x)[2];
  }
  benchmark::DoNotOptimize(sum);
}
BENCHMARK(BM_HeightAndNormalAt);

}  // namespace
}  // namespace mechsim::physics
