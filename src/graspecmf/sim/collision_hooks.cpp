#include "graspecmf/sim/collision_hooks.hpp"

#include <mujoco/mujoco.h>

#include <mutex>

#include "graspecmf/sim/collision_prefilter.hpp"
#include "graspecmf/sim/convex_narrow_phase.hpp"
#include "graspecmf/sim/pad_contact_normals.hpp"

namespace graspecmf::sim {
namespace {

thread_local const mjModel* active_model = nullptr;
thread_local CollisionHooks active_hooks;
mjfCollision narrow_phase[mjNGEOMTYPES][mjNGEOMTYPES] = {};

// MuJoCo's narrow phase for the pair, through this thread's hooks when they are for this model.
int hooked_collision(const mjModel* m, const mjData* d, mjContact* con, int g1, int g2,
                     mjtNum margin) {
  const bool hooked = m == active_model;
  if (hooked && active_hooks.prefilter != nullptr && active_hooks.prefilter->apart(m, d, g1, g2)) {
    return 0;
  }
  const int count =
      hooked && active_hooks.convex != nullptr && active_hooks.convex->handles(m, g1, g2)
          ? active_hooks.convex->collide(m, d, con, g1, g2, margin)
          : narrow_phase[m->geom_type[g1]][m->geom_type[g2]](m, d, con, g1, g2, margin);
  if (hooked && active_hooks.pad_normals != nullptr) {
    active_hooks.pad_normals->correct(m, d, con, count, g1, g2);
  }
  return count;
}

// Routes every pair type through hooked_collision, once per process.
void install_wrapper() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (int a = 0; a < mjNGEOMTYPES; ++a) {
      for (int b = 0; b < mjNGEOMTYPES; ++b) {
        narrow_phase[a][b] = mjCOLLISIONFUNC[a][b];
        if (mjCOLLISIONFUNC[a][b] != nullptr) mjCOLLISIONFUNC[a][b] = hooked_collision;
      }
    }
  });
}

}  // namespace

CollisionHooksScope::CollisionHooksScope(const mjModel* model, const CollisionHooks& hooks)
    : previous_model_(active_model), previous_hooks_(active_hooks) {
  install_wrapper();
  active_model = model;
  active_hooks = hooks;
}

CollisionHooksScope::~CollisionHooksScope() {
  active_model = previous_model_;
  active_hooks = previous_hooks_;
}

}  // namespace graspecmf::sim
