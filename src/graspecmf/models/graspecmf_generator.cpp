#include "graspecmf/models/graspecmf_generator.hpp"

#include <utility>

namespace graspecmf::models {
namespace {

Condition pack(nn::ObjectCondition c) {
  Condition packed{{std::move(c.z_terms)}};
  for (at::Tensor& t : c.layer_terms) packed.tensors.push_back(std::move(t));
  return packed;
}

nn::ObjectCondition unpack(const Condition& c) {
  return {c.tensors.front(), {c.tensors.begin() + 1, c.tensors.end()}};
}

}  // namespace

GraspEcmfGenerator::GraspEcmfGenerator(const nn::GraspFlowModelOptions& options,
                                       double prior_position_std, double cfg_drop)
    : FlowGenerator(prior_position_std, cfg_drop), network_(options) {
  register_module("encoder", network_->encoder);
  register_module("field", network_->field);
}

Condition GraspEcmfGenerator::condition(const at::Tensor& clouds) const {
  return pack(network_->averaged_condition(clouds));
}

Condition GraspEcmfGenerator::encode(const at::Tensor& clouds) const {
  return pack(network_->condition(clouds));
}

std::pair<at::Tensor, at::Tensor> GraspEcmfGenerator::velocity(const Condition& condition,
                                                               const at::Tensor& object_index,
                                                               const flow::PoseBatch& x,
                                                               const at::Tensor& t,
                                                               const at::Tensor& keep) const {
  const nn::Velocity v = network_->forward(unpack(condition), object_index, x.R, x.p, t, keep);
  return {v.omega, v.v};
}

}  // namespace graspecmf::models
