#include "graspecmf/models/flow_dgcnn_generator.hpp"

#include <string>

#include "graspecmf/core/error.hpp"

namespace graspecmf::models {

FlowDgcnnGenerator::FlowDgcnnGenerator(const nn::EncoderOptions& encoder_options,
                                       const nn::VectorFieldOptions& field_options,
                                       double prior_position_std, double cfg_drop)
    : FlowGenerator(prior_position_std, cfg_drop) {
  if (field_options.z_channels != encoder_options.out_channels) {
    throw Error("flow_dgcnn: field.z_channels (" + std::to_string(field_options.z_channels) +
                ") must equal encoder.out_channels (" +
                std::to_string(encoder_options.out_channels) + ")");
  }
  encoder = register_module("encoder", nn::DgcnnEncoder(encoder_options));
  field = register_module("field", nn::MlpField(field_options));
}

Condition FlowDgcnnGenerator::condition(const at::Tensor& clouds) const {
  return {{field->condition(encoder->forward(clouds).mean(0, /*keepdim=*/true))}};
}

Condition FlowDgcnnGenerator::encode(const at::Tensor& clouds) const {
  return {{field->condition(encoder->forward(clouds))}};
}

std::pair<at::Tensor, at::Tensor> FlowDgcnnGenerator::velocity(const Condition& condition,
                                                               const at::Tensor& object_index,
                                                               const flow::PoseBatch& x,
                                                               const at::Tensor& t,
                                                               const at::Tensor& keep) const {
  return field->forward(condition.tensors.front(), object_index, x.R, x.p, t, keep);
}

}  // namespace graspecmf::models
