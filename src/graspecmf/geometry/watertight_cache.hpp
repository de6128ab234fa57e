#pragma once
// Disk cache for make_watertight (one checksummed binary file per mesh and resolved options, named
// by a content hash, written atomically), and closed_mesh_for_simulation: the one call that the
// commands needing a closed solid (make-dataset, inspect, simulate) use to get one.

#include <filesystem>
#include <string>

#include "graspecmf/geometry/triangle_mesh.hpp"
#include "graspecmf/geometry/watertight.hpp"

namespace graspecmf::geometry {

// $XDG_CACHE_HOME/graspecmf/watertight, else ~/.cache/graspecmf/watertight (beside the convex
// decompositions' cache).
std::filesystem::path default_watertight_cache();

// The file in cache_dir that holds the wrap of this mesh with these options: named by a 64-bit
// FNV-1a hash of the vertex and triangle bytes, the resolved α and offset, the sample count, the
// backend and the format version. Throws Error as resolve_wrap_lengths does.
std::filesystem::path watertight_cache_file(const TriangleMesh& mesh,
                                            const WatertightOptions& options,
                                            const std::filesystem::path& cache_dir);

// make_watertight, with the wrap read from watertight_cache_file (report.from_cache) or, when
// missing or corrupt, computed and written there atomically (creating cache_dir). Inputs that need
// no wrap are answered without the cache. Throws Error as make_watertight does or if writing fails.
WatertightResult cached_make_watertight(const TriangleMesh& mesh, const WatertightOptions& options,
                                        const std::filesystem::path& cache_dir);

struct ClosedMeshOptions {
  bool repair = true;  // false: refuse a mesh that is not watertight (require_watertight's Error)
  WatertightOptions wrap;           // force is ignored: a closed, outward mesh is never wrapped
  std::filesystem::path cache_dir;  // empty: default_watertight_cache()
};

struct ClosedMesh {
  TriangleMesh mesh;
  WatertightReport report;
  bool repaired = false;  // mesh differs from the input (wrapped, or flipped to face outwards)
};

// The mesh as a closed solid for mass properties and simulation (metric units). A closed,
// consistently oriented, outward mesh is returned unchanged (bit for bit, repaired = false).
// Otherwise, with repair, the input flipped (closed but inward) or its cached alpha wrap; without
// repair, the old check: the input unchanged if require_watertight accepts it, else its Error.
// Errors are prefixed with `what`.
ClosedMesh closed_mesh_for_simulation(const TriangleMesh& mesh, const std::string& what,
                                      const ClosedMeshOptions& options = {});

// What the repair did, for a mesh in metres, e.g. "alpha wrap (alpha 3 mm, offset 0.1 mm; Hausdorff
// distance 2.6 mm; genus 1)" or "every triangle flipped"; empty when the report records no repair.
std::string repair_summary(const WatertightReport& report);
// One line saying what was repaired and how far the result lies from the input, for a mesh in
// metres, e.g. "mug.obj is not watertight (12 boundary, 0 non-manifold, 3 misoriented edges): using
// its alpha wrap (alpha 3 mm, offset 0.1 mm; Hausdorff distance 2.6 mm; genus 1)". Empty when the
// report records no repair.
std::string repair_note(const std::string& what, const WatertightReport& report);

}  // namespace graspecmf::geometry
