// Writing and reading the sample mug's 2000 grasps in every grasp-file format (docs/formats.md).

#include <benchmark/benchmark.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "graspecmf/formats/grasp_files.hpp"

namespace {
namespace fs = std::filesystem;
using graspecmf::formats::GraspSet;

const fs::path kSample = fs::path(GRASPECMF_DATA_DIR) / "acronym-sample" / "grasps" /
                         "Mug_10f6e09036350e92b3f21f1137c3c347_0.0002682457830986903.h5";

const GraspSet& mug() {
  static const GraspSet grasps = graspecmf::formats::read_grasps(kSample);
  return grasps;
}

// A scratch file with the extension, per process.
fs::path scratch(const std::string& extension) {
  return fs::temp_directory_path() / ("graspecmf-bench-" + std::to_string(::getpid()) + extension);
}

const char* const kExtensions[] = {".h5", ".json", ".yaml", ".npy", ".npz"};

void BM_WriteGrasps(benchmark::State& state) {
  const fs::path path = scratch(kExtensions[state.range(0)]);
  state.SetLabel(path.extension().string());
  for (auto _ : state) graspecmf::formats::write_grasps(mug(), path);
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(mug().size()));
  fs::remove(path);
}
BENCHMARK(BM_WriteGrasps)->DenseRange(0, 4)->Unit(benchmark::kMillisecond);

void BM_ReadGrasps(benchmark::State& state) {
  const fs::path path = scratch(kExtensions[state.range(0)]);
  state.SetLabel(path.extension().string());
  graspecmf::formats::write_grasps(mug(), path);
  for (auto _ : state) benchmark::DoNotOptimize(graspecmf::formats::read_grasps(path));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(mug().size()));
  fs::remove(path);
}
BENCHMARK(BM_ReadGrasps)->DenseRange(0, 4)->Unit(benchmark::kMillisecond);

}  // namespace
