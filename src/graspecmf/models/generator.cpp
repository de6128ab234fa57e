#include "graspecmf/models/generator.hpp"

#include <utility>

#include "graspecmf/core/error.hpp"
#include "graspecmf/models/flow_dgcnn_generator.hpp"
#include "graspecmf/models/graspecmf_generator.hpp"
#include "graspecmf/models/graspnet_generator.hpp"
#include "graspecmf/models/se3dif_generator.hpp"

namespace graspecmf::models {

c10::Device GeneratorImpl::device() const {
  const std::vector<at::Tensor> all = parameters();
  return all.empty() ? c10::Device(c10::kCPU) : all.front().device();
}

namespace {

Generator make_graspecmf(const TrainConfig& c) {
  return std::make_shared<GraspEcmfGenerator>(
      nn::GraspFlowModelOptions{c.model.encoder, c.model.field}, c.prior_position_std, c.cfg_drop);
}

Generator make_flow_dgcnn(const TrainConfig& c) {
  return std::make_shared<FlowDgcnnGenerator>(c.model.encoder, c.model.field, c.prior_position_std,
                                              c.cfg_drop);
}

Generator make_graspnet(const TrainConfig& c) {
  return std::make_shared<GraspNetGenerator>(c.model.type == "graspnet_vae"
                                                 ? GraspNetGenerator::Variant::kVae
                                                 : GraspNetGenerator::Variant::kImle,
                                             c.model.graspnet, c.data.position_scale);
}

Generator make_se3dif(const TrainConfig& c) {
  return std::make_shared<Se3DifGenerator>(c.data.position_scale, c.prior_position_std);
}

using Factory = Generator (*)(const TrainConfig&);

// Every model type and how to build it: the one list of model types.
const std::vector<std::pair<std::string, Factory>>& registry() {
  static const std::vector<std::pair<std::string, Factory>> types = {
      {"graspecmf", make_graspecmf},
      {"flow_dgcnn", make_flow_dgcnn},
      {"graspnet_vae", make_graspnet},
      {"graspnet_gan", make_graspnet},
      {"se3dif", make_se3dif}};
  return types;
}

}  // namespace

const std::vector<std::string>& model_types() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all;
    for (const auto& entry : registry()) all.push_back(entry.first);
    return all;
  }();
  return names;
}

Generator make_generator(const TrainConfig& config) {
  for (const auto& [name, make] : registry()) {
    if (name == config.model.type) return make(config);
  }
  throw Error("model type " + config.model.type + " is not built into this graspecmf");
}

}  // namespace graspecmf::models
