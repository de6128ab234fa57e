#include "graspecmf/data/dataset.hpp"

#include <algorithm>
#include <unordered_map>

#include "graspecmf/core/error.hpp"
#include "graspecmf/geometry/mesh_io.hpp"

namespace graspecmf::data {
namespace fs = std::filesystem;

fs::path default_mesh_root(const fs::path& grasp_file) {
  return fs::absolute(grasp_file).parent_path().parent_path();
}

fs::path resolve_mesh_path(const fs::path& mesh_root, const std::string& object_file) {
  return mesh_root / fs::path(object_file);
}

fs::path find_object_mesh(const fs::path& grasp_file, const std::string& object_file,
                          const fs::path& mesh_root) {
  const fs::path root = mesh_root.empty() ? default_mesh_root(grasp_file) : mesh_root;
  const fs::path mesh = resolve_mesh_path(root, object_file);
  std::error_code ec;
  if (!fs::is_regular_file(mesh, ec)) {
    throw Error(grasp_file.string() + ": its mesh " + mesh.string() +
                " does not exist (set the mesh root with --mesh-root)");
  }
  return mesh;
}

AcronymDataset AcronymDataset::open(const fs::path& root, const DatasetOptions& options) {
  const fs::path grasp_folder = root / "grasps";
  std::error_code ec;
  if (!fs::is_directory(grasp_folder, ec)) {
    throw Error(root.string() + ": not an ACRONYM dataset folder (no grasps/ folder)");
  }
  std::vector<fs::path> files;
  for (const auto& item : fs::directory_iterator(grasp_folder)) {
    if (item.is_regular_file() && item.path().extension() == ".h5") files.push_back(item.path());
  }
  std::sort(files.begin(), files.end());
  const fs::path mesh_root = options.mesh_root.empty() ? root : options.mesh_root;

  AcronymDataset dataset;
  read_acronym_files(
      files,
      [&](std::size_t i, AcronymGraspFile&& record) {
        const std::string name = files[i].stem().string();
        fs::path mesh;
        try {
          mesh = resolve_mesh_path(mesh_root, record.object.file);
        } catch (const Error& e) {
          dataset.skipped_.push_back({name, e.what()});
          return;
        }
        ObjectEntry entry{
            name, files[i], mesh, record.object.scale, record.size(), record.num_successful()};
        if (entry.num_successful < options.min_successful) {
          dataset.skipped_.push_back({name, std::to_string(entry.num_successful) +
                                                " successful grasps (fewer than " +
                                                std::to_string(options.min_successful) + ")"});
        } else if (!fs::is_regular_file(entry.mesh_file, ec)) {
          dataset.skipped_.push_back({name, "mesh not found: " + entry.mesh_file.string()});
        } else {
          dataset.objects_.push_back(std::move(entry));
        }
      },
      [&](std::size_t i, const std::string& error) {
        dataset.skipped_.push_back({files[i].stem().string(), error});
      });
  if (dataset.objects_.empty()) {
    throw Error(root.string() + ": no usable object among " + std::to_string(files.size()) +
                " grasp files" +
                (dataset.skipped_.empty() ? ""
                                          : " (first skipped: " + dataset.skipped_[0].name + ": " +
                                                dataset.skipped_[0].reason + ")"));
  }
  return dataset;
}

std::vector<std::string> AcronymDataset::names() const {
  std::vector<std::string> result;
  result.reserve(objects_.size());
  for (const ObjectEntry& entry : objects_) result.push_back(entry.name);
  return result;
}

std::vector<ObjectEntry> AcronymDataset::select(const std::vector<std::string>& names) const {
  std::unordered_map<std::string, const ObjectEntry*> by_name;
  for (const ObjectEntry& entry : objects_) by_name[entry.name] = &entry;
  std::vector<ObjectEntry> selected;
  selected.reserve(names.size());
  for (const std::string& name : names) {
    const auto it = by_name.find(name);
    if (it == by_name.end()) {
      throw Error("object '" + name + "' is not a usable object of this dataset");
    }
    selected.push_back(*it->second);
  }
  return selected;
}

std::vector<GraspObject> AcronymDataset::load(const std::vector<ObjectEntry>& entries) {
  std::vector<fs::path> files;
  for (const ObjectEntry& entry : entries) files.push_back(entry.grasp_file);
  std::vector<GraspObject> objects;
  read_acronym_files(
      files,
      [&](std::size_t i, AcronymGraspFile&& record) {
        const ObjectEntry& entry = entries[i];
        require_panda_gripper(record, entry.grasp_file);
        objects.push_back(
            {entry.name,
             geometry::scaled(geometry::read_mesh(entry.mesh_file), record.object.scale),
             record.successful_grasps(), record.object});
      },
      [](std::size_t, const std::string& error) { throw Error(error); });
  return objects;
}

}  // namespace graspecmf::data
