// An object from one depth view: the table found in the image, the object's points with or
// without a mask, exact equivariance when object, table and camera turn together, and bad views
// refused with one clear error.
#include "graspecmf/camera/view_input.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "graspecmf/camera/depth_render.hpp"
#include "scenes.hpp"
#include "test_support.hpp"

namespace graspecmf::camera {
namespace {

using graspecmf::testing::expect_error;

const geometry::Plane kTable{lie::Vec3::UnitZ(), 0.0};

struct Scene {
  RenderedView view;
  lie::Pose camera;
};

Scene mug_scene(const lie::Mat3& R = lie::Mat3::Identity(),
                const lie::Vec3& t = lie::Vec3::Zero()) {
  geometry::TriangleMesh mug = testing::mug_on_table();
  for (lie::Vec3& v : mug.vertices) v = R * v + t;
  const lie::Pose camera = look_at({0.3, 0.25, 0.4}, {0, 0, 0.04}, {0, 0, 1});
  const lie::Pose turned{R * camera.R, R * camera.p + t};
  const geometry::Plane table{R * kTable.normal, -(R * kTable.normal).dot(t)};
  return {render_view(geometry::MeshRayCaster(mug), realsense_d435(), turned, table), turned};
}

ViewOptions automatic_table() {
  ViewOptions options;
  options.table_mode = TableMode::automatic;
  return options;
}

TEST(ViewPoints, FindsTheTableAndTheObjectAboveIt) {
  const Scene scene = mug_scene();
  const ViewPoints view = view_points(scene.view.depth, realsense_d435(), scene.view.object_mask,
                                      scene.camera, automatic_table(), 1);
  ASSERT_TRUE(view.table);
  EXPECT_GT(view.table->normal.z(), std::cos(0.2 * M_PI / 180));
  EXPECT_NEAR(view.table->offset, 0.0, 5e-4);
  ASSERT_GT(view.object.size(), 500u);
  for (const lie::Vec3& x : view.object) EXPECT_GT(x.z(), -1e-3);
  EXPECT_GT(view.scene.size(), view.object.size());
  // Without a mask the object is what stands above the table: nearly the same points.
  const ViewPoints unmasked =
      view_points(scene.view.depth, realsense_d435(), {}, scene.camera, automatic_table(), 1);
  EXPECT_NEAR(static_cast<double>(unmasked.object.size()), static_cast<double>(view.object.size()),
              0.1 * static_cast<double>(view.object.size()));
  // Without a table or mask, every point is the object.
  const ViewPoints everything =
      view_points(scene.view.depth, realsense_d435(), {}, scene.camera, {}, 1);
  EXPECT_FALSE(everything.table);
  EXPECT_GT(everything.object.size(), 10 * view.object.size());
}

TEST(ViewPoints, TurnWithObjectTableAndCamera) {
  const lie::Mat3 R =
      Eigen::AngleAxisd(2.3, lie::Vec3(-0.4, 0.1, 0.9).normalized()).toRotationMatrix();
  const lie::Vec3 t(0.5, 0.2, -0.8);
  const Scene scene = mug_scene(), turned = mug_scene(R, t);
  for (const bool masked : {true, false}) {
    SCOPED_TRACE(masked);
    const ViewPoints a = view_points(scene.view.depth, realsense_d435(),
                                     masked ? scene.view.object_mask : std::vector<std::uint8_t>{},
                                     scene.camera, automatic_table(), 1);
    const ViewPoints b = view_points(turned.view.depth, realsense_d435(),
                                     masked ? turned.view.object_mask : std::vector<std::uint8_t>{},
                                     turned.camera, automatic_table(), 1);
    ASSERT_EQ(a.object.size(), b.object.size());
    double worst = 0.0;
    for (std::size_t i = 0; i < a.object.size(); ++i) {
      worst = std::max(worst, (R * a.object[i] + t - b.object[i]).norm());
    }
    EXPECT_LT(worst, 1e-5);
    EXPECT_LT((R * a.table->normal - b.table->normal).norm(), 1e-5);
  }
}

TEST(ViewPoints, BadViewsGetOneClearError) {
  const Scene scene = mug_scene();
  const std::vector<std::uint8_t> empty(scene.view.object_mask.size(), 0);
  expect_error([&] { view_points(scene.view.depth, realsense_d435(), empty, scene.camera, {}, 1); },
               "shows 0 points of the object");
  ViewOptions below = {};
  below.table_mode = TableMode::given;
  below.table = {-lie::Vec3::UnitZ(), 0.0};  // the sign turned: the object would be under it
  expect_error(
      [&] {
        view_points(scene.view.depth, realsense_d435(), scene.view.object_mask, scene.camera, below,
                    1);
      },
      "not above the table");
  DepthImage flat = scene.view.depth;
  for (float& z : flat.metres)
    z = z > 0 ? 0.5f : 0.0f;  // a wall facing the camera: no table below it
  ViewOptions bad = automatic_table();
  bad.voxel = -1;
  expect_error([&] { view_points(flat, realsense_d435(), {}, scene.camera, bad, 1); },
               "voxel size");
  Intrinsics small = realsense_d435();
  small.width = 320;
  small.height = 240;
  expect_error([&] { view_points(scene.view.depth, small, {}, scene.camera, {}, 1); },
               "intrinsics are for a 320 × 240 image but the depth image is 640 × 480");
}

}  // namespace
}  // namespace graspecmf::camera
