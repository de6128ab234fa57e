#pragma once
// Skips MuJoCo's convex narrow phase for geom pairs whose oriented bounding boxes are apart. In a
// grasp trial the palm and fingers overlap the bounding spheres of most of the object's parts, so
// MuJoCo 2.2.2 runs MPR on ~60 pairs per step of which ~3 touch; those misses took ~70 % of a
// trial. A skipped pair is one MPR would also have left without contacts, so results do not
// change. It acts through CollisionHooks (sim/collision_hooks.hpp).

#include <Eigen/Core>
#include <vector>

struct mjModel_;
struct mjData_;

namespace graspecmf::sim {

class CollisionPrefilter {
 public:
  // Box and mesh geoms get a local box (centre and half extents in the geom frame); other geoms
  // are never skipped.
  explicit CollisionPrefilter(const mjModel_* model);

  // True if the boxes of geoms g1 and g2 are separated by more than the contact margin plus a
  // safety gap, at the poses in data.
  bool apart(const mjModel_* model, const mjData_* data, int g1, int g2) const;

 private:
  const mjModel_* model_;
  std::vector<bool> boxed_;
  std::vector<Eigen::Vector3d> center_, half_;
};

}  // namespace graspecmf::sim
