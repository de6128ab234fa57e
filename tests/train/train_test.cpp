#include <gtest/gtest.h>
#include <torch/torch.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

#include "../geometry/test_meshes.hpp"
#include "graspecmf/core/error.hpp"
#include "graspecmf/data/acronym_file.hpp"
#include "graspecmf/eval/evaluate.hpp"
#include "graspecmf/eval/evaluation.hpp"
#include "graspecmf/flow/prior.hpp"
#include "graspecmf/geometry/mesh_io.hpp"
#include "graspecmf/lie/rotation_sets.hpp"
#include "graspecmf/metrics/emd.hpp"
#include "graspecmf/models/checkpoint.hpp"
#include "graspecmf/models/device.hpp"
#include "graspecmf/models/grasp_sampling.hpp"
#include "graspecmf/models/model_folder.hpp"
#include "graspecmf/train/trainer.hpp"
#include "run_inspection.hpp"
#include "test_support.hpp"
#include "tiny_config.hpp"
#include "tiny_dataset.hpp"

// Training, with the model-folder, sampling and evaluation code it drives.
namespace graspecmf::train {
namespace {
using namespace models;  // NOLINT: the tests exercise these layers together
using namespace eval;    // NOLINT

namespace fs = std::filesystem;
using graspecmf::testing::expect_error;
using graspecmf::testing::flat_parameters;
using graspecmf::testing::logged_losses;
using graspecmf::testing::read_file;
using graspecmf::testing::run_parameters;
using graspecmf::testing::ScratchDir;
using graspecmf::testing::tiny_config;
using graspecmf::testing::tiny_dataset;

class OneThread : public ::testing::Environment {
 public:
  void SetUp() override { at::set_num_threads(1); }
};
const auto* const kOneThread = ::testing::AddGlobalTestEnvironment(new OneThread);

TEST(TrainConfig, BundledConfigsParseAndRoundTrip) {
  const fs::path configs = fs::path(GRASPECMF_DATA_DIR) / ".." / "configs";
  int bundled = 0;
  for (const auto& entry : fs::recursive_directory_iterator(configs)) {
    if (!entry.is_regular_file()) continue;
    const TrainConfig c = read_train_config(entry.path());
    EXPECT_EQ(to_json(train_config_from_json(to_json(c))), to_json(c)) << entry.path();
    EXPECT_EQ(c.model.field.z_channels, c.model.encoder.out_channels) << entry.path();
    ++bundled;
  }
  EXPECT_GE(bundled, 16);  // the folder and configs/table1 were found and read
  const TrainConfig paper = read_train_config(configs / "paper.json");
  EXPECT_EQ(paper.model.encoder.out_channels, 341);
  EXPECT_EQ(paper.model.encoder.k, 40);
}

TEST(TrainConfig, CosineScheduleFallsFromTheRateToZero) {
  TrainConfig c = train_config_from_json(
      {{"steps", 100}, {"learning_rate", 2e-3}, {"learning_rate_schedule", "cosine"}});
  EXPECT_DOUBLE_EQ(learning_rate_at(c, 1), 2e-3);
  EXPECT_NEAR(learning_rate_at(c, 51), 1e-3, 1e-15);
  EXPECT_LT(learning_rate_at(c, 100), 1e-6);
  EXPECT_GT(learning_rate_at(c, 100), 0);
  for (std::int64_t step = 2; step <= 100; ++step) {
    EXPECT_LT(learning_rate_at(c, step), learning_rate_at(c, step - 1));
  }
  c.learning_rate_schedule = "constant";
  EXPECT_DOUBLE_EQ(learning_rate_at(c, 100), 2e-3);
}

TEST(TrainConfig, UnknownKeysAndBadValuesAreErrors) {
  EXPECT_THROW(train_config_from_json({{"stepz", 3}}), Error);
  EXPECT_THROW(train_config_from_json({{"learning_rate_schedule", "linear"}}), Error);
  EXPECT_THROW(train_config_from_json({{"model", {{"encoder", {{"k", "forty"}}}}}}), Error);
  EXPECT_THROW(train_config_from_json({{"cfg_drop", 1.5}}), Error);
  EXPECT_THROW(train_config_from_json({{"ema_decay", 1.0}}), Error);
  EXPECT_THROW(train_config_from_json({{"ema_decay", -0.1}}), Error);
  EXPECT_THROW(train_config_from_json({{"sampling", {{"solver", "rk45"}}}}), Error);
  EXPECT_THROW(train_config_from_json({{"sampling", {{"clouds", 0}}}}), Error);
  EXPECT_EQ(train_config_from_json({{"sampling", {{"clouds", 4}}}}).sampling.clouds, 4);
  EXPECT_THROW(train_config_from_json({{"sampling", {{"max_draws", -1}}}}), Error);
  const TrainConfig capped = train_config_from_json(to_json(
      train_config_from_json({{"sampling", {{"max_draws", 400}, {"fill_rejected", true}}}})));
  EXPECT_EQ(capped.sampling.max_draws, 400U);
  EXPECT_TRUE(capped.sampling.fill_rejected);
  EXPECT_THROW(train_config_from_json({{"data", {{"augmentation", "xyz"}}}}), Error);
  EXPECT_THROW(train_config_from_json({{"data", {{"stretch", 0.5}}}}), Error);
  EXPECT_THROW(train_config_from_json({{"data", {{"stretch", -0.1}}}}), Error);
  EXPECT_DOUBLE_EQ(train_config_from_json({{"data", {{"stretch", 0.1}}}}).data.stretch, 0.1);
  const TrainConfig partial = train_config_from_json(
      {{"data", {{"input", "mixed"}, {"views", {{"elevation", {20, 60}}, {"noise", false}}}}}});
  EXPECT_EQ(partial.data.input, data::CloudInput::mixed);
  EXPECT_DOUBLE_EQ(partial.data.views.min_elevation, 20.0);
  EXPECT_DOUBLE_EQ(partial.data.views.max_distance, 0.7);
  EXPECT_FALSE(partial.data.views.noisy);
  EXPECT_EQ(train_config_from_json(to_json(partial)).data.views.max_elevation, 60.0);
  EXPECT_THROW(train_config_from_json({{"data", {{"input", "half"}}}}), Error);
  EXPECT_THROW(train_config_from_json({{"data", {{"views", {{"distance", {0.9, 0.5}}}}}}}), Error);
  EXPECT_THROW(train_config_from_json({{"data", {{"views", {{"distance", 0.5}}}}}}), Error);
  EXPECT_THROW(train_config_from_json({{"data", {{"views", {{"fov", 60}}}}}}), Error);
  EXPECT_THROW(train_config_from_json({{"model", {{"encoder", {{"points", 8}, {"k", 16}}}}}}),
               Error);
}

TEST(TrainConfig, OnlySe3DifDrawsDistanceQueries) {
  const TrainConfig se3dif = train_config_from_json(
      {{"model", {{"type", "se3dif"}, {"se3dif", {{"distance_points", 250}}}}}});
  EXPECT_EQ(sampler_options(se3dif).distance_points, 250U);
  EXPECT_EQ(se3dif.data.distance_points, 0U);  // not a data key of its own
  EXPECT_EQ(
      sampler_options(train_config_from_json({{"model", {{"type", "se3dif"}}}})).distance_points,
      1000U);  // the reference's
  const TrainConfig flow =
      train_config_from_json({{"model", {{"se3dif", {{"distance_points", 250}}}}}});
  EXPECT_EQ(sampler_options(flow).distance_points, 0U);
  graspecmf::testing::expect_error(
      [] {
        train_config_from_json({{"model", {{"se3dif", {{"distance_points", 100001}}}}}});
      },
      "model.se3dif.distance_points must be at most 100000");
  graspecmf::testing::expect_error(
      [] {
        train_config_from_json({{"model", {{"se3dif", {{"points", 10}}}}}});
      },
      "model.se3dif.");
}

TEST(TrainConfig, IntegersAreIntegersWithinRange) {
  const auto expect = [](const nlohmann::json& j, const std::string& fragment) {
    graspecmf::testing::expect_error([&] { train_config_from_json(j); }, fragment);
  };
  expect({{"steps", 12.7}}, "train config: steps must be an integer");
  expect({{"seed", -1}}, "train config: seed is out of range");
  expect({{"data", {{"objects_per_step", -1}}}}, "data.objects_per_step is out of range");
  expect({{"sampling", {{"steps", 4294967296}}}}, "sampling.steps is out of range");
  expect({{"model", {{"field", {{"hidden_widths", {8, 2.5}}}}}}},
         "model.field.hidden_widths must be a list of integers");
  expect({{"data", {{"grasps_per_object", 1000000}}}}, "grasps_per_object ≤ 100000");
  expect({{"model", {{"encoder", {{"widths", {8, 100000}}}}}}}, "1 to 4096 channels");
  // 1024 objects of 100000 points with 256 neighbours: far past the memory limit.
  expect({{"data", {{"objects_per_step", 1024}}},
          {"model", {{"encoder", {{"points", 100000}, {"k", 256}}}}}},
         "the limit is 16 GiB");
  EXPECT_EQ(train_config_from_json({{"steps", 12}, {"seed", 7}}).seed, 7u);
}

TEST(TrainConfig, NumbersAreFiniteAndSlopesInRange) {
  const auto expect = [](const nlohmann::json& j, const std::string& fragment) {
    graspecmf::testing::expect_error([&] { train_config_from_json(j); }, fragment);
  };
  const double inf = std::numeric_limits<double>::infinity();
  expect({{"learning_rate", inf}}, "every number must be finite");
  expect({{"data", {{"position_scale", inf}}}}, "every number must be finite");
  expect({{"model", {{"field", {{"slope", 1.0}}}}}}, "slopes must be in [0, 1)");
  expect({{"model", {{"encoder", {{"slope", -0.1}}}}}}, "slopes must be in [0, 1)");
  // A file holding 1e999 is refused, by the parser or by the check above.
  const graspecmf::testing::ScratchDir dir;
  graspecmf::testing::write_file(dir / "c.json", R"({"learning_rate": 1e999})");
  graspecmf::testing::expect_error([&] { read_train_config(dir / "c.json"); }, "c.json: ");
  graspecmf::testing::expect_error([&] { read_train_config(dir / "absent.json"); },
                                   "absent.json: no such file");
}

// 40 seeded normal points with standard deviation `spread`.
std::vector<Eigen::Vector3d> normal_cloud(double spread) {
  std::vector<Eigen::Vector3d> cloud;
  Rng rng(4);
  for (int i = 0; i < 40; ++i) {
    const double x = rng.normal(), y = rng.normal(), z = rng.normal();
    cloud.push_back(spread * Eigen::Vector3d(x, y, z));
  }
  return cloud;
}

TEST(Sampling, GraspsFollowTheCloudsPosition) {
  torch::manual_seed(1);
  const TrainConfig config = tiny_config();
  const Generator model = make_generator(config);
  std::vector<Eigen::Vector3d> cloud = normal_cloud(1.0);
  std::vector<Eigen::Vector3d> shifted = cloud;
  for (Eigen::Vector3d& q : shifted) q += Eigen::Vector3d(0.3, -0.2, 1.0);
  const auto a = sample_grasps(*model, cloud, config, 5, config.sampling, 9);
  const auto b = sample_grasps(*model, shifted, config, 5, config.sampling, 9);
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_LT((b[i].p - a[i].p - Eigen::Vector3d(0.3, -0.2, 1.0)).norm(), 1e-5);
    EXPECT_LT((b[i].R - a[i].R).norm(), 1e-5);
    EXPECT_LT((a[i].R.transpose() * a[i].R - Eigen::Matrix3d::Identity()).norm(), 1e-5);
  }
  EXPECT_THROW(sample_grasps(*model, {}, config, 5, config.sampling, 9), Error);
  cloud[3].x() = std::nan("");
  EXPECT_THROW(sample_grasps(*model, cloud, config, 5, config.sampling, 9), Error);
}

TEST(Sampling, AveragingTheZOfSeveralClouds) {
  torch::manual_seed(1);
  TrainConfig config = tiny_config();
  const Generator model = make_generator(config);
  const std::vector<Eigen::Vector3d> cloud = normal_cloud(1.0);
  // Two copies of a cloud average to its own z: the grasps of the single cloud.
  std::vector<Eigen::Vector3d> twice = cloud;
  twice.insert(twice.end(), cloud.begin(), cloud.end());
  SamplingSettings two = config.sampling;
  two.clouds = 2;
  const auto once = sample_grasps(*model, cloud, config, 6, config.sampling, 9);
  const auto doubled = sample_grasps(*model, twice, config, 6, two, 9);
  for (std::size_t i = 0; i < once.size(); ++i) {
    EXPECT_LT((doubled[i].p - once[i].p).norm(), 1e-5) << i;
    EXPECT_LT((doubled[i].R - once[i].R).norm(), 1e-5) << i;
  }
  // Two different halves: the grasps follow the cloud when it moves (each half is centred).
  std::vector<Eigen::Vector3d> shifted = cloud;
  for (Eigen::Vector3d& q : shifted) q += Eigen::Vector3d(0.3, -0.2, 1.0);
  const auto halves = sample_grasps(*model, cloud, config, 6, two, 9);
  const auto moved = sample_grasps(*model, shifted, config, 6, two, 9);
  for (std::size_t i = 0; i < halves.size(); ++i) {
    EXPECT_LT((moved[i].p - halves[i].p - Eigen::Vector3d(0.3, -0.2, 1.0)).norm(), 1e-5) << i;
    EXPECT_LT((moved[i].R - halves[i].R).norm(), 1e-5) << i;
    EXPECT_GT((halves[i].p - once[i].p).norm(), 1e-4) << i;  // the halves' z differs from z
  }
  two.clouds = 41;  // more clouds than points
  EXPECT_THROW(sample_grasps(*model, cloud, config, 6, two, 9), Error);
}

TEST(Device, NamesParseAndCudaNeedsAGpu) {
  EXPECT_EQ(parse_device("cpu"), c10::Device(c10::kCPU));
  EXPECT_THROW(parse_device("tpu"), Error);
  EXPECT_THROW(parse_device("cudax"), Error);
  EXPECT_THROW(parse_device("cuda:many"), Error);
  if (torch::cuda::is_available()) {
    EXPECT_EQ(parse_device("cuda"), c10::Device(c10::kCUDA));
    EXPECT_THROW(parse_device("cuda:" + std::to_string(torch::cuda::device_count())), Error);
  } else {
    EXPECT_THROW(parse_device("cuda"), Error);
    EXPECT_THROW(parse_device("cuda:0"), Error);
  }
}

TEST(Sampling, GpuGraspsMatchTheCpusForOneSeed) {
  if (!torch::cuda::is_available()) GTEST_SKIP() << "no CUDA GPU visible to LibTorch";
  torch::manual_seed(1);
  const TrainConfig config = tiny_config();
  const Generator model = make_generator(config);
  const std::vector<Eigen::Vector3d> cloud = normal_cloud(1.0);
  const auto cpu = sample_grasps(*model, cloud, config, 20, config.sampling, 9);
  model->to(torch::kCUDA);
  const auto gpu = sample_grasps(*model, cloud, config, 20, config.sampling, 9);
  for (std::size_t i = 0; i < cpu.size(); ++i) {
    EXPECT_LT((gpu[i].p - cpu[i].p).norm(), 1e-4) << i;
    EXPECT_LT((gpu[i].R - cpu[i].R).norm(), 1e-4) << i;
  }
}

TEST(Training, OnAGpuTheRunLoadsOnTheCpu) {
  if (!torch::cuda::is_available()) GTEST_SKIP() << "no CUDA GPU visible to LibTorch";
  ScratchDir dir;
  const TrainConfig config = tiny_config();
  const TrainResult result = train(config, tiny_dataset(dir), dir / "run", 1, {}, torch::kCUDA);
  EXPECT_EQ(result.steps, config.steps);
  const TrainedModel trained = load_trained_model(dir / "run");
  for (const auto& p : trained.model->parameters()) {
    EXPECT_TRUE(p.is_cpu());
    EXPECT_TRUE(torch::isfinite(p).all().item<bool>());
  }
}

TEST(Sampling, RejectingCollisionsKeepsTheClearGraspsInOrder) {
  torch::manual_seed(1);
  const TrainConfig config = tiny_config();
  const Generator model = make_generator(config);
  const std::vector<Eigen::Vector3d> cloud = normal_cloud(0.05);
  const gripper::CloudGraspFilter checker(cloud, gripper::GraspChecks{true, false});
  const auto all = sample_grasps(*model, cloud, config, 40, config.sampling, 9);
  const auto clear = sample_grasps(*model, cloud, config, 40, config.sampling, 9, &checker);
  ASSERT_EQ(clear.size(), 40U);
  std::size_t kept = 0;
  for (const lie::Pose& g : all) {
    if (checker.in_collision(g)) continue;
    // The first round's clear grasps come first, in order.
    EXPECT_LT((clear[kept].p - g.p).norm(), 1e-12);
    ++kept;
  }
  EXPECT_GT(kept, 0U);
  EXPECT_LT(kept, 40U);
  for (const lie::Pose& g : clear) EXPECT_FALSE(checker.in_collision(g));
  // Space filled with points leaves no clear grasp: one clear error.
  std::vector<Eigen::Vector3d> filled;
  for (int x = -30; x <= 30; ++x) {
    for (int y = -30; y <= 30; ++y) {
      for (int z = -30; z <= 30; ++z) filled.push_back(0.02 * Eigen::Vector3d(x, y, z));
    }
  }
  const gripper::CloudGraspFilter everywhere(filled, gripper::GraspChecks{true, false});
  EXPECT_THROW(sample_grasps(*model, cloud, config, 5, config.sampling, 9, &everywhere), Error);
}

TEST(Sampling, MaxDrawsBoundsTheFilteredDrawsAndOnlyThem) {
  torch::manual_seed(1);
  const TrainConfig config = tiny_config();
  const Generator model = make_generator(config);
  const std::vector<Eigen::Vector3d> cloud = normal_cloud(0.05);
  const gripper::CloudGraspFilter checker(cloud, gripper::GraspChecks{true, false});
  const auto clear = sample_grasps(*model, cloud, config, 40, config.sampling, 9, &checker);
  SamplingSettings capped = config.sampling;
  // A generous limit leaves the draws as they were.
  capped.max_draws = 100000;
  const auto generous = sample_grasps(*model, cloud, config, 40, capped, 9, &checker);
  ASSERT_EQ(generous.size(), clear.size());
  for (std::size_t i = 0; i < clear.size(); ++i) EXPECT_EQ(generous[i].p, clear[i].p) << i;
  // Some of the first 40 collide, so a limit of 40 draws cannot supply 40 clear grasps.
  capped.max_draws = 40;
  expect_error([&] { sample_grasps(*model, cloud, config, 40, capped, 9, &checker); },
               "within the limit of 40 draws");
  // With fill_rejected the clear grasps of the 40 drawn come first, then the colliding ones, in
  // drawing order.
  const auto all = sample_grasps(*model, cloud, config, 40, config.sampling, 9);
  capped.fill_rejected = true;
  std::size_t passed = 0;
  const auto filled = sample_grasps(*model, cloud, config, 40, capped, 9, &checker, &passed);
  ASSERT_EQ(filled.size(), 40U);
  std::vector<lie::Pose> expected;
  for (const bool clear_first : {true, false}) {
    for (const lie::Pose& g : all) {
      if (checker.in_collision(g) != clear_first) expected.push_back(g);
    }
  }
  EXPECT_EQ(passed,
            static_cast<std::size_t>(std::count_if(all.begin(), all.end(), [&](const lie::Pose& g) {
              return !checker.in_collision(g);
            })));
  EXPECT_GT(passed, 0U);
  EXPECT_LT(passed, 40U);
  for (std::size_t i = 0; i < 40; ++i) EXPECT_LT((filled[i].p - expected[i].p).norm(), 1e-12) << i;
  capped.fill_rejected = false;
  capped.max_draws = 39;
  expect_error([&] { sample_grasps(*model, cloud, config, 40, capped, 9, &checker); },
               "fewer than the 40 asked for");
  // Without a filter the limit does not apply.
  const auto unfiltered = sample_grasps(*model, cloud, config, 40, capped, 9);
  ASSERT_EQ(unfiltered.size(), all.size());
  for (std::size_t i = 0; i < all.size(); ++i) EXPECT_EQ(unfiltered[i].p, all[i].p) << i;
}

TEST(Trainer, InterruptedRunResumesBitForBit) {
  const ScratchDir dir;
  const fs::path data = tiny_dataset(dir);
  // Without and with a weight average; the second also with the cosine learning-rate schedule.
  for (const double ema_decay : {0.0, 0.9}) {
    TrainConfig config = tiny_config();
    config.ema_decay = ema_decay;
    if (ema_decay > 0) config.learning_rate_schedule = "cosine";
    const fs::path whole = dir / ("whole" + std::to_string(ema_decay));
    const fs::path resumed = dir / ("resumed" + std::to_string(ema_decay));
    train(config, data, whole, 1);
    TrainCallbacks stop;
    stop.step = [](std::int64_t step, std::int64_t) {
      if (step == 4) throw std::runtime_error("killed");  // after the step-3 checkpoint
    };
    EXPECT_THROW(train(config, data, resumed, 1, stop), std::runtime_error);
    EXPECT_EQ(train(config, data, resumed, 1).resumed_from, 3);
    EXPECT_TRUE(torch::equal(run_parameters(whole), run_parameters(resumed))) << ema_decay;
    EXPECT_EQ(logged_losses(whole), logged_losses(resumed)) << ema_decay;
    EXPECT_EQ(logged_losses(whole).size(), 6u);
  }
}

TEST(Trainer, WeightAverageIsWhatARunLoads) {
  const ScratchDir dir;
  const fs::path data = tiny_dataset(dir);
  TrainConfig config = tiny_config();
  config.ema_decay = 0.9;
  train(config, data, dir / "run", 1);
  const Generator last = make_generator(config);
  load_checkpoint(dir / "run/checkpoint.pt", *last);  // the trained weights themselves
  const at::Tensor average = run_parameters(dir / "run");
  EXPECT_TRUE(torch::isfinite(average).all().item<bool>());
  EXPECT_FALSE(torch::allclose(average, flat_parameters(last)));
  // A run configured with a weight average whose checkpoint holds none is refused.
  train(tiny_config(), data, dir / "plain", 1);
  fs::create_directories(dir / "mislabelled");
  std::ofstream(dir / "mislabelled/config.json") << to_json(config).dump();
  fs::copy_file(dir / "plain/checkpoint.pt", dir / "mislabelled/checkpoint.pt");
  EXPECT_THROW(load_trained_model(dir / "mislabelled"), Error);
}

TEST(Trainer, ValidationReportsLossAndEmd) {
  const ScratchDir dir;
  TrainConfig config = tiny_config();
  config.steps = 2;
  config.validate_every = 2;
  std::vector<nlohmann::json> records;
  TrainCallbacks callbacks;
  callbacks.record = [&](const nlohmann::json& r) { records.push_back(r); };
  train(config, tiny_dataset(dir), dir / "run", 1, callbacks);
  ASSERT_FALSE(records.empty());
  const nlohmann::json& last = records.back();
  ASSERT_TRUE(last.contains("val_emd")) << last.dump();
  EXPECT_GT(last["val_emd"].get<double>(), 0.0);
  EXPECT_TRUE(std::isfinite(last["val_loss"].get<double>()));
}

TEST(Trainer, SaysWhichObjectsItSkipsAndWhy) {
  const ScratchDir dir;
  const fs::path data = tiny_dataset(dir);
  graspecmf::testing::write_file(data / "grasps/junk.h5", "not an HDF5 file");
  TrainConfig config = tiny_config();
  config.steps = 1;
  std::vector<std::pair<std::string, std::string>> skipped;
  TrainCallbacks callbacks;
  callbacks.skipped = [&](const std::string& name, const std::string& reason) {
    skipped.emplace_back(name, reason);
  };
  train(config, data, dir / "run", 1, callbacks);
  ASSERT_EQ(skipped.size(), 1u);
  EXPECT_EQ(skipped[0].first, "junk");
  EXPECT_NE(skipped[0].second.find("junk.h5"), std::string::npos) << skipped[0].second;
}

TEST(Trainer, BadInputIsOneClearError) {
  const ScratchDir dir;
  const TrainConfig config = tiny_config();
  EXPECT_THROW(train(config, dir / "missing", dir / "run", 1), Error);
  const fs::path data = tiny_dataset(dir);
  train(config, data, dir / "run", 1);
  TrainConfig other = config;
  other.learning_rate = 1e-3;
  EXPECT_THROW(train(other, data, dir / "run", 1), Error);  // another configuration
  EXPECT_THROW(load_trained_model(dir / "missing"), Error);
  // A checkpoint from a different model configuration.
  fs::create_directories(dir / "mismatch");
  TrainConfig wider = config;
  wider.model.field.hidden_widths = {16, 8};
  std::ofstream(dir / "mismatch/config.json") << to_json(wider).dump();
  fs::copy_file(dir / "run/checkpoint.pt", dir / "mismatch/checkpoint.pt");
  EXPECT_THROW(load_trained_model(dir / "mismatch"), Error);
  TrainConfig every_layer = config;
  every_layer.model.field.z_every_layer = true;
  std::ofstream(dir / "mismatch/config.json") << to_json(every_layer).dump();
  EXPECT_THROW(load_trained_model(dir / "mismatch"), Error);
}

TEST(Trainer, FineTuningStartsFromTheInitModelsWeights) {
  const ScratchDir dir;
  const fs::path data = tiny_dataset(dir);
  TrainConfig config = tiny_config();
  config.ema_decay = 0.9;
  train(config, data, dir / "base", 1);
  export_model(dir / "base", dir / "released");
  // One step at a vanishing learning rate keeps the released weights (up to the average's
  // rounding); the same run without --init starts elsewhere. The record names the step.
  TrainConfig still = config;
  still.steps = 1;
  still.learning_rate = 1e-30;
  still.weight_decay = 0;
  still.seed = 7;
  train(still, data, dir / "copy", 1, {}, c10::Device(c10::kCPU), dir / "released");
  train(still, data, dir / "fresh", 1);
  EXPECT_TRUE(
      torch::allclose(run_parameters(dir / "copy"), run_parameters(dir / "released"), 0.0, 1e-6));
  EXPECT_FALSE(
      torch::allclose(run_parameters(dir / "fresh"), run_parameters(dir / "released"), 0.0, 1e-3));
  const auto record = nlohmann::json::parse(read_file(dir / "copy/init.json"));
  EXPECT_EQ(record["step"], config.steps);
  // A few steps move them, reproducibly and resumably.
  TrainConfig tune = config;
  tune.seed = 7;
  train(tune, data, dir / "tuned", 1, {}, c10::Device(c10::kCPU), dir / "released");
  TrainCallbacks stop;
  stop.step = [](std::int64_t step, std::int64_t) {
    if (step == 4) throw std::runtime_error("killed");
  };
  EXPECT_THROW(train(tune, data, dir / "again", 1, stop, c10::Device(c10::kCPU), dir / "released"),
               std::runtime_error);
  EXPECT_EQ(train(tune, data, dir / "again", 1).resumed_from, 3);  // a resume may omit --init
  EXPECT_TRUE(torch::equal(run_parameters(dir / "tuned"), run_parameters(dir / "again")));
  EXPECT_FALSE(torch::equal(run_parameters(dir / "tuned"), run_parameters(dir / "released")));
  // Another init than the run's, an init on a run that had none, another network: errors.
  EXPECT_THROW(train(tune, data, dir / "tuned", 1, {}, c10::Device(c10::kCPU), dir / "base"),
               Error);
  EXPECT_THROW(train(config, data, dir / "base", 1, {}, c10::Device(c10::kCPU), dir / "released"),
               Error);
  TrainConfig wider = config;
  wider.model.field.hidden_widths = {16, 8};
  EXPECT_THROW(train(wider, data, dir / "wider", 1, {}, c10::Device(c10::kCPU), dir / "released"),
               Error);
  EXPECT_THROW(train(config, data, dir / "lost", 1, {}, c10::Device(c10::kCPU), dir / "missing"),
               Error);
}

// Flips the sign bit of every parameter's first float in the file at path (tensors are stored
// uncompressed, so their bytes appear verbatim).
void flip_first_sign_bits(const fs::path& path, const Generator& model) {
  std::string bytes = read_file(path);
  for (const at::Tensor& p : model->parameters()) {
    const at::Tensor values = p.detach().flatten().contiguous();
    const std::string pattern(static_cast<const char*>(values.data_ptr()),
                              std::min<std::size_t>(values.nbytes(), 16));
    const std::size_t at = bytes.find(pattern);
    ASSERT_NE(at, std::string::npos);
    bytes[at + 3] = static_cast<char>(bytes[at + 3] ^ 0x80);
  }
  graspecmf::testing::write_file(path, bytes);
}

TEST(Checkpoint, DamageIsFoundByTheZipCrcsAndTheContentHash) {
  const ScratchDir dir;
  const TrainConfig config = tiny_config();
  train(config, tiny_dataset(dir), dir / "run", 1);
  const TrainedModel trained = load_trained_model(dir / "run");
  save_weights(dir / "weights.pt", *trained.model, 6);
  const Generator model = make_generator(config);
  EXPECT_EQ(load_weights(dir / "weights.pt", *model), 6);
  EXPECT_TRUE(torch::equal(flat_parameters(model), flat_parameters(trained.model)));
  // One sign bit flipped in each weight tensor: the ZIP container's CRC-32 refuses it before
  // LibTorch reads it.
  fs::copy_file(dir / "run/checkpoint.pt", dir / "flipped.pt");
  flip_first_sign_bits(dir / "weights.pt", trained.model);
  flip_first_sign_bits(dir / "flipped.pt", trained.model);
  expect_error([&] { load_weights(dir / "weights.pt", *model); },
               "weights.pt: damaged or not a ZIP archive: entry 'archive/data/");
  expect_error([&] { load_checkpoint(dir / "flipped.pt", *model); }, "flipped.pt: damaged");
  // A truncated file is refused by name.
  const std::string whole = read_file(dir / "run/checkpoint.pt");
  graspecmf::testing::write_file(dir / "truncated.pt", whole.substr(0, whole.size() / 2));
  expect_error([&] { load_checkpoint(dir / "truncated.pt", *model); },
               "truncated.pt: damaged or not a ZIP archive");
  // A whole archive whose tensors differ from those the content hash was computed over (another
  // tool rewrote it, or damage the CRCs were recomputed over), and one with no hash.
  torch::serialize::OutputArchive stale, weights;
  model->save(weights);
  stale.write("weights", weights);
  stale.write("step", torch::tensor({int64_t{6}}, torch::kLong));
  stale.write(
      "tensor_count",
      torch::tensor({static_cast<int64_t>(model->parameters().size() + model->buffers().size())}));
  stale.save_to((dir / "unhashed.pt").string());
  expect_error([&] { load_weights(dir / "unhashed.pt", *model); }, "carries no content hash");
  stale.write("content_hash", torch::tensor({int64_t{12345}}, torch::kLong));
  stale.save_to((dir / "stale.pt").string());
  expect_error([&] { load_weights(dir / "stale.pt", *model); },
               "stale.pt: damaged: its tensors do not match the content hash");
  expect_error([&] { load_weights(dir / "unhashed.pt", *model); }, "carries no content hash");
}

// The tiny dataset's first box, loaded into memory.
data::GraspObject tiny_box() {
  const ScratchDir dir;
  const data::AcronymDataset dataset = data::AcronymDataset::open(tiny_dataset(dir));
  return data::AcronymDataset::load({dataset.objects()[0]})[0];
}

TEST(Evaluation, KeepsTheGeneratedGraspsInTheObjectsFrame) {
  torch::manual_seed(1);
  const data::GraspObject box = tiny_box();
  const TrainConfig config = tiny_config();
  const Generator model = make_generator(config);
  const ObjectEvaluation e =
      evaluate_object(*model, box, config, test_rotations(), 10, config.sampling, 3);
  ASSERT_EQ(e.generated.size(), 3u);
  // A common rotation leaves the EMD unchanged, so the grasps rotated back into the object's
  // frame have each rotation's EMD against the unrotated reference.
  const std::vector<lie::Pose> reference = reference_grasps(box, 10, 3);
  for (std::size_t r = 0; r < 3; ++r) {
    ASSERT_EQ(e.generated[r].size(), 10u);
    EXPECT_NEAR(metrics::earth_movers_distance(e.generated[r], reference), e.emd[r], 1e-9) << r;
  }
  // The object keeps its grasp file's record.
  EXPECT_EQ(box.info.file, "meshes/Box/b0.obj");
}

TEST(Evaluation, SingleViewsAboveTheTable) {
  torch::manual_seed(1);
  const data::GraspObject box = tiny_box();
  const TrainConfig config = tiny_config();
  const Generator model = make_generator(config);
  const InputSetting input{camera::ViewSampling(), true};
  EXPECT_EQ(to_string(input), "views above the table");
  const ObjectEvaluation e =
      evaluate_object(*model, box, config, test_rotations(), 10, config.sampling, 3, {}, input);
  ASSERT_EQ(e.views.size(), 3u);
  EXPECT_NE(e.views[0].azimuth, e.views[1].azimuth);  // one camera per rotation
  // No hand reaches below the table the box stands on, in the box's frame.
  const geometry::TriangleMesh hand = geometry::read_mesh(graspecmf::testing::gripper_mesh_file());
  const double table_z = geometry::bounding_box(box.mesh).min.z();
  for (const std::vector<lie::Pose>& grasps : e.generated) {
    ASSERT_EQ(grasps.size(), 10u);
    for (const lie::Pose& g : grasps) {
      for (const Eigen::Vector3d& v : hand.vertices) EXPECT_GT((g.R * v + g.p).z(), table_z - 1e-9);
    }
  }
  // The same views again for the same seed; the whole surface gives other EMDs.
  const ObjectEvaluation again =
      evaluate_object(*model, box, config, test_rotations(), 10, config.sampling, 3, {}, input);
  EXPECT_EQ(again.views[2].noise_seed, e.views[2].noise_seed);
}

TEST(Evaluation, ResumesAfterTheFinishedObjects) {
  torch::manual_seed(1);
  const ScratchDir dir;
  const data::AcronymDataset dataset = data::AcronymDataset::open(tiny_dataset(dir));
  const std::vector<data::GraspObject> boxes = data::AcronymDataset::load(dataset.objects());
  const TrainConfig config = tiny_config();
  TrainedModel trained{config, make_generator(config), 7};
  trained.model->eval();
  EvaluationOptions options;
  options.num = 6;
  options.seed = 2;
  options.sampling = config.sampling;
  std::vector<std::vector<ObjectResult>> saved;
  EvaluationCallbacks callbacks;
  callbacks.finished = [&](const std::vector<ObjectResult>& done) { saved.push_back(done); };
  const EvaluationReport full = evaluate_model(trained, "m", boxes, &boxes, options, callbacks);
  ASSERT_EQ(saved.size(), 3U);
  EXPECT_EQ(saved[1].size(), 2U);
  // Resumed after the first object: it is taken as saved (marked here), the others come out as
  // in the uninterrupted run, bit for bit, and only they are reported finished.
  std::vector<ObjectResult> first = saved[0];
  first[0].emd[0] = 9.0;
  saved.clear();
  const EvaluationReport resumed =
      evaluate_model(trained, "m", boxes, &boxes, options, callbacks, first);
  ASSERT_EQ(resumed.objects.size(), 3U);
  EXPECT_EQ(resumed.objects[0].emd[0], 9.0);
  EXPECT_EQ(saved.size(), 2U);
  for (std::size_t i = 1; i < 3; ++i) {
    EXPECT_EQ(resumed.objects[i].emd, full.objects[i].emd) << i;
    EXPECT_EQ(resumed.objects[i].baselines->nearest_emd, full.objects[i].baselines->nearest_emd);
  }
  // A resumed run of everything evaluates nothing.
  saved.clear();
  EXPECT_EQ(evaluate_model(trained, "m", boxes, nullptr, options, callbacks, full.objects)
                .objects[2]
                .mean_emd,
            full.objects[2].mean_emd);
  EXPECT_TRUE(saved.empty());
  first[0].name = "other";
  expect_error([&] { evaluate_model(trained, "m", boxes, nullptr, options, {}, first); },
               "resumed result 1 is of other, not Box_b0_1");
  // The identity changes with any setting that changes a result, and not otherwise.
  const nlohmann::json identity = evaluation_identity(trained, "m", boxes, true, options);
  EXPECT_EQ(evaluation_identity(trained, "m", boxes, true, options), identity);
  EXPECT_EQ(identity["objects"][2], "Box_b2_1");
  EXPECT_EQ(identity["device"], "cpu");
  EvaluationOptions other = options;
  other.threads = 2;
  EXPECT_EQ(evaluation_identity(trained, "m", boxes, true, other), identity);
  other.sampling.steps += 1;
  EXPECT_NE(evaluation_identity(trained, "m", boxes, true, other), identity);
  EXPECT_NE(evaluation_identity(trained, "m", boxes, false, options), identity);
  EXPECT_NE(evaluation_identity(trained, "m", {boxes[0]}, true, options), identity);
  other = options;
  other.trial.friction = 0.5;
  EXPECT_NE(evaluation_identity(trained, "m", boxes, true, other), identity);
}

TEST(Baselines, NearestObjectAndRandomGrasps) {
  const ScratchDir dir;
  const fs::path root = tiny_dataset(dir);
  const data::AcronymDataset dataset = data::AcronymDataset::open(root);
  const std::vector<data::GraspObject> boxes = data::AcronymDataset::load(dataset.objects());
  ASSERT_EQ(boxes.size(), 3u);
  // The 6 cm box's nearest shape among the 4 and 5 cm boxes is the 5 cm one.
  const std::vector<data::GraspObject> smaller = {boxes[0], boxes[1]};
  const BaselineEvaluation b = evaluate_baselines(boxes[2], TrainingShapes(smaller, 7), 50, 7);
  EXPECT_EQ(b.scores.nearest, boxes[1].name);
  EXPECT_EQ(b.n, 50u);
  EXPECT_EQ(b.scores.nearest_n, 50u);
  // The kept nearest grasps are the ones compared.
  ASSERT_EQ(b.nearest_grasps.size(), 50u);
  EXPECT_DOUBLE_EQ(
      metrics::earth_movers_distance(b.nearest_grasps, reference_grasps(boxes[2], 50, 7)),
      b.scores.nearest_emd);
  EXPECT_GT(b.scores.random_emd, 0.5);  // random rotations: the geodesic EMD is dominated by angles
  // 120 successful grasps hold two disjoint draws of 50 (a floor) but not of 61.
  ASSERT_TRUE(b.scores.floor_emd.has_value());
  EXPECT_GT(*b.scores.floor_emd, 0.0);
  EXPECT_FALSE(evaluate_baselines(boxes[2], TrainingShapes(smaller, 7), 61, 7).scores.floor_emd);
  // A training object is compared with the nearest other one (leave-one-out), not with itself.
  const std::vector<data::GraspObject> with_itself = {boxes[1], boxes[0]};
  const BaselineEvaluation own =
      evaluate_baselines(boxes[0], TrainingShapes(with_itself, 7), 50, 7);
  EXPECT_EQ(own.scores.nearest, boxes[1].name);
  EXPECT_GT(own.scores.nearest_emd, 0.0);
  const std::vector<data::GraspObject> only_itself = {boxes[0]};
  EXPECT_THROW(evaluate_baselines(boxes[0], TrainingShapes(only_itself, 7), 50, 7), Error);
  EXPECT_THROW(TrainingShapes({}, 7), Error);
  // Given one view, the nearest shape is still the 5 cm box: the training boxes are seen from
  // the same camera.
  const camera::ViewSampling views;
  const InputSetting input{views, false};
  Rng rng(4);
  const camera::ViewDraw view = camera::draw_view(views, rng);
  const BaselineEvaluation seen =
      evaluate_baselines(boxes[2], TrainingShapes(smaller, 7, views), 50, 7, {}, input, &view);
  EXPECT_EQ(seen.scores.nearest, boxes[1].name);
  EXPECT_EQ(seen.nearest_grasps.size(), 50u);
  EXPECT_THROW(evaluate_baselines(boxes[2], TrainingShapes(smaller, 7), 50, 7, {}, input, &view),
               Error);  // not set up for views
  EXPECT_THROW(evaluate_baselines(boxes[2], TrainingShapes(smaller, 7, views), 50, 7, {}, input),
               Error);  // no view given
}

}  // namespace
}  // namespace graspecmf::train
