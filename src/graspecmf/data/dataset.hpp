#pragma once
// An ACRONYM-style dataset folder: grasps/*.h5 (one file per object) plus a mesh root holding the
// meshes the files name. Scanning is cheap (labels only); meshes are loaded per object on demand.

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "graspecmf/data/acronym_file.hpp"
#include "graspecmf/geometry/triangle_mesh.hpp"

namespace graspecmf::data {

struct DatasetOptions {
  std::filesystem::path mesh_root;   // empty: the dataset root itself
  std::size_t min_successful = 100;  // objects with fewer successful grasps are skipped
};

struct ObjectEntry {
  std::string name;  // the grasp file's stem
  std::filesystem::path grasp_file;
  std::filesystem::path mesh_file;
  double scale = 1.0;
  std::size_t num_grasps = 0;
  std::size_t num_successful = 0;
};

struct SkippedObject {
  std::string name;
  std::string reason;
};

// An object ready for training or evaluation: metric mesh and its successful grasps.
struct GraspObject {
  std::string name;
  geometry::TriangleMesh mesh;    // raw mesh × scale, in the grasp file's frame
  std::vector<lie::Pose> grasps;  // successful grasps only
  AcronymObjectInfo info;         // the grasp file's object record (mesh, scale, mass properties)
};

// Where the ACRONYM layout puts the mesh root for a grasp file: the folder above grasps/.
std::filesystem::path default_mesh_root(const std::filesystem::path& grasp_file);
// The mesh file an ACRONYM record names, resolved against a mesh root.
std::filesystem::path resolve_mesh_path(const std::filesystem::path& mesh_root,
                                        const std::string& object_file);

// The existing mesh file of a grasp file's object: resolve_mesh_path against mesh_root, or against
// default_mesh_root(grasp_file) when mesh_root is empty. Throws Error if that file does not exist.
std::filesystem::path find_object_mesh(const std::filesystem::path& grasp_file,
                                       const std::string& object_file,
                                       const std::filesystem::path& mesh_root);

class AcronymDataset {
 public:
  // Scans root/grasps/*.h5 in name order. Unreadable files, missing meshes and objects with fewer
  // than min_successful successful grasps are skipped with a reason. Throws Error if root/grasps
  // does not exist or no object is usable.
  static AcronymDataset open(const std::filesystem::path& root, const DatasetOptions& options = {});

  const std::vector<ObjectEntry>& objects() const { return objects_; }
  const std::vector<SkippedObject>& skipped() const { return skipped_; }
  // The names of all usable objects, in scan order.
  std::vector<std::string> names() const;
  // The entries with these names, in this order; throws Error for a name that is not usable.
  std::vector<ObjectEntry> select(const std::vector<std::string>& names) const;
  // Reads the objects' meshes (scaled to metres) and successful grasps, in order; throws Error for
  // the first that cannot be read.
  static std::vector<GraspObject> load(const std::vector<ObjectEntry>& entries);

 private:
  std::vector<ObjectEntry> objects_;
  std::vector<SkippedObject> skipped_;
};

}  // namespace graspecmf::data
