// Collision checks of the Panda box model against the sample mug (the open-gripper filter of
// dataset generation).

#include <benchmark/benchmark.h>

#include <filesystem>

#include "graspecmf/data/acronym_file.hpp"
#include "graspecmf/geometry/mesh_io.hpp"
#include "graspecmf/gripper/panda.hpp"

namespace {
namespace fs = std::filesystem;

const fs::path kSample = fs::path(GRASPECMF_DATA_DIR) / "acronym-sample";

void BM_InCollisionSampleGrasps(benchmark::State& state) {
  const auto record = graspecmf::data::read_acronym_file(
      kSample / "grasps" / "Mug_10f6e09036350e92b3f21f1137c3c347_0.0002682457830986903.h5");
  const auto mug = graspecmf::geometry::scaled(
      graspecmf::geometry::read_mesh(kSample / record.object.file), record.object.scale);
  std::size_t i = 0;
  for (auto _ : state) {
    const auto pose = graspecmf::lie::Pose::from_matrix(record.transforms[i++ % record.size()]);
    benchmark::DoNotOptimize(graspecmf::gripper::in_collision(mug, pose));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));  // grasps
}
BENCHMARK(BM_InCollisionSampleGrasps)->Unit(benchmark::kMicrosecond);

}  // namespace
