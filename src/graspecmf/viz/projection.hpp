#pragma once
// The software renderer's camera: an orthographic projection of 3-D points into a square image,
// fitted to a set of points.

#include <vector>

#include "graspecmf/geometry/triangle_mesh.hpp"

namespace graspecmf::viz {

using Vec3 = Eigen::Vector3d;

class Projection {
 public:
  // A camera looking along `direction` (from the camera towards the scene; need not be unit) with
  // `up` projected to the image's vertical, centred on the points of `fit` and scaled so that
  // their bounding rectangle on the screen spans size pixels less a 5 % margin on each side.
  // Throws Error if fit is empty or not finite, size is outside [8, 4096] or direction ∥ up.
  Projection(const std::vector<Vec3>& fit, int size, const Vec3& direction, const Vec3& up);

  // (column, row, depth) of a point: pixel coordinates from the image's top-left corner (pixel
  // (i, j) covers [i, i + 1) × [j, j + 1)) and the distance along the view direction in the
  // points' units (larger is farther from the camera).
  Vec3 operator()(const Vec3& point) const;

  int size() const { return size_; }
  // Pixels per unit of the points' coordinates.
  double scale() const { return scale_; }
  // The unit vectors of the screen's right and up directions and of the view direction.
  const Vec3& right() const { return right_; }
  const Vec3& up() const { return up_; }
  const Vec3& forward() const { return forward_; }

 private:
  int size_;
  Vec3 right_, up_, forward_;
  double center_x_ = 0.0, center_y_ = 0.0;  // screen coordinates of the image centre
  double scale_ = 1.0;
};

}  // namespace graspecmf::viz
