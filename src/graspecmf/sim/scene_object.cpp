#include "graspecmf/sim/scene_object.hpp"

#include "graspecmf/core/error.hpp"
#include "graspecmf/core/user_cache.hpp"
#include "graspecmf/geometry/mass_properties.hpp"

namespace graspecmf::sim {
namespace fs = std::filesystem;

SceneObject make_scene_object(const geometry::TriangleMesh& metric_mesh,
                              const data::AcronymObjectInfo& info, const TrialConfig& config,
                              const geometry::DecompositionOptions& decomposition,
                              const fs::path& cache_dir) {
  SceneObject object;
  if (config.legacy_object_frame) {
    object.parts = geometry::cached_convex_decomposition(metric_mesh, decomposition, cache_dir);
  } else {
    // Cut in a frame fixed to the solid, so that the parts move with the object. The lattice cuts
    // are sensitive to round-off, so the mesh is quantised first.
    const lie::Pose frame = geometry::principal_frame(metric_mesh);
    object.parts = geometry::cached_convex_decomposition(
        geometry::quantized(geometry::transformed(metric_mesh, lie::inverse(frame)), kRoundOffGrid),
        decomposition, cache_dir);
    for (geometry::TriangleMesh& part : object.parts) part = geometry::transformed(part, frame);
  }
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
  return user_cache_dir("decompositions");
}

}  // namespace graspecmf::sim
