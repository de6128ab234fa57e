// The vector field: equivariance, the split first layer against the full input list, the null
// condition, and the whole model's gradients, serialisation and errors.

#include "graspecmf/nn/vector_field.hpp"

#include <gtest/gtest.h>
#include <torch/serialize.h>

#include <sstream>
#include <vector>

#include "graspecmf/core/error.hpp"
#include "graspecmf/nn/grasp_flow_model.hpp"
#include "nn_test_support.hpp"

namespace graspecmf::nn {
namespace {

using graspecmf::testing::random_rotation;
using graspecmf::testing::relative_error;
using graspecmf::testing::rotate;

using VectorFieldTest = graspecmf::testing::NnTest;

VectorFieldOptions small_field() {
  VectorFieldOptions options;
  options.z_channels = 16;
  options.hidden_widths = {32, 32, 16};
  return options;
}

GraspFlowModelOptions small_model() {
  GraspFlowModelOptions options;
  options.encoder.widths = {8, 8, 8, 8, 8};
  options.encoder.k = 8;
  options.encoder.out_channels = 16;
  options.encoder.points = 64;
  options.field = small_field();
  return options;
}

// G grasps spread over O objects: rotations, positions, times, keep flags and object indices.
struct Grasps {
  torch::Tensor object_index, rotation, position, time, keep;
};

Grasps random_grasps(int64_t g, int64_t objects) {
  Grasps grasps;
  grasps.object_index = torch::randint(objects, {g}, torch::kLong);
  // Orthonormal frames from QR of Gaussian matrices (their handedness does not matter here).
  grasps.rotation = std::get<0>(torch::linalg_qr(torch::randn({g, 3, 3})));
  grasps.position = torch::randn({g, 3});
  grasps.time = torch::rand({g});
  grasps.keep = (torch::rand({g}) > 0.3).to(torch::kFloat);
  return grasps;
}

Velocity run(const VectorField& field, const torch::Tensor& z, const Grasps& x) {
  return field->forward(field->condition(z), x.object_index, x.rotation, x.position, x.time,
                        x.keep);
}

VectorFieldOptions small_field_z_every_layer() {
  VectorFieldOptions options = small_field();
  options.z_every_layer = true;
  return options;
}

// The field with its input lists written out: [z, r1, r2, r3, p, t·f_equi] per grasp, and with
// z_every_layer [h, z] for each later hidden layer.
Velocity naive_field(const VectorField& field, const torch::Tensor& z, const Grasps& x) {
  const int64_t g = x.rotation.size(0);
  const auto z_per_grasp = z.index_select(0, x.object_index) * x.keep.view({g, 1, 1});
  const auto inputs =
      torch::cat({z_per_grasp, x.rotation.transpose(1, 2), x.position.unsqueeze(1)}, 1);
  const auto lifted = x.time.view({g, 1, 1}) * field->lift->forward(inputs);
  auto h = field->layers.front()->forward(torch::cat({inputs, lifted}, 1));
  for (std::size_t l = 1; l < field->layers.size(); ++l) {
    if (field->options().z_every_layer) h = torch::cat({h, z_per_grasp}, 1);
    h = field->layers[l]->forward(h);
  }
  const auto out = field->out->forward(h);
  return {out.select(1, 0), out.select(1, 1)};
}

TEST_F(VectorFieldTest, SplitFirstLayerMatchesTheFullInputList) {
  VectorField field;  // paper-sized: 341 z vectors, widths 256, 256, 128, 128, 128
  const auto z = torch::randn({3, 341, 3});
  const auto x = random_grasps(40, 3);
  const auto fast = run(field, z, x);
  const auto naive = naive_field(field, z, x);
  ASSERT_EQ(fast.omega.sizes(), (std::vector<int64_t>{40, 3}));
  ASSERT_EQ(fast.v.sizes(), (std::vector<int64_t>{40, 3}));
  EXPECT_LT(relative_error(fast.omega, naive.omega), 1e-5);
  EXPECT_LT(relative_error(fast.v, naive.v), 1e-5);
}

TEST_F(VectorFieldTest, ZEveryLayerMatchesTheFullInputLists) {
  VectorField field(small_field_z_every_layer());
  EXPECT_EQ(field->layers[1]->feature->weight.size(1), 32 + 16);
  const auto z = torch::randn({3, 16, 3});
  const auto x = random_grasps(40, 3);
  const auto fast = run(field, z, x);
  const auto naive = naive_field(field, z, x);
  EXPECT_LT(relative_error(fast.omega, naive.omega), 1e-5);
  EXPECT_LT(relative_error(fast.v, naive.v), 1e-5);
}

// Rotating z and the poses by 3 random rotations rotates the field's output.
void expect_equivariant(const VectorField& field, int64_t z_channels) {
  const auto z = torch::randn({2, z_channels, 3});
  const auto x = random_grasps(50, 2);
  const auto velocity = run(field, z, x);
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const auto g = random_rotation(seed);
    Grasps rotated = x;
    rotated.rotation = torch::matmul(g, x.rotation);
    rotated.position = rotate(x.position, g);
    const auto turned = run(field, rotate(z, g), rotated);
    EXPECT_LT(relative_error(turned.omega, rotate(velocity.omega, g)), 1e-4) << "seed " << seed;
    EXPECT_LT(relative_error(turned.v, rotate(velocity.v, g)), 1e-4) << "seed " << seed;
  }
}

TEST_F(VectorFieldTest, IsEquivariant) {
  expect_equivariant(VectorField(), 341);
  expect_equivariant(VectorField(small_field_z_every_layer()), 16);
}

// With keep = 0 the field does not depend on z; with keep = 1 (bool) it does.
void expect_null_condition_ignores_z(const VectorField& field) {
  auto x = random_grasps(30, 2);
  x.keep = torch::zeros({30});
  const auto a = run(field, torch::randn({2, 16, 3}), x);
  const auto b = run(field, torch::randn({2, 16, 3}), x);
  EXPECT_TRUE(torch::equal(a.omega, b.omega));
  EXPECT_TRUE(torch::equal(a.v, b.v));
  x.keep = torch::ones({30}, torch::kBool);
  EXPECT_GT(relative_error(run(field, torch::randn({2, 16, 3}), x).v,
                           run(field, torch::randn({2, 16, 3}), x).v),
            1e-3);
}

TEST_F(VectorFieldTest, NullConditionIgnoresZ) {
  for (const auto& options : {small_field(), small_field_z_every_layer()}) {
    expect_null_condition_ignores_z(VectorField(options));
  }
}

TEST_F(VectorFieldTest, RejectsBadInput) {
  VectorField field(small_field());
  const auto condition = field->condition(torch::randn({2, 16, 3}));
  const auto x = random_grasps(5, 2);
  const auto call = [&](const Grasps& y) {
    return field->forward(condition, y.object_index, y.rotation, y.position, y.time, y.keep);
  };
  EXPECT_NO_THROW(call(x));
  EXPECT_THROW(field->condition(torch::randn({2, 15, 3})), Error);
  auto bad = x;
  bad.object_index = torch::full({5}, 2, torch::kLong);
  EXPECT_THROW(call(bad), Error);
  bad = x;
  bad.rotation = torch::randn({5, 3});
  EXPECT_THROW(call(bad), Error);
  bad = x;
  bad.position = torch::randn({4, 3});
  EXPECT_THROW(call(bad), Error);
  bad = x;
  bad.time = torch::rand({5, 1});
  EXPECT_THROW(call(bad), Error);
  bad = x;
  bad.keep = torch::ones({5}, torch::kLong);
  EXPECT_THROW(call(bad), Error);
  bad = x;
  bad.object_index = x.object_index.to(torch::kInt);
  EXPECT_THROW(call(bad), Error);
  // A condition computed without z_every_layer's terms, and one with them.
  VectorField every(small_field_z_every_layer());
  EXPECT_THROW(every->forward(condition, x.object_index, x.rotation, x.position, x.time, x.keep),
               Error);
  EXPECT_THROW(field->forward(every->condition(torch::randn({2, 16, 3})), x.object_index,
                              x.rotation, x.position, x.time, x.keep),
               Error);
}

TEST_F(VectorFieldTest, AveragedConditionIsTheMeanOfTheCloudsEncodings) {
  torch::NoGradGuard no_grad;
  GraspFlowModel model(small_model());
  const torch::Tensor clouds = torch::randn({2, 64, 3});
  // One cloud: exactly condition()'s terms.
  EXPECT_TRUE(torch::equal(model->averaged_condition(clouds.slice(0, 0, 1)).z_terms,
                           model->condition(clouds.slice(0, 0, 1)).z_terms));
  // Two clouds: the field's terms of the mean encoding (one object), unlike either cloud's.
  const torch::Tensor mean_z = model->encoder->forward(clouds).mean(0, true);
  const torch::Tensor averaged = model->averaged_condition(clouds).z_terms;
  EXPECT_EQ(averaged.size(0), 1);
  EXPECT_TRUE(torch::allclose(averaged, model->field->condition(mean_z).z_terms));
  EXPECT_FALSE(torch::allclose(averaged, model->condition(clouds.slice(0, 0, 1)).z_terms));
}

TEST_F(VectorFieldTest, ModelGradientsReachEveryParameter) {
  GraspFlowModel model(small_model());
  const auto condition = model->condition(torch::randn({2, 64, 3}));
  const auto x = random_grasps(64, 2);
  const auto velocity = model(condition, x.object_index, x.rotation, x.position, x.time, x.keep);
  const auto loss = (velocity.omega - torch::randn({64, 3})).pow(2).mean() +
                    (velocity.v - torch::randn({64, 3})).pow(2).mean();
  loss.backward();
  for (const auto& item : model->named_parameters()) {
    const auto& name = item.key();
    const auto& parameter = item.value();
    ASSERT_TRUE(parameter.grad().defined()) << name;
    EXPECT_TRUE(torch::isfinite(parameter.grad()).all().item<bool>()) << name;
    EXPECT_GT(parameter.grad().abs().sum().item<double>(), 0.0) << name;
  }
}

TEST_F(VectorFieldTest, ModelIsEquivariantEndToEnd) {
  GraspFlowModel model(small_model());
  const auto points = torch::randn({2, 64, 3});
  const auto x = random_grasps(20, 2);
  const auto velocity =
      model(model->condition(points), x.object_index, x.rotation, x.position, x.time, x.keep);
  const auto g = random_rotation(3);
  const auto turned = model(model->condition(rotate(points, g)), x.object_index,
                            torch::matmul(g, x.rotation), rotate(x.position, g), x.time, x.keep);
  EXPECT_LT(relative_error(turned.omega, rotate(velocity.omega, g)), 1e-4);
  EXPECT_LT(relative_error(turned.v, rotate(velocity.v, g)), 1e-4);
}

TEST_F(VectorFieldTest, ModelSavesAndLoads) {
  GraspFlowModel saved(small_model());
  std::stringstream buffer;
  torch::save(saved, buffer);
  GraspFlowModel loaded(small_model());
  torch::load(loaded, buffer);
  const auto points = torch::randn({1, 64, 3});
  const auto x = random_grasps(8, 1);
  const auto a =
      saved(saved->condition(points), x.object_index, x.rotation, x.position, x.time, x.keep);
  const auto b =
      loaded(loaded->condition(points), x.object_index, x.rotation, x.position, x.time, x.keep);
  EXPECT_TRUE(torch::equal(a.omega, b.omega));
  EXPECT_TRUE(torch::equal(a.v, b.v));
}

TEST_F(VectorFieldTest, ModelRejectsMismatchedOptions) {
  auto options = small_model();
  options.field.z_channels = 17;
  EXPECT_THROW(GraspFlowModel{options}, Error);
  EXPECT_NO_THROW(GraspFlowModel{small_model()});
}

}  // namespace
}  // namespace graspecmf::nn
