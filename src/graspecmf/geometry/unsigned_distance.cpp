#include "graspecmf/geometry/unsigned_distance.hpp"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <vector>

#include "graspecmf/core/error.hpp"

namespace graspecmf::geometry {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using CgalTriangle = Kernel::Triangle_3;
using TriangleIterator = std::vector<CgalTriangle>::const_iterator;
using AabbTree = CGAL::AABB_tree<
    CGAL::AABB_traits<Kernel, CGAL::AABB_triangle_primitive<Kernel, TriangleIterator>>>;

Point to_point(const Vec3& v) {
  return {v.x(), v.y(), v.z()};
}

}  // namespace

struct UnsignedDistance::Tree {
  std::vector<CgalTriangle> triangles;  // the tree's primitives point into this
  AabbTree tree;
};

UnsignedDistance::UnsignedDistance(const TriangleMesh& mesh) : tree_(std::make_unique<Tree>()) {
  validate_mesh(mesh, "surface distance");
  for (const Triangle& t : mesh.triangles) {
    const Point a = to_point(mesh.vertices[t[0]]);
    const Point b = to_point(mesh.vertices[t[1]]);
    const Point c = to_point(mesh.vertices[t[2]]);
    if (!CGAL::collinear(a, b, c)) tree_->triangles.emplace_back(a, b, c);
  }
  if (tree_->triangles.empty()) {
    throw Error("surface distance: every triangle of a mesh has zero area");
  }
  tree_->tree.insert(tree_->triangles.begin(), tree_->triangles.end());
  tree_->tree.accelerate_distance_queries();
}

UnsignedDistance::~UnsignedDistance() = default;
UnsignedDistance::UnsignedDistance(UnsignedDistance&&) noexcept = default;
UnsignedDistance& UnsignedDistance::operator=(UnsignedDistance&&) noexcept = default;

double UnsignedDistance::operator()(const Vec3& q) const {
  return std::sqrt(tree_->tree.squared_distance(to_point(q)));
}

}  // namespace graspecmf::geometry
