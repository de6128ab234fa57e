// Reading and writing ACRONYM grasp files, and summarising an object (what `inspect` does).

#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>
#include <vector>

#include "graspecmf/core/isolated_call.hpp"
#include "graspecmf/data/acronym_file.hpp"
#include "graspecmf/data/object_summary.hpp"

namespace {
namespace fs = std::filesystem;

const fs::path kSample = fs::path(GRASPECMF_DATA_DIR) / "acronym-sample" / "grasps" /
                         "Mug_10f6e09036350e92b3f21f1137c3c347_0.0002682457830986903.h5";

void BM_ReadAcronymFile(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(graspecmf::data::read_acronym_file(kSample));
  state.SetItemsProcessed(state.iterations() * 2000);  // grasps
}
BENCHMARK(BM_ReadAcronymFile)->Unit(benchmark::kMillisecond);

// A dataset's worth of files (here the sample, 16 times) read in one batch: one child process reads
// them all before the caller does.
void BM_ReadAcronymFiles16(benchmark::State& state) {
  const std::vector<fs::path> files(16, kSample);
  for (auto _ : state) {
    std::size_t grasps = 0;
    graspecmf::data::read_acronym_files(
        files, [&](std::size_t, graspecmf::data::AcronymGraspFile&& r) { grasps += r.size(); },
        [](std::size_t, const std::string&) {});
    benchmark::DoNotOptimize(grasps);
  }
  state.SetItemsProcessed(state.iterations() * 16 * 2000);
}
BENCHMARK(BM_ReadAcronymFiles16)->Unit(benchmark::kMillisecond);

// The part of a read that isolates libhdf5: starting and reaping a child process that does nothing.
void BM_IsolatedEmptyCall(benchmark::State& state) {
  for (auto _ : state) {
    benchmark::DoNotOptimize(graspecmf::run_isolated([] {}, std::chrono::seconds(10)));
  }
}
BENCHMARK(BM_IsolatedEmptyCall)->Unit(benchmark::kMillisecond);

void BM_WriteAcronymFile(benchmark::State& state) {
  const auto record = graspecmf::data::read_acronym_file(kSample);
  const fs::path out = fs::temp_directory_path() / "graspecmf_bench_write.h5";
  for (auto _ : state) graspecmf::data::write_acronym_file(record, out);
  fs::remove(out);
  state.SetItemsProcessed(state.iterations() * 2000);
}
BENCHMARK(BM_WriteAcronymFile)->Unit(benchmark::kMillisecond);

void BM_SummarizeObject(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(graspecmf::data::summarize_acronym_object(kSample));
}
BENCHMARK(BM_SummarizeObject)->Unit(benchmark::kMillisecond);

}  // namespace
