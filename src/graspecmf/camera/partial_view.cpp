#include "graspecmf/camera/partial_view.hpp"

#include <algorithm>
#include <cmath>

#include "graspecmf/camera/camera_pose.hpp"
#include "graspecmf/camera/depth_render.hpp"
#include "graspecmf/core/error.hpp"

namespace graspecmf::camera {

void validate(const ViewSampling& s, const std::string& what) {
  const auto in = [](double v, double lo, double hi) { return v >= lo && v <= hi; };
  if (!in(s.min_elevation, 1.0, 89.0) || !in(s.max_elevation, 1.0, 89.0) ||
      s.min_elevation > s.max_elevation) {
    throw Error(what + ": the elevations must satisfy 1 ≤ min ≤ max ≤ 89 degrees");
  }
  if (!in(s.min_distance, 0.15, 5.0) || !in(s.max_distance, 0.15, 5.0) ||
      s.min_distance > s.max_distance) {
    throw Error(what + ": the distances must satisfy 0.15 ≤ min ≤ max ≤ 5 m");
  }
  validate(s.intrinsics, what);
  if (s.intrinsics.width <= 0) throw Error(what + ": the intrinsics must give the image size");
  validate(s.noise, what);
}

lie::Pose camera_above(const geometry::BoundingBox& box, double azimuth_degrees,
                       double elevation_degrees, double distance) {
  const double az = azimuth_degrees * M_PI / 180.0, el = elevation_degrees * M_PI / 180.0;
  const lie::Vec3 middle = box.center();
  const lie::Vec3 eye = middle + distance * lie::Vec3(std::cos(el) * std::cos(az),
                                                      std::cos(el) * std::sin(az), std::sin(el));
  return look_at(eye, middle, lie::Vec3::UnitZ());
}

Intrinsics window_around(const Intrinsics& k, const lie::Pose& base_from_camera,
                         const lie::Vec3& centre, double radius) {
  const lie::Vec3 c = base_from_camera.R.transpose() * (centre - base_from_camera.p);
  if (c.z() - radius <= 1e-3) return k;  // the sphere reaches the camera: the whole image
  // x / z and y / z are monotonic in each coordinate, so over the sphere's bounding cube they are
  // extreme at its corners.
  double u_lo = k.width, u_hi = 0.0, v_lo = k.height, v_hi = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    const lie::Vec3 x =
        c + radius * lie::Vec3(corner & 1 ? 1 : -1, corner & 2 ? 1 : -1, corner & 4 ? 1 : -1);
    const Eigen::Vector2d uv = project(k, x);
    u_lo = std::min(u_lo, uv.x());
    u_hi = std::max(u_hi, uv.x());
    v_lo = std::min(v_lo, uv.y());
    v_hi = std::max(v_hi, uv.y());
  }
  const int u0 = std::clamp(static_cast<int>(std::floor(u_lo)) - 1, 0, k.width);
  const int u1 = std::clamp(static_cast<int>(std::ceil(u_hi)) + 2, u0, k.width);
  const int v0 = std::clamp(static_cast<int>(std::floor(v_lo)) - 1, 0, k.height);
  const int v1 = std::clamp(static_cast<int>(std::ceil(v_hi)) + 2, v0, k.height);
  Intrinsics window = k;
  window.cx -= u0;
  window.cy -= v0;
  window.width = u1 - u0;
  window.height = v1 - v0;
  return window;
}

ViewDraw draw_view(const ViewSampling& sampling, Rng& rng) {
  ViewDraw draw;
  draw.azimuth = rng.uniform(0.0, 360.0);
  draw.elevation = rng.uniform(sampling.min_elevation, sampling.max_elevation);
  draw.distance = rng.uniform(sampling.min_distance, sampling.max_distance);
  draw.noise_seed = rng.next_u64();
  draw.points_seed = rng.next_u64();
  return draw;
}

std::vector<lie::Vec3> partial_cloud(const geometry::MeshRayCaster& mesh,
                                     const ViewSampling& sampling, const ViewDraw& draw) {
  const geometry::BoundingBox box = geometry::bounding_box(mesh.mesh());
  const lie::Pose pose = camera_above(box, draw.azimuth, draw.elevation, draw.distance);
  const Intrinsics k =
      window_around(sampling.intrinsics, pose, box.center(), 0.5 * box.extent().norm());
  if (k.width == 0 || k.height == 0) {
    throw Error("partial view: the object is outside the camera's image");
  }
  const geometry::Plane table{lie::Vec3::UnitZ(), -box.min.z()};
  RenderedView view = render_view(mesh, k, pose, table);
  if (sampling.noisy) view.depth = noisy_depth(view, k, sampling.noise, draw.noise_seed);
  ViewOptions options = sampling.points;
  options.table_mode = TableMode::none;
  return view_points(view.depth, k, view.object_mask, pose, options, draw.points_seed).object;
}

std::vector<lie::Vec3> partial_cloud(const geometry::MeshRayCaster& mesh,
                                     const ViewSampling& sampling, Rng& rng) {
  return partial_cloud(mesh, sampling, draw_view(sampling, rng));
}

std::vector<lie::Vec3> pick_points(const std::vector<lie::Vec3>& points, std::size_t count,
                                   std::size_t draws, Rng& rng) {
  if (points.empty()) throw Error("cannot pick points from an empty cloud");
  std::vector<lie::Vec3> picked;
  picked.reserve(count * draws);
  std::vector<lie::Vec3> pool = points;
  const std::size_t n = pool.size();
  for (std::size_t draw = 0; draw < draws; ++draw) {
    for (std::size_t i = 0; i < count; ++i) {
      if (i < n) {  // a partial Fisher–Yates shuffle
        std::swap(pool[i], pool[i + rng.index(n - i)]);
        picked.push_back(pool[i]);
      } else {
        picked.push_back(pool[rng.index(n)]);
      }
    }
  }
  return picked;
}

}  // namespace graspecmf::camera
