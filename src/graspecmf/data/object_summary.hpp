#pragma once
// A checked summary of one ACRONYM object: the grasp file's contents beside quantities recomputed
// from its mesh (bounding box, topology, volume, centre of mass), for `graspecmf inspect`.

#include <filesystem>
#include <optional>

#include "graspecmf/data/acronym_file.hpp"
#include "graspecmf/geometry/mass_properties.hpp"
#include "graspecmf/geometry/mesh_topology.hpp"

namespace graspecmf::data {

struct ObjectSummary {
  std::filesystem::path grasp_file;
  std::filesystem::path mesh_file;
  AcronymGraspFile record;
  double max_rigidity_error = 0.0;  // worst transform's deviation from a proper rigid transform
  std::size_t num_vertices = 0, num_triangles = 0;
  geometry::MeshTopology topology;
  geometry::BoundingBox bounding_box;  // metric mesh
  // Recomputed with the file's density (1 if absent); only for a closed, consistently oriented
  // mesh.
  std::optional<geometry::MassProperties> mass_properties;
};

// Reads the grasp file and the mesh it names (resolved against mesh_root; empty: the ACRONYM
// default) and summarises both. Throws Error for unreadable files or a broken mesh.
ObjectSummary summarize_acronym_object(const std::filesystem::path& grasp_file,
                                       const std::filesystem::path& mesh_root = {});

}  // namespace graspecmf::data
