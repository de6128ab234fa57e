#include "graspecmf/models/generator.hpp"

#include "graspecmf/core/error.hpp"
#include "graspecmf/models/flow_dgcnn_generator.hpp"
#include "graspecmf/models/graspecmf_generator.hpp"
#include "graspecmf/models/graspnet_generator.hpp"

namespace graspecmf::models {

c10::Device GeneratorImpl::device() const {
  const std::vector<at::Tensor> all = parameters();
  return all.empty() ? c10::Device(c10::kCPU) : all.front().device();
}

Generator make_generator(const TrainConfig& config) {
  if (config.model.type == "graspecmf") {
    return std::make_shared<GraspEcmfGenerator>(
        nn::GraspFlowModelOptions{config.model.encoder, config.model.field},
        config.prior_position_std, config.cfg_drop);
  }
  if (config.model.type == "flow_dgcnn") {
    return std::make_shared<FlowDgcnnGenerator>(config.model.encoder, config.model.field,
                                                config.prior_position_std, config.cfg_drop);
  }
  if (config.model.type == "graspnet_vae" || config.model.type == "graspnet_gan") {
    return std::make_shared<GraspNetGenerator>(config.model.type == "graspnet_vae"
                                                   ? GraspNetGenerator::Variant::kVae
                                                   : GraspNetGenerator::Variant::kImle,
                                               config.model.graspnet, config.data.position_scale);
  }
  throw Error("model type " + config.model.type + " is not built into this graspecmf");
}

}  // namespace graspecmf::models
