// Partial views for training: the window render sees exactly what the whole image sees of the
// object, a partial cloud is the camera's side of the surface, seeded, and bad ranges are refused.
#include "graspecmf/camera/partial_view.hpp"

#include <gtest/gtest.h>

#include "graspecmf/camera/depth_render.hpp"
#include "scenes.hpp"
#include "test_support.hpp"

namespace graspecmf::camera {
namespace {

TEST(PartialView, WindowSeesWhatTheWholeImageSeesOfTheObject) {
  const geometry::TriangleMesh mug = testing::mug_on_table();
  const geometry::MeshRayCaster caster(mug);
  const geometry::BoundingBox box = geometry::bounding_box(mug);
  const geometry::Plane table{lie::Vec3::UnitZ(), 0.0};
  for (const double azimuth : {0.0, 130.0, 250.0}) {
    const lie::Pose pose = camera_above(box, azimuth, 40.0, 0.5);
    const Intrinsics whole = realsense_d435();
    const Intrinsics window = window_around(whole, pose, box.center(), 0.5 * box.extent().norm());
    EXPECT_LT(window.width * window.height, whole.width * whole.height / 4);
    const RenderedView a = render_view(caster, whole, pose, table);
    const RenderedView b = render_view(caster, window, pose, table);
    const int u0 = static_cast<int>(whole.cx - window.cx),
              v0 = static_cast<int>(whole.cy - window.cy);
    long seen_whole = 0, seen_window = 0;
    for (std::size_t i = 0; i < a.object_mask.size(); ++i) seen_whole += a.object_mask[i];
    for (int v = 0; v < window.height; ++v) {
      for (int u = 0; u < window.width; ++u) {
        const std::size_t i = static_cast<std::size_t>(v * window.width + u);
        const std::size_t j = static_cast<std::size_t>((v + v0) * whole.width + u + u0);
        seen_window += b.object_mask[i];
        ASSERT_EQ(b.object_mask[i], a.object_mask[j]);
        ASSERT_EQ(b.depth.metres[i], a.depth.metres[j]);
      }
    }
    EXPECT_GT(seen_whole, 3000);
    EXPECT_EQ(seen_window, seen_whole);  // nothing of the object lies outside the window
  }
}

TEST(PartialView, PartialCloudIsTheCamerasSideOfTheSurface) {
  const lie::Vec3 centre(0.0, 0.0, 0.05);
  const double r = 0.05;
  const geometry::MeshRayCaster sphere(testing::uv_sphere(centre, r, 96, 48));
  ViewSampling exact;
  exact.noisy = false;
  Rng rng(5);
  for (int view = 0; view < 4; ++view) {
    const std::vector<lie::Vec3> cloud = partial_cloud(sphere, exact, rng);
    ASSERT_GT(cloud.size(), 1000u);
    lie::Vec3 mean = lie::Vec3::Zero();
    for (const lie::Vec3& x : cloud) {
      mean += x;
      EXPECT_NEAR((x - centre).norm(), r, 1.5e-4);  // facets' sagitta and the voxel means
    }
    mean /= static_cast<double>(cloud.size());
    // One side only: a little less than a hemisphere (whose area centroid is r / 2 from the
    // centre; the pixels thin out towards the silhouette, moving the mean to about 0.64 r), and
    // above the centre, as the cameras are at 30° to 70° elevation. Both sides would give 0.
    const double offset = (mean - centre).norm();
    EXPECT_GT(offset, 0.45 * r);
    EXPECT_LT(offset, 0.75 * r);
    EXPECT_GT(mean.z() - centre.z(), 0.5 * r * std::sin(M_PI / 6) - 0.002);
  }
  Rng a(9), b(9), c(10);
  const ViewSampling noisy;
  const std::vector<lie::Vec3> first = partial_cloud(sphere, noisy, a);
  EXPECT_EQ(first, partial_cloud(sphere, noisy, b));
  EXPECT_NE(first, partial_cloud(sphere, noisy, c));
}

TEST(PartialView, BadRangesAreRefused) {
  using graspecmf::testing::expect_error;
  ViewSampling s;
  EXPECT_NO_THROW(validate(s, "views"));
  s.max_elevation = 90.0;
  expect_error([&] { validate(s, "views"); }, "views: the elevations");
  s = ViewSampling();
  s.min_elevation = 80.0;
  expect_error([&] { validate(s, "views"); }, "elevations");
  s = ViewSampling();
  s.min_distance = 0.1;
  expect_error([&] { validate(s, "views"); }, "distances");
  s = ViewSampling();
  s.intrinsics.width = s.intrinsics.height = 0;
  expect_error([&] { validate(s, "views"); }, "image size");
  s = ViewSampling();
  s.noise.edge_dropout = 1.5;
  EXPECT_THROW(validate(s, "views"), Error);
}

}  // namespace
}  // namespace graspecmf::camera
