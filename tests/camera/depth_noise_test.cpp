// The depth camera's noise model: deterministic for a seed, the axial spread it claims on a flat
// table, grazing surfaces lost, half the silhouette's pixels lost, and bad parameters refused.
#include "graspecmf/camera/depth_noise.hpp"

#include <gtest/gtest.h>

#include "scenes.hpp"
#include "test_support.hpp"

namespace graspecmf::camera {
namespace {

const geometry::Plane kTable{lie::Vec3::UnitZ(), 0.0};

RenderedView top_down_view(const lie::Vec3& eye) {
  const geometry::MeshRayCaster sphere(testing::uv_sphere({0.0, 0.0, 0.05}, 0.05, 48, 24));
  return render_view(sphere, realsense_d435(), look_at(eye, {0, 0, 0}, {0, 1, 0}), kTable);
}

TEST(DepthNoise, SeededAndDeterministic) {
  const RenderedView view = top_down_view({0.0, 0.0, 0.6});
  const DepthNoise noise;
  EXPECT_EQ(noisy_depth(view, realsense_d435(), noise, 4).metres,
            noisy_depth(view, realsense_d435(), noise, 4).metres);
  EXPECT_NE(noisy_depth(view, realsense_d435(), noise, 4).metres,
            noisy_depth(view, realsense_d435(), noise, 5).metres);
}

TEST(DepthNoise, AxialSpreadOnAFlatTableIsTheModels) {
  const RenderedView view = top_down_view({0.0, 0.0, 0.6});
  DepthNoise noise;
  noise.subpixel = 0.0;  // the spread alone
  noise.random_dropout = 0.0;
  const DepthImage out = noisy_depth(view, realsense_d435(), noise, 7);
  double sum = 0.0, square = 0.0;
  int count = 0;
  for (std::size_t i = 0; i < out.metres.size(); ++i) {
    if (view.object_mask[i] || out.metres[i] == 0.0f || view.incidence[i] < 0.99f) continue;
    const double error = out.metres[i] - view.depth.metres[i];
    sum += error;
    square += error * error;
    ++count;
  }
  ASSERT_GT(count, 10000);
  const double mean = sum / count, spread = std::sqrt(square / count - mean * mean);
  // σ(0.6 m, ~0°) = 1.2 mm + 1.9 mm (0.2)² ≈ 1.276 mm; the angle term adds under 0.1 %.
  EXPECT_NEAR(spread, 0.001276, 0.00004);
  EXPECT_NEAR(mean, 0.0, 0.00003);
  // With quantisation, depths fall on the disparity grid fx · baseline / (k · subpixel).
  noise.subpixel = 0.08;
  const DepthImage quantised = noisy_depth(view, realsense_d435(), noise, 7);
  for (std::size_t i = 0; i < quantised.metres.size(); i += 101) {
    if (quantised.metres[i] == 0.0f) continue;
    const double steps = 615.0 * 0.05 / quantised.metres[i] / 0.08;
    EXPECT_NEAR(steps, std::round(steps), 1e-3);
  }
}

TEST(DepthNoise, GrazingSurfacesAndSilhouettesAreLost) {
  // A camera 1 cm above the table looking across it: the table is seen at over 85°.
  const geometry::MeshRayCaster far_sphere(testing::uv_sphere({5.0, 0.0, 0.05}, 0.05, 8, 4));
  const RenderedView grazing = render_view(
      far_sphere, realsense_d435(), look_at({0, 0, 0.01}, {3.0, 0.0, 0.0}, {0, 0, 1}), kTable);
  DepthNoise noise;
  const DepthImage out = noisy_depth(grazing, realsense_d435(), noise, 1);
  std::size_t seen = 0, kept = 0;
  for (std::size_t i = 0; i < out.metres.size(); ++i) {
    if (grazing.object_mask[i] || grazing.depth.metres[i] == 0.0f || grazing.incidence[i] > 0.08f)
      continue;
    ++seen;
    kept += out.metres[i] != 0.0f;
  }
  ASSERT_GT(seen, 1000u);
  EXPECT_EQ(kept, 0u);
  // Table pixels beside the sphere's silhouette (a 5 cm jump) are lost half the time.
  const RenderedView view = top_down_view({0.0, 0.0, 0.6});
  noise.random_dropout = 0.0;
  const DepthImage silhouette = noisy_depth(view, realsense_d435(), noise, 2);
  std::size_t edges = 0, lost = 0;
  for (int v = 1; v + 1 < 480; ++v) {
    for (int u = 1; u + 1 < 640; ++u) {
      const std::size_t i = static_cast<std::size_t>(v) * 640 + u;
      const bool beside = view.object_mask[i + 1] || view.object_mask[i - 1] ||
                          view.object_mask[i + 640] || view.object_mask[i - 640];
      if (view.object_mask[i] || !beside) continue;
      ++edges;
      lost += silhouette.metres[i] == 0.0f;
    }
  }
  ASSERT_GT(edges, 300u);
  EXPECT_NEAR(static_cast<double>(lost) / static_cast<double>(edges), 0.5, 0.1);
}

TEST(DepthNoise, BadParametersAreRefused) {
  DepthNoise noise;
  noise.edge_dropout = 1.5;
  graspecmf::testing::expect_error([&] { validate(noise, "--noise"); }, "at most 1");
  noise = {};
  noise.grazing_end_degrees = 95;
  graspecmf::testing::expect_error([&] { validate(noise, "--noise"); }, "grazing");
  noise = {};
  noise.sigma_base = -1;
  graspecmf::testing::expect_error([&] { validate(noise, "--noise"); }, "at least 0");
}

}  // namespace
}  // namespace graspecmf::camera
