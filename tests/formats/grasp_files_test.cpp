#include "graspecmf/formats/grasp_files.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "graspecmf/core/error.hpp"
#include "graspecmf/core/npy.hpp"
#include "graspecmf/core/random.hpp"
#include "graspecmf/core/zip_archive.hpp"
#include "graspecmf/gripper/panda.hpp"
#include "graspecmf/lie/so3.hpp"
#include "test_support.hpp"

namespace graspecmf::formats {
namespace {
namespace fs = std::filesystem;
using graspecmf::testing::expect_error;
using graspecmf::testing::sample_grasp_file;
using graspecmf::testing::ScratchDir;
using Vec3 = Eigen::Vector3d;

fs::path fixture(const std::string& name) {
  return fs::path(GRASPECMF_DATA_DIR) / "formats" / name;
}

double max_difference(const std::vector<Mat4>& a, const std::vector<Mat4>& b) {
  EXPECT_EQ(a.size(), b.size());
  double worst = 0;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
    worst = std::max(worst, (a[i] - b[i]).cwiseAbs().maxCoeff());
  }
  return worst;
}

// n random rigid poses (exact rotations from the exponential map), with scores and widths.
GraspSet random_grasps(std::size_t n) {
  Rng rng(7);
  GraspSet grasps;
  for (std::size_t i = 0; i < n; ++i) {
    Mat4 T = Mat4::Identity();
    T.topLeftCorner<3, 3>() = lie::so3_exp(Vec3(rng.normal(), rng.normal(), rng.normal()));
    T.topRightCorner<3, 1>() = Vec3(rng.normal(), rng.normal(), rng.normal()) * 0.1;
    grasps.poses.push_back(T);
    grasps.scores.push_back(rng.uniform());
    grasps.widths.push_back(0.08 * rng.uniform());
  }
  return grasps;
}

// The grasps after writing them as `name` and reading them back with the same options.
GraspSet round_trip(const GraspSet& grasps, const fs::path& path,
                    const FormatOptions& options = {}) {
  write_grasps(grasps, path, options);
  return read_grasps(path, options);
}

TEST(GraspFiles, EveryFormatRoundTripsExactRigidPosesScoresAndWidths) {
  const ScratchDir dir;
  const GraspSet grasps = random_grasps(50);
  for (const std::string name : {"a.yaml", "b.npy", "c.npz", "d.json"}) {
    SCOPED_TRACE(name);
    const GraspSet back = round_trip(grasps, dir.path() / name);
    EXPECT_LT(max_difference(back.poses, grasps.poses), 1e-12);
    ASSERT_EQ(back.scores.size(), grasps.scores.size());
    ASSERT_EQ(back.widths.size(), grasps.widths.size());
    for (std::size_t i = 0; i < grasps.size(); ++i) {
      EXPECT_NEAR(back.scores[i], grasps.scores[i], 1e-15);
      EXPECT_NEAR(back.widths[i], grasps.widths[i], 1e-15);
    }
  }
}

TEST(GraspFiles, TheSampleMugsGraspsSurviveEveryFormat) {
  const ScratchDir dir;
  const GraspSet mug = read_grasps(sample_grasp_file());
  ASSERT_EQ(mug.size(), 2000u);
  for (const std::string name : {"a.h5", "b.json", "c.yaml", "d.npy", "e.npz"}) {
    SCOPED_TRACE(name);
    GraspSet back = round_trip(mug, dir.path() / name);
    // Through a quaternion, the stored matrices (orthonormal to about 1e-8) become the nearest
    // rotations; every other format keeps their doubles.
    EXPECT_LT(max_difference(back.poses, mug.poses), name == "c.yaml" ? 1e-7 : 1e-12);
    // Labels survive as labels or as scores of 1 and 0.
    for (std::size_t i = 0; i < mug.size(); ++i) {
      ASSERT_EQ(confidence(back, i), confidence(mug, i)) << i;
    }
  }
  // Both ACRONYM layouts keep the object motions and the object.
  const GraspSet json = round_trip(mug, dir.path() / "f.json", {GraspFormat::acronym_json});
  EXPECT_EQ(json.qualities->motion_shaking_angular, mug.qualities->motion_shaking_angular);
  EXPECT_EQ(json.object->file, mug.object->file);
  EXPECT_EQ(json.object->scale, mug.object->scale);
  EXPECT_TRUE(unkept_fields(mug, GraspFormat::acronym_json).empty());
  EXPECT_EQ(unkept_fields(mug, GraspFormat::json), std::vector<std::string>{"object motions"});
}

TEST(GraspFiles, JsonLayoutsAreToldApartByContent) {
  const ScratchDir dir;
  GraspSet grasps = random_grasps(3);
  grasps.qualities = data::GraspQualities{};
  grasps.qualities->object_in_gripper = {1, 0, 1};
  write_grasps(grasps, dir.path() / "flat.json", {GraspFormat::acronym_json});
  write_grasps(grasps, dir.path() / "plain.json");
  const std::string plain = graspecmf::testing::read_file(dir.path() / "plain.json");
  EXPECT_NE(plain.find("true"), std::string::npos);  // GraspGen indexes with boolean masks
  for (const std::string name : {"flat.json", "plain.json"}) {
    const GraspSet back = read_grasps(dir.path() / name);
    EXPECT_EQ(back.qualities->object_in_gripper, grasps.qualities->object_in_gripper);
  }
}

TEST(GraspFiles, GraspNetRowsAnchorTheFingertipsDepthAheadOfTheGraspPoint) {
  // graspnetAPI's own rows: row 0 is the identity rotation (approach +x, closing +y) at
  // (0.1, 0.2, 0.3) with depth 0.02 and width 0.05.
  const GraspSet grasps = read_grasps(fixture("graspnet_float32.npy"));
  ASSERT_EQ(grasps.size(), 2u);
  EXPECT_NEAR(grasps.scores[0], 0.9, 1e-7);
  EXPECT_NEAR(grasps.widths[1], 0.03, 1e-7);
  const lie::Pose pose = lie::Pose::from_matrix(grasps.poses[0]);
  EXPECT_LT((pose.R.col(2) - Vec3::UnitX()).norm(), 1e-7);  // ACRONYM approach = GraspNet x
  EXPECT_LT((pose.R.col(0) - Vec3::UnitY()).norm(), 1e-7);  // ACRONYM closing = GraspNet y
  // The fingertips' centre lies `depth` past the grasp point along the approach.
  const Vec3 tips = lie::apply(pose, Vec3(0, 0, gripper::panda::kFingertipZ));
  EXPECT_LT((tips - Vec3(0.1 + 0.02, 0.2, 0.3)).norm(), 1e-6);
  // Written back with the same depth, the second row's grasp point is the file's.
  const ScratchDir dir;
  GraspSet second;
  second.poses = {grasps.poses[1]};
  const GraspSet back =
      round_trip(second, dir.path() / "g.npy",
                 FormatOptions{std::nullopt, IsaacGripperFrame::automatic, 0.04, 7});
  EXPECT_LT(max_difference(back.poses, second.poses), 1e-12);
  // The right fingertip of ACRONYM's frame, (0.04, 0, 0.1122), is at (depth, 0.04, 0) in
  // GraspNet's.
  GraspSet identity;
  identity.poses = {Mat4::Identity()};
  const double depth = 0.03;
  write_grasps(identity, dir.path() / "i.npy",
               {std::nullopt, IsaacGripperFrame::automatic, depth, 0});
  const std::string bytes = graspecmf::testing::read_file(dir.path() / "i.npy");
  const double* row = reinterpret_cast<const double*>(bytes.data() + 128);
  Eigen::Matrix3d R;
  R << row[4], row[5], row[6], row[7], row[8], row[9], row[10], row[11], row[12];
  const Vec3 in_graspnet =
      R.transpose() * (Vec3(0.04, 0, 0.1122) - Vec3(row[13], row[14], row[15]));
  EXPECT_LT((in_graspnet - Vec3(depth, 0.04, 0)).norm(), 1e-12);
  EXPECT_EQ(row[3], depth);
  EXPECT_EQ(row[1], 0.08);
}

TEST(GraspFiles, IsaacPandaHandIsAcronymsFrameTurnedAboutZ) {
  const ScratchDir dir;
  GraspSet identity;
  identity.poses = {Mat4::Identity()};
  write_grasps(identity, dir.path() / "hand.yaml");
  const std::string text = graspecmf::testing::read_file(dir.path() / "hand.yaml");
  EXPECT_NE(text.find("gripper_frame: panda_hand"), std::string::npos);
  EXPECT_NE(text.find("w: 0.707106781186547"), std::string::npos) << text;
  // Read as ACRONYM's frame, the file's pose is T_acronym_hand: the hand's +y (its first finger's
  // axis in the URDF) is ACRONYM's −x.
  const GraspSet raw =
      read_grasps(dir.path() / "hand.yaml", {std::nullopt, IsaacGripperFrame::acronym});
  EXPECT_LT((raw.poses[0].block<3, 1>(0, 1) - Vec3(-1, 0, 0)).norm(), 1e-12);
  // Read by its gripper_frame field, it is the identity again.
  EXPECT_LT(max_difference(read_grasps(dir.path() / "hand.yaml").poses, identity.poses), 1e-15);
}

TEST(GraspFiles, IsaacSimsDocumentedGraspReads) {
  const GraspSet grasps = read_grasps(fixture("isaac_example.yaml"));
  ASSERT_EQ(grasps.size(), 1u);
  EXPECT_NEAR(grasps.widths[0], 2 * 0.00943, 1e-15);
  // Isaac places the hand at position with the normalised quaternion's rotation.
  const Eigen::Quaterniond q = Eigen::Quaterniond(0.00332, 0.98453, 0.16837, 0.04837).normalized();
  const Mat4 hand =
      grasps.poses[0] * Eigen::Affine3d(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ())).matrix();
  EXPECT_LT((hand.topLeftCorner<3, 3>() - q.toRotationMatrix()).norm(), 1e-12);
  EXPECT_LT((hand.topRightCorner<3, 1>() - Vec3(-0.04346, 0.06759, 0.19895)).norm(), 1e-15);
}

TEST(GraspFiles, ContactGraspNetContactsAreOnTheMinusXPadCentre) {
  const ScratchDir dir;
  const GraspSet grasps = random_grasps(4);
  write_grasps(grasps, dir / "c.npz");
  // Contact-GraspNet's construction: t = contact + (w/2)·x − 0.1034·z, so T⁻¹·contact is
  // (−w/2, 0, 0.1034).
  for (const ZipEntry& entry :
       read_zip_archive(graspecmf::testing::read_file(dir / "c.npz"), "c")) {
    if (entry.name != "contact_pts.npy") continue;
    const NpyArray contacts = parse_npy(entry.contents, entry.name);
    ASSERT_EQ(contacts.shape, (std::vector<std::size_t>{4, 3}));
    for (std::size_t i = 0; i < 4; ++i) {
      const lie::Pose pose = lie::Pose::from_matrix(grasps.poses[i]);
      const Vec3 local = lie::apply(
          lie::inverse(pose),
          Vec3(contacts.values[3 * i], contacts.values[3 * i + 1], contacts.values[3 * i + 2]));
      EXPECT_LT((local - Vec3(-grasps.widths[i] / 2, 0, 0.1034)).norm(), 1e-12);
    }
  }
  const GraspSet back = read_grasps(dir / "c.npz");
  EXPECT_EQ(back.widths, grasps.widths);
  const GraspSet compressed = read_grasps(fixture("contact_graspnet_compressed.npz"));
  ASSERT_EQ(compressed.size(), 3u);
  EXPECT_NEAR(compressed.scores[2], 0.7, 1e-7);
  EXPECT_EQ(compressed.poses[1](0, 3), 0.2f);
  expect_error([] { read_grasps(fixture("contact_graspnet_pickled.npz")); }, "pickled");
}

TEST(GraspFiles, BadInputGetsOneClearError) {
  const ScratchDir dir;
  GraspSet bent = random_grasps(2);
  bent.poses[1](0, 0) += 1e-3;
  expect_error([&] { write_grasps(bent, dir.path() / "x.json"); },
               "grasp 1 is not a rigid transform");
  GraspSet nan = random_grasps(2);
  nan.scores[0] = std::nan("");
  expect_error([&] { write_grasps(nan, dir.path() / "x.npy"); }, "grasp 0's scores is not finite");
  expect_error([&] { write_grasps(random_grasps(1), dir.path() / "x.h5"); }, "--object");
  expect_error([&] { write_grasps(random_grasps(1), dir.path() / "x.txt"); }, "extension");
  EXPECT_FALSE(fs::exists(dir.path() / "x.json"));
  graspecmf::testing::write_file(dir.path() / "bad.yaml",
                                 "format: isaac_grasp\ngrasps:\n  g: {position: [0, 0]}\n");
  expect_error([&] { read_grasps(dir.path() / "bad.yaml"); }, "g has no orientation");
  graspecmf::testing::write_file(dir.path() / "other.yaml", "format: something\n");
  expect_error([&] { read_grasps(dir.path() / "other.yaml"); }, "not an isaac_grasp file");
  graspecmf::testing::write_file(dir.path() / "bad.json",
                                 "{\"grasps\": {\"transforms\": [[[1,0,0,0]]]}}");
  expect_error([&] { read_grasps(dir.path() / "bad.json"); }, "transform 0 is not 4×4");
  expect_error([&] { read_grasps(sample_grasp_file(), {GraspFormat::graspnet}); },
               "not a .npy array");
  expect_error([] { parse_format("csv"); }, "known: acronym, acronym-json");
}

}  // namespace
}  // namespace graspecmf::formats
