// EMD cost: the exact assignment is O(n³); n = 1290 is the sample mug's successful grasps.

#include <benchmark/benchmark.h>

#include "graspecmf/core/random.hpp"
#include "graspecmf/lie/rotation_sets.hpp"
#include "graspecmf/metrics/emd.hpp"

namespace {

using graspecmf::lie::Pose;

std::vector<Pose> random_poses(std::size_t n, std::uint64_t seed) {
  graspecmf::Rng rng(seed);
  std::vector<Pose> poses;
  for (const Eigen::Matrix3d& R : graspecmf::lie::random_rotations(n, seed)) {
    Pose pose;
    pose.R = R;
    pose.p = Eigen::Vector3d(rng.normal(), rng.normal(), rng.normal()) * 0.05;
    poses.push_back(pose);
  }
  return poses;
}

void BM_Emd(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const std::vector<Pose> a = random_poses(n, 1), b = random_poses(n, 2);
  for (auto _ : state) benchmark::DoNotOptimize(graspecmf::metrics::earth_movers_distance(a, b));
}
BENCHMARK(BM_Emd)->Arg(100)->Arg(1290)->Unit(benchmark::kMillisecond);

}  // namespace
