#include "graspecmf/dataset/antipodal_candidates.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <utility>

#include "graspecmf/core/error.hpp"
#include "graspecmf/core/random.hpp"
#include "graspecmf/geometry/mass_properties.hpp"
#include "graspecmf/geometry/mesh_topology.hpp"
#include "graspecmf/geometry/ray_cast.hpp"
#include "graspecmf/geometry/surface_sampling.hpp"

namespace graspecmf::dataset {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr std::size_t kAttemptsPerGrasp = 50;  // the default max_attempts per requested grasp
constexpr std::size_t kMinAttempts = 10000;    // ... but never fewer (mugs accept ~4 % of draws)
constexpr double kTipClearance = 0.002;        // contacts stay this far below the fingertip (m)
// Finger points within this distance of the innermost one form the pad's inner face (m).
constexpr double kInnerFaceTolerance = 0.001;
// The ray starts this fraction of the mesh's bounding-box diagonal inside the surface, so that it
// cannot hit the triangle it starts on.
constexpr double kRayInset = 1e-8;

void check_range(bool ok, const std::string& name, double value, const std::string& range) {
  if (ok) return;
  std::ostringstream message;
  message << "antipodal sampling option " << name << " = " << value << " is outside " << range;
  throw Error(message.str());
}

// Two unit vectors that complete the unit vector axis to an orthonormal basis.
std::pair<Vec3, Vec3> perpendicular_basis(const Vec3& axis) {
  int k = 0;
  axis.cwiseAbs().minCoeff(&k);
  const Vec3 u = axis.cross(Vec3::Unit(k)).normalized();
  return {u, axis.cross(u)};
}

// Throws Error unless the watertight mesh is consistently oriented with outward normals.
void require_outward(const geometry::TriangleMesh& mesh, const std::string& what) {
  if (!geometry::analyze_topology(mesh).consistently_oriented) {
    throw Error(what + ": the mesh is not consistently oriented");
  }
  if (!(geometry::mass_properties(mesh).volume > 0.0)) {
    throw Error(what + ": the mesh's normals point inwards (negative volume)");
  }
}

}  // namespace

void validate(const AntipodalOptions& options) {
  if (options.num_grasps == 0) throw Error("antipodal sampling option num_grasps must be ≥ 1");
  if (options.max_attempts == 0 &&
      options.num_grasps > std::numeric_limits<std::size_t>::max() / kAttemptsPerGrasp) {
    throw Error("antipodal sampling option num_grasps = " + std::to_string(options.num_grasps) +
                " is too large for the default max_attempts");
  }
  check_range(options.ray_cone >= 0.0 && options.ray_cone < 0.5 * kPi, "ray_cone", options.ray_cone,
              "[0, π/2) rad");
  check_range(options.max_contact_angle >= 0.0 && options.max_contact_angle <= 0.5 * kPi,
              "max_contact_angle", options.max_contact_angle, "[0, π/2] rad");
  check_range(options.opening > 0.0 && options.opening <= gripper::panda::kMaxOpening, "opening",
              options.opening, "(0, " + std::to_string(gripper::panda::kMaxOpening) + "] m");
  check_range(options.width_margin >= 0.0 && options.width_margin < 0.5 * options.opening,
              "width_margin", options.width_margin, "[0, opening / 2) m");
}

DepthRange contact_depth_range() {
  const std::vector<Vec3> finger = gripper::finger_points();
  double inner = std::numeric_limits<double>::infinity();
  for (const Vec3& p : finger) inner = std::min(inner, p.x());
  DepthRange range{std::numeric_limits<double>::infinity(),
                   -std::numeric_limits<double>::infinity()};
  for (const Vec3& p : finger) {
    if (p.x() > inner + kInnerFaceTolerance) continue;
    range.min = std::min(range.min, p.z());
    range.max = std::max(range.max, p.z());
  }
  range.max -= kTipClearance;
  return range;
}

std::vector<GraspCandidate> sample_antipodal_grasps(const geometry::TriangleMesh& mesh,
                                                    const AntipodalOptions& options,
                                                    std::uint64_t seed) {
  validate(options);
  const std::string what = "antipodal grasp sampling";
  geometry::require_watertight(mesh, what);
  require_outward(mesh, what);

  const geometry::MeshRayCaster caster(mesh);
  const geometry::SurfaceSampler sampler(mesh);
  const DepthRange depth = contact_depth_range();
  const double inset = kRayInset * geometry::bounding_box(mesh).extent().norm();
  const double max_width = options.opening - 2.0 * options.width_margin;
  const double cos_cone = std::cos(options.ray_cone);
  const double cos_contact = std::cos(options.max_contact_angle);
  const std::size_t attempts = options.max_attempts > 0
                                   ? options.max_attempts
                                   : std::max(kMinAttempts, kAttemptsPerGrasp * options.num_grasps);

  Rng rng(seed);
  std::vector<GraspCandidate> candidates;
  for (std::size_t attempt = 0; attempt < attempts && candidates.size() < options.num_grasps;
       ++attempt) {
    const geometry::SurfacePoints surface = sampler.sample(1, rng);
    const Vec3& p1 = surface.points[0];
    const Vec3& n1 = surface.normals[0];

    // Ray direction uniform over the cap of half-angle ray_cone around −n1.
    const double cos_tilt = 1.0 - rng.uniform() * (1.0 - cos_cone);
    const double sin_tilt = std::sqrt(std::max(0.0, 1.0 - cos_tilt * cos_tilt));
    const double azimuth = 2.0 * kPi * rng.uniform();
    const auto [u, v] = perpendicular_basis(-n1);
    const Vec3 direction =
        -cos_tilt * n1 + sin_tilt * (std::cos(azimuth) * u + std::sin(azimuth) * v);
    const std::optional<geometry::RayHit> hit = caster.first_hit(p1 - inset * n1, direction);
    if (!hit) continue;

    const Vec3& p2 = hit->point;
    const double width = (p2 - p1).norm();
    if (!(width > 0.0) || width > max_width) continue;
    const Vec3 x = (p2 - p1) / width;
    const Vec3 n2 = geometry::triangle_normal(mesh, hit->triangle);
    if (n2.dot(x) < cos_contact || (-n1).dot(x) < cos_contact) continue;

    // Approach uniform about the closing axis, contacts' midpoint on it at a uniform depth.
    const auto [a, b] = perpendicular_basis(x);
    const double roll = 2.0 * kPi * rng.uniform();
    const Vec3 z = std::cos(roll) * a + std::sin(roll) * b;
    const double height = rng.uniform(depth.min, depth.max);
    lie::Pose grasp;
    grasp.R.col(0) = x;
    grasp.R.col(1) = z.cross(x);
    grasp.R.col(2) = z;
    grasp.p = 0.5 * (p1 + p2) - height * z;
    if (gripper::in_collision(caster, grasp, options.opening)) continue;
    candidates.push_back({grasp, p1, p2, n1, n2});
  }
  return candidates;
}

}  // namespace graspecmf::dataset
