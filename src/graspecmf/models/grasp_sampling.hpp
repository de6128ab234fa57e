#pragma once
// Drawing grasps from a trained generator (docs/method.md, "Sampling: integrating the flow"):
// centre and scale the cloud, draw grasps in network units, and map them back to the cloud's frame
// in metres, optionally keeping only those a grasp filter passes.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "graspecmf/flow/pose_batch.hpp"
#include "graspecmf/gripper/cloud_grasp_filter.hpp"
#include "graspecmf/lie/se3.hpp"
#include "graspecmf/models/generator.hpp"
#include "graspecmf/models/train_config.hpp"

namespace graspecmf::models {

// n grasps for a cloud in metres (any frame, ≥ k points per cloud): split into settings.clouds
// consecutive equal parts (a remainder is dropped), each centred on its centroid and scaled by
// position_scale for the encoder; the parts' z are averaged and the grasps placed about the mean
// centroid. The generator's random draws come from seed; grasps are returned as T_object_gripper
// in the cloud's frame, metres. Runs on the model's device; the draws are made on the CPU, so a
// seed gives the same grasps (to rounding) on every device. A `filter` that refines moves each
// grasp (CloudGraspFilter::refined) before its checks. With a `filter`, only grasps it keeps are
// returned: the first round draws n (the grasps of the unfiltered call), later ones the missing
// count over the kept fraction so far, with a quarter to spare (64 to 64 n grasps), all within
// settings.max_draws grasps when it is not 0, and if fewer than n are kept after
// kMaxSamplingRounds or that many draws, Error is thrown, or with settings.fill_rejected the kept
// grasps are followed by the first rejected ones, up to n. `passed`, when given, receives the
// number of returned grasps the filter kept (n without a filter). Throws Error for an empty or
// non-finite cloud, n = 0, or 0 < max_draws < n with a filter.
inline constexpr int kMaxSamplingRounds = 8;
std::vector<lie::Pose> sample_grasps(const GeneratorImpl& model,
                                     const std::vector<Eigen::Vector3d>& cloud,
                                     const TrainConfig& config, std::size_t n,
                                     const SamplingSettings& settings, std::uint64_t seed,
                                     const gripper::CloudGraspFilter* filter = nullptr,
                                     std::size_t* passed = nullptr);

}  // namespace graspecmf::models
