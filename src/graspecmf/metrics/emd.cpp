#include "graspecmf/metrics/emd.hpp"

#include <cmath>

#include "graspecmf/core/error.hpp"
#include "graspecmf/lie/so3.hpp"
#include "graspecmf/metrics/assignment.hpp"

namespace graspecmf::metrics {

double grasp_distance(const lie::Pose& a, const lie::Pose& b, GraspDistance distance) {
  if (distance == GraspDistance::geodesic) return lie::pose_distance(a, b);
  return (a.p - b.p).norm() + 1.0 - std::cos(lie::so3_distance(a.R, b.R));
}

double earth_movers_distance(const std::vector<lie::Pose>& a, const std::vector<lie::Pose>& b,
                             GraspDistance distance) {
  if (a.empty() || a.size() != b.size()) {
    throw Error("EMD needs two non-empty sets of the same size (got " + std::to_string(a.size()) +
                " and " + std::to_string(b.size()) + ")");
  }
  const auto n = static_cast<Eigen::Index>(a.size());
  Eigen::MatrixXd cost(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) {
      cost(i, j) =
          grasp_distance(a[static_cast<std::size_t>(i)], b[static_cast<std::size_t>(j)], distance);
    }
  }
  if (!cost.allFinite()) throw Error("EMD: a grasp pose is not finite");
  const std::vector<int> column = min_cost_assignment(cost);
  double total = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) total += cost(i, column[static_cast<std::size_t>(i)]);
  return total / static_cast<double>(n);
}

}  // namespace graspecmf::metrics
