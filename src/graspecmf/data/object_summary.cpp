#include "graspecmf/data/object_summary.hpp"

#include <algorithm>

#include "graspecmf/data/dataset.hpp"
#include "graspecmf/geometry/mesh_io.hpp"
#include "graspecmf/geometry/watertight_cache.hpp"

namespace graspecmf::data {
namespace fs = std::filesystem;

ObjectSummary summarize_acronym_object(const fs::path& grasp_file, const fs::path& mesh_root,
                                       bool repair) {
  ObjectSummary summary;
  summary.grasp_file = grasp_file;
  summary.record = read_acronym_file(grasp_file);
  for (const Mat4& transform : summary.record.transforms) {
    summary.max_rigidity_error =
        std::max(summary.max_rigidity_error, lie::rigidity_error(transform));
  }
  summary.mesh_file = find_object_mesh(grasp_file, summary.record.object.file, mesh_root);
  const geometry::TriangleMesh mesh =
      geometry::scaled(geometry::read_mesh(summary.mesh_file), summary.record.object.scale);
  summary.num_vertices = mesh.vertices.size();
  summary.num_triangles = mesh.triangles.size();
  summary.topology = geometry::analyze_topology(mesh);
  summary.bounding_box = geometry::bounding_box(mesh);
  const double density = summary.record.object.density.value_or(1.0);
  if (summary.topology.consistently_oriented) {
    summary.mass_properties = geometry::mass_properties(mesh, density);
  } else if (repair) {
    const geometry::ClosedMesh closed =
        geometry::closed_mesh_for_simulation(mesh, summary.mesh_file.filename().string());
    summary.repair = closed.report;
    summary.mass_properties = geometry::mass_properties(closed.mesh, density);
  }
  return summary;
}

}  // namespace graspecmf::data
