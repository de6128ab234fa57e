#include "graspecmf/geometry/mesh_topology.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "graspecmf/geometry/mass_properties.hpp"
#include "graspecmf/geometry/mesh_io.hpp"
#include "test_meshes.hpp"

namespace graspecmf::geometry {
namespace {

using namespace graspecmf::geometry::testing;

TEST(Topology, MugIsAClosedGenusOneSurface) {
  const MeshTopology topo = analyze_topology(read_mesh(kMugPath));
  EXPECT_EQ(topo.num_vertices, 1167u);
  EXPECT_EQ(topo.num_edges, 3501u);  // 3F/2 for a closed mesh
  EXPECT_EQ(topo.num_boundary_edges, 0u);
  EXPECT_EQ(topo.num_nonmanifold_edges, 0u);
  EXPECT_EQ(topo.num_misoriented_edges, 0u);
  EXPECT_TRUE(topo.watertight);
  EXPECT_TRUE(topo.consistently_oriented);
  EXPECT_EQ(topo.num_components, 1u);
  EXPECT_EQ(topo.euler_characteristic, 0);
  EXPECT_EQ(topo.genus, 1);
}

TEST(Topology, CubeIsASphere) {
  const MeshTopology topo = analyze_topology(make_unit_cube());
  EXPECT_EQ(topo.num_vertices, 8u);
  EXPECT_EQ(topo.num_edges, 18u);
  EXPECT_EQ(topo.euler_characteristic, 2);
  EXPECT_TRUE(topo.watertight);
  EXPECT_TRUE(topo.consistently_oriented);
  EXPECT_EQ(topo.num_components, 1u);
  EXPECT_EQ(topo.genus, 0);
}

TEST(Topology, CubeWithAHoleIsNotWatertight) {
  TriangleMesh cube = make_unit_cube();
  cube.triangles.pop_back();
  const MeshTopology topo = analyze_topology(cube);
  EXPECT_EQ(topo.num_boundary_edges, 3u);
  EXPECT_EQ(topo.num_nonmanifold_edges, 0u);
  EXPECT_FALSE(topo.watertight);
  EXPECT_FALSE(topo.consistently_oriented);
  EXPECT_EQ(topo.genus, -1);
  EXPECT_EQ(topo.num_components, 1u);
}

TEST(Topology, FlippedTriangleIsMisoriented) {
  TriangleMesh cube = make_unit_cube();
  std::swap(cube.triangles[5][1], cube.triangles[5][2]);
  const MeshTopology topo = analyze_topology(cube);
  EXPECT_TRUE(topo.watertight);
  EXPECT_EQ(topo.num_misoriented_edges, 3u);  // all three sides of the flipped triangle
  EXPECT_FALSE(topo.consistently_oriented);
  EXPECT_EQ(topo.genus, -1);
}

TEST(Topology, InvertedCubeIsStillConsistent) {
  const MeshTopology topo = analyze_topology(inverted(make_unit_cube()));
  EXPECT_TRUE(topo.consistently_oriented);
  EXPECT_EQ(topo.genus, 0);
}

TEST(Topology, NonManifoldEdge) {
  // A third triangle hung on the cube's edge (0, 1).
  TriangleMesh cube = make_unit_cube();
  cube.vertices.emplace_back(0.5, -1.0, -1.0);
  cube.triangles.push_back({0, 1, 8});
  const MeshTopology topo = analyze_topology(cube);
  EXPECT_EQ(topo.num_nonmanifold_edges, 1u);
  EXPECT_EQ(topo.num_boundary_edges, 2u);
  EXPECT_FALSE(topo.watertight);
  EXPECT_EQ(topo.num_components, 1u);
}

TEST(Topology, TwoDisjointCubes) {
  const TriangleMesh two = merged(make_unit_cube(), make_box(Vec3(3, 0, 0), Vec3(4, 1, 1)));
  const MeshTopology topo = analyze_topology(two);
  EXPECT_EQ(topo.num_components, 2u);
  EXPECT_TRUE(topo.consistently_oriented);
  EXPECT_EQ(topo.euler_characteristic, 4);
  EXPECT_EQ(topo.genus, 0);

  const std::vector<TriangleMesh> parts = connected_components(two);
  ASSERT_EQ(parts.size(), 2u);
  for (const TriangleMesh& part : parts) {
    EXPECT_EQ(part.vertices.size(), 8u);
    EXPECT_EQ(part.triangles.size(), 12u);
    EXPECT_EQ(analyze_topology(part).genus, 0);
  }
  // In order of their first triangle, with their own vertices.
  EXPECT_EQ(bounding_box(parts[0]).min, Vec3(0, 0, 0));
  EXPECT_EQ(bounding_box(parts[1]).min, Vec3(3, 0, 0));
}

TEST(Topology, CubesTouchingAtAVertexAreTwoComponents) {
  // Edge connectivity only: sharing vertex 7 = (1,1,1) does not join the cubes.
  TriangleMesh a = make_unit_cube();
  const TriangleMesh b = make_box(Vec3(1, 1, 1), Vec3(2, 2, 2));
  TriangleMesh both = merged(a, b);
  for (Triangle& t : both.triangles) {
    for (std::uint32_t& v : t) v = v == 8 ? 7 : v;  // b's corner (1,1,1) is index 8
  }
  const MeshTopology topo = analyze_topology(both);
  EXPECT_EQ(topo.num_components, 2u);
  EXPECT_EQ(topo.num_vertices, 15u);
  EXPECT_EQ(topo.genus, 0);  // the shared vertex counts in each component
  const std::vector<TriangleMesh> parts = connected_components(both);
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(parts[1].vertices.size(), 8u);
}

// Double cone over an n-gon: apexes 0 and 1 each have degree n (beyond the small-bucket path).
TriangleMesh make_bipyramid(int n) {
  TriangleMesh mesh;
  mesh.vertices = {Vec3(0, 0, 1), Vec3(0, 0, -1)};
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * M_PI * i / n;
    mesh.vertices.emplace_back(std::cos(a), std::sin(a), 0.0);
  }
  for (int i = 0; i < n; ++i) {
    const auto r0 = static_cast<std::uint32_t>(2 + i);
    const auto r1 = static_cast<std::uint32_t>(2 + (i + 1) % n);
    mesh.triangles.push_back({0, r0, r1});
    mesh.triangles.push_back({1, r1, r0});
  }
  return mesh;
}

TEST(Topology, HighDegreeVertices) {
  TriangleMesh mesh = make_bipyramid(50);
  MeshTopology topo = analyze_topology(mesh);
  EXPECT_EQ(topo.num_vertices, 52u);
  EXPECT_EQ(topo.num_edges, 150u);
  EXPECT_TRUE(topo.consistently_oriented);
  EXPECT_EQ(topo.genus, 0);
  EXPECT_GT(mass_properties(mesh).volume, 0.0);
  std::swap(mesh.triangles[7][1], mesh.triangles[7][2]);
  topo = analyze_topology(mesh);
  EXPECT_EQ(topo.num_misoriented_edges, 3u);
  mesh.triangles.erase(mesh.triangles.begin() + 20);
  topo = analyze_topology(mesh);
  EXPECT_EQ(topo.num_boundary_edges, 3u);
}

TEST(Topology, TorusHasGenusOne) {
  const TriangleMesh torus = make_torus(1.0, 0.3, 24, 12);
  const MeshTopology topo = analyze_topology(torus);
  EXPECT_TRUE(topo.consistently_oriented);
  EXPECT_EQ(topo.euler_characteristic, 0);
  EXPECT_EQ(topo.genus, 1);
  // Outward: positive volume close to 2π² R r² (the polyhedron is slightly smaller).
  const double volume = mass_properties(torus).volume;
  EXPECT_GT(volume, 0.9 * 2 * M_PI * M_PI * 0.09);
  EXPECT_LT(volume, 2 * M_PI * M_PI * 0.09);
}

TEST(Topology, TorusAndCubeSumGenera) {
  const TriangleMesh both =
      merged(make_torus(1.0, 0.3, 16, 8), make_box(Vec3(5, 5, 5), Vec3(6, 6, 6)));
  const MeshTopology topo = analyze_topology(both);
  EXPECT_EQ(topo.num_components, 2u);
  EXPECT_EQ(topo.genus, 1);
}

TEST(Topology, GripperHasThreeClosedParts) {
  const TriangleMesh gripper = read_mesh(kGripperPath);
  const MeshTopology topo = analyze_topology(gripper);
  EXPECT_EQ(topo.num_components, 3u);
  EXPECT_TRUE(topo.watertight);
  const std::vector<TriangleMesh> parts = connected_components(gripper);
  ASSERT_EQ(parts.size(), 3u);
  std::size_t triangles = 0;
  for (const TriangleMesh& part : parts) {
    EXPECT_TRUE(analyze_topology(part).watertight);
    EXPECT_GT(mass_properties(part).volume, 0.0);  // each part faces outwards
    triangles += part.triangles.size();
  }
  EXPECT_EQ(triangles, gripper.triangles.size());
}

}  // namespace
}  // namespace graspecmf::geometry
