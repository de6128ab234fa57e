#pragma once
// A tiny ACRONYM-style dataset for training tests: three boxes with 120 "successful" random grasps
// each (the loader keeps objects with ≥ 100), split 2 train / 1 val in splits.json.

#include <fstream>
#include <nlohmann/json.hpp>

#include "../geometry/test_meshes.hpp"
#include "graspecmf/data/acronym_file.hpp"
#include "graspecmf/geometry/mesh_io.hpp"
#include "graspecmf/lie/rotation_sets.hpp"
#include "test_support.hpp"

namespace graspecmf::testing {

// The dataset folder dir/data.
inline std::filesystem::path tiny_dataset(const ScratchDir& dir) {
  const std::filesystem::path root = dir / "data";
  std::filesystem::create_directories(root / "grasps");
  std::filesystem::create_directories(root / "meshes/Box");
  Rng rng(3);
  nlohmann::json split = {{"train", nlohmann::json::array()},
                          {"val", nlohmann::json::array()},
                          {"test", nlohmann::json::array()}};
  for (int i = 0; i < 3; ++i) {
    const double size = 0.04 + 0.01 * i;
    geometry::write_mesh(
        geometry::testing::make_box(Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(size)),
        root / ("meshes/Box/b" + std::to_string(i) + ".obj"));
    data::AcronymGraspFile record;
    record.object.file = "meshes/Box/b" + std::to_string(i) + ".obj";
    data::GraspQualities q;
    for (int g = 0; g < 120; ++g) {
      lie::Pose pose;
      pose.R = lie::random_rotation(rng);
      pose.p = Eigen::Vector3d(rng.uniform(), rng.uniform(), rng.uniform()) * size;
      record.transforms.push_back(pose.matrix());
      q.object_in_gripper.push_back(1);
    }
    q.motion_closing_linear = q.motion_closing_angular = q.motion_shaking_linear =
        q.motion_shaking_angular = std::vector<double>(120, 0.0);
    record.qualities = q;
    const std::string name = "Box_b" + std::to_string(i) + "_1";
    data::write_acronym_file(record, root / "grasps" / (name + ".h5"));
    split[i < 2 ? "train" : "val"].push_back(name);
  }
  std::ofstream(root / "splits.json") << split.dump();
  return root;
}

}  // namespace graspecmf::testing
