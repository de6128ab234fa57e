// Watertight conversion of the open-pieces mug (data/real-object/mug-open-pieces.obj): CGAL's alpha
// wrap with the default options against a voxel flood-fill wrap, the baseline that the choice in
// docs/prepare-mesh.md was measured against. Counters: the symmetric Hausdorff distance to the
// input (mm), the volume over the original mug's, the genus (−1 when the surface has non-manifold
// edges) and the vertex count.

#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <vector>

#include "graspecmf/geometry/mass_properties.hpp"
#include "graspecmf/geometry/mesh_io.hpp"
#include "graspecmf/geometry/mesh_topology.hpp"
#include "graspecmf/geometry/watertight.hpp"

namespace {

using namespace graspecmf::geometry;

constexpr double kMugScale = 0.0002682457830986903;
constexpr double kMugVolume = 8.72532e-05;

const TriangleMesh& open_pieces_mug() {
  static const TriangleMesh mesh = scaled(
      read_mesh(std::filesystem::path(GRASPECMF_DATA_DIR) / "real-object/mug-open-pieces.obj"),
      kMugScale);
  return mesh;
}

// Voxels of size h that the surface passes through (found by sampling each triangle at spacing
// h / 2) block a 6-connected flood fill from the border of a grid padded by 2h; the faces between
// the unreached voxels and the reached ones, oriented outwards, form the wrap.
TriangleMesh voxel_wrap(const TriangleMesh& mesh, double h) {
  const BoundingBox box = bounding_box(mesh);
  const Vec3 origin = box.min - Vec3::Constant(2 * h);
  std::array<int, 3> n{};
  for (int k = 0; k < 3; ++k) n[k] = static_cast<int>(std::ceil(box.extent()[k] / h)) + 4;
  const auto index = [&](int i, int j, int k) {
    return static_cast<std::size_t>(i) +
           static_cast<std::size_t>(n[0]) *
               (static_cast<std::size_t>(j) + static_cast<std::size_t>(n[1]) * k);
  };
  std::vector<std::uint8_t> state(static_cast<std::size_t>(n[0]) * n[1] * n[2], 0);  // 1 blocked
  for (const Triangle& t : mesh.triangles) {
    const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    const int steps = std::max(1, static_cast<int>(std::ceil(2 * longest / h)));
    for (int i = 0; i <= steps; ++i) {
      for (int j = 0; i + j <= steps; ++j) {
        const Vec3 p = a + (b - a) * (double(i) / steps) + (c - a) * (double(j) / steps);
        const Vec3 q = (p - origin) / h;
        state[index(int(q.x()), int(q.y()), int(q.z()))] = 1;
      }
    }
  }
  std::deque<std::array<int, 3>> queue{{0, 0, 0}};
  state[0] = 2;  // 2: outside
  constexpr int kSteps[6][3] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
  while (!queue.empty()) {
    const std::array<int, 3> v = queue.front();
    queue.pop_front();
    for (const auto& s : kSteps) {
      const int i = v[0] + s[0], j = v[1] + s[1], k = v[2] + s[2];
      if (i < 0 || j < 0 || k < 0 || i >= n[0] || j >= n[1] || k >= n[2]) continue;
      std::uint8_t& x = state[index(i, j, k)];
      if (x == 0) {
        x = 2;
        queue.push_back({i, j, k});
      }
    }
  }
  TriangleMesh out;
  std::vector<std::uint32_t> corner(static_cast<std::size_t>(n[0] + 1) * (n[1] + 1) * (n[2] + 1),
                                    ~0u);
  const auto vertex = [&](int i, int j, int k) {
    std::uint32_t& id =
        corner[static_cast<std::size_t>(i) +
               static_cast<std::size_t>(n[0] + 1) *
                   (static_cast<std::size_t>(j) + static_cast<std::size_t>(n[1] + 1) * k)];
    if (id == ~0u) {
      id = static_cast<std::uint32_t>(out.vertices.size());
      out.vertices.push_back(origin + h * Vec3(i, j, k));
    }
    return id;
  };
  for (int k = 0; k < n[2]; ++k) {
    for (int j = 0; j < n[1]; ++j) {
      for (int i = 0; i < n[0]; ++i) {
        if (state[index(i, j, k)] == 2) continue;
        for (int axis = 0; axis < 3; ++axis) {
          for (const int side : {0, 1}) {
            std::array<int, 3> m{i, j, k};
            m[axis] += side ? 1 : -1;
            if (state[index(m[0], m[1], m[2])] != 2) continue;  // the padding is outside
            // The face's corners counter-clockwise seen from outside (along ± axis).
            const int u = (axis + 1) % 3, w = (axis + 2) % 3;
            std::array<std::array<int, 3>, 4> c;
            for (int q = 0; q < 4; ++q) {
              c[q] = {i, j, k};
              c[q][axis] += side;
              c[q][u] += (q == 1 || q == 2);
              c[q][w] += (q >= 2);
            }
            std::array<std::uint32_t, 4> id{};
            for (int q = 0; q < 4; ++q) id[q] = vertex(c[q][0], c[q][1], c[q][2]);
            if (side) {
              out.triangles.push_back({id[0], id[1], id[2]});
              out.triangles.push_back({id[0], id[2], id[3]});
            } else {
              out.triangles.push_back({id[0], id[2], id[1]});
              out.triangles.push_back({id[0], id[3], id[2]});
            }
          }
        }
      }
    }
  }
  return out;
}

void report(benchmark::State& state, const TriangleMesh& wrap) {
  const MeshTopology t = analyze_topology(wrap);
  state.counters["hausdorff_mm"] = 1000 * surface_distance(open_pieces_mug(), wrap).hausdorff();
  state.counters["volume_ratio"] = mass_properties(wrap).volume / kMugVolume;
  state.counters["genus"] = t.consistently_oriented ? t.genus : -1;
  state.counters["vertices"] = static_cast<double>(wrap.vertices.size());
}

void BM_AlphaWrapOpenPiecesMug(benchmark::State& state) {
  WatertightResult result;
  for (auto _ : state) result = make_watertight(open_pieces_mug());
  report(state, result.mesh);
}
BENCHMARK(BM_AlphaWrapOpenPiecesMug)->Unit(benchmark::kMillisecond)->Iterations(1);

// Argument: voxel size in micrometres.
void BM_VoxelWrapOpenPiecesMug(benchmark::State& state) {
  TriangleMesh wrap;
  for (auto _ : state) wrap = voxel_wrap(open_pieces_mug(), 1e-6 * double(state.range(0)));
  report(state, wrap);
}
BENCHMARK(BM_VoxelWrapOpenPiecesMug)->Unit(benchmark::kMillisecond)->Arg(1000)->Arg(500)->Arg(250);

}  // namespace
