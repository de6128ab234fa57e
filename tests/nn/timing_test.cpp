// Timings, not tests: disabled by default. Run with
//   nn_tests --gtest_also_run_disabled_tests --gtest_filter='*Timing*'
// With another process busy on the cores, set OMP_WAIT_POLICY=passive: spinning OpenMP threads
// made 2 threads 3× slower than 1 here. OpenBLAS 0.3.21 does not recognise this machine's CPU
// and falls back to its slow Prescott kernels; OPENBLAS_CORETYPE=Haswell halves the encoder time.

#include <ATen/Parallel.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <vector>

#include "graspecmf/nn/grasp_flow_model.hpp"

namespace graspecmf::nn {
namespace {

// Median wall time in milliseconds of `runs` calls after one warm-up call.
double median_ms(const std::function<void()>& call, int runs) {
  call();
  std::vector<double> times;
  for (int r = 0; r < runs; ++r) {
    const auto start = std::chrono::steady_clock::now();
    call();
    times.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
            .count());
  }
  std::nth_element(times.begin(), times.begin() + runs / 2, times.end());
  return times[static_cast<std::size_t>(runs / 2)];
}

TEST(NnTiming, DISABLED_PaperSizedModel) {
  torch::manual_seed(1);
  GraspFlowModel model;
  const auto points = torch::randn({1, 1024, 3});
  const auto batch = torch::randn({4, 1024, 3});
  const int64_t g = 1000;
  const auto index = torch::zeros({g}, torch::kLong);
  const auto rotation = std::get<0>(torch::linalg_qr(torch::randn({g, 3, 3})));
  const auto position = torch::randn({g, 3});
  const auto time = torch::rand({g});
  const auto keep = torch::ones({g});
  for (const int threads : {1, 2}) {
    at::set_num_threads(threads);
    {
      torch::NoGradGuard no_grad;
      const double encoder = median_ms([&] { model->encoder(points); }, 7);
      const auto condition = model->condition(points);
      const double field =
          median_ms([&] { model(condition, index, rotation, position, time, keep); }, 7);
      std::printf("threads %d: encoder 1x1024 points %.1f ms, field %lld grasps %.1f ms\n", threads,
                  encoder, static_cast<long long>(g), field);
    }
    const double train = median_ms(
        [&] {
          const auto condition = model->condition(batch);
          const auto velocity = model(condition, torch::randint(4, {g}, torch::kLong), rotation,
                                      position, time, keep);
          (velocity.omega.pow(2).mean() + velocity.v.pow(2).mean()).backward();
        },
        3);
    std::printf("threads %d: training step (4 clouds, %lld grasps, forward + backward) %.1f ms\n",
                threads, static_cast<long long>(g), train);
  }
}

}  // namespace
}  // namespace graspecmf::nn
