#include "graspecmf/viz/projection.hpp"

#include <algorithm>
#include <limits>

#include "graspecmf/core/error.hpp"

namespace graspecmf::viz {
namespace {

constexpr double kMargin = 0.05;

}  // namespace

Projection::Projection(const std::vector<Vec3>& fit, int size, const Vec3& direction,
                       const Vec3& up)
    : size_(size) {
  if (fit.empty()) throw Error("render: nothing to fit into the view");
  if (size < 8 || size > 4096) throw Error("render: size must be in [8, 4096]");
  forward_ = direction.normalized();
  const Vec3 right = forward_.cross(up);
  if (!(right.norm() > 1e-9)) throw Error("render: the view direction is parallel to up");
  right_ = right.normalized();
  up_ = right_.cross(forward_);
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d hi = -lo;
  for (const Vec3& p : fit) {
    if (!p.allFinite()) throw Error("render: a coordinate is not finite");
    const Eigen::Vector2d s(p.dot(right_), p.dot(up_));
    lo = lo.cwiseMin(s);
    hi = hi.cwiseMax(s);
  }
  const double extent = std::max({hi.x() - lo.x(), hi.y() - lo.y(), 1e-12});
  scale_ = size * (1.0 - 2.0 * kMargin) / extent;
  center_x_ = 0.5 * (lo.x() + hi.x());
  center_y_ = 0.5 * (lo.y() + hi.y());
}

Vec3 Projection::operator()(const Vec3& point) const {
  return {0.5 * size_ + (point.dot(right_) - center_x_) * scale_,
          0.5 * size_ - (point.dot(up_) - center_y_) * scale_,  // image rows grow downwards
          point.dot(forward_)};
}

}  // namespace graspecmf::viz
