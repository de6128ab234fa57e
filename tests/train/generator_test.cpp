// One battery for every generator type (models::model_types()): shapes, seeded sampling, a falling
// loss, bit-for-bit resume and loading for sampling; and equivariance, which only GraspECMF has.
#include "graspecmf/models/generator.hpp"

#include <gtest/gtest.h>
#include <torch/torch.h>

#include <numeric>
#include <string>

#include "graspecmf/flow/pose_batch.hpp"
#include "graspecmf/flow/prior.hpp"
#include "graspecmf/lie/rotation_sets.hpp"
#include "graspecmf/models/flow_generator.hpp"
#include "graspecmf/models/grasp_sampling.hpp"
#include "graspecmf/train/trainer.hpp"
#include "run_inspection.hpp"
#include "tiny_config.hpp"
#include "tiny_dataset.hpp"

namespace graspecmf::models {
namespace {

using graspecmf::testing::logged_losses;
using graspecmf::testing::run_parameters;
using graspecmf::testing::ScratchDir;

TrainConfig tiny_config(const std::string& type) {
  TrainConfig c = graspecmf::testing::tiny_config();
  c.model.type = type;
  return c;
}

// Four seeded clouds of 32 points, network units.
at::Tensor clouds(int64_t count) {
  at::Generator generator = flow::make_generator(5);
  return at::randn({count, 32, 3}, generator, torch::kFloat);
}

class GeneratorBattery : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    at::set_num_threads(1);
    torch::manual_seed(1);
  }
};

TEST_P(GeneratorBattery, DrawsRotationsAndPositionsOfTheRequestedCount) {
  const Generator model = make_generator(tiny_config(GetParam()));
  model->eval();
  const Condition condition = model->condition(clouds(3));
  at::Generator generator = flow::make_generator(2);
  const flow::PoseBatch x = model->draw(condition, 7, SamplingSettings{}, generator);
  ASSERT_EQ(x.R.sizes(), (std::vector<int64_t>{7, 3, 3}));
  ASSERT_EQ(x.p.sizes(), (std::vector<int64_t>{7, 3}));
  const at::Tensor identity = torch::eye(3).expand({7, 3, 3});
  EXPECT_LT((torch::matmul(x.R.transpose(1, 2), x.R) - identity).abs().max().item<double>(), 1e-4);
  EXPECT_TRUE(torch::isfinite(x.p).all().item<bool>());
  EXPECT_GT(model->parameters().size(), 0U);
  EXPECT_FALSE(model->sampler(SamplingSettings{}).empty());
}

TEST_P(GeneratorBattery, ASeedGivesTheSameGrasps) {
  const TrainConfig config = tiny_config(GetParam());
  const Generator model = make_generator(config);
  model->eval();
  std::vector<Eigen::Vector3d> cloud;
  const at::Tensor points = clouds(1)[0].to(torch::kDouble) * 0.05;
  for (int64_t i = 0; i < 32; ++i) {
    cloud.emplace_back(points[i][0].item<double>(), points[i][1].item<double>(),
                       points[i][2].item<double>());
  }
  const auto a = sample_grasps(*model, cloud, config, 5, config.sampling, 9);
  const auto b = sample_grasps(*model, cloud, config, 5, config.sampling, 9);
  const auto c = sample_grasps(*model, cloud, config, 5, config.sampling, 10);
  double changed = 0;
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_EQ(a[i].p, b[i].p) << i;
    EXPECT_EQ(a[i].R, b[i].R) << i;
    changed += (a[i].p - c[i].p).norm();
  }
  EXPECT_GT(changed, 1e-6);  // another seed, other grasps
}

TEST_P(GeneratorBattery, TheLossFallsOnATinySet) {
  const ScratchDir dir;
  TrainConfig config = tiny_config(GetParam());
  config.steps = 100;
  // SE(3)-DiF's deep, weight-normalised energy diverges at 1e-2, and its score-matching target
  // n/σ(t) is heavy-tailed (E[1/σ²] diverges as t → 0), so 100 steps lower its loss by ≈ 18 %.
  const bool diffusion = GetParam() == "se3dif";
  config.learning_rate = diffusion ? 1e-3 : 1e-2;
  config.checkpoint_every = 100;
  train::train(config, graspecmf::testing::tiny_dataset(dir), dir / "run", 1);
  const std::vector<double> losses = logged_losses(dir / "run");
  ASSERT_EQ(losses.size(), 100U);
  const double first = std::accumulate(losses.begin(), losses.begin() + 10, 0.0);
  const double last = std::accumulate(losses.end() - 10, losses.end(), 0.0);
  EXPECT_LT(last, (diffusion ? 0.9 : 0.8) * first) << GetParam();
}

TEST_P(GeneratorBattery, AnInterruptedRunResumesBitForBit) {
  const ScratchDir dir;
  const auto data = graspecmf::testing::tiny_dataset(dir);
  const TrainConfig config = tiny_config(GetParam());
  train::train(config, data, dir / "whole", 1);
  train::TrainCallbacks stop;
  stop.step = [](std::int64_t step, std::int64_t) {
    if (step == 4) throw std::runtime_error("killed");  // after the step-3 checkpoint
  };
  EXPECT_THROW(train::train(config, data, dir / "resumed", 1, stop), std::runtime_error);
  EXPECT_EQ(train::train(config, data, dir / "resumed", 1).resumed_from, 3);
  EXPECT_TRUE(torch::equal(run_parameters(dir / "whole"), run_parameters(dir / "resumed")));
  EXPECT_EQ(logged_losses(dir / "whole"), logged_losses(dir / "resumed"));
  // The run loads as a model of its type.
  EXPECT_EQ(load_trained_model(dir / "whole").config.model.type, GetParam());
}

INSTANTIATE_TEST_SUITE_P(AllModelTypes, GeneratorBattery, ::testing::ValuesIn(model_types()),
                         [](const ::testing::TestParamInfo<std::string>& p) { return p.param; });

// The relative change of the flow's endpoints when the cloud and the starting poses are rotated,
// against rotating the endpoints: 0 for an equivariant generator, to rounding.
double equivariance_error(const std::string& type) {
  torch::manual_seed(1);
  const Generator generator = make_generator(tiny_config(type));
  const auto& model = dynamic_cast<const FlowGenerator&>(*generator);
  const at::Tensor points = clouds(1);
  at::Generator random = flow::make_generator(2);
  const flow::PoseBatch x0 = flow::sample_prior(16, 1.0, random);
  const Eigen::Matrix3d g = lie::random_rotations(1, 5)[0];
  const at::Tensor G = torch::from_blob(const_cast<double*>(Eigen::Matrix3d(g.transpose()).data()),
                                        {3, 3}, torch::kDouble)
                           .to(torch::kFloat);  // row-major g
  SamplingSettings settings;
  settings.steps = 5;
  const flow::PoseBatch x = model.integrate(model.condition(points), x0, settings);
  const flow::PoseBatch gx =
      model.integrate(model.condition(points.matmul(G.t())),
                      {torch::matmul(G, x0.R), x0.p.matmul(G.t())}, settings);
  const double scale = x.R.norm().item<double>() + x.p.norm().item<double>();
  return ((gx.R - torch::matmul(G, x.R)).norm().item<double>() +
          (gx.p - x.p.matmul(G.t())).norm().item<double>()) /
         scale;
}

TEST(GeneratorEquivariance, OnlyGraspEcmfIsEquivariant) {
  EXPECT_LT(equivariance_error("graspecmf"), 1e-5);
  EXPECT_GT(equivariance_error("flow_dgcnn"), 1e-2);  // the check can fail
}

// 6-DOF GraspNet at the reference's sizes: the decoder (xyz + latent per point) and three heads;
// the VAE adds the encoder (xyz + 4 × 4 grasp per point) and the μ and log-variance heads. The
// counts follow from the layer shapes (docs/method.md): 3.87 M and 1.93 M.
TEST(GraspNetGenerator, ParameterCountsFollowTheReference) {
  const auto count = [](const std::string& type) {
    TrainConfig config;
    config.model.type = type;
    int64_t n = 0;
    for (const at::Tensor& p : make_generator(config)->parameters()) n += p.numel();
    return n;
  };
  EXPECT_EQ(count("graspnet_gan"), 1926016 + 8200);
  EXPECT_EQ(count("graspnet_vae"), 1926016 + 8200 + 1926912 + 4100);
}

// A drawn grasp depends on its cloud and its latent: grasp i reads cloud i mod M, so drawing from
// the same cloud twice gives the draws of a one-cloud condition.
TEST(GraspNetGenerator, GraspICyclesThroughTheClouds) {
  torch::manual_seed(1);
  const Generator model = make_generator(tiny_config("graspnet_gan"));
  model->eval();
  const at::Tensor two = clouds(2);
  at::Generator a = flow::make_generator(4), b = flow::make_generator(4);
  const flow::PoseBatch both = model->draw(model->condition(two), 4, SamplingSettings{}, a);
  const flow::PoseBatch first =
      model->draw(model->condition(two.slice(0, 0, 1)), 4, SamplingSettings{}, b);
  for (const int64_t i : {0, 2}) EXPECT_TRUE(torch::allclose(both.p[i], first.p[i])) << i;
  for (const int64_t i : {1, 3}) EXPECT_FALSE(torch::allclose(both.p[i], first.p[i])) << i;
}

}  // namespace
}  // namespace graspecmf::models
