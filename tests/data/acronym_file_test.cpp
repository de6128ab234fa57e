#include "graspecmf/data/acronym_file.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "graspecmf/core/error.hpp"
#include "graspecmf/data/hdf5_file.hpp"
#include "graspecmf/lie/so3.hpp"
#include "test_support.hpp"

namespace graspecmf::data {
namespace {
namespace fs = std::filesystem;
using graspecmf::testing::expect_error;
using graspecmf::testing::sample_grasp_file;
using graspecmf::testing::ScratchDir;

TEST(AcronymFile, SampleMugFacts) {
  const AcronymGraspFile record = read_acronym_file(sample_grasp_file());
  ASSERT_EQ(record.size(), 2000u);
  EXPECT_EQ(record.num_successful(), 1290u);
  EXPECT_EQ(record.successful_grasps().size(), 1290u);
  EXPECT_EQ(record.gripper_type, "panda");
  EXPECT_EQ(record.gripper_configuration.value(), 0.04);
  EXPECT_EQ(record.object.file, "meshes/Mug/10f6e09036350e92b3f21f1137c3c347.obj");
  EXPECT_EQ(record.object.scale, 0.0002682458);
  EXPECT_EQ(record.object.density.value(), 150.0);
  EXPECT_EQ(record.object.friction.value(), 1.0);
  EXPECT_EQ(record.object.mass.value(), 0.0130879738);
  EXPECT_EQ(record.object.volume.value(), 8.72532e-05);
  EXPECT_EQ(record.object.com.value(), Vec3(6.8594e-06, -0.00212206, 0.0938568045));
  EXPECT_EQ(record.object.inertia.value()(0, 0), 2.24212e-05);
  EXPECT_EQ(record.object.inertia.value()(0, 1), 9.08e-08);
}

TEST(AcronymFile, TransformsAreRigidWith330HalfTurns) {
  const AcronymGraspFile record = read_acronym_file(sample_grasp_file());
  int half_turns = 0;
  for (const Mat4& T : record.transforms) {
    EXPECT_LT(lie::rigidity_error(T), 2e-10);
    const Mat3 R = T.topLeftCorner<3, 3>();
    half_turns += R.isApprox(R.transpose(), 1e-12) && lie::so3_angle(R) > 3.0;
  }
  // The ACRONYM sample's notes said 334; h5py and this code both count 330 exact half turns
  // (symmetric R, trace = −1 to 1e-12).
  EXPECT_EQ(half_turns, 330);
}

TEST(AcronymFile, QualitiesAreReadInGraspOrder) {
  // The labels agree with a 0.012 threshold on the shaking motion for 99.65 % of the grasps (1993,
  // counted with h5py); reading the arrays in another order or from the wrong dataset breaks this.
  const GraspQualities q = read_acronym_file(sample_grasp_file()).qualities.value();
  ASSERT_EQ(q.motion_shaking_linear.size(), 2000u);
  ASSERT_EQ(q.motion_closing_angular.size(), 2000u);
  int agree = 0;
  for (std::size_t i = 0; i < 2000; ++i) {
    agree += (q.object_in_gripper[i] != 0) == (q.motion_shaking_linear[i] < 0.012);
  }
  EXPECT_EQ(agree, 1993);
}

TEST(AcronymFile, RoundTripIsExactWithTheSameLayout) {
  ScratchDir dir;
  const AcronymGraspFile original = read_acronym_file(sample_grasp_file());
  write_acronym_file(original, dir / "copy.h5");
  const AcronymGraspFile copy = read_acronym_file(dir / "copy.h5");

  ASSERT_EQ(copy.transforms.size(), original.transforms.size());
  for (std::size_t i = 0; i < original.size(); ++i) {
    ASSERT_EQ(copy.transforms[i], original.transforms[i]) << "grasp " << i;
  }
  const GraspQualities &a = original.qualities.value(), &b = copy.qualities.value();
  EXPECT_EQ(a.object_in_gripper, b.object_in_gripper);
  EXPECT_EQ(a.motion_closing_linear, b.motion_closing_linear);
  EXPECT_EQ(a.motion_closing_angular, b.motion_closing_angular);
  EXPECT_EQ(a.motion_shaking_linear, b.motion_shaking_linear);
  EXPECT_EQ(a.motion_shaking_angular, b.motion_shaking_angular);
  EXPECT_EQ(copy.gripper_type, original.gripper_type);
  EXPECT_EQ(copy.gripper_configuration, original.gripper_configuration);
  EXPECT_EQ(copy.object.file, original.object.file);
  EXPECT_EQ(copy.object.scale, original.object.scale);
  EXPECT_EQ(copy.object.density, original.object.density);
  EXPECT_EQ(copy.object.friction, original.object.friction);
  EXPECT_EQ(copy.object.mass, original.object.mass);
  EXPECT_EQ(copy.object.volume, original.object.volume);
  EXPECT_EQ(copy.object.com, original.object.com);
  EXPECT_EQ(copy.object.inertia, original.object.inertia);

  // Same datasets, types, shapes, chunking and compression as ACRONYM's own file.
  const Hdf5Reader theirs(sample_grasp_file()), ours(dir / "copy.h5");
  ASSERT_EQ(ours.dataset_paths(), theirs.dataset_paths());
  EXPECT_EQ(ours.dataset_paths().size(), 16u);
  for (const std::string& path : theirs.dataset_paths()) {
    const DatasetLayout expected = theirs.layout(path), actual = ours.layout(path);
    EXPECT_TRUE(actual == expected) << path << ": type " << actual.type << " vs " << expected.type;
  }
}

TEST(AcronymFile, H5pyChunkRule) {
  // Expected values printed by h5py 3.7's guess_chunk (Debian python3-h5py).
  EXPECT_EQ(h5py_chunk_shape({2000}, 8), (Shape{1000}));
  EXPECT_EQ(h5py_chunk_shape({1290, 4, 4}, 8), (Shape{323, 2, 2}));
  EXPECT_EQ(h5py_chunk_shape({2000, 4, 4}, 8), (Shape{500, 2, 2}));
  EXPECT_EQ(h5py_chunk_shape({1}, 8), (Shape{1}));
  EXPECT_EQ(h5py_chunk_shape({3, 3}, 8), (Shape{3, 3}));
  EXPECT_EQ(h5py_chunk_shape({100000, 4, 4}, 8), (Shape{6250, 1, 1}));
}

TEST(AcronymFile, MissingFile) {
  expect_error([] { read_acronym_file("/nonexistent/file.h5"); }, "no such file");
}

TEST(AcronymFile, NotAnHdf5File) {
  ScratchDir dir;
  std::ofstream(dir / "text.h5") << "this is not HDF5\n";
  expect_error([&] { read_acronym_file(dir / "text.h5"); }, "not an HDF5 file");
}

TEST(AcronymFile, HdfFileWithoutTransforms) {
  ScratchDir dir;
  {
    Hdf5Writer writer(dir / "partial.h5");
    writer.write_string("object/file", "meshes/x.obj");
    writer.write_double("object/scale", 1.0);
    writer.close();
  }
  expect_error([&] { read_acronym_file(dir / "partial.h5"); }, "no /grasps/transforms");
}

TEST(AcronymFile, WrongTransformShape) {
  ScratchDir dir;
  {
    Hdf5Writer writer(dir / "bad.h5");
    writer.write_doubles("grasps/transforms", std::vector<double>(2 * 9, 0.0), {2, 3, 3});
    writer.write_string("object/file", "meshes/x.obj");
    writer.write_double("object/scale", 1.0);
    writer.close();
  }
  expect_error([&] { read_acronym_file(dir / "bad.h5"); }, "expected (N, 4, 4)");
}

// A copy of the sample with grasp 7's transform or label changed, written as h5py would.
fs::path altered_sample(const ScratchDir& dir, const Mat4& transform, std::int64_t label) {
  const AcronymGraspFile record = read_acronym_file(sample_grasp_file());
  std::vector<double> transforms;
  for (std::size_t i = 0; i < record.size(); ++i) {
    Mat4 T = i == 7 ? transform : record.transforms[i];
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) transforms.push_back(T(r, c));
  }
  std::vector<std::int64_t> labels = record.qualities->object_in_gripper;
  labels[7] = label;
  const fs::path path = dir / "altered.h5";
  Hdf5Writer writer(path);
  writer.write_doubles("grasps/transforms", transforms, {record.size(), 4, 4});
  writer.write_int64s("grasps/qualities/flex/object_in_gripper", labels, {record.size()});
  writer.write_string("object/file", record.object.file);
  writer.write_double("object/scale", record.object.scale);
  writer.close();
  return path;
}

TEST(AcronymFile, NonRigidTransformsAndOtherLabelsAreRefused) {
  ScratchDir dir;
  const Mat4 good = read_acronym_file(sample_grasp_file()).transforms[7];
  EXPECT_EQ(read_acronym_file(altered_sample(dir, good, 1)).transforms[7], good);
  Mat4 scaled = good;
  scaled.topLeftCorner<3, 3>() *= 2.0;
  Mat4 mirrored = good;
  mirrored.col(0) *= -1.0;
  Mat4 projective = good;
  projective(3, 0) = 0.5;
  for (const Mat4& bad : {scaled, mirrored, projective}) {
    expect_error([&] { read_acronym_file(altered_sample(dir, bad, 1)); },
                 "/grasps/transforms[7] is not a rigid transform");
  }
  for (const std::int64_t label : {-3, 4}) {
    expect_error([&] { read_acronym_file(altered_sample(dir, good, label)); },
                 "object_in_gripper[7] is " + std::to_string(label) + "; labels are 0 or 1");
  }
}

TEST(AcronymFile, MassPropertiesMustBePositiveAndFinite) {
  ScratchDir dir;
  const AcronymGraspFile sample = read_acronym_file(sample_grasp_file());
  ASSERT_TRUE(sample.object.mass && sample.object.inertia);
  AcronymGraspFile record = sample;
  record.object.mass = -0.1;
  write_acronym_file(record, dir / "mass.h5");
  expect_error([&] { read_acronym_file(dir / "mass.h5"); }, "/object/mass must be a positive");
  record = sample;
  record.object.density = 0.0;
  write_acronym_file(record, dir / "density.h5");
  expect_error([&] { read_acronym_file(dir / "density.h5"); }, "/object/density");
  record = sample;
  *record.object.inertia = -*record.object.inertia;
  write_acronym_file(record, dir / "inertia.h5");
  expect_error([&] { read_acronym_file(dir / "inertia.h5"); }, "/object/inertia");
}

TEST(AcronymFile, OnlyThePandaGripperIsSupported) {
  AcronymGraspFile record = read_acronym_file(sample_grasp_file());
  require_panda_gripper(record, sample_grasp_file());  // "franka_panda"
  record.gripper_type = "robotiq_2f_85";
  expect_error([&] { require_panda_gripper(record, "r.h5"); },
               "r.h5: gripper type 'robotiq_2f_85' is not supported");
}

TEST(AcronymFile, LabelCountMustMatchGraspCount) {
  ScratchDir dir;
  AcronymGraspFile record = read_acronym_file(sample_grasp_file());
  record.transforms.resize(10);
  expect_error([&] { write_acronym_file(record, dir / "bad.h5"); }, "quality array has 2000");
  EXPECT_FALSE(fs::exists(dir / "bad.h5"));
}

TEST(AcronymFile, FailedWriteLeavesNoFileAndKeepsTheOldOne) {
  ScratchDir dir;
  AcronymGraspFile record = read_acronym_file(sample_grasp_file());
  write_acronym_file(record, dir / "out.h5");
  const auto size_before = fs::file_size(dir / "out.h5");
  record.transforms[5](0, 3) = std::nan("");
  expect_error([&] { write_acronym_file(record, dir / "out.h5"); }, "non-finite");
  EXPECT_EQ(fs::file_size(dir / "out.h5"), size_before);
  EXPECT_EQ(read_acronym_file(dir / "out.h5").transforms[5],
            read_acronym_file(sample_grasp_file()).transforms[5]);
  EXPECT_EQ(dir.num_files(), 1u);
}

TEST(AcronymFile, StandardInertiaFlipsOffDiagonals) {
  Mat3 stored;
  stored << 1, 2, 3, 2, 4, 5, 3, 5, 6;
  Mat3 expected;
  expected << 1, -2, -3, -2, 4, -5, -3, -5, 6;
  EXPECT_EQ(standard_inertia(stored), expected);
}

// Moving the record moves its grasps and centre of mass and turns its inertia (stored with
// ACRONYM's sign), so that the object's inertia about a moved axis is unchanged.
TEST(AcronymFile, MovedRigidlyMovesGraspsComAndInertia) {
  const AcronymGraspFile record = read_acronym_file(sample_grasp_file());
  lie::Pose motion;
  motion.R = lie::so3_exp(Vec3(0.2, -0.4, 1.1));
  motion.p = Vec3(2.7, 1.2, 0.0);
  const AcronymGraspFile moved = moved_rigidly(record, motion);
  ASSERT_EQ(moved.size(), record.size());
  EXPECT_EQ(moved.qualities->object_in_gripper, record.qualities->object_in_gripper);
  const Mat4 expected = motion.matrix() * record.transforms[7];
  EXPECT_LT((moved.transforms[7] - expected).norm(), 1e-12);
  EXPECT_LT((*moved.object.com - (motion.R * *record.object.com + motion.p)).norm(), 1e-12);
  const Vec3 axis = Vec3(1, 2, 3).normalized();
  const double before = axis.dot(standard_inertia(*record.object.inertia) * axis);
  const Vec3 moved_axis = motion.R * axis;
  const double after = moved_axis.dot(standard_inertia(*moved.object.inertia) * moved_axis);
  EXPECT_NEAR(after, before, 1e-12 * before);
  EXPECT_EQ(moved.object.mass, record.object.mass);
}
}  // namespace
}  // namespace graspecmf::data
