#pragma once
// Building an ACRONYM-style dataset folder: for each object (a procedural mug or a user mesh),
// antipodal grasp candidates labelled by the MuJoCo shake test, written as
//   OUT/grasps/<Category>_<name>_<scale>.h5   (the ACRONYM layout, written last, atomically)
//   OUT/meshes/<Category>/<name>.obj          (the mesh the record names)
//   OUT/splits.json, OUT/manifest.json, OUT/preview.png, OUT/log.jsonl (timings)
// Resumable: objects whose grasp file exists are not redone, and every file except log.jsonl is
// byte-identical to an uninterrupted run's.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "graspecmf/dataset/antipodal_candidates.hpp"
#include "graspecmf/geometry/convex_decomposition.hpp"
#include "graspecmf/geometry/procedural_mug.hpp"
#include "graspecmf/geometry/watertight.hpp"
#include "graspecmf/sim/trial_config.hpp"

namespace graspecmf::dataset {

// One object to generate: a procedural mug, or a mesh file (metric = file × scale).
struct ObjectSource {
  std::string name;      // unique within the dataset, [A-Za-z0-9-] only
  std::string category;  // "Mug" or "Object"
  std::optional<geometry::MugParameters> mug;
  std::filesystem::path mesh_file;
  double scale = 1.0;
};

// count procedural mugs of the family, named mug-<seed>-<index>, with parameters drawn from the
// seed.
std::vector<ObjectSource> procedural_mug_sources(std::size_t count, std::uint64_t seed,
                                                 geometry::MugFamily family);
// Every .obj/.stl/.ply/.glb/.gltf file directly in dir (sorted by name), named after the file's
// stem with other characters replaced by '-'. Throws Error if dir is missing or holds no mesh file
// or two files map to the same name.
std::vector<ObjectSource> mesh_folder_sources(const std::filesystem::path& dir, double scale);

// The per-object timing log's name in the output folder (one JSON object per line).
inline constexpr const char* kTimingLogName = "log.jsonl";

struct MakeDatasetOptions {
  std::filesystem::path out;
  std::vector<ObjectSource> objects;
  std::string preset;         // recorded in the manifest when set
  std::uint64_t seed = 0;     // candidate sampling and the split
  double density = 150.0;     // kg/m³ (ACRONYM uses 150 for every object)
  std::size_t val_count = 0;  // objects in the validation and test splits; the rest train
  std::size_t test_count = 0;
  AntipodalOptions candidates;
  sim::TrialConfig trial;
  geometry::DecompositionOptions decomposition;
  std::filesystem::path cache;  // decomposition cache; empty = sim::default_decomposition_cache()
  // A mesh that is not a closed, outward solid is alpha-wrapped (flipped if only inward) by
  // geometry::closed_mesh_for_simulation and the wrap is stored and labelled; false skips it.
  bool repair = true;
  geometry::WatertightOptions wrap;  // the wrap's α and offset (defaults: 3 mm, α / 30)
  std::filesystem::path wrap_cache;  // empty = geometry::default_watertight_cache()
  int threads = 1;
};

struct ObjectOutcome {
  std::string name;
  std::string grasp_file;  // relative to out; empty when skipped
  std::string skipped;     // the reason, empty when the object was made
  std::string repaired;    // geometry::repair_note when its mesh was wrapped or flipped
  bool resumed = false;    // its grasp file was already there
  std::size_t candidates = 0, successful = 0;
  std::size_t unstable = 0;  // trials that went unstable (0 when resumed: files do not record it)
  double seconds = 0.0;
};

struct DatasetProgress {
  // Trials finished and the planned total, over the objects this run makes (objects already
  // there do not count), the total being those objects × the candidates requested.
  std::function<void(std::size_t done, std::size_t total)> trials;
  // Called after each object is made, resumed or skipped.
  std::function<void(const ObjectOutcome&)> object;
};

// Makes (or resumes) the dataset; returns one outcome per object. Throws Error at once if out
// cannot be written, if it holds a dataset made with other options, or if the options are invalid;
// an object whose mesh is unreadable (or, without repair, not watertight) is skipped with its
// reason. A repaired object's meshes/ file holds the wrap (in the object's units).
std::vector<ObjectOutcome> make_dataset(const MakeDatasetOptions& options,
                                        const DatasetProgress& progress = {});

}  // namespace graspecmf::dataset
