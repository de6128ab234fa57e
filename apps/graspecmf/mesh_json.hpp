#pragma once
// The JSON of a mesh's size and topology that inspect and prepare-mesh both print.

#include <cstddef>
#include <nlohmann/json.hpp>

#include "graspecmf/geometry/mesh_topology.hpp"

namespace graspecmf::apps {

// Counts, watertightness, orientation, edge defects and genus (null unless consistently oriented).
inline nlohmann::json mesh_topology_json(std::size_t vertices, std::size_t triangles,
                                         const geometry::MeshTopology& t) {
  return {{"vertices", vertices},
          {"triangles", triangles},
          {"components", t.num_components},
          {"watertight", t.watertight},
          {"consistently_oriented", t.consistently_oriented},
          {"boundary_edges", t.num_boundary_edges},
          {"nonmanifold_edges", t.num_nonmanifold_edges},
          {"misoriented_edges", t.num_misoriented_edges},
          {"genus", t.consistently_oriented ? nlohmann::json(t.genus) : nlohmann::json(nullptr)}};
}

}  // namespace graspecmf::apps
