#include "graspecmf/data/dataset.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <set>

#include "graspecmf/core/error.hpp"
#include "graspecmf/data/splits.hpp"
#include "test_support.hpp"

namespace graspecmf::data {
namespace {
namespace fs = std::filesystem;
using graspecmf::testing::sample_grasp_file;
using graspecmf::testing::sample_mesh_file;
using graspecmf::testing::ScratchDir;

// A dataset folder with the sample mug, a copy with only 50 successes, a copy whose mesh is
// missing and a file that is not HDF5.
class DatasetTest : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::create_directories(dir_ / "grasps");
    fs::create_directories(dir_ / "meshes" / "Mug");
    fs::copy_file(sample_mesh_file(), dir_ / "meshes" / "Mug" / sample_mesh_file().filename());
    fs::copy_file(sample_grasp_file(), dir_ / "grasps" / "a_mug.h5");

    AcronymGraspFile few = read_acronym_file(sample_grasp_file());
    std::size_t kept = 0;
    for (auto& label : few.qualities->object_in_gripper) {
      if (label != 0 && ++kept > 50) label = 0;
    }
    write_acronym_file(few, dir_ / "grasps" / "b_few.h5");

    AcronymGraspFile orphan = read_acronym_file(sample_grasp_file());
    orphan.object.file = "meshes/Mug/missing.obj";
    write_acronym_file(orphan, dir_ / "grasps" / "c_orphan.h5");

    std::ofstream(dir_ / "grasps" / "d_broken.h5") << "garbage";
    std::ofstream(dir_ / "grasps" / "notes.txt") << "ignored: not .h5";
  }
  ScratchDir dir_;
};

TEST_F(DatasetTest, KeepsUsableObjectsAndSaysWhyOthersAreSkipped) {
  const AcronymDataset dataset = AcronymDataset::open(dir_.path());
  ASSERT_EQ(dataset.objects().size(), 1u);
  const ObjectEntry& mug = dataset.objects()[0];
  EXPECT_EQ(mug.name, "a_mug");
  EXPECT_EQ(mug.num_grasps, 2000u);
  EXPECT_EQ(mug.num_successful, 1290u);
  EXPECT_EQ(mug.scale, 0.0002682458);

  ASSERT_EQ(dataset.skipped().size(), 3u);
  EXPECT_EQ(dataset.skipped()[0].name, "b_few");
  EXPECT_NE(dataset.skipped()[0].reason.find("50 successful"), std::string::npos);
  EXPECT_EQ(dataset.skipped()[1].name, "c_orphan");
  EXPECT_NE(dataset.skipped()[1].reason.find("mesh not found"), std::string::npos);
  EXPECT_EQ(dataset.skipped()[2].name, "d_broken");
  EXPECT_NE(dataset.skipped()[2].reason.find("not an HDF5 file"), std::string::npos);
}

TEST_F(DatasetTest, ThresholdIsConfigurable) {
  DatasetOptions options;
  options.min_successful = 50;
  EXPECT_EQ(AcronymDataset::open(dir_.path(), options).names(),
            (std::vector<std::string>{"a_mug", "b_few"}));
}

TEST_F(DatasetTest, LoadsMetricMeshAndSuccessfulGrasps) {
  const AcronymDataset dataset = AcronymDataset::open(dir_.path());
  const GraspObject mug = AcronymDataset::load(dataset.select({"a_mug"}))[0];
  EXPECT_EQ(mug.grasps.size(), 1290u);
  EXPECT_EQ(mug.mesh.vertices.size(), 1167u);
  const geometry::BoundingBox box = geometry::bounding_box(mug.mesh);
  EXPECT_NEAR(box.min.z(), 0.0514, 1e-4);
  EXPECT_NEAR(box.max.z(), 0.1525, 1e-4);
  EXPECT_NEAR(box.min.y(), -0.0630, 1e-4);
}

TEST_F(DatasetTest, SelectRejectsUnknownOrSkippedNames) {
  const AcronymDataset dataset = AcronymDataset::open(dir_.path());
  EXPECT_THROW(dataset.select({"b_few"}), Error);
  EXPECT_THROW(dataset.select({"nope"}), Error);
}

TEST(Dataset, MissingFolderIsAClearError) {
  try {
    AcronymDataset::open("/nonexistent/dataset");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("no grasps/ folder"), std::string::npos) << e.what();
  }
}

TEST(Dataset, DefaultMeshRootIsAboveTheGraspsFolder) {
  EXPECT_EQ(default_mesh_root("/data/acronym/grasps/x.h5"), fs::path("/data/acronym"));
}

std::vector<std::string> numbered_names(int n) {
  std::vector<std::string> names;
  for (int i = 0; i < n; ++i) names.push_back("object_" + std::to_string(i));
  return names;
}

TEST(Splits, RandomSplitIsDeterministicDisjointAndComplete) {
  const SplitFractions fractions{10.0 / 130.0, 20.0 / 130.0};
  const DatasetSplit a = random_split(numbered_names(130), fractions, 5);
  std::vector<std::string> shuffled = numbered_names(130);
  std::reverse(shuffled.begin(), shuffled.end());
  const DatasetSplit b = random_split(shuffled, fractions, 5);  // input order does not matter
  const DatasetSplit c = random_split(numbered_names(130), fractions, 6);
  EXPECT_EQ(a.train.size(), 100u);
  EXPECT_EQ(a.val.size(), 10u);
  EXPECT_EQ(a.test.size(), 20u);
  EXPECT_EQ(a.train, b.train);
  EXPECT_EQ(a.test, b.test);
  EXPECT_NE(a.test, c.test);
  std::set<std::string> all(a.train.begin(), a.train.end());
  all.insert(a.val.begin(), a.val.end());
  all.insert(a.test.begin(), a.test.end());
  EXPECT_EQ(all.size(), 130u);
}

TEST(Splits, FileRoundTripAndErrors) {
  ScratchDir dir;
  const DatasetSplit split = random_split(numbered_names(20), {}, 1);
  write_split_file(split, dir / "split.json");
  const DatasetSplit read = read_split_file(dir / "split.json");
  EXPECT_EQ(read.train, split.train);
  EXPECT_EQ(read.val, split.val);
  EXPECT_EQ(read.test, split.test);

  std::ofstream(dir / "dup.json") << R"({"train": ["a", "b"], "val": ["a"], "test": []})";
  EXPECT_THROW(read_split_file(dir / "dup.json"), Error);
  std::ofstream(dir / "partial.json") << R"({"train": ["a"]})";
  EXPECT_THROW(read_split_file(dir / "partial.json"), Error);
  std::ofstream(dir / "broken.json") << "{ not json";
  EXPECT_THROW(read_split_file(dir / "broken.json"), Error);
  EXPECT_THROW(read_split_file(dir / "missing.json"), Error);
  EXPECT_THROW(random_split(numbered_names(5), {0.7, 0.7}, 1), Error);
}

}  // namespace
}  // namespace graspecmf::data
