// The commands on a full disk (every write past a size cap fails): one error line naming the
// target, a non-zero exit, no crash, no temporary file left, nothing already written lost.

#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "cli_support.hpp"
#include "test_support.hpp"

namespace {
namespace fs = std::filesystem;
using graspecmf::testing::CliRun;
using graspecmf::testing::expect_error_after_progress;
using graspecmf::testing::expect_one_error_line;
using graspecmf::testing::read_file;
using graspecmf::testing::run;
using graspecmf::testing::run_on_full_disk;
using graspecmf::testing::sample_grasp_file;
using graspecmf::testing::ScratchDir;
using graspecmf::testing::temporary_files;
using graspecmf::testing::write_file;

// A cap above the commands' own stdout and stderr, below every output file written here.
constexpr long kCap = 1500;

TEST(CliFullDisk, SimulateKeepsTheOldOutput) {
  ScratchDir dir;
  const std::string common = "simulate " + sample_grasp_file().string() +
                             " --every 500 --threads 1 --cache " + (dir / "cache").string();
  ASSERT_EQ(run(common, dir).exit_code, 0);  // fills the decomposition cache
  fs::create_directories(dir / "out");
  write_file(dir / "out/r.h5", "old");
  for (const char* name : {"r.h5", "r.json"}) {
    const fs::path target = dir / "out" / name;
    const CliRun r = run_on_full_disk(common + " --out " + target.string(), dir, kCap);
    expect_error_after_progress(r, "cannot write " + target.string());
    EXPECT_TRUE(temporary_files(dir / "out").empty());
  }
  EXPECT_EQ(read_file(dir / "out/r.h5"), "old");
  EXPECT_FALSE(fs::exists(dir / "out/r.json"));
}

TEST(CliFullDisk, ViewWritesNeitherPageNorPicture) {
  ScratchDir dir;
  const std::string view = "view " + sample_grasp_file().string() + " --max 20";
  for (const auto& [option, name] : {std::pair{" --out ", "v.html"}, {" --png ", "v.png"}}) {
    const fs::path target = dir / name;
    expect_one_error_line(run_on_full_disk(view + option + target.string(), dir, kCap),
                          "cannot write " + target.string());
    EXPECT_FALSE(fs::exists(target));
  }
  EXPECT_TRUE(temporary_files(dir.path()).empty());
}

TEST(CliFullDisk, MakeDatasetStopsCleanlyAndResumes) {
  ScratchDir dir;
  const std::string args = "make-dataset --mugs 2 --seed 5 --grasps 4 --threads 1 --out " +
                           (dir / "ds").string() + " --cache " + (dir / "cache").string();
  const CliRun full = run_on_full_disk(args, dir, kCap);
  expect_error_after_progress(full, "cannot write " + (dir / "ds").string());
  EXPECT_TRUE(temporary_files(dir / "ds").empty());
  // A temporary file left by a killed run is removed when the run resumes.
  write_file(dir / "ds/grasps/.Mug_mug-5-0000_1.h5.tmp-1-0", "partial");
  const CliRun resumed = run(args, dir);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.out.find("2 objects: 2 made"), std::string::npos) << resumed.out;
  EXPECT_TRUE(temporary_files(dir / "ds").empty());
}

}  // namespace
