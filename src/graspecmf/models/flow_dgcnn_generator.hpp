#pragma once
// The non-equivariant flow (`model.type` "flow_dgcnn"): GraspECMF's flow matching, prior and
// samplers with an ordinary DGCNN encoder and an MLP vector field, the cleanest ablation of
// equivariance (docs/method.md, "Comparison models").

#include "graspecmf/models/flow_generator.hpp"
#include "graspecmf/nn/dgcnn_encoder.hpp"
#include "graspecmf/nn/mlp_field.hpp"

namespace graspecmf::models {

class FlowDgcnnGenerator : public FlowGenerator {
 public:
  // Widths count scalars; field.z_channels must equal encoder.out_channels. Throws Error on
  // invalid options.
  FlowDgcnnGenerator(const nn::EncoderOptions& encoder, const nn::VectorFieldOptions& field,
                     double prior_position_std, double cfg_drop);

  // The field's z part of the mean of the M clouds' encodings.
  Condition condition(const at::Tensor& clouds) const override;

  nn::DgcnnEncoder encoder{nullptr};
  nn::MlpField field{nullptr};

 protected:
  Condition encode(const at::Tensor& clouds) const override;
  std::pair<at::Tensor, at::Tensor> velocity(const Condition& condition,
                                             const at::Tensor& object_index,
                                             const flow::PoseBatch& x, const at::Tensor& t,
                                             const at::Tensor& keep) const override;
};

}  // namespace graspecmf::models
