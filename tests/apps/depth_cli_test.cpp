// graspecmf sample from one depth image (the mug-view fixture rendered from the sample mug) with
// the bundled model: grasps stay above the table, simulate and view take them, and bad views get
// one clear error. (Turning the camera turns the model's input exactly: camera_tests'
// ViewPoints.TurnWithObjectTableAndCamera.)

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "graspecmf/data/acronym_file.hpp"
#include "graspecmf/geometry/mesh_io.hpp"

namespace {
namespace fs = std::filesystem;
using graspecmf::testing::expect_one_error_line;
using graspecmf::testing::run;
using graspecmf::testing::ScratchDir;

const fs::path kView = fs::path(GRASPECMF_DATA_DIR) / "camera" / "mug-view";
constexpr double kTableZ = 0.0514;  // the sample mug's lowest point, in its scaled mesh frame

std::string view_args(const std::string& pose) {
  return "--depth " + (kView / "depth.png").string() + " --mask " + (kView / "mask.png").string() +
         " --intrinsics " + (kView / "intrinsics.json").string() + " --camera-pose " + pose +
         " --threads 1 --seed 1";
}

// The lowest point of the Franka gripper's collision mesh over the grasps.
double lowest_gripper_point(const std::vector<graspecmf::data::Mat4>& grasps) {
  const graspecmf::geometry::TriangleMesh hand =
      graspecmf::geometry::read_mesh(graspecmf::testing::gripper_mesh_file());
  double lowest = 1e9;
  for (const graspecmf::data::Mat4& T : grasps) {
    for (const Eigen::Vector3d& v : hand.vertices) {
      lowest = std::min(lowest, (T.topLeftCorner<3, 3>() * v + T.topRightCorner<3, 1>()).z());
    }
  }
  return lowest;
}

TEST(CliDepth, GraspsFromOneViewStayAboveTheTableAndSimulate) {
  ScratchDir dir;
  const std::string pose = (kView / "camera_pose.json").string();
  const std::string out = (dir / "g.h5").string();
  const auto sampled = run("sample " + view_args(pose) + " --table auto --num 40 --object-mesh " +
                               fs::absolute(graspecmf::testing::sample_mesh_file()).string() +
                               " --object-scale 0.0002682458 --out " + out,
                           dir);
  ASSERT_EQ(sampled.exit_code, 0) << sampled.err;
  const graspecmf::data::AcronymGraspFile grasps = graspecmf::data::read_acronym_file(out);
  ASSERT_EQ(grasps.size(), 40u);
  // The fitted table is the true one to within the camera's noise (a millimetre or two).
  EXPECT_GT(lowest_gripper_point(grasps.transforms), kTableZ - 0.003);
  // Without the table some grasps come from below, through it.
  const std::string free_out = (dir / "free.h5").string();
  ASSERT_EQ(run("sample " + view_args(pose) + " --num 40 --out " + free_out, dir).exit_code, 0);
  EXPECT_LT(lowest_gripper_point(graspecmf::data::read_acronym_file(free_out).transforms),
            kTableZ - 0.02);
  // simulate and view take the grasps, with the mesh they record.
  const auto simulated =
      run("simulate " + out + " --threads 1 --out " + (dir / "labels.json").string(), dir);
  EXPECT_EQ(simulated.exit_code, 0) << simulated.err;
  const auto viewed = run("view " + out + " --out " + (dir / "v.html").string(), dir);
  EXPECT_EQ(viewed.exit_code, 0) << viewed.err;
}

TEST(CliDepth, BadViewsGetOneClearError) {
  ScratchDir dir;
  const std::string out = (dir / "g.h5").string();
  const std::string depth = (kView / "depth.png").string();
  expect_one_error_line(run("sample --depth " + depth + " --out " + out, dir), "--intrinsics");
  expect_one_error_line(
      run("sample " + view_args((kView / "camera_pose.json").string()) + " --units mm --out " + out,
          dir),
      "--depth");
  expect_one_error_line(run("sample --mesh " + graspecmf::testing::sample_mesh_file().string() +
                                " --scale 0.0002682458 --object-mesh x.obj --out " + out,
                            dir),
                        "--object-mesh");
  expect_one_error_line(run("sample --depth " + (kView / "mask.png").string() + " --intrinsics " +
                                (kView / "intrinsics.json").string() + " --out " + out,
                            dir),
                        "8-bit PNG");
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
