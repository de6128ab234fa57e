#pragma once
// ACRONYM-style antipodal grasp candidates for the Panda hand: a random surface point, a ray cast
// through the object from it to a second contact, a check that the pair is antipodal within a
// friction cone, a random approach about the closing axis and depth along the finger pads, and
// the gripper collision check.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "graspecmf/geometry/triangle_mesh.hpp"
#include "graspecmf/gripper/panda.hpp"

namespace graspecmf::dataset {

using Vec3 = Eigen::Vector3d;

struct AntipodalOptions {
  std::size_t num_grasps = 2000;  // stop after this many candidates
  std::size_t max_attempts = 0;   // surface points drawn at most; 0 = max(50 × num_grasps, 10⁴)
  // Half-angle (rad) of the cone around the inward normal that the ray direction is drawn from,
  // uniformly over the cone's solid angle: 0.15 rad ≈ 8.6°, well inside the friction cone.
  double ray_cone = 0.15;
  // Largest angle (rad) between each contact's outward normal and the direction the finger
  // presses along it: the friction cone of μ = 0.5, atan(0.5) ≈ 26.6°.
  double max_contact_angle = 0.4636476090008061;
  double opening = gripper::panda::kMaxOpening;  // finger opening of the hand (m)
  // Free space left between each contact and its finger pad: the contacts are at most
  // opening − 2 × width_margin apart (m).
  double width_margin = 0.005;
};

// Throws Error naming the first option out of range: num_grasps ≥ 1 (and ≤ 2^64 / 50 when
// max_attempts is 0), ray_cone ∈ [0, π/2), max_contact_angle ∈ [0, π/2],
// opening ∈ (0, kMaxOpening], width_margin ∈ [0, opening / 2).
void validate(const AntipodalOptions& options);

// Heights on the gripper's z axis (m) where the sampled contacts' midpoint may lie: from the
// bottom of the finger pads' inner face to 2 mm short of the fingertip (read off finger_points).
struct DepthRange {
  double min = 0.0;
  double max = 0.0;
};
DepthRange contact_depth_range();

struct GraspCandidate {
  lie::Pose grasp;  // T_object_gripper: x = closing axis (contact1 → contact2), z = approach
  // On the surface: contact1 is the sampled point, contact2 the ray's hit.
  Vec3 contact1 = Vec3::Zero(), contact2 = Vec3::Zero();
  // Outward unit normals of the triangles they lie on.
  Vec3 normal1 = Vec3::Zero(), normal2 = Vec3::Zero();
};

// Up to options.num_grasps collision-free antipodal candidates on a watertight, outward mesh, in
// the order drawn (fewer if options.max_attempts surface points run out first). Each draw: p1 with
// normal n1 uniform over the surface area; a ray from just inside p1 along −n1 tilted uniformly
// within ray_cone; its first hit p2 (normal n2); rejected unless |p2 − p1| ≤ opening −
// 2 width_margin and both n2 and −n1 lie within max_contact_angle of x = (p2 − p1) / |p2 − p1|;
// then z uniform among the unit vectors ⊥ x, y = z × x, and the midpoint placed on the z axis at a
// height uniform in contact_depth_range(); rejected if the hand at options.opening collides
// (gripper::in_collision's answer, computed through MeshRayCaster::overlaps).
// The same mesh, options and seed always give the same candidates, and a larger num_grasps only
// appends to them. Throws Error on bad options or a mesh that is not watertight and outward.
std::vector<GraspCandidate> sample_antipodal_grasps(const geometry::TriangleMesh& mesh,
                                                    const AntipodalOptions& options,
                                                    std::uint64_t seed);

}  // namespace graspecmf::dataset
