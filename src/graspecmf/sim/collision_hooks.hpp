#pragma once
// Routes MuJoCo's narrow-phase collision functions (a process-wide table) through per-thread
// hooks, so that one trial can skip geom pairs, collide convex pairs its own way and correct the
// contacts found without touching other models or threads.

struct mjModel_;

namespace graspecmf::sim {

class CollisionPrefilter;
class ConvexNarrowPhase;
class PadContactNormals;

// What a thread's narrow phase consults; any pointer may be null.
struct CollisionHooks {
  const CollisionPrefilter* prefilter = nullptr;   // skips pairs that cannot touch
  ConvexNarrowPhase* convex = nullptr;             // replaces MuJoCo's for the pairs it handles
  const PadContactNormals* pad_normals = nullptr;  // corrects finger-pad contact normals
};

// While a scope lives, this thread's narrow-phase calls in `model` go through `hooks`; calls for
// other models, and calls without a scope, run MuJoCo's own functions unchanged.
class CollisionHooksScope {
 public:
  CollisionHooksScope(const mjModel_* model, const CollisionHooks& hooks);
  ~CollisionHooksScope();
  CollisionHooksScope(const CollisionHooksScope&) = delete;
  CollisionHooksScope& operator=(const CollisionHooksScope&) = delete;

 private:
  const mjModel_* previous_model_;
  CollisionHooks previous_hooks_;
};

}  // namespace graspecmf::sim
