#pragma once
// The convex narrow phase for mesh and box geoms, as MuJoCo 2.2.2 runs it (libccd's MPR, then with
// multiccd four more MPR runs with both geoms tilted by ±1 mrad about the contact's tangents),
// but faster: MuJoCo's mesh support function climbs the hull graph from vertex 0 on every call,
// which took ~20 % of a grasp trial; here each geom's climb starts where its previous one ended.
// It acts through CollisionHooks (sim/collision_hooks.hpp).

#include <vector>

struct mjModel_;
struct mjData_;
struct mjContact_;

namespace graspecmf::sim {

class ConvexNarrowPhase {
 public:
  // Prepares every mesh geom that has a convex-hull graph, and every box geom.
  explicit ConvexNarrowPhase(const mjModel_* model);
  ~ConvexNarrowPhase();

  // True if both geoms were prepared and one is a mesh, so collide() can take the pair (box–box
  // pairs keep MuJoCo's box collider).
  bool handles(const mjModel_* model, int g1, int g2) const;

  // Writes up to 5 contacts of pair (g1, g2) (normal from g1 to g2, MuJoCo's conventions) and
  // returns their number; multi-contact search when the model enables multiccd.
  int collide(const mjModel_* model, const mjData_* data, mjContact_* contacts, int g1, int g2,
              double margin);

  // Forgets where the climbs ended, so a trial's contacts do not depend on earlier trials.
  void reset();

  struct Shape;  // a prepared hull or box, in its geom frame (defined in the .cpp)

 private:
  const mjModel_* model_;
  std::vector<int> shape_of_geom_;  // −1: not prepared
  std::vector<Shape> shapes_;
  std::vector<int> warm_start_;  // per geom: the vertex its last climb ended on
};

}  // namespace graspecmf::sim
