#include "graspecmf/geometry/plane_fit.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <sstream>

#include "graspecmf/core/error.hpp"
#include "graspecmf/core/random.hpp"

namespace graspecmf::geometry {
namespace {

// The points within `distance` of the plane.
std::vector<Vec3> near(const std::vector<Vec3>& points, const Plane& plane, double distance) {
  std::vector<Vec3> inliers;
  for (const Vec3& x : points) {
    if (std::abs(plane.signed_distance(x)) <= distance) inliers.push_back(x);
  }
  return inliers;
}

// The least-squares plane of the points: through their mean, normal to the direction of least
// spread.
Plane least_squares(const std::vector<Vec3>& points) {
  Vec3 mean = Vec3::Zero();
  for (const Vec3& x : points) mean += x;
  mean /= static_cast<double>(points.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const Vec3& x : points) scatter += (x - mean) * (x - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(scatter);
  Plane plane;
  plane.normal = solver.eigenvectors().col(0).normalized();  // eigenvalues ascend
  plane.offset = -plane.normal.dot(mean);
  return plane;
}

}  // namespace

Plane parse_plane(const std::string& text, const std::string& what) {
  std::vector<double> values;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    std::size_t used = 0;
    try {
      values.push_back(std::stod(item, &used));
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || item.find_first_not_of(" \t", used) != std::string::npos) {
      throw Error(what + ": \"" + text + "\" is not four numbers a,b,c,d");
    }
  }
  const Vec3 normal = values.size() == 4 ? Vec3(values[0], values[1], values[2]) : Vec3::Zero();
  const double length = normal.norm();
  if (values.size() != 4 || !std::isfinite(values[3]) || !normal.allFinite() || length == 0.0) {
    throw Error(what + ": \"" + text + "\" is not a plane a,b,c,d (a x + b y + c z + d = 0)");
  }
  return {normal / length, values[3] / length};
}

Plane fit_plane(const std::vector<Vec3>& points, double inlier_distance, std::size_t min_inliers,
                std::uint64_t seed, int trials) {
  if (points.size() < 3) throw Error("a plane needs at least 3 points");
  if (!std::isfinite(inlier_distance) || inlier_distance <= 0.0) {
    throw Error("the plane's inlier distance must be positive");
  }
  Rng rng(seed);
  Plane best;
  std::size_t best_count = 0;
  for (int trial = 0; trial < trials; ++trial) {
    const Vec3& a = points[rng.index(points.size())];
    const Vec3& b = points[rng.index(points.size())];
    const Vec3& c = points[rng.index(points.size())];
    const Vec3 normal = (b - a).cross(c - a);
    if (normal.norm() < 1e-12) continue;
    const Plane plane{normal.normalized(), -normal.normalized().dot(a)};
    std::size_t count = 0;
    for (const Vec3& x : points) count += std::abs(plane.signed_distance(x)) <= inlier_distance;
    if (count > best_count) {
      best_count = count;
      best = plane;
    }
  }
  if (best_count < std::max<std::size_t>(min_inliers, 3)) {
    throw Error("no plane holds " + std::to_string(std::max<std::size_t>(min_inliers, 3)) +
                " of the " + std::to_string(points.size()) + " points within " +
                std::to_string(inlier_distance) + " m");
  }
  return least_squares(near(points, best, inlier_distance));
}

}  // namespace graspecmf::geometry
