#include "graspecmf/data/object_summary.hpp"

#include <algorithm>

#include "graspecmf/core/error.hpp"
#include "graspecmf/data/dataset.hpp"
#include "graspecmf/geometry/mesh_io.hpp"

namespace graspecmf::data {
namespace fs = std::filesystem;

ObjectSummary summarize_acronym_object(const fs::path& grasp_file, const fs::path& mesh_root) {
  ObjectSummary summary;
  summary.grasp_file = grasp_file;
  summary.record = read_acronym_file(grasp_file);
  for (const Mat4& transform : summary.record.transforms) {
    summary.max_rigidity_error =
        std::max(summary.max_rigidity_error, lie::rigidity_error(transform));
  }
  const fs::path root = mesh_root.empty() ? default_mesh_root(grasp_file) : mesh_root;
  summary.mesh_file = resolve_mesh_path(root, summary.record.object.file);
  std::error_code ec;
  if (!fs::is_regular_file(summary.mesh_file, ec)) {
    throw Error(grasp_file.string() + ": its mesh " + summary.mesh_file.string() +
                " does not exist (set the mesh root with --mesh-root)");
  }
  const geometry::TriangleMesh mesh =
      geometry::scaled(geometry::read_mesh(summary.mesh_file), summary.record.object.scale);
  summary.num_vertices = mesh.vertices.size();
  summary.num_triangles = mesh.triangles.size();
  summary.topology = geometry::analyze_topology(mesh);
  summary.bounding_box = geometry::bounding_box(mesh);
  if (summary.topology.consistently_oriented) {
    summary.mass_properties =
        geometry::mass_properties(mesh, summary.record.object.density.value_or(1.0));
  }
  return summary;
}

}  // namespace graspecmf::data
