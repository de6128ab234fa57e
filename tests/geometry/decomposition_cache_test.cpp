#include "graspecmf/geometry/decomposition_cache.hpp"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "convex_part_checks.hpp"
#include "graspecmf/geometry/convex_decomposition.hpp"
#include "mug_fixture.hpp"
#include "test_meshes.hpp"

namespace graspecmf::geometry {
namespace {

using namespace graspecmf::geometry::testing;

TEST(DecompositionCache, WritesOnceThenReads) {
  ScratchDir dir;
  const fs::path cache = dir / "cache" / "nested";  // created on demand
  const DecompositionOptions options;
  const fs::path file = decomposition_cache_file(metric_mug(), options, cache);
  EXPECT_EQ(file.parent_path(), cache);
  EXPECT_FALSE(fs::exists(file));
  expect_same_parts(cached_convex_decomposition(metric_mug(), options, cache), mug_parts());
  ASSERT_TRUE(fs::exists(file));
  const std::string bytes = read_file(file);
  expect_same_parts(cached_convex_decomposition(metric_mug(), options, cache), mug_parts());
  EXPECT_EQ(read_file(file), bytes);
  EXPECT_EQ(fs::directory_iterator(cache)->path(), file);  // nothing else left there

  // A valid file under the mug's name is used as is, without recomputing: put a box's
  // decomposition there and the mug's lookup returns the box.
  const TriangleMesh box = make_unit_cube();
  const std::vector<TriangleMesh> box_parts = cached_convex_decomposition(box, options, cache);
  fs::copy_file(decomposition_cache_file(box, options, cache), file,
                fs::copy_options::overwrite_existing);
  expect_same_parts(cached_convex_decomposition(metric_mug(), options, cache), box_parts);
}

TEST(DecompositionCache, KeyCoversMeshAndOptions) {
  const fs::path dir = "/cache";
  const DecompositionOptions options;
  const fs::path file = decomposition_cache_file(metric_mug(), options, dir);
  DecompositionOptions finer = options;
  finer.resolution = 65;
  DecompositionOptions looser = options;
  looser.concavity = 0.0021;
  EXPECT_NE(decomposition_cache_file(metric_mug(), finer, dir), file);
  EXPECT_NE(decomposition_cache_file(metric_mug(), looser, dir), file);
  EXPECT_NE(decomposition_cache_file(scaled(metric_mug(), 1.0 + 1e-15), options, dir), file);
  TriangleMesh flipped = metric_mug();
  std::swap(flipped.triangles[7][1], flipped.triangles[7][2]);
  EXPECT_NE(decomposition_cache_file(flipped, options, dir), file);
  EXPECT_EQ(decomposition_cache_file(metric_mug(), options, dir), file);
}

TEST(DecompositionCache, CorruptFilesAreRecomputed) {
  ScratchDir dir;
  const TriangleMesh torus = make_torus(1.0, 0.3, 24, 12);
  const DecompositionOptions options{24, 16, 0.002, 4};
  const std::vector<TriangleMesh> parts = convex_decomposition(torus, options);
  const fs::path file = decomposition_cache_file(torus, options, dir.path());
  cached_convex_decomposition(torus, options, dir.path());
  const std::string good = read_file(file);
  std::string flipped = good;
  flipped[good.size() / 2] = static_cast<char>(flipped[good.size() / 2] ^ 0x10);
  const std::string corruptions[] = {
      "",      "GCVXDEC1", good.substr(0, good.size() - 1), good.substr(0, good.size() / 3),
      flipped, good + "x"};
  for (const std::string& bytes : corruptions) {
    write_file(file, bytes);
    expect_same_parts(cached_convex_decomposition(torus, options, dir.path()), parts);
    EXPECT_EQ(read_file(file), good) << "rewritten after a " << bytes.size() << "-byte file";
  }
}

}  // namespace
}  // namespace graspecmf::geometry
