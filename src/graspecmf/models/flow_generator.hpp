#pragma once
// Conditional flow matching on SO(3) × R³ for any velocity network (docs/method.md, "Flow matching
// on SO(3) × R³" and "Sampling"): the Haar × Gaussian prior, the geodesic path and its loss with
// classifier-free-guidance dropout in training; the guided flow integrated with a Lie-group solver
// in sampling. GraspECMF and the non-equivariant flow differ only in the network.

#include <utility>

#include "graspecmf/models/generator.hpp"

namespace graspecmf::models {

// The most grasps integrated in one batch on the CPU and on a GPU; larger requests are integrated
// in chunks of this size (docs/model.md, "Speed").
inline constexpr std::int64_t kCpuIntegrationChunk = 256;
inline constexpr std::int64_t kGpuIntegrationChunk = 16384;

class FlowGenerator : public GeneratorImpl {
 public:
  // Draws x0 from the prior (position standard deviation prior_position_std, network units) and
  // integrates the guided field to t = 1 with the settings' solver, steps and guidance.
  flow::PoseBatch draw(const Condition& condition, std::int64_t count,
                       const SamplingSettings& settings, at::Generator& generator) const final;
  // The guided flow from given starting poses x0 (network units, on the generator's device) to
  // t = 1, a chunk of grasps at a time. No gradients.
  flow::PoseBatch integrate(const Condition& condition, const flow::PoseBatch& x0,
                            const SamplingSettings& settings) const;
  // The flow-matching loss: per grasp a prior sample, a uniform time t, the point x_t of the
  // geodesic path to the grasp and its velocity as the target; the condition is dropped with
  // probability cfg_drop. Draws x0, then t, then the keep mask from `generator`.
  at::Tensor loss(const TrainingBatch& batch, at::Generator& generator) const final;
  // "<solver>-<steps>, guidance <w>".
  std::string sampler(const SamplingSettings& settings) const final;

 protected:
  FlowGenerator(double prior_position_std, double cfg_drop);
  // The conditions of O clouds [O, N, 3], one object each, as one Condition (training).
  virtual Condition encode(const at::Tensor& clouds) const = 0;
  // (ω, v), each [G, 3], for poses x of the objects object_index [G] of `condition`, at times t
  // [G]; keep [G] is 1 where a grasp sees its object and 0 where it sees the null condition.
  virtual std::pair<at::Tensor, at::Tensor> velocity(const Condition& condition,
                                                     const at::Tensor& object_index,
                                                     const flow::PoseBatch& x, const at::Tensor& t,
                                                     const at::Tensor& keep) const = 0;

 private:
  double prior_position_std_;
  double cfg_drop_;
};

}  // namespace graspecmf::models
