#include "graspecmf/data/network_frame.hpp"

#include "graspecmf/core/error.hpp"

namespace graspecmf::data {

NetworkFrame NetworkFrame::of_points(const Eigen::Vector3d* points, std::size_t count,
                                     const Eigen::Matrix3d& g, double scale) {
  if (count == 0) throw Error("a network frame needs at least one point");
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < count; ++i) sum += g * points[i];
  return {g, sum / static_cast<double>(count), scale};
}

lie::Pose NetworkFrame::to_network(const lie::Pose& grasp) const {
  return {rotation * grasp.R, to_network(grasp.p)};
}

lie::Pose NetworkFrame::from_network(const lie::Pose& grasp) const {
  return {rotation.transpose() * grasp.R, rotation.transpose() * (grasp.p / scale + centroid)};
}

}  // namespace graspecmf::data
