#pragma once
// Earth Mover's Distance between two equally sized sets of grasp poses (docs/method.md,
// "Evaluation: the EMD"): the mean cost of the exact optimal one-to-one matching.

#include <vector>

#include "graspecmf/lie/se3.hpp"

namespace graspecmf::metrics {

enum class GraspDistance {
  // sqrt(θ² + ‖Δp‖²), radians and metres (the paper's EMD; rotation dominates).
  geodesic,
  // ‖Δp‖ + (1 − cos θ) (the SE(3)-DiffusionFields variant).
  diffusion_fields,
};

// The distance between two poses under the chosen definition.
double grasp_distance(const lie::Pose& a, const lie::Pose& b, GraspDistance distance);

// Mean matched distance of the optimal assignment between a and b. Throws Error if the sets are
// empty, differ in size or contain a non-finite pose.
double earth_movers_distance(const std::vector<lie::Pose>& a, const std::vector<lie::Pose>& b,
                             GraspDistance distance = GraspDistance::geodesic);

}  // namespace graspecmf::metrics
