#include "graspecmf/viz/render.hpp"

#include <gtest/gtest.h>
#include <stb/stb_image.h>

#include <filesystem>

#include "graspecmf/core/error.hpp"
#include "test_support.hpp"

namespace graspecmf::viz {
namespace {

geometry::TriangleMesh unit_cube() {
  geometry::TriangleMesh mesh;
  for (int i = 0; i < 8; ++i) mesh.vertices.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  mesh.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                    {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return mesh;
}

bool white(const Image& image, int x, int y) {
  const std::size_t i = 3 * (static_cast<std::size_t>(y) * image.width + x);
  return image.rgb[i] == 255 && image.rgb[i + 1] == 255 && image.rgb[i + 2] == 255;
}

TEST(Render, ASquareFacingTheCameraFillsTheFrameInsideTheMargin) {
  ViewOptions options;
  options.size = 100;
  options.direction = Vec3(0, 0, -1);  // looking down at the top face
  options.up = Vec3(0, 1, 0);
  const Image image = render_mesh(unit_cube(), options);
  ASSERT_EQ(image.rgb.size(), 100u * 100u * 3u);
  EXPECT_FALSE(white(image, 50, 50));
  EXPECT_FALSE(white(image, 6, 6));  // the square spans pixels 5..94
  EXPECT_TRUE(white(image, 3, 50));
  EXPECT_TRUE(white(image, 96, 50));
  // Flat face, one normal: one shade everywhere.
  EXPECT_EQ(image.rgb[3 * (50 * 100 + 50)], image.rgb[3 * (10 * 100 + 80)]);
}

TEST(Render, NearerSurfacesHideFartherOnesInAnyTriangleOrder) {
  // A flat square at z = 1 above a tilted one (a different shade) below it, seen from above.
  geometry::TriangleMesh both;
  both.vertices = {{0, 0, 1},    {1, 0, 1}, {1, 1, 1}, {0, 1, 1},
                   {0, 0, -0.5}, {1, 0, 0}, {1, 1, 0}, {0, 1, -0.5}};
  const std::vector<geometry::Triangle> flat = {{0, 1, 2}, {0, 2, 3}};
  const std::vector<geometry::Triangle> tilted = {{4, 5, 6}, {4, 6, 7}};
  ViewOptions options;
  options.size = 64;
  options.direction = Vec3(0, 0, -1);
  options.up = Vec3(0, 1, 0);
  geometry::TriangleMesh only_flat = both;
  only_flat.triangles = flat;
  const std::uint8_t expected = render_mesh(only_flat, options).rgb[3 * (32 * 64 + 32)];
  for (bool flat_first : {true, false}) {
    both.triangles = flat_first ? flat : tilted;
    const auto& rest = flat_first ? tilted : flat;
    both.triangles.insert(both.triangles.end(), rest.begin(), rest.end());
    EXPECT_EQ(render_mesh(both, options).rgb[3 * (32 * 64 + 32)], expected);
  }
  geometry::TriangleMesh only_tilted = both;
  only_tilted.triangles = tilted;
  EXPECT_NE(render_mesh(only_tilted, options).rgb[3 * (32 * 64 + 32)], expected);
}

TEST(Render, ContactSheetTilesImagesAndPngRoundTrips) {
  ViewOptions options;
  options.size = 32;
  const Image cube = render_mesh(unit_cube(), options);
  const Image sheet = contact_sheet({cube, cube, cube}, 2);
  EXPECT_EQ(sheet.width, 2 * (32 + 4) + 4);
  EXPECT_EQ(sheet.height, 2 * (32 + 4) + 4);
  const graspecmf::testing::ScratchDir dir;
  const auto path = dir / "sheet.png";
  write_png(sheet, path);
  int w = 0, h = 0, channels = 0;
  unsigned char* pixels = stbi_load(path.c_str(), &w, &h, &channels, 3);
  ASSERT_NE(pixels, nullptr);
  EXPECT_EQ(w, sheet.width);
  EXPECT_EQ(h, sheet.height);
  EXPECT_TRUE(std::equal(sheet.rgb.begin(), sheet.rgb.end(), pixels));
  stbi_image_free(pixels);
}

TEST(Render, BadInputIsAnError) {
  EXPECT_THROW(render_mesh(geometry::TriangleMesh{}), Error);
  ViewOptions tiny;
  tiny.size = 2;
  EXPECT_THROW(render_mesh(unit_cube(), tiny), Error);
  ViewOptions parallel;
  parallel.direction = Vec3(0, 0, 1);
  EXPECT_THROW(render_mesh(unit_cube(), parallel), Error);
  EXPECT_THROW(contact_sheet({}, 3), Error);
  const Image cube = render_mesh(unit_cube());
  EXPECT_THROW(write_png(cube, "/nonexistent-dir/x.png"), Error);
}

}  // namespace
}  // namespace graspecmf::viz
