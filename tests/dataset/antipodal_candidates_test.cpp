#include "graspecmf/dataset/antipodal_candidates.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "../geometry/mug_fixture.hpp"
#include "graspecmf/core/error.hpp"
#include "graspecmf/geometry/procedural_mug.hpp"
#include "graspecmf/gripper/panda.hpp"

namespace graspecmf::dataset {
namespace {

using geometry::TriangleMesh;
using geometry::testing::make_box;
using geometry::testing::metric_mug;

// 6 cm × 4 cm × 10 cm, away from the origin.
TriangleMesh test_box() {
  return make_box(Vec3(0.2, -0.1, 0.3), Vec3(0.26, -0.06, 0.4));
}

// Distance from p to triangle abc (closest point by Voronoi regions, Ericson §5.1.5).
double point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return (p - a).norm();
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return (p - b).norm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + d1 / (d1 - d3) * ab)).norm();
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return (p - c).norm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + d2 / (d2 - d6) * ac)).norm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    return (p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).norm();
  }
  const double denom = 1.0 / (va + vb + vc);
  return (p - (a + ab * vb * denom + ac * vc * denom)).norm();
}

// True if p lies on the mesh (within tol) on a triangle whose outward normal is `normal`.
bool on_surface_with_normal(const TriangleMesh& mesh, const Vec3& p, const Vec3& normal,
                            double tol) {
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const geometry::Triangle& tri = mesh.triangles[t];
    const Vec3 &a = mesh.vertices[tri[0]], &b = mesh.vertices[tri[1]], &c = mesh.vertices[tri[2]];
    const Vec3 lo = a.cwiseMin(b).cwiseMin(c).array() - tol;
    const Vec3 hi = a.cwiseMax(b).cwiseMax(c).array() + tol;
    if ((p.array() < lo.array()).any() || (p.array() > hi.array()).any()) continue;
    if (point_triangle_distance(p, a, b, c) <= tol &&
        (geometry::triangle_normal(mesh, t) - normal).norm() < 1e-12) {
      return true;
    }
  }
  return false;
}

// Checks every documented property of each candidate; in_collision (the exhaustive test) on
// every `collision_stride`-th one.
void expect_valid_candidates(const TriangleMesh& mesh, const std::vector<GraspCandidate>& found,
                             const AntipodalOptions& options, std::size_t collision_stride = 1) {
  const DepthRange depth = contact_depth_range();
  const double cos_contact = std::cos(options.max_contact_angle);
  for (std::size_t i = 0; i < found.size(); ++i) {
    const GraspCandidate& g = found[i];
    const lie::Mat3& R = g.grasp.R;
    EXPECT_LT(lie::orthogonality_error(R), 1e-12) << "candidate " << i;
    EXPECT_NEAR(R.determinant(), 1.0, 1e-12) << "candidate " << i;

    const Vec3 span = g.contact2 - g.contact1;
    EXPECT_LE(span.norm(), options.opening - 2.0 * options.width_margin) << "candidate " << i;
    EXPECT_LT((R.col(0) - span.normalized()).norm(), 1e-12) << "candidate " << i;
    EXPECT_GE(g.normal2.dot(R.col(0)), cos_contact - 1e-12) << "candidate " << i;
    EXPECT_GE(-g.normal1.dot(R.col(0)), cos_contact - 1e-12) << "candidate " << i;

    // The contacts' midpoint in the gripper frame: on the z axis, between the pads.
    const Vec3 mid = lie::apply(lie::inverse(g.grasp), 0.5 * (g.contact1 + g.contact2));
    EXPECT_LT(mid.head<2>().norm(), 1e-12) << "candidate " << i;
    EXPECT_GE(mid.z(), depth.min - 1e-12) << "candidate " << i;
    EXPECT_LE(mid.z(), depth.max + 1e-12) << "candidate " << i;

    EXPECT_TRUE(on_surface_with_normal(mesh, g.contact1, g.normal1, 1e-12)) << "candidate " << i;
    EXPECT_TRUE(on_surface_with_normal(mesh, g.contact2, g.normal2, 1e-12)) << "candidate " << i;
    if (i % collision_stride == 0) {
      EXPECT_FALSE(gripper::in_collision(mesh, g.grasp, options.opening)) << "candidate " << i;
    }
  }
}

void expect_identical(const std::vector<GraspCandidate>& a, const std::vector<GraspCandidate>& b,
                      std::size_t count) {
  ASSERT_GE(a.size(), count);
  ASSERT_GE(b.size(), count);
  for (std::size_t i = 0; i < count; ++i) {
    EXPECT_EQ(a[i].grasp.matrix(), b[i].grasp.matrix()) << "candidate " << i;
    EXPECT_EQ(a[i].contact1, b[i].contact1) << "candidate " << i;
    EXPECT_EQ(a[i].contact2, b[i].contact2) << "candidate " << i;
    EXPECT_EQ(a[i].normal1, b[i].normal1) << "candidate " << i;
    EXPECT_EQ(a[i].normal2, b[i].normal2) << "candidate " << i;
  }
}

TEST(AntipodalCandidates, DepthRangeIsTheFingerPad) {
  const DepthRange depth = contact_depth_range();
  EXPECT_NEAR(depth.min, 0.09456, 1e-9);  // lowest point of the pad's inner face
  EXPECT_NEAR(depth.max, 0.11212 - 0.002, 1e-9);
  EXPECT_GT(depth.min, gripper::panda::kPalmTopZ);
  EXPECT_LT(depth.max, gripper::panda::kFingertipZ);
  EXPECT_GT(gripper::panda::kPadCenterZ, depth.min);
  EXPECT_LT(gripper::panda::kPadCenterZ, depth.max);
}

TEST(AntipodalCandidates, BoxCandidatesAreValid) {
  const TriangleMesh box = test_box();
  AntipodalOptions options;
  options.num_grasps = 300;
  const std::vector<GraspCandidate> found = sample_antipodal_grasps(box, options, 1);
  ASSERT_EQ(found.size(), 300u);
  expect_valid_candidates(box, found, options);

  // The depth and the approach about the closing axis vary over their whole ranges.
  const DepthRange depth = contact_depth_range();
  double lowest = depth.max, highest = depth.min;
  int approach_up = 0, approach_down = 0;
  for (const GraspCandidate& g : found) {
    const double height = (0.5 * (g.contact1 + g.contact2) - g.grasp.p).dot(g.grasp.R.col(2));
    lowest = std::min(lowest, height);
    highest = std::max(highest, height);
    approach_up += g.grasp.R(2, 2) > 0.5;
    approach_down += g.grasp.R(2, 2) < -0.5;
  }
  const double span = depth.max - depth.min;
  EXPECT_LT(lowest, depth.min + 0.05 * span);
  EXPECT_GT(highest, depth.max - 0.05 * span);
  EXPECT_GT(approach_up, 10);
  EXPECT_GT(approach_down, 10);
}

TEST(AntipodalCandidates, BoxClosingAxesAreFaceNormalsWithoutACone) {
  const TriangleMesh box = test_box();
  AntipodalOptions options;
  options.num_grasps = 300;
  options.ray_cone = 0.0;
  const std::vector<GraspCandidate> found = sample_antipodal_grasps(box, options, 2);
  ASSERT_EQ(found.size(), 300u);
  int across_x = 0, across_y = 0;
  for (const GraspCandidate& g : found) {
    const Vec3 x = g.grasp.R.col(0).cwiseAbs();
    // The 10 cm side (z) is wider than the 7 cm the hand allows with its margins.
    const bool is_x = (x - Vec3::UnitX()).norm() < 1e-12, is_y = (x - Vec3::UnitY()).norm() < 1e-12;
    EXPECT_TRUE(is_x || is_y) << x.transpose();
    across_x += is_x;
    across_y += is_y;
    EXPECT_NEAR((g.contact2 - g.contact1).norm(), is_x ? 0.06 : 0.04, 1e-12);
  }
  EXPECT_GT(across_x, 30);
  EXPECT_GT(across_y, 30);
}

TEST(AntipodalCandidates, SameSeedSameCandidates) {
  const TriangleMesh box = test_box();
  AntipodalOptions options;
  options.num_grasps = 100;
  const std::vector<GraspCandidate> first = sample_antipodal_grasps(box, options, 7);
  const std::vector<GraspCandidate> again = sample_antipodal_grasps(box, options, 7);
  ASSERT_EQ(first.size(), again.size());
  expect_identical(first, again, first.size());

  // More grasps from the same seed only append.
  options.num_grasps = 150;
  expect_identical(first, sample_antipodal_grasps(box, options, 7), first.size());

  // Another seed gives other candidates.
  const std::vector<GraspCandidate> other = sample_antipodal_grasps(box, options, 8);
  ASSERT_FALSE(other.empty());
  int same = 0;
  for (std::size_t i = 0; i < std::min(first.size(), other.size()); ++i) {
    same += first[i].contact1 == other[i].contact1;
  }
  EXPECT_EQ(same, 0);
}

TEST(AntipodalCandidates, MugYieldsValidCandidates) {
  const TriangleMesh& mug = metric_mug();
  const AntipodalOptions options;
  const std::vector<GraspCandidate> found = sample_antipodal_grasps(mug, options, 3);
  EXPECT_GE(found.size(), 1800u);
  expect_valid_candidates(mug, found, options, 4);
}

TEST(AntipodalCandidates, ProceduralMugYieldsValidCandidates) {
  // A finer mesh (≈ 10–20 k triangles) than the sample's 2334.
  const TriangleMesh mug = geometry::mug_mesh(geometry::MugParameters{});
  const AntipodalOptions options;
  const std::vector<GraspCandidate> found = sample_antipodal_grasps(mug, options, 4);
  EXPECT_GE(found.size(), 1800u);
  std::vector<GraspCandidate> every_tenth;
  for (std::size_t i = 0; i < found.size(); i += 10) every_tenth.push_back(found[i]);
  expect_valid_candidates(mug, every_tenth, options);
}

TEST(AntipodalCandidates, StopsAfterMaxAttempts) {
  AntipodalOptions options;
  options.max_attempts = 20;
  const std::vector<GraspCandidate> few = sample_antipodal_grasps(test_box(), options, 5);
  EXPECT_LE(few.size(), 20u);
  options.max_attempts = 0;
  options.num_grasps = few.size() + 50;
  expect_identical(few, sample_antipodal_grasps(test_box(), options, 5), few.size());

  // Nothing fits in the hand: a 20 cm cube gives no candidate, and no error.
  options.num_grasps = 10;
  EXPECT_TRUE(
      sample_antipodal_grasps(make_box(Vec3::Zero(), Vec3::Constant(0.2)), options, 6).empty());
}

TEST(AntipodalCandidates, RejectsBadOptions) {
  const auto expect_error_naming = [](const AntipodalOptions& options, const std::string& name) {
    try {
      validate(options);
      ADD_FAILURE() << name << " accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
    EXPECT_THROW(sample_antipodal_grasps(test_box(), options, 1), Error);
  };
  EXPECT_NO_THROW(validate(AntipodalOptions{}));
  AntipodalOptions options;
  options.num_grasps = 0;
  expect_error_naming(options, "num_grasps");
  options = {};
  options.ray_cone = -0.1;
  expect_error_naming(options, "ray_cone");
  options.ray_cone = 1.6;
  expect_error_naming(options, "ray_cone");
  options = {};
  options.max_contact_angle = 1.6;
  expect_error_naming(options, "max_contact_angle");
  options.max_contact_angle = NAN;
  expect_error_naming(options, "max_contact_angle");
  options = {};
  options.opening = 0.0;
  expect_error_naming(options, "opening");
  options.opening = 0.09;
  expect_error_naming(options, "opening");
  options = {};
  options.width_margin = 0.04;
  expect_error_naming(options, "width_margin");
  options.width_margin = -0.001;
  expect_error_naming(options, "width_margin");
}

TEST(AntipodalCandidates, RejectsOpenAndInwardMeshes) {
  TriangleMesh open = test_box();
  open.triangles.pop_back();
  EXPECT_THROW(sample_antipodal_grasps(open, AntipodalOptions{}, 1), Error);
  EXPECT_THROW(
      sample_antipodal_grasps(geometry::testing::inverted(test_box()), AntipodalOptions{}, 1),
      Error);
  EXPECT_THROW(sample_antipodal_grasps(TriangleMesh{}, AntipodalOptions{}, 1), Error);
}

}  // namespace
}  // namespace graspecmf::dataset
