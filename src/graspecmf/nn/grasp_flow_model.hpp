#pragma once
// The GraspECMF network: the VN-DGCNN encoder and the conditional vector field in one module, so
// one torch::save/torch::load covers all parameters. Units and centring are the caller's.

#include <torch/nn/module.h>
#include <torch/nn/pimpl.h>

#include "graspecmf/nn/encoder.hpp"
#include "graspecmf/nn/vector_field.hpp"

namespace graspecmf::nn {

// Paper-sized by default; field.z_channels must equal encoder.out_channels.
struct GraspFlowModelOptions {
  EncoderOptions encoder;
  VectorFieldOptions field;
};

class GraspFlowModelImpl : public torch::nn::Module {
 public:
  // Throws Error on inconsistent or invalid options.
  explicit GraspFlowModelImpl(GraspFlowModelOptions options = {});

  // Clouds [O, N, 3] (centred, scaled) → the z terms of the O objects (Encoder, then
  // VectorField::condition).
  ObjectCondition condition(const torch::Tensor& points) const;

  // Clouds [M, N, 3] of one object (each centred, scaled) → that object's z terms, from the mean
  // of the M encoder outputs; M = 1 gives condition()'s result exactly.
  ObjectCondition averaged_condition(const torch::Tensor& clouds) const;

  // The field for G grasps of those objects; see VectorFieldImpl::forward.
  Velocity forward(const ObjectCondition& condition, const torch::Tensor& object_index,
                   const torch::Tensor& rotation, const torch::Tensor& position,
                   const torch::Tensor& time, const torch::Tensor& keep) const;

  const GraspFlowModelOptions& options() const { return options_; }

  // The device the parameters live on (all of them move together with to()).
  c10::Device device() const;

  Encoder encoder{nullptr};
  VectorField field{nullptr};

 private:
  GraspFlowModelOptions options_;
};
TORCH_MODULE(GraspFlowModel);

}  // namespace graspecmf::nn
