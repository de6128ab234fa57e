#pragma once
// The simulated ACRONYM sample mug of the sim tests: its scene object, every stride-th grasp and
// ACRONYM's labels for them, optionally with the mug and its grasps moved rigidly.

#include <vector>

#include "graspecmf/data/acronym_file.hpp"
#include "graspecmf/geometry/mesh_io.hpp"
#include "graspecmf/sim/scene_object.hpp"
#include "test_support.hpp"

namespace graspecmf::sim::testing {

struct SampleMug {
  SceneObject object;
  std::vector<lie::Pose> grasps;
  std::vector<std::int64_t> labels;  // ACRONYM's object_in_gripper
};

inline SampleMug sample_mug(std::size_t stride, const TrialConfig& config = {},
                            const lie::Pose& motion = {}) {
  const data::AcronymGraspFile record =
      data::moved_rigidly(data::read_acronym_file(graspecmf::testing::sample_grasp_file()), motion);
  const geometry::TriangleMesh mesh = geometry::transformed(
      geometry::scaled(geometry::read_mesh(graspecmf::testing::sample_mesh_file()),
                       record.object.scale),
      motion);
  const graspecmf::testing::ScratchDir cache;
  SampleMug mug;
  mug.object = make_scene_object(mesh, record.object, config, geometry::DecompositionOptions{},
                                 cache.path());
  for (std::size_t i = 0; i < record.size(); i += stride) {
    mug.grasps.push_back(lie::Pose::from_matrix(record.transforms[i]));
    mug.labels.push_back(record.qualities->object_in_gripper[i]);
  }
  return mug;
}

}  // namespace graspecmf::sim::testing
