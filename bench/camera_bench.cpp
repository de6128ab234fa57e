// Camera layer timings on the ACRONYM sample mug (2334 triangles) standing on a table, seen by a
// RealSense D435-like camera (640 × 480) from 0.55 m at 45° elevation: rendering, the noise model,
// the view's points as `sample --depth` takes them, and one training step's partial cloud.

#include <benchmark/benchmark.h>

#include <filesystem>

#include "graspecmf/camera/depth_noise.hpp"
#include "graspecmf/camera/depth_render.hpp"
#include "graspecmf/camera/partial_view.hpp"
#include "graspecmf/camera/view_input.hpp"
#include "graspecmf/geometry/mesh_io.hpp"

namespace {

using namespace graspecmf;

const std::filesystem::path kMug = std::filesystem::path(GRASPECMF_DATA_DIR) /
                                   "acronym-sample/meshes/Mug/10f6e09036350e92b3f21f1137c3c347.obj";
constexpr double kMugScale = 0.0002682457830986903;

struct Scene {
  geometry::MeshRayCaster mug{geometry::scaled(geometry::read_mesh(kMug), kMugScale)};
  geometry::BoundingBox box = geometry::bounding_box(mug.mesh());
  geometry::Plane table{lie::Vec3::UnitZ(), -box.min.z()};
  camera::Intrinsics k = camera::realsense_d435();
  lie::Pose pose = camera::camera_above(box, 210.0, 45.0, 0.55);
  camera::RenderedView view = camera::render_view(mug, k, pose, table);
};

const Scene& scene() {
  static const Scene s;
  return s;
}

void BM_RenderView640x480(benchmark::State& state) {
  const Scene& s = scene();
  for (auto _ : state) benchmark::DoNotOptimize(camera::render_view(s.mug, s.k, s.pose, s.table));
}
BENCHMARK(BM_RenderView640x480)->Unit(benchmark::kMillisecond);

void BM_NoisyDepth640x480(benchmark::State& state) {
  const Scene& s = scene();
  const camera::DepthNoise noise;
  std::uint64_t seed = 0;
  for (auto _ : state) benchmark::DoNotOptimize(camera::noisy_depth(s.view, s.k, noise, ++seed));
}
BENCHMARK(BM_NoisyDepth640x480)->Unit(benchmark::kMillisecond);

// Back-projection, 2 mm voxels, outlier removal and (with Arg 1) the RANSAC table fit.
void BM_ViewPoints(benchmark::State& state) {
  const Scene& s = scene();
  camera::ViewOptions options;
  options.table_mode = state.range(0) ? camera::TableMode::automatic : camera::TableMode::none;
  const camera::DepthImage depth = camera::noisy_depth(s.view, s.k, camera::DepthNoise(), 1);
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        camera::view_points(depth, s.k, s.view.object_mask, s.pose, options, 1));
  }
}
BENCHMARK(BM_ViewPoints)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// What a training step pays per partial object: a random camera, the window render, noise and
// the object's points.
void BM_PartialCloud(benchmark::State& state) {
  const Scene& s = scene();
  const camera::ViewSampling sampling;
  Rng rng(1);
  for (auto _ : state) benchmark::DoNotOptimize(camera::partial_cloud(s.mug, sampling, rng));
}
BENCHMARK(BM_PartialCloud)->Unit(benchmark::kMillisecond);

}  // namespace
