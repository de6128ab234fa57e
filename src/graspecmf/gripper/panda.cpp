#include "graspecmf/gripper/panda.hpp"

#include <algorithm>
#include <string>

#include "graspecmf/core/error.hpp"

namespace graspecmf::gripper {
namespace {

using geometry::OrientedBox;

// Axis-aligned box in the gripper frame from its corners.
OrientedBox box_between(const Vec3& lo, const Vec3& hi) {
  OrientedBox box;
  box.pose.p = 0.5 * (lo + hi);
  box.half_extents = 0.5 * (hi - lo);
  return box;
}

// Finger profile of the right (+x) finger, measured from its inner face (x = opening / 2) outwards,
// as z bands [z0, z1] × [inner, outer] that contain the collision mesh's finger hull.
struct FingerBand {
  double z0, z1, inner, outer;
};
constexpr FingerBand kFingerBands[] = {
    {panda::kFingerBaseZ, 0.0776, 0.0011, 0.0264},  // wide base block (inner face slants)
    {0.0776, 0.0946, -0.0001, 0.0253},              // taper (outer face slopes inwards)
    {0.0946, panda::kFingertipZ, -0.0001, 0.0192},  // pad and tip
};

// The right finger's vertices in franka_gripper_collision_mesh.stl (fully open, inner pad face at
// x = 0.04): the base block where it leaves the palm, then the pad, which is ±8.7 mm wide and
// narrows to ±5.5 mm at the tip.
const Vec3 kOpenFingerPoints[] = {
    {0.04253, 0.01039, 0.05853},  {0.04258, -0.01045, 0.05855}, {0.06640, -0.01036, 0.05855},
    {0.06631, 0.01040, 0.05857},  {0.05510, -0.01049, 0.07684}, {0.05610, 0.01048, 0.07739},
    {0.06525, -0.01040, 0.07744}, {0.06522, 0.01039, 0.07759},  {0.03998, 0.00873, 0.09456},
    {0.03987, -0.00869, 0.10857}, {0.05392, 0.00884, 0.10899},  {0.03994, 0.00862, 0.10935},
    {0.05399, -0.00862, 0.10973}, {0.05422, 0.00778, 0.11077},  {0.03998, -0.00614, 0.11198},
    {0.03991, 0.00548, 0.11212},  {0.05427, -0.00584, 0.11220}, {0.05429, 0.00528, 0.11225},
};

// Palm housing bounds from the collision mesh's palm part.
const Vec3 kPalmMin(-0.1005, -0.0317, -0.0260);
const Vec3 kPalmMax(0.1040, 0.0317, panda::kPalmTopZ);

// The marker: cylinders of ACRONYM's create_gripper_marker, with fingers at x = ±(opening/2 + 1
// mm).
constexpr double kMarkerFingerOffset = 0.001;

}  // namespace

void check_opening(double opening) {
  if (!(opening >= 0.0 && opening <= panda::kMaxOpening)) {
    throw Error("gripper opening " + std::to_string(opening) + " m is outside [0, " +
                std::to_string(panda::kMaxOpening) + "]");
  }
}

std::vector<OrientedBox> collision_boxes(double opening) {
  check_opening(opening);
  std::vector<OrientedBox> boxes = {box_between(kPalmMin, kPalmMax)};
  const double half = 0.5 * opening;
  for (const double side : {-1.0, 1.0}) {
    for (const FingerBand& band : kFingerBands) {
      const double x_inner = side * (half + band.inner), x_outer = side * (half + band.outer);
      boxes.push_back(
          box_between(Vec3(std::min(x_inner, x_outer), -panda::kFingerHalfWidthY, band.z0),
                      Vec3(std::max(x_inner, x_outer), panda::kFingerHalfWidthY, band.z1)));
    }
  }
  return boxes;
}

std::vector<Vec3> finger_points(double opening) {
  check_opening(opening);
  std::vector<Vec3> points;
  for (const Vec3& p : kOpenFingerPoints) {
    points.push_back(p + Vec3(0.5 * (opening - panda::kMaxOpening), 0, 0));
  }
  return points;
}

geometry::TriangleMesh collision_mesh(double opening) {
  geometry::TriangleMesh mesh;
  for (const OrientedBox& box : collision_boxes(opening)) {
    const geometry::TriangleMesh part = geometry::box_mesh(box);
    const auto offset = static_cast<std::uint32_t>(mesh.vertices.size());
    mesh.vertices.insert(mesh.vertices.end(), part.vertices.begin(), part.vertices.end());
    for (const geometry::Triangle& t : part.triangles) {
      mesh.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    }
  }
  return mesh;
}

bool in_collision(const geometry::TriangleMesh& object, const lie::Pose& grasp, double opening) {
  for (const OrientedBox& box : collision_boxes(opening)) {
    if (geometry::box_overlaps_mesh(geometry::transformed(box, grasp), object)) return true;
  }
  return false;
}

bool in_collision(const geometry::MeshRayCaster& object, const lie::Pose& grasp, double opening) {
  const std::vector<OrientedBox> boxes = collision_boxes(opening);
  return std::any_of(boxes.begin(), boxes.end(), [&](const OrientedBox& box) {
    return object.overlaps(geometry::transformed(box, grasp));
  });
}

std::array<Vec3, 6> control_points(double opening) {
  check_opening(opening);
  const double x = 0.5 * opening + kMarkerFingerOffset;
  return {Vec3(0, 0, 0),
          Vec3(0, 0, panda::kPalmTopZ),
          Vec3(-x, 0, panda::kPalmTopZ),
          Vec3(x, 0, panda::kPalmTopZ),
          Vec3(-x, 0, panda::kFingertipZ),
          Vec3(x, 0, panda::kFingertipZ)};
}

std::vector<std::pair<Vec3, Vec3>> marker_segments(double opening) {
  const std::array<Vec3, 6> p = control_points(opening);
  return {{p[0], p[1]}, {p[2], p[3]}, {p[2], p[4]}, {p[3], p[5]}};
}

}  // namespace graspecmf::gripper
