#pragma once
// A checked summary of one ACRONYM object: the grasp file's contents beside quantities recomputed
// from its mesh (bounding box, topology, volume, centre of mass), for `graspecmf inspect`.

#include <filesystem>
#include <optional>

#include "graspecmf/data/acronym_file.hpp"
#include "graspecmf/geometry/mass_properties.hpp"
#include "graspecmf/geometry/mesh_topology.hpp"
#include "graspecmf/geometry/watertight.hpp"

namespace graspecmf::data {

struct ObjectSummary {
  std::filesystem::path grasp_file;
  std::filesystem::path mesh_file;
  AcronymGraspFile record;
  double max_rigidity_error = 0.0;  // worst transform's deviation from a proper rigid transform
  std::size_t num_vertices = 0, num_triangles = 0;
  geometry::MeshTopology topology;
  geometry::BoundingBox bounding_box;  // metric mesh
  // Recomputed with the file's density (1 if absent) for a closed, consistently oriented mesh,
  // or, with repair, for the closed mesh repair made.
  std::optional<geometry::MassProperties> mass_properties;
  // Set when the mesh was not consistently oriented and repair replaced it for the mass
  // properties (geometry::closed_mesh_for_simulation: its alpha wrap).
  std::optional<geometry::WatertightReport> repair;
};

// Reads the grasp file and the mesh it names (resolved against mesh_root; empty: the ACRONYM
// default) and summarises both. With repair, a mesh that is not closed and consistently oriented
// gets its mass properties from its alpha wrap (cached in geometry::default_watertight_cache()).
// Throws Error for unreadable files or a broken mesh.
ObjectSummary summarize_acronym_object(const std::filesystem::path& grasp_file,
                                       const std::filesystem::path& mesh_root = {},
                                       bool repair = false);

}  // namespace graspecmf::data
