// The ray-cast depth renderer and back-projection: a rendered plane and sphere back-project onto
// themselves, to float rounding or to the PNG's millimetre, and turning the whole scene (object,
// table and camera) turns nothing in the image.
#include "graspecmf/camera/depth_render.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "graspecmf/camera/view_cloud.hpp"
#include "graspecmf/lie/so3.hpp"
#include "scenes.hpp"
#include "test_support.hpp"

namespace graspecmf::camera {
namespace {

using testing::uv_sphere;

const geometry::Plane kTable{Vec3::UnitZ(), 0.0};

std::vector<Vec3> in_base(std::vector<Vec3> points, const lie::Pose& base_from_camera) {
  for (Vec3& x : points) x = base_from_camera.R * x + base_from_camera.p;
  return points;
}

TEST(DepthRender, PlaneAndSphereBackProjectOntoThemselves) {
  const Vec3 centre(0.0, 0.0, 0.05);
  const double r = 0.05;
  const geometry::MeshRayCaster sphere(uv_sphere(centre, r, 96, 48));
  const lie::Pose camera = look_at({0.35, -0.2, 0.45}, {0, 0, 0.03}, {0, 0, 1});
  const RenderedView view = render_view(sphere, realsense_d435(), camera, kTable);
  const std::vector<Vec3> table = in_base(
      back_project(view.depth, realsense_d435(), view.object_mask, Pixels::background), camera);
  const std::vector<Vec3> ball =
      in_base(back_project(view.depth, realsense_d435(), view.object_mask, Pixels::object), camera);
  ASSERT_GT(table.size(), 100000u);
  ASSERT_GT(ball.size(), 8000u);
  double table_error = 0.0, inside = 0.0, outside = 0.0;
  for (const Vec3& x : table) table_error = std::max(table_error, std::abs(x.z()));
  for (const Vec3& x : ball) {
    inside = std::max(inside, r - (x - centre).norm());
    outside = std::max(outside, (x - centre).norm() - r);
  }
  std::cout << "plane: max |z| " << table_error << " m; sphere: " << inside << " m inside, "
            << outside << " m outside\n";
  EXPECT_LT(table_error, 1e-6);  // float32 depth at ~0.6 m
  EXPECT_LT(outside, 1e-6);      // the facets are chords: inside the sphere, never out
  EXPECT_LT(inside, 1.2e-4);     // a facet's sagitta: r (1 − cos(π/48)) ≈ 1.07e-4 m
  // Every pixel sees something; on the table the incidence is the ray's angle to the vertical.
  EXPECT_EQ(table.size() + ball.size(), 640u * 480u);
  for (std::size_t i = 0; i < view.incidence.size(); i += 997) {
    if (view.object_mask[i]) continue;
    const int u = static_cast<int>(i % 640), v = static_cast<int>(i / 640);
    const Vec3 ray = (camera.R * back_project(realsense_d435(), u, v, 1.0)).normalized();
    EXPECT_NEAR(view.incidence[i], std::abs(ray.z()), 1e-6);
  }
}

TEST(DepthRender, MillimetrePngKeepsBackProjectionWithinItsQuantisation) {
  const graspecmf::testing::ScratchDir dir;
  const geometry::MeshRayCaster sphere(uv_sphere({0.0, 0.0, 0.05}, 0.05, 48, 24));
  const lie::Pose camera = look_at({0.35, -0.2, 0.45}, {0, 0, 0.03}, {0, 0, 1});
  RenderedView view = render_view(sphere, realsense_d435(), camera, kTable);
  write_depth_png(view.depth, dir / "d.png");
  view.depth = read_depth_image(dir / "d.png");
  double error = 0.0;
  for (const Vec3& x :
       in_base(back_project(view.depth, realsense_d435(), view.object_mask, Pixels::background),
               camera)) {
    error = std::max(error, std::abs(x.z()));
  }
  // ±0.5 mm along the optical axis is at most 0.5 mm × |ray| / z ≈ 0.6 mm at the corners.
  EXPECT_LT(error, 0.00061);
  EXPECT_GT(error, 0.0001);  // and the quantisation is there
}

TEST(DepthRender, TurningObjectTableAndCameraTogetherLeavesTheImage) {
  const geometry::TriangleMesh mug = testing::mug_on_table();
  const lie::Pose camera = look_at({0.3, 0.25, 0.4}, {0, 0, 0.04}, {0, 0, 1});
  const RenderedView view =
      render_view(geometry::MeshRayCaster(mug), realsense_d435(), camera, kTable);
  const lie::Mat3 R = Eigen::AngleAxisd(1.1, Vec3(0.3, -0.5, 0.8).normalized()).toRotationMatrix();
  const Vec3 t(0.2, -0.7, 1.3);
  geometry::TriangleMesh turned = mug;
  for (Vec3& v : turned.vertices) v = R * v + t;
  const geometry::Plane table{R * kTable.normal, kTable.offset - (R * kTable.normal).dot(t)};
  const lie::Pose turned_camera{R * camera.R, R * camera.p + t};
  const RenderedView other =
      render_view(geometry::MeshRayCaster(turned), realsense_d435(), turned_camera, table);
  double worst = 0.0;
  std::size_t mask_changes = 0;
  for (std::size_t i = 0; i < view.depth.metres.size(); ++i) {
    worst = std::max(worst,
                     static_cast<double>(std::abs(view.depth.metres[i] - other.depth.metres[i])));
    mask_changes += view.object_mask[i] != other.object_mask[i];
  }
  EXPECT_LT(worst, 1e-5);
  EXPECT_LE(mask_changes, 2u);  // a ray through a silhouette edge may fall either way
  EXPECT_GT(std::count(view.object_mask.begin(), view.object_mask.end(), 1), 5000);
}

TEST(DepthRender, BadCamerasAreRefused) {
  const geometry::MeshRayCaster sphere(uv_sphere({0, 0, 0}, 0.05, 8, 4));
  Intrinsics k = realsense_d435();
  k.width = k.height = 0;
  graspecmf::testing::expect_error([&] { render_view(sphere, k, lie::Pose{}, std::nullopt); },
                                   "image size");
}

}  // namespace
}  // namespace graspecmf::camera
