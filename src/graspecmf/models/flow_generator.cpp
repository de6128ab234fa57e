#include "graspecmf/models/flow_generator.hpp"

#include <torch/torch.h>

#include <algorithm>
#include <sstream>

#include "graspecmf/flow/loss.hpp"
#include "graspecmf/flow/path.hpp"
#include "graspecmf/flow/prior.hpp"
#include "graspecmf/flow/sampler.hpp"

namespace graspecmf::models {

FlowGenerator::FlowGenerator(double prior_position_std, double cfg_drop)
    : prior_position_std_(prior_position_std), cfg_drop_(cfg_drop) {}

std::string FlowGenerator::sampler(const SamplingSettings& settings) const {
  std::ostringstream text;
  text << settings.solver << '-' << settings.steps << ", guidance " << settings.guidance;
  return text.str();
}

flow::PoseBatch FlowGenerator::draw(const Condition& condition, std::int64_t count,
                                    const SamplingSettings& settings,
                                    at::Generator& generator) const {
  const c10::Device target = device();
  const flow::PoseBatch prior = flow::sample_prior(count, prior_position_std_, generator);
  return integrate(condition, {prior.R.to(target), prior.p.to(target)}, settings);
}

flow::PoseBatch FlowGenerator::integrate(const Condition& condition, const flow::PoseBatch& x0,
                                         const SamplingSettings& settings) const {
  torch::NoGradGuard no_grad;
  const flow::ConditionalField field = [&](const flow::PoseBatch& x, const at::Tensor& t,
                                           const at::Tensor& keep) {
    const at::Tensor object = torch::zeros({x.R.size(0)}, x.R.options().dtype(torch::kLong));
    return velocity(condition, object, x, t, keep);
  };
  const flow::VectorField guided = flow::guided_field(field, settings.guidance);
  const flow::Solver solver = flow::parse_solver(settings.solver);
  // Each grasp's path is independent of the others: chunks keep the field's tensors in cache and
  // in reused heap memory, and memory bounded for any count.
  const std::int64_t batch = x0.R.is_cuda() ? kGpuIntegrationChunk : kCpuIntegrationChunk;
  std::vector<at::Tensor> rotations, positions;
  const std::int64_t count = x0.R.size(0);
  for (std::int64_t first = 0; first < count; first += batch) {
    const std::int64_t n = std::min<std::int64_t>(batch, count - first);
    const flow::PoseBatch chunk{x0.R.narrow(0, first, n), x0.p.narrow(0, first, n)};
    const flow::PoseBatch x1 = flow::integrate(guided, chunk, solver, settings.steps);
    rotations.push_back(x1.R);
    positions.push_back(x1.p);
  }
  return {torch::cat(rotations), torch::cat(positions)};
}

at::Tensor FlowGenerator::loss(const TrainingBatch& batch, at::Generator& generator) const {
  const std::int64_t g = batch.grasps.R.size(0);
  const c10::Device target = batch.points.device();
  const Condition condition = encode(batch.points);
  const flow::PoseBatch x0 = flow::sample_prior(g, prior_position_std_, generator);
  const at::Tensor t = at::rand({g}, generator, torch::kFloat).to(target);
  const flow::PathPoint path =
      flow::geodesic_path({x0.R.to(target), x0.p.to(target)}, batch.grasps, t);
  const at::Tensor keep = flow::cfg_keep_mask(g, cfg_drop_, generator).to(target);
  const auto [omega, v] = velocity(condition, batch.object_index, path.x_t, t, keep);
  return flow::flow_matching_loss(omega, v, path.omega, path.v);
}

}  // namespace graspecmf::models
