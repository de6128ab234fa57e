#pragma once
// GraspECMF as a generator (`model.type` "graspecmf", the default): the VN-DGCNN encoder and the
// SO(3)-equivariant vector field of nn::GraspFlowModel under flow matching.

#include "graspecmf/models/flow_generator.hpp"
#include "graspecmf/nn/grasp_flow_model.hpp"

namespace graspecmf::models {

class GraspEcmfGenerator : public FlowGenerator {
 public:
  // Throws Error on inconsistent network options (see nn::GraspFlowModelImpl).
  GraspEcmfGenerator(const nn::GraspFlowModelOptions& options, double prior_position_std,
                     double cfg_drop);

  // The mean of the M clouds' encoder outputs, conditioned (nn::GraspFlowModelImpl).
  Condition condition(const at::Tensor& clouds) const override;
  // The network; its encoder and field are this module's children, so parameters are named
  // "encoder.…" and "field.…" as in nn::GraspFlowModel's own checkpoints.
  const nn::GraspFlowModel& network() const { return network_; }

 protected:
  Condition encode(const at::Tensor& clouds) const override;
  std::pair<at::Tensor, at::Tensor> velocity(const Condition& condition,
                                             const at::Tensor& object_index,
                                             const flow::PoseBatch& x, const at::Tensor& t,
                                             const at::Tensor& keep) const override;

 private:
  nn::GraspFlowModel network_;
};

}  // namespace graspecmf::models
