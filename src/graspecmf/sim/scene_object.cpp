#include "graspecmf/sim/scene_object.hpp"

#include <cstdlib>

#include "graspecmf/core/error.hpp"
#include "graspecmf/geometry/mass_properties.hpp"

namespace graspecmf::sim {
namespace fs = std::filesystem;

SceneObject make_scene_object(const geometry::TriangleMesh& metric_mesh,
                              const data::AcronymObjectInfo& info, const TrialConfig& config,
                              const geometry::DecompositionOptions& decomposition,
                              const fs::path& cache_dir) {
  SceneObject object;
  object.parts = geometry::cached_convex_decomposition(metric_mesh, decomposition, cache_dir);
  if (info.mass && info.com && info.inertia) {
    object.mass = *info.mass;
    object.center_of_mass = *info.com;
    object.inertia = data::standard_inertia(*info.inertia);
  } else {
    const geometry::MassProperties mp =
        geometry::mass_properties(metric_mesh, info.density.value_or(config.default_density));
    if (!(mp.volume > 0)) throw Error("the object mesh encloses no positive volume");
    object.mass = mp.mass;
    object.center_of_mass = mp.center_of_mass;
    object.inertia = mp.inertia;
  }
  return object;
}

fs::path default_decomposition_cache() {
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg != nullptr && *xdg != '\0') {
    return fs::path(xdg) / "graspecmf" / "decompositions";
  }
  if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0') {
    return fs::path(home) / ".cache" / "graspecmf" / "decompositions";
  }
  return fs::temp_directory_path() / "graspecmf" / "decompositions";
}

}  // namespace graspecmf::sim
