#pragma once
// The simulated object for an ACRONYM record: convex parts of its metric mesh (cached on disk) and
// its mass properties.

#include <filesystem>

#include "graspecmf/data/acronym_file.hpp"
#include "graspecmf/geometry/decomposition_cache.hpp"
#include "graspecmf/sim/grasp_scene.hpp"

namespace graspecmf::sim {

// Mass, centre of mass and inertia come from the record where it stores them (ACRONYM's inertia
// sign corrected), else from the closed mesh at the record's density or config.default_density.
// Parts come from cached_convex_decomposition under cache_dir, of the mesh in its principal frame
// (in its own frame with config.legacy_object_frame). Throws Error for an open mesh.
SceneObject make_scene_object(const geometry::TriangleMesh& metric_mesh,
                              const data::AcronymObjectInfo& info, const TrialConfig& config,
                              const geometry::DecompositionOptions& decomposition,
                              const std::filesystem::path& cache_dir);

// The default decomposition cache: $XDG_CACHE_HOME/graspecmf/decompositions, else
// ~/.cache/graspecmf/decompositions, else a folder in the system temporary directory.
std::filesystem::path default_decomposition_cache();

}  // namespace graspecmf::sim
