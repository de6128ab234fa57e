#pragma once
// The frame every network sees an object in (docs/method.md, "Units and frames"):
// x_net = scale · (g x − c), with g a rotation (the training augmentation; the identity when
// sampling), c the centroid of the rotated cloud, and scale the model's position scale. Torch-free.

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "graspecmf/lie/se3.hpp"

namespace graspecmf::data {

struct NetworkFrame {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // g
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();      // c, metres, after the rotation
  double scale = 1.0;

  // The frame of count points (metres, object frame) rotated by g, c their rotated mean. Throws
  // Error if count is 0.
  static NetworkFrame of_points(const Eigen::Vector3d* points, std::size_t count,
                                const Eigen::Matrix3d& g, double scale);
  static NetworkFrame of_points(const std::vector<Eigen::Vector3d>& points,
                                const Eigen::Matrix3d& g, double scale) {
    return of_points(points.data(), points.size(), g, scale);
  }

  // A point of the object's frame in network units.
  Eigen::Vector3d to_network(const Eigen::Vector3d& x) const {
    return scale * (rotation * x - centroid);
  }
  // A grasp T_object_gripper in network units (its rotation R becomes g R).
  lie::Pose to_network(const lie::Pose& grasp) const;
  // The inverse of to_network: a grasp in network units back in the object's frame, metres.
  lie::Pose from_network(const lie::Pose& grasp) const;
};

}  // namespace graspecmf::data
