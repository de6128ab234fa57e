// The paper-sized model on the CPU (issue 5's targets, 2 threads): encoder ≤ 150 ms for 1024
// points, 100 grasps end to end ≤ 0.5 s with RKMK4-20 + guidance, training step (4 × 300) ≤ 3 s.
// Every benchmark takes the LibTorch thread count as its last argument. Freed memory is kept in the
// heap, as the graspecmf model commands do (graspecmf/core/heap_retention.hpp).

#include <benchmark/benchmark.h>
#include <torch/torch.h>

#include "graspecmf/core/heap_retention.hpp"
#include "graspecmf/flow/prior.hpp"
#include "graspecmf/models/grasp_sampling.hpp"
#include "graspecmf/models/graspecmf_generator.hpp"
#include "graspecmf/models/train_config.hpp"

namespace {

using graspecmf::models::GraspEcmfGenerator;
using graspecmf::models::SamplingSettings;
using graspecmf::models::TrainConfig;

// Reported in the benchmark's context line as heap_retention: on/off.
const bool kHeapRetained = [] {
  benchmark::AddCustomContext("heap_retention", graspecmf::retain_freed_memory() ? "on" : "off");
  return true;
}();

// The paper-sized GraspECMF generator (the default config), in eval mode.
const GraspEcmfGenerator& paper_model() {
  static const std::shared_ptr<GraspEcmfGenerator> model = [] {
    torch::manual_seed(0);
    const TrainConfig config;
    auto m = std::make_shared<GraspEcmfGenerator>(
        graspecmf::nn::GraspFlowModelOptions{config.model.encoder, config.model.field},
        config.prior_position_std, config.cfg_drop);
    m->eval();
    return m;
  }();
  return *model;
}

// The machine's float32 matrix-product rate, the yardstick for the model's FLOP counts.
void BM_MatMul1024(benchmark::State& state) {
  at::set_num_threads(static_cast<int>(state.range(0)));
  const at::Tensor a = torch::randn({1024, 1024}), b = torch::randn({1024, 1024});
  for (auto _ : state) benchmark::DoNotOptimize(a.matmul(b));
  state.counters["GFLOP/s"] = benchmark::Counter(
      2.0 * 1024 * 1024 * 1024 * state.iterations() / 1e9, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_MatMul1024)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_Encoder1024(benchmark::State& state) {
  at::set_num_threads(static_cast<int>(state.range(0)));
  torch::NoGradGuard no_grad;
  const at::Tensor points = torch::randn({1, 1024, 3});
  for (auto _ : state) benchmark::DoNotOptimize(paper_model().network()->encoder->forward(points));
}
BENCHMARK(BM_Encoder1024)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// Grasps for one object, encoder included: args = solver (0 euler, 1 heun, 2 rkmk4), steps,
// grasps, threads.
void BM_SampleGrasps(benchmark::State& state) {
  at::set_num_threads(static_cast<int>(state.range(3)));
  const char* solvers[] = {"euler", "heun", "rkmk4"};
  SamplingSettings settings;
  settings.solver = solvers[state.range(0)];
  settings.steps = static_cast<int>(state.range(1));
  const auto n = static_cast<std::size_t>(state.range(2));
  std::vector<Eigen::Vector3d> cloud;
  graspecmf::Rng rng(1);
  for (int i = 0; i < 1024; ++i) cloud.emplace_back(rng.normal(), rng.normal(), rng.normal());
  for (Eigen::Vector3d& q : cloud) q *= 0.04;
  const TrainConfig config;
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        graspecmf::models::sample_grasps(paper_model(), cloud, config, n, settings, 3));
  }
  state.counters["grasps/s"] =
      benchmark::Counter(static_cast<double>(n) * state.iterations(), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SampleGrasps)
    ->ArgsProduct({{0}, {10}, {100, 1000}, {1, 2}})
    ->ArgsProduct({{1}, {10}, {100, 1000}, {1, 2}})
    ->ArgsProduct({{2}, {20}, {100, 1000}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Times training steps (loss, backward, Adam) of a fresh generator of the config's type on a
// random batch of the config's shape (objects_per_step clouds of encoder.points points,
// grasps_per_object grasps each, and the distance queries its type draws), with `threads` LibTorch
// threads.
void time_training_steps(benchmark::State& state, const TrainConfig& config, int64_t threads) {
  at::set_num_threads(static_cast<int>(threads));
  torch::manual_seed(0);
  const graspecmf::models::Generator model = graspecmf::models::make_generator(config);
  torch::optim::Adam optimizer(model->parameters(), torch::optim::AdamOptions(1e-4));
  at::Generator generator = graspecmf::flow::make_generator(1);
  const auto objects = static_cast<int64_t>(config.data.objects_per_step);
  const auto grasps = static_cast<int64_t>(config.data.grasps_per_object);
  const auto queries =
      static_cast<int64_t>(graspecmf::models::sampler_options(config).distance_points);
  graspecmf::models::TrainingBatch batch;
  batch.points = torch::randn({objects, config.model.encoder.points, 3});
  batch.object_index = torch::arange(objects).repeat_interleave(grasps);
  batch.grasps = graspecmf::flow::sample_prior(objects * grasps, 1.0, generator);
  if (queries > 0) {
    batch.distance_points = torch::randn({objects, queries, 3});
    batch.distances = torch::rand({objects, queries}) * 0.2;
  }
  for (auto _ : state) {
    const at::Tensor loss = model->loss(batch, generator);
    optimizer.zero_grad();
    loss.backward();
    optimizer.step();
  }
}

// One flow-matching step of the paper-sized model, 4 objects × 300 grasps: arg = threads.
void BM_TrainingStep(benchmark::State& state) {
  time_training_steps(state, TrainConfig{}, state.range(0));
}
BENCHMARK(BM_TrainingStep)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// One step of 6-DOF GraspNet at the reference's sizes (1024 points, 64 grasps: 4 objects × 16):
// args = variant (0 VAE, 1 GAN), threads.
void BM_GraspNetTrainingStep(benchmark::State& state) {
  TrainConfig config;
  config.model.type = state.range(0) == 0 ? "graspnet_vae" : "graspnet_gan";
  config.data.grasps_per_object = 16;
  time_training_steps(state, config, state.range(1));
}
BENCHMARK(BM_GraspNetTrainingStep)
    ->ArgsProduct({{0, 1}, {2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The Table I config (configs/table1/, docs/results/table1.md) of model 0 graspecmf,
// 1 flow_dgcnn, 2 graspnet_vae, 3 graspnet_gan or 4 se3dif, with the benchmark labelled by it.
TrainConfig table1_config(benchmark::State& state, int64_t model) {
  const char* models[] = {"graspecmf", "flow_dgcnn", "graspnet_vae", "graspnet_gan", "se3dif"};
  const std::string name = models[model];
  state.SetLabel(name);
  return graspecmf::models::read_train_config(std::string(GRASPECMF_DATA_DIR) +
                                              "/../configs/table1/" + name + ".json");
}

// One training step of each Table I config on one thread: arg = model.
void BM_Table1TrainingStep(benchmark::State& state) {
  time_training_steps(state, table1_config(state, state.range(0)), 1);
}
BENCHMARK(BM_Table1TrainingStep)->DenseRange(0, 4)->Unit(benchmark::kMillisecond)->UseRealTime();

// 100 grasps from an untrained generator of each Table I config, its sampling settings, one
// thread, encoder included: arg = model.
void BM_Table1Sampling(benchmark::State& state) {
  at::set_num_threads(1);
  const TrainConfig config = table1_config(state, state.range(0));
  torch::manual_seed(0);
  const graspecmf::models::Generator model = graspecmf::models::make_generator(config);
  model->eval();
  std::vector<Eigen::Vector3d> cloud;
  graspecmf::Rng rng(1);
  for (int i = 0; i < 512; ++i) cloud.emplace_back(rng.normal(), rng.normal(), rng.normal());
  for (Eigen::Vector3d& q : cloud) q *= 0.04;
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        graspecmf::models::sample_grasps(*model, cloud, config, 100, config.sampling, 3));
  }
}
BENCHMARK(BM_Table1Sampling)->DenseRange(0, 4)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
