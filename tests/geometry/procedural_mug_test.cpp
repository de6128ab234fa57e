#include "graspecmf/geometry/procedural_mug.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "graspecmf/core/error.hpp"
#include "graspecmf/geometry/mass_properties.hpp"
#include "graspecmf/geometry/mesh_topology.hpp"
#include "graspecmf/geometry/point_inside.hpp"

namespace graspecmf::geometry {
namespace {

constexpr double kPi = 3.14159265358979323846;

MugParameters seeded_mug(std::uint64_t seed, MugFamily family = MugFamily::classic) {
  Rng rng(seed);
  return random_mug_parameters(rng, family);
}

// The mesh battery, run for every family.
class EveryFamily : public ::testing::TestWithParam<MugFamily> {};

INSTANTIATE_TEST_SUITE_P(ProceduralMug, EveryFamily,
                         ::testing::Values(MugFamily::classic, MugFamily::varied),
                         [](const auto& param_info) { return to_string(param_info.param); });

TEST_P(EveryFamily, ManySeedsGiveClosedOutwardManifoldsOfTheRightGenus) {
  int with_handle = 0;
  for (std::uint64_t seed = 0; seed < 60; ++seed) {
    const MugParameters mug = seeded_mug(seed, GetParam());
    const TriangleMesh mesh = mug_mesh(mug);
    const MeshTopology topology = analyze_topology(mesh);
    ASSERT_TRUE(topology.consistently_oriented) << "seed " << seed;
    ASSERT_EQ(topology.num_components, 1u) << "seed " << seed;
    // A handle is a loop: one tunnel through the solid.
    const int genus = mug.handle == MugHandle::none ? 0 : 1;
    ASSERT_EQ(topology.genus, genus) << "seed " << seed;
    ASSERT_GT(mass_properties(mesh).volume, 0.0) << "seed " << seed;
    with_handle += genus;
  }
  // A few mugs have no handle: 6 % of the classic family, 20 % of the varied one.
  EXPECT_GE(with_handle, GetParam() == MugFamily::classic ? 50 : 38);
  EXPECT_LT(with_handle, GetParam() == MugFamily::classic ? 60 : 56);
}

TEST(ProceduralMug, ParametersSpanTheRequestedRanges) {
  for (std::uint64_t seed = 0; seed < 200; ++seed) {
    const MugParameters mug = seeded_mug(seed);
    EXPECT_NO_THROW(validate(mug));
    EXPECT_GE(mug.height, 0.07);
    EXPECT_LE(mug.height, 0.13);
    EXPECT_GE(mug.outer_radius, 0.032);
    EXPECT_LE(mug.outer_radius, 0.052);
    EXPECT_GE(mug.wall, 0.0025);
    EXPECT_LE(mug.wall, 0.006);
    EXPECT_GE(mug.base, 0.003);
    EXPECT_LE(mug.base, 0.01);
    if (mug.handle == MugHandle::none) continue;
    EXPECT_GE(mug.handle_thickness, 0.006);
    EXPECT_LE(mug.handle_thickness, 0.015);
    EXPECT_GE(mug.handle_clearance, 0.015);
    EXPECT_LE(mug.handle_clearance, 0.035);
    EXPECT_GE(mug.handle_low, 0.15);
    EXPECT_LE(mug.handle_high, 0.9);
  }
}

TEST(ProceduralMug, SameSeedSameMeshDifferentSeedDifferentMug) {
  const TriangleMesh a = mug_mesh(seeded_mug(7));
  const TriangleMesh b = mug_mesh(seeded_mug(7));
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  for (std::size_t i = 0; i < a.vertices.size(); ++i) ASSERT_EQ(a.vertices[i], b.vertices[i]);
  EXPECT_NE(seeded_mug(7).height, seeded_mug(8).height);
}

TEST(ProceduralMug, StraightMugWithoutHandleHasTheVolumeOfItsPolygonalShell) {
  MugParameters mug;
  mug.handle = MugHandle::none;
  const double r = mug.outer_radius, ri = r - mug.wall;
  // A 72-gon of circumradius r has area r² · 36 sin(2π / 72).
  const double polygon = 36.0 * std::sin(2.0 * kPi / 72.0);
  const double expected = polygon * (r * r * mug.height - ri * ri * (mug.height - mug.base));
  EXPECT_NEAR(mass_properties(mug_mesh(mug)).volume, expected, 1e-9);
}

TEST(ProceduralMug, DimensionsFollowTheParameters) {
  MugParameters mug;  // straight, flat rim, C handle towards +x
  const BoundingBox box = bounding_box(mug_mesh(mug));
  EXPECT_NEAR(box.min.z(), 0.0, 1e-12);
  EXPECT_NEAR(box.max.z(), mug.height, 1e-12);
  EXPECT_NEAR(box.min.x(), -mug.outer_radius, 1e-12);
  // The handle's outer side: wall + clearance + thickness.
  EXPECT_NEAR(box.max.x(), mug.outer_radius + mug.handle_clearance + mug.handle_thickness, 5e-4);
}

TEST(ProceduralMug, CavityAndHandleHoleAreOutsideTheSolid) {
  for (MugHandle handle : {MugHandle::c_shape, MugHandle::d_loop}) {
    MugParameters mug;
    mug.handle = handle;
    const TriangleMesh mesh = mug_mesh(mug);
    const double z_mid = 0.5 * (mug.handle_low + mug.handle_high) * mug.height;
    EXPECT_FALSE(is_inside(mesh, Vec3(0, 0, 0.5 * mug.height)));  // cavity
    EXPECT_FALSE(is_inside(mesh, Vec3(mug.outer_radius + 0.5 * mug.handle_clearance, 0, z_mid)));
    EXPECT_TRUE(is_inside(mesh, Vec3(0, 0, 0.5 * mug.base)));  // bottom
    EXPECT_TRUE(is_inside(mesh, Vec3(mug.outer_radius - 0.5 * mug.wall, 0, z_mid)));
    // The handle tube at its farthest point.
    const double tube = mug.outer_radius + mug.handle_clearance + 0.5 * mug.handle_thickness;
    EXPECT_TRUE(is_inside(mesh, Vec3(tube, 0, z_mid)));
  }
}

// Overlapping or self-intersecting sheets would give winding numbers other than 0 or 1.
TEST_P(EveryFamily, WindingNumberIsZeroOrOneEverywhere) {
  for (std::uint64_t seed = 0; seed < 6; ++seed) {
    const TriangleMesh mesh = mug_mesh(seeded_mug(seed, GetParam()));
    const BoundingBox box = bounding_box(mesh);
    Rng rng(100 + seed);
    for (int i = 0; i < 300; ++i) {
      const Vec3 q(rng.uniform(box.min.x(), box.max.x()), rng.uniform(box.min.y(), box.max.y()),
                   rng.uniform(box.min.z(), box.max.z()));
      const double w = winding_number(mesh, q);
      ASSERT_TRUE(std::abs(w) < 1e-6 || std::abs(w - 1.0) < 1e-6) << "seed " << seed << " w " << w;
    }
  }
}

TEST(ProceduralMug, VariedFamilyHasFlaresRoughSurfacesCupsAndWiderSizes) {
  int flared = 0, rough = 0, cups = 0, short_ones = 0, tall_ones = 0;
  for (std::uint64_t seed = 0; seed < 200; ++seed) {
    const MugParameters mug = seeded_mug(seed, MugFamily::varied);
    EXPECT_NO_THROW(validate(mug));
    flared += mug.flare > 0.0;
    rough += mug.roughness > 0.0;
    cups += mug.handle == MugHandle::none;
    short_ones += mug.height < 0.07;
    tall_ones += mug.height > 0.13;
    EXPECT_LE(mug.roughness, 0.25 * mug.wall);
  }
  // About 19 %, 36 % and 20 % after redraws, and 18 % of heights outside the classic range.
  EXPECT_GT(flared, 30);
  EXPECT_GT(rough, 40);
  EXPECT_GT(cups, 20);
  EXPECT_GT(short_ones, 10);
  EXPECT_GT(tall_ones, 10);
  // The classic family has none of the new features.
  for (std::uint64_t seed = 0; seed < 50; ++seed) {
    const MugParameters mug = seeded_mug(seed);
    EXPECT_EQ(mug.flare, 0.0);
    EXPECT_EQ(mug.roughness, 0.0);
  }
}

TEST(ProceduralMug, FlareWidensTheLipAndRoughnessStaysWithinItsAmplitude) {
  MugParameters mug;
  mug.handle = MugHandle::none;
  mug.flare = 0.006;
  mug.flare_height = 0.2;
  const BoundingBox flared = bounding_box(mug_mesh(mug));
  EXPECT_NEAR(flared.max.x(), mug.outer_radius + mug.flare, 1e-9);
  mug.flare = 0.0;
  mug.roughness = 0.001;
  mug.roughness_seed = 5;
  const TriangleMesh rough = mug_mesh(mug);
  const TriangleMesh smooth = [&] {
    MugParameters m = mug;
    m.roughness = 0.0;
    return mug_mesh(m);
  }();
  ASSERT_EQ(rough.vertices.size(), smooth.vertices.size());
  double largest = 0.0;
  for (std::size_t i = 0; i < rough.vertices.size(); ++i) {
    const double moved = (rough.vertices[i] - smooth.vertices[i]).norm();
    EXPECT_LE(moved, mug.roughness + 1e-12);
    EXPECT_NEAR(rough.vertices[i].z(), smooth.vertices[i].z(), 1e-15);  // radial only
    largest = std::max(largest, moved);
  }
  EXPECT_GT(largest, 0.5 * mug.roughness);
  EXPECT_TRUE(analyze_topology(rough).consistently_oriented);
}

TEST(ProceduralMug, FamilyNamesRoundTrip) {
  for (MugFamily f : {MugFamily::classic, MugFamily::varied}) {
    EXPECT_EQ(mug_family_from_string(to_string(f)), f);
  }
  EXPECT_THROW(mug_family_from_string("fancy"), Error);
}

TEST(ProceduralMug, InconsistentParametersAreRejected) {
  MugParameters thick;
  thick.wall = 0.02;
  thick.outer_radius = 0.02;
  EXPECT_THROW(validate(thick), Error);
  MugParameters high;
  high.handle_high = 0.99;
  EXPECT_THROW(mug_mesh(high), Error);
  MugParameters swapped;
  swapped.handle_low = 0.8;
  swapped.handle_high = 0.3;
  EXPECT_THROW(validate(swapped), Error);
  MugParameters nan;
  nan.height = std::nan("");
  EXPECT_THROW(validate(nan), Error);
  MugParameters into_flare;
  into_flare.flare = 0.005;
  into_flare.flare_height = 0.3;  // the handle's upper attachment at 0.8 is in the flare
  EXPECT_THROW(validate(into_flare), Error);
  MugParameters too_rough;
  too_rough.roughness = 0.5 * too_rough.wall;
  EXPECT_THROW(validate(too_rough), Error);
  MugParameters no_handle;
  no_handle.handle = MugHandle::none;
  no_handle.handle_high = 0.99;  // ignored without a handle
  EXPECT_NO_THROW(validate(no_handle));
}

}  // namespace
}  // namespace graspecmf::geometry
