// The MuJoCo shake test on the sample mug: CPU time of one trial on one thread, and grasps per
// second of a batch on two threads (the cost targets: ≤ 0.1 s per trial).

#include <benchmark/benchmark.h>

#include <filesystem>
#include <vector>

#include "graspecmf/data/acronym_file.hpp"
#include "graspecmf/geometry/mesh_io.hpp"
#include "graspecmf/sim/batch.hpp"
#include "graspecmf/sim/scene_object.hpp"

namespace {
namespace fs = std::filesystem;
using namespace graspecmf;

const fs::path kSample = fs::path(GRASPECMF_DATA_DIR) / "acronym-sample";

struct Mug {
  sim::SceneObject object;
  std::vector<lie::Pose> grasps;
};

// The sample mug (decomposition from the default cache) and every 20th of its grasps.
const Mug& mug() {
  static const Mug m = [] {
    const auto record = data::read_acronym_file(
        kSample / "grasps" / "Mug_10f6e09036350e92b3f21f1137c3c347_0.0002682457830986903.h5");
    const auto mesh =
        geometry::scaled(geometry::read_mesh(kSample / record.object.file), record.object.scale);
    Mug result;
    result.object = sim::make_scene_object(mesh, record.object, sim::TrialConfig{},
                                           geometry::DecompositionOptions{},
                                           sim::default_decomposition_cache());
    for (std::size_t i = 0; i < record.size(); i += 20) {
      result.grasps.push_back(lie::Pose::from_matrix(record.transforms[i]));
    }
    return result;
  }();
  return m;
}

void BM_MugTrialOneThread(benchmark::State& state) {
  sim::GraspSimulator simulator(mug().object, sim::TrialConfig{});
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(simulator.run(mug().grasps[i++ % mug().grasps.size()]));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));  // trials
}
BENCHMARK(BM_MugTrialOneThread)->Unit(benchmark::kMillisecond)->Iterations(100);

void BM_MugBatchTwoThreads(benchmark::State& state) {
  for (auto _ : state) {
    benchmark::DoNotOptimize(sim::run_trials(mug().object, mug().grasps, sim::TrialConfig{}, 2));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * mug().grasps.size()));
}
BENCHMARK(BM_MugBatchTwoThreads)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);

}  // namespace
