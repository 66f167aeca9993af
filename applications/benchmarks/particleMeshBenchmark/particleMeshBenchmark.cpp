// Generation speed of particleMesh: n × n material sites in a box (n = 1000: one million),
// alone and standing in a tank (a U-shaped polyline wall with its layers, the clearance
// test on every site, lithostatic pressure). Timings, not a test:
//
//   particleMeshBenchmark                                  # all sizes
//   particleMeshBenchmark --benchmark_filter=/1000$        # the one-million cases
//   OMP_NUM_THREADS=1 particleMeshBenchmark ...            # one thread
#include <benchmark/benchmark.h>

#include "geometry/Box.hpp"
#include "particleGeneration/ParticleGenerator.hpp"

namespace {

isph::Scene boxScene(long n, bool tank) {
  const double dx = 0.001;
  const double side = static_cast<double>(n) * dx;
  isph::Scene scene;
  scene.spacing = dx;
  scene.materials = {"sand"};
  scene.patches = {{"tank", 25.0}};
  isph::RegionSpec region;
  region.name = "block";
  region.shape = std::make_unique<isph::Box>(isph::Vec2(0, 0), isph::Vec2(side, side));
  region.density = 1379;
  scene.regions.push_back(std::move(region));
  if (tank) {
    isph::WallSpec wall;
    wall.name = "tank";
    wall.density = 1379;
    const std::vector<isph::Vec2> points{{0, 1.5 * side}, {0, 0}, {side, 0}, {side, 1.5 * side}};
    wall.surface = std::make_unique<isph::WallSurface>(isph::Polyline(points), "polyline");
    wall.side = isph::MaterialSide::automatic;
    scene.walls.push_back(std::move(wall));
    scene.initialPressure = isph::InitialPressure::lithostatic;
    scene.gravity = isph::Vec3(0, -9.81, 0);
  }
  return scene;
}

void generate(benchmark::State& state, bool tank) {
  const isph::Scene scene = boxScene(state.range(0), tank);
  std::size_t particles = 0;
  for (auto _ : state) {
    const isph::GenerationResult result = isph::generateParticles(scene);
    particles = result.cloud.size();
    benchmark::DoNotOptimize(result.cloud.positions.data());
  }
  state.counters["particles"] = static_cast<double>(particles);
  state.counters["particles/s"] = benchmark::Counter(static_cast<double>(particles),
                                                     benchmark::Counter::kIsIterationInvariantRate);
}

void boxOnly(benchmark::State& state) { generate(state, false); }
void boxInTank(benchmark::State& state) { generate(state, true); }

BENCHMARK(boxOnly)->Arg(64)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(boxInTank)->Arg(64)->Arg(1000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
