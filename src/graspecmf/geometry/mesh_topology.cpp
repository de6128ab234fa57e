#include "graspecmf/geometry/mesh_topology.hpp"

#include <algorithm>
#include <numeric>
#include <unordered_map>

#include "graspecmf/core/error.hpp"

namespace graspecmf::geometry {

namespace {

constexpr std::uint32_t kUnset = ~std::uint32_t{0};

// Union-find over triangle indices with path halving and union by size.
class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n) : parent_(n), size_(n, 1) {
    std::iota(parent_.begin(), parent_.end(), std::uint32_t{0});
  }
  std::uint32_t find(std::uint32_t x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }
  void unite(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (size_[a] < size_[b]) std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
  }

 private:
  std::vector<std::uint32_t> parent_;
  std::vector<std::uint32_t> size_;
};

// One directed triangle side; key packs the undirected edge (min << 32 | max).
struct HalfEdge {
  std::uint64_t key;
  std::uint32_t triangle;
  bool forward;  // traversed from the smaller to the larger vertex index
};

// All half-edges grouped by undirected edge (sorted by key), each group in triangle order. A
// counting sort by the smaller vertex, then a sort of each (degree-sized) bucket: linear in
// practice, several times faster than one comparison sort of all 3F half-edges.
std::vector<HalfEdge> sorted_half_edges(const TriangleMesh& mesh) {
  const std::size_t num_half_edges = 3 * mesh.triangles.size();
  std::vector<std::uint32_t> start(mesh.vertices.size() + 1, 0);
  for (const Triangle& tri : mesh.triangles) {
    for (int k = 0; k < 3; ++k) ++start[std::min(tri[k], tri[(k + 1) % 3]) + 1];
  }
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) start[v + 1] += start[v];
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  std::vector<HalfEdge> half_edges(num_half_edges);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& tri = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = tri[k];
      const std::uint32_t b = tri[(k + 1) % 3];
      const std::uint64_t lo = std::min(a, b);
      const std::uint64_t hi = std::max(a, b);
      half_edges[fill[lo]++] = {lo << 32 | hi, static_cast<std::uint32_t>(t), a < b};
    }
  }
  const auto by_key_then_triangle = [](const HalfEdge& x, const HalfEdge& y) {
    return x.key != y.key ? x.key < y.key : x.triangle < y.triangle;
  };
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const auto first = half_edges.begin() + start[v];
    const auto last = half_edges.begin() + start[v + 1];
    if (last - first > 16) {
      std::sort(first, last, by_key_then_triangle);
      continue;
    }
    if (first == last) continue;
    // Insertion sort; entries arrive in triangle order, so it is stable in the triangle.
    for (auto it = first + 1; it < last; ++it) {
      const HalfEdge x = *it;
      auto hole = it;
      for (; hole > first && x.key < (hole - 1)->key; --hole) *hole = *(hole - 1);
      *hole = x;
    }
  }
  return half_edges;
}

// Calls visit(first, last) for each run of half-edges on one undirected edge.
template <typename Visit>
void for_each_edge(const std::vector<HalfEdge>& half_edges, Visit visit) {
  std::size_t i = 0;
  while (i < half_edges.size()) {
    std::size_t j = i + 1;
    while (j < half_edges.size() && half_edges[j].key == half_edges[i].key) ++j;
    visit(i, j);
    i = j;
  }
}

// Component label per triangle, numbered 0, 1, … in order of each component's first triangle.
std::vector<std::uint32_t> component_labels(const TriangleMesh& mesh,
                                            const std::vector<HalfEdge>& half_edges,
                                            std::size_t& num_components) {
  DisjointSets sets(mesh.triangles.size());
  for_each_edge(half_edges, [&](std::size_t first, std::size_t last) {
    for (std::size_t k = first + 1; k < last; ++k) {
      sets.unite(half_edges[first].triangle, half_edges[k].triangle);
    }
  });
  std::vector<std::uint32_t> label_of_root(mesh.triangles.size(), kUnset);
  std::vector<std::uint32_t> labels(mesh.triangles.size());
  num_components = 0;
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    std::uint32_t& label = label_of_root[sets.find(t)];
    if (label == kUnset) label = static_cast<std::uint32_t>(num_components++);
    labels[t] = label;
  }
  return labels;
}

}  // namespace

MeshTopology analyze_topology(const TriangleMesh& mesh) {
  MeshTopology topo;
  const std::vector<HalfEdge> half_edges = sorted_half_edges(mesh);
  const std::vector<std::uint32_t> labels = component_labels(mesh, half_edges, topo.num_components);

  std::vector<long> edges_per_component(topo.num_components, 0);
  for_each_edge(half_edges, [&](std::size_t first, std::size_t last) {
    ++topo.num_edges;
    ++edges_per_component[labels[half_edges[first].triangle]];
    const std::size_t count = last - first;
    if (count == 1) ++topo.num_boundary_edges;
    if (count >= 3) ++topo.num_nonmanifold_edges;
    if (count == 2 && half_edges[first].forward == half_edges[first + 1].forward) {
      ++topo.num_misoriented_edges;
    }
  });

  // Vertices per component, counting a vertex where components touch in each of them: the first
  // component seen per vertex is tracked directly, further ones (rare) as sorted pairs.
  std::vector<long> vertices_per_component(topo.num_components, 0);
  std::vector<std::uint32_t> first_component(mesh.vertices.size(), kUnset);
  std::vector<std::uint64_t> extra;  // (component << 32 | vertex) beyond a vertex's first
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (const std::uint32_t v : mesh.triangles[t]) {
      std::uint32_t& seen = first_component[v];
      if (seen == kUnset) {
        seen = labels[t];
        ++topo.num_vertices;
        ++vertices_per_component[seen];
      } else if (seen != labels[t]) {
        extra.push_back(static_cast<std::uint64_t>(labels[t]) << 32 | v);
      }
    }
  }
  std::sort(extra.begin(), extra.end());
  extra.erase(std::unique(extra.begin(), extra.end()), extra.end());
  for (const std::uint64_t pair : extra) ++vertices_per_component[pair >> 32];

  std::vector<long> triangles_per_component(topo.num_components, 0);
  for (const std::uint32_t label : labels) ++triangles_per_component[label];

  topo.euler_characteristic = static_cast<long>(topo.num_vertices) -
                              static_cast<long>(topo.num_edges) +
                              static_cast<long>(mesh.triangles.size());
  topo.watertight =
      !mesh.triangles.empty() && topo.num_boundary_edges == 0 && topo.num_nonmanifold_edges == 0;
  topo.consistently_oriented = topo.watertight && topo.num_misoriented_edges == 0;
  if (topo.consistently_oriented) {
    long genus = 0;
    for (std::size_t c = 0; c < topo.num_components; ++c) {
      const long chi =
          vertices_per_component[c] - edges_per_component[c] + triangles_per_component[c];
      genus += (2 - chi) / 2;
    }
    topo.genus = static_cast<int>(genus);
  }
  return topo;
}

std::vector<TriangleMesh> connected_components(const TriangleMesh& mesh) {
  std::size_t num_components = 0;
  const std::vector<std::uint32_t> labels =
      component_labels(mesh, sorted_half_edges(mesh), num_components);
  std::vector<TriangleMesh> parts(num_components);
  // Per component, its new index of each old vertex (hash maps keep this linear overall).
  std::vector<std::unordered_map<std::uint32_t, std::uint32_t>> new_index(num_components);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    TriangleMesh& part = parts[labels[t]];
    auto& index = new_index[labels[t]];
    Triangle tri{};
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t old = mesh.triangles[t][k];
      const auto [it, inserted] =
          index.try_emplace(old, static_cast<std::uint32_t>(part.vertices.size()));
      if (inserted) part.vertices.push_back(mesh.vertices[old]);
      tri[k] = it->second;
    }
    part.triangles.push_back(tri);
  }
  return parts;
}

void require_watertight(const TriangleMesh& mesh, const std::string& what) {
  validate_mesh(mesh, what);
  const MeshTopology topology = analyze_topology(mesh);
  if (!topology.watertight) {
    throw Error(what + ": the mesh is not watertight (" +
                std::to_string(topology.num_boundary_edges) + " boundary and " +
                std::to_string(topology.num_nonmanifold_edges) + " non-manifold edges)");
  }
}

}  // namespace graspecmf::geometry
