#include "graspecmf/nn/grasp_flow_model.hpp"

#include <string>
#include <utility>

#include "graspecmf/nn/checks.hpp"

namespace graspecmf::nn {

GraspFlowModelImpl::GraspFlowModelImpl(GraspFlowModelOptions options)
    : options_(std::move(options)) {
  detail::require(options_.field.z_channels == options_.encoder.out_channels,
                  "GraspFlowModel: field.z_channels (" + std::to_string(options_.field.z_channels) +
                      ") must equal encoder.out_channels (" +
                      std::to_string(options_.encoder.out_channels) + ")");
  encoder = register_module("encoder", Encoder(options_.encoder));
  field = register_module("field", VectorField(options_.field));
}

ObjectCondition GraspFlowModelImpl::condition(const torch::Tensor& points) const {
  return field->condition(encoder->forward(points));
}

ObjectCondition GraspFlowModelImpl::averaged_condition(const torch::Tensor& clouds) const {
  return field->condition(encoder->forward(clouds).mean(0, /*keepdim=*/true));
}

Velocity GraspFlowModelImpl::forward(const ObjectCondition& condition,
                                     const torch::Tensor& object_index,
                                     const torch::Tensor& rotation, const torch::Tensor& position,
                                     const torch::Tensor& time, const torch::Tensor& keep) const {
  return field->forward(condition, object_index, rotation, position, time, keep);
}

c10::Device GraspFlowModelImpl::device() const {
  return encoder->parameters().front().device();
}

}  // namespace graspecmf::nn
