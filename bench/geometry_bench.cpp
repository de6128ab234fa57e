// Geometry layer timings on the ACRONYM sample mug (1167 vertices, 2334 triangles).

#include <benchmark/benchmark.h>

#include <filesystem>

#include "graspecmf/core/random.hpp"
#include "graspecmf/geometry/convex_decomposition.hpp"
#include "graspecmf/geometry/mass_properties.hpp"
#include "graspecmf/geometry/mesh_io.hpp"
#include "graspecmf/geometry/mesh_topology.hpp"
#include "graspecmf/geometry/point_inside.hpp"
#include "graspecmf/geometry/surface_sampling.hpp"
#include "graspecmf/geometry/voxel_grid.hpp"

namespace {

using namespace graspecmf::geometry;

const std::filesystem::path kMug = std::filesystem::path(GRASPECMF_DATA_DIR) /
                                   "acronym-sample/meshes/Mug/10f6e09036350e92b3f21f1137c3c347.obj";
constexpr double kMugScale = 0.0002682457830986903;

const TriangleMesh& metric_mug() {
  static const TriangleMesh mug = scaled(read_mesh(kMug), kMugScale);
  return mug;
}

void BM_ReadMugObj(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(read_mesh(kMug));
}
BENCHMARK(BM_ReadMugObj)->Unit(benchmark::kMicrosecond);

void BM_AnalyzeTopology(benchmark::State& state) {
  const TriangleMesh& mug = metric_mug();
  for (auto _ : state) benchmark::DoNotOptimize(analyze_topology(mug));
}
BENCHMARK(BM_AnalyzeTopology)->Unit(benchmark::kMicrosecond);

void BM_MassProperties(benchmark::State& state) {
  const TriangleMesh& mug = metric_mug();
  for (auto _ : state) benchmark::DoNotOptimize(mass_properties(mug, 150.0));
}
BENCHMARK(BM_MassProperties)->Unit(benchmark::kMicrosecond);

void BM_SampleSurface1024(benchmark::State& state) {
  const TriangleMesh& mug = metric_mug();
  const SurfaceSampler sampler(mug);
  graspecmf::Rng rng(1);
  for (auto _ : state) benchmark::DoNotOptimize(sampler.sample(1024, rng));
  state.SetItemsProcessed(state.iterations() * 1024);
}
BENCHMARK(BM_SampleSurface1024)->Unit(benchmark::kMicrosecond);

void BM_WindingNumber(benchmark::State& state) {
  const TriangleMesh& mug = metric_mug();
  const Vec3 q(0.0, 0.0, 0.11);
  for (auto _ : state) benchmark::DoNotOptimize(winding_number(mug, q));
}
BENCHMARK(BM_WindingNumber)->Unit(benchmark::kMicrosecond);

void BM_VoxelizeMug64(benchmark::State& state) {
  const TriangleMesh& mug = metric_mug();
  for (auto _ : state) benchmark::DoNotOptimize(voxelize(mug, 64));
}
BENCHMARK(BM_VoxelizeMug64)->Unit(benchmark::kMillisecond);

void BM_ConvexDecompositionMug(benchmark::State& state) {
  const TriangleMesh& mug = metric_mug();
  for (auto _ : state) benchmark::DoNotOptimize(convex_decomposition(mug));
}
BENCHMARK(BM_ConvexDecompositionMug)->Unit(benchmark::kMillisecond);

}  // namespace
