#pragma once
// The interface every grasp generator implements (GraspECMF and the comparison models): encode an
// object's point clouds, draw grasps for it, and the training loss of a batch, all in network units
// (data::NetworkFrame). The trainer, grasp sampling, evaluation and checkpoints use only this
// interface; make_generator builds the one a config names (docs/config.md, `model.type`).

#include <ATen/core/Generator.h>
#include <torch/nn/module.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "graspecmf/flow/pose_batch.hpp"
#include "graspecmf/models/train_config.hpp"

namespace graspecmf::models {

// An object's encoding, computed once and reused for every grasp drawn for it; what the tensors
// hold is the generator's own business.
struct Condition {
  std::vector<at::Tensor> tensors;
};

// One training step, network units, on the generator's device.
struct TrainingBatch {
  at::Tensor points;        // [O, N, 3] float32 clouds
  at::Tensor object_index;  // [G] int64: the object of each grasp
  flow::PoseBatch grasps;   // R [G, 3, 3], p [G, 3] float32: successful grasps
  // Undefined unless the sampler drew distance-field queries (sampler_options):
  at::Tensor distance_points;  // [O, K, 3] float32 queries near each object's surface
  at::Tensor distances;        // [O, K] float32 their unsigned distances to it
};

class GeneratorImpl : public torch::nn::Module {
 public:
  // Clouds [M, N, 3] of one object (each in its own network frame) → its condition, from the mean
  // of the M clouds' encodings.
  virtual Condition condition(const at::Tensor& clouds) const = 0;
  // count grasps for a condition, network units, on the generator's device. Random draws come from
  // `generator` (a CPU generator, so that a seed gives the same grasps on every device). No
  // gradients.
  virtual flow::PoseBatch draw(const Condition& condition, std::int64_t count,
                               const SamplingSettings& settings,
                               at::Generator& generator) const = 0;
  // The training loss of a batch, differentiable in the parameters; random draws come from
  // `generator` (CPU).
  virtual at::Tensor loss(const TrainingBatch& batch, at::Generator& generator) const = 0;
  // How draw makes grasps under `settings`, in a few words for reports (e.g. "rkmk4-20,
  // guidance 2").
  virtual std::string sampler(const SamplingSettings& settings) const = 0;
  // The device the parameters live on.
  c10::Device device() const;
};
using Generator = std::shared_ptr<GeneratorImpl>;

// The model types make_generator builds (docs/config.md, `model.type`), in the docs' order.
const std::vector<std::string>& model_types();

// A fresh generator with the config's model type and settings, its parameters drawn from
// torch's global generator (seed it with torch::manual_seed). Throws Error for an unknown type.
Generator make_generator(const TrainConfig& config);

}  // namespace graspecmf::models
