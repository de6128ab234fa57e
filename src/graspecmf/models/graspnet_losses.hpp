#pragma once
// The training losses of 6-DOF GraspNet (Mousavian et al. 2019), its VAE and its "GAN" (IMLE)
// variants (docs/method.md, "Comparison models"): distances between the gripper's control points.

#include <ATen/core/Tensor.h>

#include "graspecmf/flow/pose_batch.hpp"

namespace graspecmf::models {

// The gripper's six control points in metres [6, 3] (float32): the origin twice, then the two
// finger tips' inner and outer points (x ±0.0527 m, z 0.0753 and 0.1053 m).
at::Tensor panda_control_points();

// The control points of grasps (R, p) [G, 6, 3]: scale · R m_k + p, for p already in units of
// `scale` metres. Throws Error on a malformed batch.
at::Tensor grasp_control_points(const flow::PoseBatch& grasps, double scale);

// e(A_i, B_j) for control points a [Ga, 6, 3] and b [Gb, 6, 3]: the L1 distance of each point
// pair, averaged over the six → [Ga, Gb].
at::Tensor pairwise_control_point_distance(const at::Tensor& a, const at::Tensor& b);

// The VAE loss of predictions matched one-to-one with truths [G, 6, 3]: mean c_i e_i − w_c mean
// log max(c_i, 1e-10) + β mean KL(N(μ_i, exp logvar_i) ‖ N(0, I)), for confidences c [G] and
// μ, logvar [G, L]. Throws Error on wrong shapes.
at::Tensor vae_loss(const at::Tensor& predicted, const at::Tensor& truth,
                    const at::Tensor& confidence, const at::Tensor& mu, const at::Tensor& logvar,
                    double kl_weight, double confidence_weight);

// The IMLE loss of N predictions [N, 6, 3] against M truths [M, 6, 3] of one object: each truth
// takes its nearest prediction i*(j); mean_j c_{i*(j)} e(i*(j), j) − w_c mean_i log max(c_i,
// 1e-4). Predictions nobody takes get only the confidence term. Throws Error on wrong shapes or
// an empty set.
at::Tensor imle_loss(const at::Tensor& predicted, const at::Tensor& truth,
                     const at::Tensor& confidence, double confidence_weight);

}  // namespace graspecmf::models
