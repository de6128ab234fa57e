#include <benchmark/benchmark.h>

#include <cstddef>
#include <vector>

#include "graspecmf/core/random.hpp"
#include "graspecmf/lie/rotation_sets.hpp"
#include "graspecmf/lie/se3.hpp"
#include "graspecmf/lie/so3.hpp"

namespace {

using graspecmf::Rng;
using namespace graspecmf::lie;

constexpr std::size_t kInputs = 1024;  // cycled so the compiler cannot fold a constant input

std::vector<Vec3> random_tangents() {
  Rng rng(1);
  std::vector<Vec3> w(kInputs);
  for (Vec3& v : w) v = Vec3(rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2));
  return w;
}

std::vector<Pose> random_poses() {
  Rng rng(2);
  std::vector<Pose> x(kInputs);
  for (Pose& p : x) {
    p.R = random_rotation(rng);
    p.p = Vec3(rng.normal(), rng.normal(), rng.normal());
  }
  return x;
}

void BM_so3_exp(benchmark::State& state) {
  const std::vector<Vec3> w = random_tangents();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(so3_exp(w[i]));
    i = (i + 1) % kInputs;
  }
}
BENCHMARK(BM_so3_exp);

void BM_so3_log(benchmark::State& state) {
  const std::vector<Mat3> R = random_rotations(kInputs, 3);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(so3_log(R[i]));
    i = (i + 1) % kInputs;
  }
}
BENCHMARK(BM_so3_log);

void BM_pose_distance(benchmark::State& state) {
  const std::vector<Pose> x = random_poses();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(pose_distance(x[i], x[(i + 1) % kInputs]));
    i = (i + 1) % kInputs;
  }
}
BENCHMARK(BM_pose_distance);

void BM_super_fibonacci_rotations(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(super_fibonacci_rotations(n));
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_super_fibonacci_rotations)->Arg(1000);

}  // namespace
