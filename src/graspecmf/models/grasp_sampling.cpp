#include "graspecmf/models/grasp_sampling.hpp"

#include <torch/torch.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>

#include "graspecmf/core/error.hpp"
#include "graspecmf/data/network_frame.hpp"

namespace graspecmf::models {

namespace {

// Grasps to draw in a later sampling round: the missing count over the kept fraction so far
// (1/64 if none was kept), with a quarter to spare; at least 64, at most 64 n and 2^20 (so a
// round's candidates take at most about 150 MB).
std::size_t next_round_size(std::size_t n, std::size_t missing, std::size_t kept,
                            std::size_t drawn) {
  constexpr std::size_t kMaxRound = std::size_t{1} << 20;
  const double kept_fraction =
      kept == 0 ? 1.0 / 64 : static_cast<double>(kept) / static_cast<double>(drawn);
  const auto wanted =
      static_cast<std::size_t>(std::ceil(1.25 * static_cast<double>(missing) / kept_fraction));
  return std::clamp<std::size_t>(wanted, 64,
                                 std::max<std::size_t>(64, std::min(64 * n, kMaxRound)));
}

// The seed of sampling round r ≥ 1 (round 0 uses the caller's seed).
std::uint64_t round_seed(std::uint64_t seed, int round) {
  return seed ^ (0x9E3779B97F4A7C15ULL * static_cast<std::uint64_t>(round));
}

}  // namespace

std::vector<lie::Pose> sample_grasps(const GeneratorImpl& model,
                                     const std::vector<Eigen::Vector3d>& cloud,
                                     const TrainConfig& config, std::size_t n,
                                     const SamplingSettings& settings, std::uint64_t seed,
                                     const gripper::CloudGraspFilter* filter, std::size_t* passed) {
  if (cloud.empty()) throw Error("sampling needs a non-empty point cloud");
  if (n == 0) throw Error("sampling needs at least one grasp");
  if (settings.clouds < 1) throw Error("sampling needs at least one cloud");
  if (filter != nullptr && settings.max_draws != 0 && settings.max_draws < n) {
    throw Error("sampling may draw at most " + std::to_string(settings.max_draws) +
                " grasps (max_draws), fewer than the " + std::to_string(n) + " asked for");
  }
  for (const Eigen::Vector3d& q : cloud) {
    if (!q.allFinite()) throw Error("the point cloud has a non-finite coordinate");
  }
  const auto parts = static_cast<std::size_t>(settings.clouds);
  const std::size_t size = cloud.size() / parts;
  if (size == 0) throw Error("the point cloud has fewer points than clouds to encode");
  const double scale = config.data.position_scale;
  // Part c, centred on its own centroid as in training, is row c of points [clouds, size, 3].
  at::Tensor points =
      torch::empty({static_cast<int64_t>(parts), static_cast<int64_t>(size), 3}, torch::kFloat);
  auto access = points.accessor<float, 3>();
  data::NetworkFrame frame;  // the grasps' frame: the mean of the parts' centroids
  frame.scale = scale;
  for (std::size_t c = 0; c < parts; ++c) {
    const Eigen::Vector3d* first = cloud.data() + c * size;
    const data::NetworkFrame part =
        data::NetworkFrame::of_points(first, size, Eigen::Matrix3d::Identity(), scale);
    frame.centroid += part.centroid / static_cast<double>(parts);
    for (std::size_t i = 0; i < size; ++i) {
      const Eigen::Vector3d x = part.to_network(first[i]);
      for (int k = 0; k < 3; ++k) {
        access[static_cast<int64_t>(c)][static_cast<int64_t>(i)][k] = static_cast<float>(x[k]);
      }
    }
  }
  torch::NoGradGuard no_grad;
  // The generator's random draws are on the CPU, so a seed gives the same grasps on every device.
  const c10::Device device = model.device();
  const Condition condition = model.condition(points.to(device));
  std::vector<lie::Pose> grasps, rejected;  // rejected: the first n, for fill_rejected
  std::size_t drawn = 0;
  const std::size_t budget = filter == nullptr || settings.max_draws == 0
                                 ? std::numeric_limits<std::size_t>::max()
                                 : settings.max_draws;
  for (int round = 0; round < kMaxSamplingRounds && grasps.size() < n && drawn < budget; ++round) {
    const std::size_t count =
        std::min(budget - drawn,
                 round == 0 ? n : next_round_size(n, n - grasps.size(), grasps.size(), drawn));
    at::Generator generator = flow::make_generator(round == 0 ? seed : round_seed(seed, round));
    const flow::PoseBatch x1 =
        model.draw(condition, static_cast<int64_t>(count), settings, generator);
    const at::Tensor R = x1.R.to(torch::kCPU, torch::kDouble).contiguous();
    const at::Tensor p = x1.p.to(torch::kCPU, torch::kDouble).contiguous();
    drawn += count;
    for (std::size_t g = 0; g < count && grasps.size() < n; ++g) {
      lie::Pose grasp =
          frame.from_network({Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(
                                  R.data_ptr<double>() + 9 * g),
                              Eigen::Map<const Eigen::Vector3d>(p.data_ptr<double>() + 3 * g)});
      if (filter != nullptr && filter->refines()) grasp = filter->refined(grasp);
      if (filter == nullptr || filter->keeps(grasp)) {
        grasps.push_back(grasp);
      } else if (settings.fill_rejected && rejected.size() < n) {
        rejected.push_back(grasp);
      }
    }
  }
  if (passed != nullptr) *passed = grasps.size();
  if (grasps.size() < n && settings.fill_rejected) {
    grasps.insert(grasps.end(), rejected.begin(),
                  rejected.begin() + static_cast<std::ptrdiff_t>(n - grasps.size()));
  }
  if (grasps.size() < n) {
    throw Error("only " + std::to_string(grasps.size()) + " of " + std::to_string(drawn) +
                " sampled grasps pass the grasp filter (" + std::to_string(n) + " needed) " +
                (drawn >= budget ? "within the limit of " + std::to_string(budget) + " draws"
                                 : "after " + std::to_string(kMaxSamplingRounds) + " rounds"));
  }
  return grasps;
}

}  // namespace graspecmf::models
