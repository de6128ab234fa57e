// Collision checks of the Panda box model against the sample mug: against its mesh (the
// open-gripper filter of dataset generation) and against a dense surface cloud of it (the
// --reject-collisions filter of sampling).

#include <benchmark/benchmark.h>

#include <filesystem>

#include "graspecmf/data/acronym_file.hpp"
#include "graspecmf/geometry/mesh_io.hpp"
#include "graspecmf/gripper/cloud_grasp_filter.hpp"
#include "graspecmf/gripper/panda.hpp"

namespace {
namespace fs = std::filesystem;

const fs::path kSample = fs::path(GRASPECMF_DATA_DIR) / "acronym-sample";

struct SampleMug {
  graspecmf::data::AcronymGraspFile record = graspecmf::data::read_acronym_file(
      kSample / "grasps" / "Mug_10f6e09036350e92b3f21f1137c3c347_0.0002682457830986903.h5");
  graspecmf::geometry::TriangleMesh mesh = graspecmf::geometry::scaled(
      graspecmf::geometry::read_mesh(kSample / record.object.file), record.object.scale);
};

void BM_InCollisionSampleGrasps(benchmark::State& state) {
  const SampleMug mug;
  std::size_t i = 0;
  for (auto _ : state) {
    const auto pose =
        graspecmf::lie::Pose::from_matrix(mug.record.transforms[i++ % mug.record.size()]);
    benchmark::DoNotOptimize(graspecmf::gripper::in_collision(mug.mesh, pose));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));  // grasps
}
BENCHMARK(BM_InCollisionSampleGrasps)->Unit(benchmark::kMicrosecond);

// The sample mug's grasps (almost all clear and deep, so every point is visited) through
// CloudGraspFilter::keeps on its kFilterCloudPoints-point cloud: the collision check alone
// (argument 0), then with the depth check too (argument 1).
void BM_CloudGraspFilterSampleGrasps(benchmark::State& state) {
  const SampleMug mug;
  const graspecmf::gripper::CloudGraspFilter filter(graspecmf::gripper::filter_cloud(mug.mesh, 0),
                                                    {true, state.range(0) == 1});
  std::size_t i = 0;
  for (auto _ : state) {
    const auto pose =
        graspecmf::lie::Pose::from_matrix(mug.record.transforms[i++ % mug.record.size()]);
    benchmark::DoNotOptimize(filter.keeps(pose));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));  // grasps
}
BENCHMARK(BM_CloudGraspFilterSampleGrasps)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

}  // namespace
