#include "graspecmf/geometry/ray_cast.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "graspecmf/core/error.hpp"
#include "graspecmf/geometry/exact_predicates.hpp"
#include "graspecmf/geometry/point_inside.hpp"

namespace graspecmf::geometry {
namespace {

constexpr std::uint32_t kLeafSize = 4;
// The traversal stack never holds more than one entry per level (plus one); median splits keep
// the depth at most 32 for 2^32 triangles.
constexpr std::size_t kStackSize = 64;

// Directions of the segments for the inside test: all components non-zero and of different sizes,
// so that no segment runs parallel to an axis-aligned face or along a (±1, ±1, ±1) diagonal.
const Vec3 kInsideDirections[] = {
    {0.5234, 0.6817, 0.5108},
    {-0.6123, 0.3377, 0.7149},
    {0.2843, -0.8211, 0.4947},
    {-0.4417, -0.5589, -0.7018},
};

// Clips [t0, t1] to the slab intervals of the box [lo, hi] along origin + t · direction (inv is
// 1 / direction); false if the interval becomes empty.
bool clip_to_box(const Vec3& lo, const Vec3& hi, const Vec3& origin, const Vec3& direction,
                 const Vec3& inv, double& t0, double& t1) {
  for (int k = 0; k < 3; ++k) {
    if (direction[k] == 0.0) {
      if (origin[k] < lo[k] || origin[k] > hi[k]) return false;
      continue;
    }
    double near = (lo[k] - origin[k]) * inv[k], far = (hi[k] - origin[k]) * inv[k];
    if (near > far) std::swap(near, far);
    t0 = std::max(t0, near);
    t1 = std::min(t1, far);
    if (t0 > t1) return false;
  }
  return true;
}

bool boxes_overlap(const Vec3& lo_a, const Vec3& hi_a, const Vec3& lo_b, const Vec3& hi_b) {
  return (lo_a.array() <= hi_b.array()).all() && (lo_b.array() <= hi_a.array()).all();
}

// Exact sign of a proper crossing of segment q → far through triangle abc: +1 leaving through
// its front (outward) side, −1 entering, 0 missing; nothing when degenerate (an endpoint on the
// plane, or the segment through an edge or vertex).
std::optional<int> segment_crossing(const Vec3& q, const Vec3& far, const Vec3& a, const Vec3& b,
                                    const Vec3& c) {
  const int side_q = orientation(a, b, c, q), side_far = orientation(a, b, c, far);
  if (side_q == side_far && side_q != 0) return 0;
  const int ab = orientation(q, far, a, b), bc = orientation(q, far, b, c),
            ca = orientation(q, far, c, a);
  const bool mixed = std::min({ab, bc, ca}) < 0 && std::max({ab, bc, ca}) > 0;
  if (mixed) return 0;
  if (side_q == 0 || side_far == 0 || ab == 0 || bc == 0 || ca == 0) return std::nullopt;
  return side_q < 0 ? 1 : -1;
}

}  // namespace

MeshRayCaster::MeshRayCaster(const TriangleMesh& mesh) : mesh_(mesh) {
  validate_mesh(mesh_, "ray caster mesh");
  if (mesh_.triangles.size() > std::numeric_limits<std::uint32_t>::max() / 2) {
    throw Error("ray caster mesh: too many triangles (" + std::to_string(mesh_.triangles.size()) +
                ")");
  }
  bounds_ = bounding_box(mesh_);
  const double magnitude = bounds_.min.cwiseAbs().cwiseMax(bounds_.max.cwiseAbs()).maxCoeff();
  pad_ = 1e-9 * (bounds_.extent().norm() + magnitude);

  const auto n = static_cast<std::uint32_t>(mesh_.triangles.size());
  std::vector<Vec3> centroids;
  centroids.reserve(n);
  for (const Triangle& t : mesh_.triangles) {
    centroids.push_back((mesh_.vertices[t[0]] + mesh_.vertices[t[1]] + mesh_.vertices[t[2]]) / 3.0);
  }
  order_.resize(n);
  std::iota(order_.begin(), order_.end(), 0u);
  nodes_.reserve(2 * (n / kLeafSize + 1));
  build(0, n, centroids);

  corner_.reserve(n);
  e1_.reserve(n);
  e2_.reserve(n);
  for (const std::uint32_t t : order_) {
    const Triangle& tri = mesh_.triangles[t];
    corner_.push_back(mesh_.vertices[tri[0]]);
    e1_.push_back(mesh_.vertices[tri[1]] - mesh_.vertices[tri[0]]);
    e2_.push_back(mesh_.vertices[tri[2]] - mesh_.vertices[tri[0]]);
  }
}

std::uint32_t MeshRayCaster::build(std::uint32_t begin, std::uint32_t end,
                                   const std::vector<Vec3>& centroids) {
  const auto index = static_cast<std::uint32_t>(nodes_.size());
  nodes_.push_back(Node{});
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  Vec3 centroid_lo = lo, centroid_hi = hi;
  for (std::uint32_t i = begin; i < end; ++i) {
    for (const std::uint32_t v : mesh_.triangles[order_[i]]) {
      lo = lo.cwiseMin(mesh_.vertices[v]);
      hi = hi.cwiseMax(mesh_.vertices[v]);
    }
    centroid_lo = centroid_lo.cwiseMin(centroids[order_[i]]);
    centroid_hi = centroid_hi.cwiseMax(centroids[order_[i]]);
  }
  lo.array() -= pad_;
  hi.array() += pad_;
  if (end - begin <= kLeafSize) {
    nodes_[index] = Node{lo, hi, begin, end - begin};
    return index;
  }
  int axis = 0;
  (centroid_hi - centroid_lo).maxCoeff(&axis);
  const std::uint32_t mid = begin + (end - begin) / 2;
  // Ties broken by triangle index: the split, and so the whole tree, is fully determined.
  std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                   [&](std::uint32_t a, std::uint32_t b) {
                     const double ca = centroids[a][axis], cb = centroids[b][axis];
                     return ca < cb || (ca == cb && a < b);
                   });
  build(begin, mid, centroids);
  const std::uint32_t right = build(mid, end, centroids);
  nodes_[index] = Node{lo, hi, right, 0};
  return index;
}

std::optional<RayHit> MeshRayCaster::first_hit(const Vec3& origin, const Vec3& direction,
                                               double t_min, double t_max) const {
  if (!origin.allFinite() || !direction.allFinite() || direction.isZero(0.0)) {
    throw Error("ray cast: the origin and direction must be finite and the direction non-zero");
  }
  const Vec3 inv = direction.cwiseInverse();
  double best_t = t_max;
  std::size_t best_triangle = mesh_.triangles.size();

  struct Entry {
    std::uint32_t node;
    double t_enter;
  };
  std::array<Entry, kStackSize> stack;
  std::size_t size = 0;
  double t0 = t_min, t1 = t_max;
  if (!(t_min <= t_max) ||
      !clip_to_box(nodes_[0].lo, nodes_[0].hi, origin, direction, inv, t0, t1)) {
    return std::nullopt;
  }
  stack[size++] = {0, t0};
  while (size > 0) {
    const Entry entry = stack[--size];
    if (entry.t_enter > best_t) continue;
    const Node& node = nodes_[entry.node];
    if (node.count > 0) {
      for (std::uint32_t slot = node.first; slot < node.first + node.count; ++slot) {
        // Möller–Trumbore.
        const Vec3 p = direction.cross(e2_[slot]);
        const double det = e1_[slot].dot(p);
        if (std::abs(det) < 1e-300) continue;
        const Vec3 s = origin - corner_[slot];
        const double u = s.dot(p) / det;
        if (u < 0.0 || u > 1.0) continue;
        const Vec3 q = s.cross(e1_[slot]);
        const double v = direction.dot(q) / det;
        if (v < 0.0 || u + v > 1.0) continue;
        const double t = e2_[slot].dot(q) / det;
        if (t < t_min || t > best_t) continue;
        if (t < best_t || order_[slot] < best_triangle) {
          best_t = t;
          best_triangle = order_[slot];
        }
      }
      continue;
    }
    // Visit the nearer child first: push it last.
    const std::uint32_t children[2] = {entry.node + 1, node.first};
    double enter[2];
    bool hit[2];
    for (int c = 0; c < 2; ++c) {
      double c0 = t_min, c1 = best_t;
      hit[c] = clip_to_box(nodes_[children[c]].lo, nodes_[children[c]].hi, origin, direction, inv,
                           c0, c1);
      enter[c] = c0;
    }
    const int nearer = (hit[1] && (!hit[0] || enter[1] < enter[0])) ? 1 : 0;
    for (const int c : {1 - nearer, nearer}) {
      if (hit[c]) stack[size++] = {children[c], enter[c]};
    }
  }
  if (best_triangle == mesh_.triangles.size()) return std::nullopt;
  return RayHit{best_t, origin + best_t * direction, best_triangle};
}

std::optional<int> MeshRayCaster::crossing_number(const Vec3& q, const Vec3& far) const {
  const Vec3 direction = far - q;
  const Vec3 inv = direction.cwiseInverse();
  std::array<std::uint32_t, kStackSize> stack;
  std::size_t size = 0;
  stack[size++] = 0;
  int winding = 0;
  while (size > 0) {
    const Node& node = nodes_[stack[--size]];
    double t0 = 0.0, t1 = 1.0;
    if (!clip_to_box(node.lo, node.hi, q, direction, inv, t0, t1)) continue;
    if (node.count == 0) {
      stack[size++] = node.first;
      stack[size++] = static_cast<std::uint32_t>(&node - nodes_.data()) + 1;
      continue;
    }
    for (std::uint32_t slot = node.first; slot < node.first + node.count; ++slot) {
      const Triangle& t = mesh_.triangles[order_[slot]];
      const std::optional<int> crossing = segment_crossing(
          q, far, mesh_.vertices[t[0]], mesh_.vertices[t[1]], mesh_.vertices[t[2]]);
      if (!crossing) return std::nullopt;
      winding += *crossing;
    }
  }
  return winding;
}

bool MeshRayCaster::contains(const Vec3& q) const {
  if ((q.array() < bounds_.min.array()).any() || (q.array() > bounds_.max.array()).any()) {
    return false;
  }
  // Each segment ends outside the bounding box, where the winding number is 0.
  const double length = 2.0 * ((q - bounds_.center()).norm() + bounds_.extent().norm());
  for (const Vec3& direction : kInsideDirections) {
    if (const std::optional<int> winding = crossing_number(q, q + length * direction)) {
      return *winding > 0;
    }
  }
  return is_inside(mesh_, q);
}

bool MeshRayCaster::overlaps(const OrientedBox& box) const {
  // Culling is conservative (padded): the exact test is box_overlaps_triangle.
  const Eigen::Matrix3d to_box = box.pose.R.transpose(), to_box_abs = to_box.cwiseAbs();
  const Vec3 reach = to_box_abs.transpose() * box.half_extents + Vec3::Constant(pad_);
  const Vec3 lo = box.pose.p - reach, hi = box.pose.p + reach;
  // A node is separated from the box along one of the box's axes.
  const auto separated = [&](const Node& node) {
    const Vec3 center = to_box * (0.5 * (node.lo + node.hi) - box.pose.p);
    const Vec3 radius = to_box_abs * (0.5 * (node.hi - node.lo)) + box.half_extents;
    return (center.cwiseAbs() - radius).maxCoeff() > pad_;
  };
  std::array<std::uint32_t, kStackSize> stack;
  std::size_t size = 0;
  stack[size++] = 0;
  while (size > 0) {
    const std::uint32_t index = stack[--size];
    const Node& node = nodes_[index];
    if (!boxes_overlap(node.lo, node.hi, lo, hi) || separated(node)) continue;
    if (node.count == 0) {
      stack[size++] = node.first;
      stack[size++] = index + 1;
      continue;
    }
    for (std::uint32_t slot = node.first; slot < node.first + node.count; ++slot) {
      const Triangle& t = mesh_.triangles[order_[slot]];
      const Vec3 &a = mesh_.vertices[t[0]], &b = mesh_.vertices[t[1]], &c = mesh_.vertices[t[2]];
      if (!boxes_overlap(a.cwiseMin(b).cwiseMin(c), a.cwiseMax(b).cwiseMax(c), lo, hi)) continue;
      if (box_overlaps_triangle(box, a, b, c)) return true;
    }
  }
  return contains(box.pose.p);
}

}  // namespace graspecmf::geometry
