#include "graspecmf/train/grasp_sampling.hpp"

#include <torch/torch.h>

#include "graspecmf/core/error.hpp"
#include "graspecmf/flow/prior.hpp"
#include "graspecmf/flow/sampler.hpp"

namespace graspecmf::train {

flow::PoseBatch integrate_grasps(const nn::GraspFlowModel& model, const at::Tensor& points,
                                 const flow::PoseBatch& x0, const SamplingSettings& settings) {
  torch::NoGradGuard no_grad;
  const nn::ObjectCondition condition = model->condition(points.unsqueeze(0));
  const flow::ConditionalField field = [&](const flow::PoseBatch& x, const at::Tensor& t,
                                           const at::Tensor& keep) {
    const at::Tensor object = torch::zeros({x.R.size(0)}, torch::kLong);
    const nn::Velocity velocity = model->forward(condition, object, x.R, x.p, t, keep);
    return std::make_pair(velocity.omega, velocity.v);
  };
  return flow::integrate(flow::guided_field(field, settings.guidance), x0,
                         flow::parse_solver(settings.solver), settings.steps);
}

std::vector<lie::Pose> sample_grasps(const nn::GraspFlowModel& model,
                                     const std::vector<Eigen::Vector3d>& cloud,
                                     const TrainConfig& config, std::size_t n,
                                     const SamplingSettings& settings, std::uint64_t seed) {
  if (cloud.empty()) throw Error("sampling needs a non-empty point cloud");
  if (n == 0) throw Error("sampling needs at least one grasp");
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& q : cloud) {
    if (!q.allFinite()) throw Error("the point cloud has a non-finite coordinate");
    centroid += q;
  }
  centroid /= static_cast<double>(cloud.size());
  const double scale = config.data.position_scale;
  at::Tensor points = torch::empty({static_cast<int64_t>(cloud.size()), 3}, torch::kFloat);
  auto access = points.accessor<float, 2>();
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      access[static_cast<int64_t>(i)][k] = static_cast<float>(scale * (cloud[i][k] - centroid[k]));
    }
  }
  at::Generator generator = flow::make_generator(seed);
  const flow::PoseBatch x0 =
      flow::sample_prior(static_cast<int64_t>(n), config.prior_position_std, generator);
  const flow::PoseBatch x1 = integrate_grasps(model, points, x0, settings);
  const at::Tensor R = x1.R.to(torch::kDouble).contiguous();
  const at::Tensor p = x1.p.to(torch::kDouble).contiguous();
  std::vector<lie::Pose> grasps(n);
  for (std::size_t g = 0; g < n; ++g) {
    grasps[g].R = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(
        R.data_ptr<double>() + 9 * g);
    grasps[g].p =
        Eigen::Map<const Eigen::Vector3d>(p.data_ptr<double>() + 3 * g) / scale + centroid;
  }
  return grasps;
}

}  // namespace graspecmf::train
