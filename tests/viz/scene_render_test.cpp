// render_scene and scene_sheet: segments drawn z-buffered over the mesh, checked on a cube and on
// the sample mug with some of its grasps as gripper markers.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "graspecmf/core/error.hpp"
#include "graspecmf/data/acronym_file.hpp"
#include "graspecmf/geometry/mesh_io.hpp"
#include "graspecmf/geometry/ray_cast.hpp"
#include "graspecmf/gripper/panda.hpp"
#include "graspecmf/viz/scene_sheet.hpp"
#include "test_support.hpp"

namespace graspecmf::viz {
namespace {

using Rgb = std::array<int, 3>;
constexpr Rgb kRed{200, 50, 50}, kGreen{40, 160, 60}, kBlue{40, 90, 200};

geometry::TriangleMesh unit_cube() {
  geometry::TriangleMesh mesh;
  for (int i = 0; i < 8; ++i) mesh.vertices.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  mesh.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                    {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return mesh;
}

Rgb pixel(const Image& image, int x, int y) {
  const std::size_t i = 3 * (static_cast<std::size_t>(y) * image.width + x);
  return {image.rgb[i], image.rgb[i + 1], image.rgb[i + 2]};
}

// The pixel a projected point falls in.
Rgb pixel_at(const Image& image, const Vec3& projected) {
  return pixel(image, static_cast<int>(std::floor(projected.x())),
               static_cast<int>(std::floor(projected.y())));
}

// True if a pixel within one of the point's pixel has a colour accepted by `is`.
template <typename Pred>
bool near(const Image& image, const Vec3& projected, Pred is) {
  const int cx = static_cast<int>(std::floor(projected.x()));
  const int cy = static_cast<int>(std::floor(projected.y()));
  for (int y = std::max(0, cy - 1); y <= std::min(image.height - 1, cy + 1); ++y) {
    for (int x = std::max(0, cx - 1); x <= std::min(image.width - 1, cx + 1); ++x) {
      if (is(pixel(image, x, y))) return true;
    }
  }
  return false;
}

bool is_marker(const Rgb& c) {
  return c == kRed || c == kGreen || c == kBlue;
}
// The default surface colour (0.55, 0.65, 0.8) shaded: blue > green > red, not white.
bool is_surface(const Rgb& c) {
  return c[2] > c[1] && c[1] > c[0] && c[2] < 255;
}

ViewOptions top_view(int size) {
  ViewOptions options;
  options.size = size;
  options.direction = Vec3(0, 0, -1);  // looking down: +x right, +y up in the image
  options.up = Vec3(0, 1, 0);
  return options;
}

TEST(RenderScene, SegmentsShowWhereNothingIsNearerAndOnTheSurface) {
  const std::vector<Segment> segments = {
      {{0.1, 0.5, 2}, {0.9, 0.5, 2}, kRed},      // above the cube: drawn over it
      {{0.5, 0.1, -1}, {0.5, 0.9, -1}, kGreen},  // below the cube: hidden
      {{0.2, 0.2, 1}, {0.8, 0.2, 1}, kBlue}};    // on the top face: drawn
  const Image image = render_scene(unit_cube(), segments, top_view(100));
  const Projection project({Vec3(0, 0, 0), Vec3(1, 1, 1)}, 100, Vec3(0, 0, -1), Vec3(0, 1, 0));
  EXPECT_EQ(pixel_at(image, project(Vec3(0.3, 0.5, 2))), kRed);
  EXPECT_EQ(pixel_at(image, project(Vec3(0.5, 0.5, 2))), kRed);  // where red crosses green
  EXPECT_TRUE(is_surface(pixel_at(image, project(Vec3(0.5, 0.3, -1)))));
  EXPECT_EQ(pixel_at(image, project(Vec3(0.5, 0.2, 1))), kBlue);
  // Without segments the image is render_mesh's.
  EXPECT_EQ(render_scene(unit_cube(), {}, top_view(100)).rgb,
            render_mesh(unit_cube(), top_view(100)).rgb);
}

TEST(RenderScene, TheViewFitsTheSegmentsToo) {
  const std::vector<Segment> segments = {{{-2, 0.5, 0.5}, {0, 0.5, 0.5}, kRed}};
  const Image image = render_scene(unit_cube(), segments, top_view(120));
  const Projection project({Vec3(-2, 0.5, 0.5), Vec3(0, 0, 0), Vec3(1, 1, 1)}, 120, Vec3(0, 0, -1),
                           Vec3(0, 1, 0));
  EXPECT_NEAR(project(Vec3(-2, 0.5, 0.5)).x(), 6.0, 1e-9);  // the 5 % margin
  EXPECT_NEAR(project(Vec3(1, 0.5, 0.5)).x(), 114.0, 1e-9);
  EXPECT_EQ(pixel_at(image, project(Vec3(-1.9, 0.5, 0.5))), kRed);
  EXPECT_TRUE(is_surface(pixel_at(image, project(Vec3(0.5, 0.8, 1)))));
  const Rgb white{255, 255, 255};
  EXPECT_EQ(pixel_at(image, project(Vec3(-1, 0.9, 0.5))), white);
}

// The sample mug in metres and, as gripper markers, its first `per_label` successful and first
// `per_label` failed grasps (green and red).
struct MugScene {
  geometry::TriangleMesh mesh;
  std::vector<Segment> segments;
  std::vector<Vec3> marker_points;  // the markers' control points
};

MugScene sample_mug_scene(std::size_t per_label) {
  const data::AcronymGraspFile record =
      data::read_acronym_file(graspecmf::testing::sample_grasp_file());
  MugScene scene;
  scene.mesh = geometry::scaled(geometry::read_mesh(graspecmf::testing::sample_mesh_file()),
                                record.object.scale);
  std::size_t successes = 0, failures = 0;
  for (std::size_t i = 0; i < record.size(); ++i) {
    const bool success = record.qualities->object_in_gripper[i] != 0;
    std::size_t& count = success ? successes : failures;
    if (count == per_label) continue;
    ++count;
    const lie::Pose pose = lie::Pose::from_matrix(record.transforms[i]);
    for (const auto& [p, q] : gripper::marker_segments()) {
      scene.segments.push_back({lie::apply(pose, p), lie::apply(pose, q), success ? kGreen : kRed});
    }
    for (const Vec3& x : gripper::control_points())
      scene.marker_points.push_back(lie::apply(pose, x));
  }
  return scene;
}

TEST(RenderScene, TheSampleMugAndItsGraspMarkersShowWhereTheyProject) {
  const MugScene scene = sample_mug_scene(4);
  ASSERT_EQ(scene.segments.size(), 8u * gripper::marker_segments().size());
  const geometry::MeshRayCaster caster(scene.mesh);
  std::vector<Vec3> fit = scene.mesh.vertices;
  for (const Segment& s : scene.segments) {
    fit.push_back(s.a);
    fit.push_back(s.b);
  }
  for (const Vec3& direction : sheet_directions()) {
    SCOPED_TRACE(::testing::Message() << "view direction " << direction.transpose());
    ViewOptions options;
    options.size = 320;
    options.direction = direction;
    const Image image = render_scene(scene.mesh, scene.segments, options);
    const Projection project(fit, options.size, options.direction, options.up);
    // True if nothing of the mesh lies between x and the camera.
    auto visible = [&](const Vec3& x) { return !caster.first_hit(x, -project.forward(), 1e-6); };
    int markers_checked = 0, markers_seen = 0;
    for (const Vec3& x : scene.marker_points) {
      if (!visible(x)) continue;
      ++markers_checked;
      markers_seen += near(image, project(x), is_marker);
    }
    EXPECT_GE(markers_checked, 20);
    EXPECT_EQ(markers_seen, markers_checked);
    int surface_checked = 0, surface_seen = 0;
    for (std::size_t v = 0; v < scene.mesh.vertices.size(); v += 7) {
      const Vec3& x = scene.mesh.vertices[v];
      if (!visible(x)) continue;
      ++surface_checked;
      surface_seen +=
          near(image, project(x), [](const Rgb& c) { return is_surface(c) || is_marker(c); });
    }
    EXPECT_GE(surface_checked, 50);
    EXPECT_GE(surface_seen, surface_checked * 95 / 100);
    int green = 0, red = 0, surface = 0;
    for (int y = 0; y < image.height; ++y) {
      for (int x = 0; x < image.width; ++x) {
        const Rgb c = pixel(image, x, y);
        green += c == kGreen;
        red += c == kRed;
        surface += is_surface(c);
      }
    }
    EXPECT_GT(green, 100);
    EXPECT_GT(red, 100);
    EXPECT_GT(surface, 320 * 320 / 20);
  }
}

TEST(SceneSheet, TilesTheViewsFromEachSheetDirection) {
  const MugScene scene = sample_mug_scene(2);
  const Image sheet = scene_sheet(scene.mesh, scene.segments, 64);
  ASSERT_EQ(sheet.width, kSheetColumns * (64 + 4) + 4);
  ASSERT_EQ(sheet.height, 2 * (64 + 4) + 4);
  for (std::size_t i = 0; i < sheet_directions().size(); ++i) {
    ViewOptions options;
    options.size = 64;
    options.direction = sheet_directions()[i];
    const Image view = render_scene(scene.mesh, scene.segments, options);
    const int ox = 4 + static_cast<int>(i) % kSheetColumns * 68,
              oy = 4 + static_cast<int>(i) / kSheetColumns * 68;
    for (int y = 0; y < 64; ++y) {
      for (int x = 0; x < 64; ++x) ASSERT_EQ(pixel(sheet, ox + x, oy + y), pixel(view, x, y)) << i;
    }
  }
}

TEST(RenderScene, BadInputIsAnError) {
  const double nan = std::nan("");
  EXPECT_THROW(render_scene(unit_cube(), {{{0, 0, 0}, {nan, 0, 0}, kRed}}), Error);
  ViewOptions no_width;
  no_width.line_width = 0;
  EXPECT_THROW(render_scene(unit_cube(), {}, no_width), Error);
  EXPECT_THROW(render_scene(geometry::TriangleMesh{}, {{{0, 0, 0}, {1, 0, 0}, kRed}}), Error);
  EXPECT_THROW(Projection({}, 64, Vec3(0, 0, -1), Vec3(0, 1, 0)), Error);
}

}  // namespace
}  // namespace graspecmf::viz
