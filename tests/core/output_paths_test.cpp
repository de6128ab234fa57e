#include "graspecmf/core/output_paths.hpp"

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace {
namespace fs = std::filesystem;
using graspecmf::inside_folder;
using graspecmf::require_distinct_output;
using graspecmf::same_path;
using graspecmf::testing::expect_error;
using graspecmf::testing::ScratchDir;
using graspecmf::testing::write_file;

TEST(OutputPaths, SamePathSeesThroughSpellingsAndLinks) {
  ScratchDir dir;
  fs::create_directories(dir / "a/b");
  write_file(dir / "a/b/f.h5", "x");
  fs::create_symlink(dir / "a/b/f.h5", dir / "link.h5");
  EXPECT_TRUE(same_path(dir / "a/b/f.h5", dir / "a/b/../b/./f.h5"));
  EXPECT_TRUE(same_path(dir / "link.h5", dir / "a/b/f.h5"));
  EXPECT_TRUE(same_path(dir / "a/new.h5", dir / "a/b/../new.h5"));  // not there yet
  EXPECT_FALSE(same_path(dir / "a/b/f.h5", dir / "a/b/g.h5"));
  EXPECT_FALSE(same_path(dir / "a/b/f.h5", ""));
}

TEST(OutputPaths, InsideFolder) {
  ScratchDir dir;
  fs::create_directories(dir / "run");
  EXPECT_TRUE(inside_folder(dir / "run/config.json", dir / "run"));
  EXPECT_TRUE(inside_folder(dir / "run/", dir / "run"));
  EXPECT_TRUE(inside_folder(dir / "run/x/../y", dir / "run/"));
  EXPECT_FALSE(inside_folder(dir / "runs/config.json", dir / "run"));
  EXPECT_FALSE(inside_folder(dir.path(), dir / "run"));
}

TEST(OutputPaths, RefusesAnOutputThatIsAnInput) {
  ScratchDir dir;
  write_file(dir / "in.h5", "x");
  expect_error(
      [&] {
        require_distinct_output("--out", dir / "in.h5", {dir / "other", dir / "in.h5"});
      },
      "--out " + (dir / "in.h5").string() + " is also the input");
  expect_error([&] { require_distinct_output("--out", dir / "data/x.json", {}, {dir / "data"}); },
               "is also the input " + (dir / "data").string());
  require_distinct_output("--out", dir / "out.h5", {dir / "in.h5", ""}, {dir / "data"});
}

}  // namespace
