#include "graspecmf/metrics/baselines.hpp"

#include <cmath>
#include <limits>

#include "graspecmf/core/error.hpp"
#include "graspecmf/core/random.hpp"
#include "graspecmf/lie/rotation_sets.hpp"

namespace graspecmf::metrics {
namespace {

// Mean over a of the distance to the nearest point of b.
double mean_nearest(const std::vector<geometry::Vec3>& a, const std::vector<geometry::Vec3>& b) {
  double total = 0.0;
  for (const geometry::Vec3& p : a) {
    double best = std::numeric_limits<double>::infinity();
    for (const geometry::Vec3& q : b) best = std::min(best, (p - q).squaredNorm());
    total += std::sqrt(best);
  }
  return total / static_cast<double>(a.size());
}

}  // namespace

std::vector<lie::Pose> random_grasps_in_box(const geometry::BoundingBox& box, double margin,
                                            std::size_t n, std::uint64_t seed) {
  if (!(margin >= 0.0) || !std::isfinite(margin)) throw Error("the box margin must be ≥ 0");
  Rng rng(seed);
  std::vector<lie::Pose> grasps(n);
  for (lie::Pose& g : grasps) {
    g.R = lie::random_rotation(rng);
    for (int k = 0; k < 3; ++k) g.p[k] = rng.uniform(box.min[k] - margin, box.max[k] + margin);
  }
  return grasps;
}

double chamfer_distance(const std::vector<geometry::Vec3>& a,
                        const std::vector<geometry::Vec3>& b) {
  if (a.empty() || b.empty()) throw Error("the Chamfer distance needs two non-empty clouds");
  return mean_nearest(a, b) + mean_nearest(b, a);
}

}  // namespace graspecmf::metrics
