#include "graspecmf/sim/collision_prefilter.hpp"

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <memory>

#include "graspecmf/core/random.hpp"
#include "graspecmf/lie/rotation_sets.hpp"
#include "load_model.hpp"

namespace graspecmf::sim {
namespace {

// A free box and a free tetrahedral mesh, no gravity: only their relative pose matters.
constexpr const char* kScene = R"(<mujoco>
  <option gravity="0 0 0"/>
  <asset><mesh name="tet" vertex="0 0 0  0.04 0 0  0 0.03 0  0 0 0.05"/></asset>
  <worldbody>
    <body name="a"><freejoint/><geom type="box" size="0.02 0.01 0.03"/></body>
    <body name="b"><freejoint/><geom type="mesh" mesh="tet"/></body>
  </worldbody>
</mujoco>)";

// A pair the filter calls apart never has a contact, and close pairs are not skipped.
TEST(CollisionPrefilter, SkipsOnlyPairsWithoutContacts) {
  std::unique_ptr<mjModel, void (*)(mjModel*)> model(testing::load_model(kScene), mj_deleteModel);
  ASSERT_NE(model, nullptr);
  std::unique_ptr<mjData, void (*)(mjData*)> data(mj_makeData(model.get()), mj_deleteData);
  const CollisionPrefilter filter(model.get());
  Rng rng(5);
  int skipped = 0, touching = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    for (int body = 0; body < 2; ++body) {
      double* q = data->qpos + 7 * body;
      for (int k = 0; k < 3; ++k) q[k] = body == 0 ? 0.0 : rng.uniform(-0.08, 0.08);
      const Eigen::Quaterniond r(lie::random_rotation(rng));
      q[3] = r.w();
      q[4] = r.x();
      q[5] = r.y();
      q[6] = r.z();
    }
    mj_forward(model.get(), data.get());  // without a Scope: MuJoCo's own narrow phase
    const bool apart = filter.apart(model.get(), data.get(), 0, 1);
    skipped += apart;
    touching += data->ncon > 0;
    if (apart) {
      ASSERT_EQ(data->ncon, 0) << "trial " << trial;
    }
    // Overlapping centres are never apart.
    if ((Eigen::Map<const Eigen::Vector3d>(data->qpos + 7)).norm() < 0.005) {
      ASSERT_FALSE(apart);
    }
  }
  EXPECT_GT(skipped, 1500);  // most random placements are far apart
  EXPECT_GT(touching, 100);
}

}  // namespace
}  // namespace graspecmf::sim
