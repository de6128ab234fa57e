#include "graspecmf/camera/view_cloud.hpp"

#include <cmath>
#include <nanoflann.hpp>
#include <string>
#include <unordered_map>

#include "graspecmf/core/error.hpp"

namespace graspecmf::camera {
namespace {

// nanoflann's view of a point list.
struct PointList {
  const std::vector<Vec3>& points;
  std::size_t kdtree_get_point_count() const { return points.size(); }
  double kdtree_get_pt(std::size_t i, std::size_t axis) const {
    return points[i][static_cast<int>(axis)];
  }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};

using KdTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointList>,
                                                   PointList, 3, std::size_t>;

}  // namespace

std::vector<Vec3> back_project(const DepthImage& depth, const Intrinsics& intrinsics,
                               const std::vector<std::uint8_t>& mask, Pixels pixels) {
  if (intrinsics.width != 0 &&
      (intrinsics.width != depth.width || intrinsics.height != depth.height)) {
    throw Error("the intrinsics are for a " + std::to_string(intrinsics.width) + " × " +
                std::to_string(intrinsics.height) + " image but the depth image is " +
                std::to_string(depth.width) + " × " + std::to_string(depth.height));
  }
  if (pixels != Pixels::all && mask.size() != depth.metres.size()) {
    throw Error("the mask does not have the depth image's size");
  }
  std::vector<Vec3> points;
  for (int v = 0; v < depth.height; ++v) {
    for (int u = 0; u < depth.width; ++u) {
      const std::size_t i = static_cast<std::size_t>(v) * depth.width + u;
      const float z = depth.metres[i];
      if (!(z > 0.0f)) continue;
      if (pixels == Pixels::object && mask[i] == 0) continue;
      if (pixels == Pixels::background && mask[i] != 0) continue;
      points.push_back(camera::back_project(intrinsics, u, v, z));
    }
  }
  return points;
}

std::vector<Vec3> voxel_downsample(const std::vector<Vec3>& points, double voxel) {
  if (!std::isfinite(voxel) || voxel < 0.0) throw Error("the voxel size must be at least 0");
  if (voxel == 0.0) return points;
  struct Cell {
    Vec3 sum = Vec3::Zero();
    int count = 0;
  };
  struct KeyHash {
    std::size_t operator()(const Eigen::Vector3i& key) const {
      return static_cast<std::size_t>(key.x()) * 73856093u ^
             static_cast<std::size_t>(key.y()) * 19349663u ^
             static_cast<std::size_t>(key.z()) * 83492791u;
    }
  };
  struct KeyEqual {
    bool operator()(const Eigen::Vector3i& a, const Eigen::Vector3i& b) const { return a == b; }
  };
  std::unordered_map<Eigen::Vector3i, std::size_t, KeyHash, KeyEqual> slot;
  std::vector<Cell> cells;
  for (const Vec3& q : points) {
    const Vec3 scaled = (q / voxel).array().floor();
    if (!scaled.allFinite() || scaled.cwiseAbs().maxCoeff() > 1e9) {
      throw Error("a point is too far from the origin for this voxel size");
    }
    const auto [at, fresh] = slot.try_emplace(scaled.cast<int>(), cells.size());
    if (fresh) cells.emplace_back();
    cells[at->second].sum += q;
    ++cells[at->second].count;
  }
  std::vector<Vec3> out;
  out.reserve(cells.size());
  for (const Cell& cell : cells) out.push_back(cell.sum / cell.count);
  return out;
}

std::vector<Vec3> remove_outliers(const std::vector<Vec3>& points, int neighbours,
                                  double std_ratio) {
  if (neighbours < 0) throw Error("the outlier test's neighbour count must be at least 0");
  if (!std::isfinite(std_ratio) || std_ratio <= 0.0) {
    throw Error("the outlier test's standard-deviation ratio must be positive");
  }
  const auto k = static_cast<std::size_t>(neighbours);
  if (k == 0 || points.size() < k + 1) return points;
  const PointList list{points};
  const KdTree tree(3, list, nanoflann::KDTreeSingleIndexAdaptorParams(10));  // built here
  std::vector<double> mean_distance(points.size());
  std::vector<std::size_t> index(k + 1);
  std::vector<double> squared(k + 1);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::size_t found = tree.knnSearch(points[i].data(), k + 1, index.data(), squared.data());
    double sum = 0.0;
    for (std::size_t j = 0; j < found; ++j)
      sum += std::sqrt(squared[j]);  // the point itself adds 0
    mean_distance[i] = sum / static_cast<double>(found - 1);
  }
  double mean = 0.0, square = 0.0;
  for (const double d : mean_distance) mean += d;
  mean /= static_cast<double>(points.size());
  for (const double d : mean_distance) square += (d - mean) * (d - mean);
  const double limit = mean + std_ratio * std::sqrt(square / static_cast<double>(points.size()));
  std::vector<Vec3> kept;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (mean_distance[i] <= limit) kept.push_back(points[i]);
  }
  return kept;
}

}  // namespace graspecmf::camera
