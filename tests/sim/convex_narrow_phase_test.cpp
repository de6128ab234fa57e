#include "graspecmf/sim/convex_narrow_phase.hpp"

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <memory>
#include <string>

#include "graspecmf/core/random.hpp"
#include "graspecmf/lie/rotation_sets.hpp"
#include "load_model.hpp"

namespace graspecmf::sim {
namespace {

using Vec3 = Eigen::Vector3d;

// Three free bodies, no gravity: a box and two hulls of random points (MuJoCo builds each hull's
// vertex graph). Geoms 0, 1, 2.
std::string scene(bool multiccd, Rng& rng) {
  std::string meshes;
  for (int m = 0; m < 2; ++m) {
    std::string vertices;
    for (int k = 0; k < 40; ++k) {
      vertices += std::to_string(rng.uniform(-0.03, 0.03)) + " " +
                  std::to_string(rng.uniform(-0.02, 0.02)) + " " +
                  std::to_string(rng.uniform(-0.025, 0.025)) + "  ";
    }
    meshes += "<mesh name=\"hull" + std::to_string(m) + "\" vertex=\"" + vertices + "\"/>";
  }
  return std::string(R"(<mujoco><option gravity="0 0 0"><flag multiccd=")") +
         (multiccd ? "enable" : "disable") + R"("/></option><asset>)" + meshes + R"(</asset>
  <worldbody>
    <body><freejoint/><geom type="box" size="0.02 0.01 0.03"/></body>
    <body><freejoint/><geom type="mesh" mesh="hull0"/></body>
    <body><freejoint/><geom type="mesh" mesh="hull1"/></body>
  </worldbody></mujoco>)";
}

struct Fixture {
  std::unique_ptr<mjModel, void (*)(mjModel*)> model{nullptr, mj_deleteModel};
  std::unique_ptr<mjData, void (*)(mjData*)> data{nullptr, mj_deleteData};

  explicit Fixture(bool multiccd) {
    Rng rng(11);
    model.reset(testing::load_model(scene(multiccd, rng)));
    if (model) data.reset(mj_makeData(model.get()));
  }

  // Random orientations; g1's body at the origin, g2's body along a random direction just far
  // enough in that the pair overlaps by `depth` (found by bisection with MuJoCo's collider), and
  // the third body far away. Grasp contacts are shallow, and MPR's answer for deep overlaps
  // shifts with round-off.
  void place(Rng& rng, int g1, int g2, double depth) {
    const Vec3 away = Vec3(rng.normal(), rng.normal(), rng.normal()).normalized();
    for (int body = 0; body < 3; ++body) {
      double* q = data->qpos + 7 * body;
      const Eigen::Quaterniond r(lie::random_rotation(rng));
      Eigen::Map<Vec3>{q} = body == g1 ? Vec3::Zero() : Vec3(0.5 * (body + 1), 0, 0);
      q[3] = r.w();
      q[4] = r.x();
      q[5] = r.y();
      q[6] = r.z();
    }
    mjContact scratch[mjMAXCONPAIR];
    double inside = 0.0, outside = 0.2;
    for (int i = 0; i < 40; ++i) {
      const double s = 0.5 * (inside + outside);
      Eigen::Map<Vec3>(data->qpos + 7 * g2) = s * away;
      mj_kinematics(model.get(), data.get());
      (mujoco(scratch, g1, g2, 0.0) > 0 ? inside : outside) = s;
    }
    Eigen::Map<Vec3>(data->qpos + 7 * g2) = (inside - depth) * away;
    mj_kinematics(model.get(), data.get());
  }

  // MuJoCo's own narrow phase for the pair.
  int mujoco(mjContact* contacts, int g1, int g2, double margin) const {
    const int t1 = model->geom_type[g1], t2 = model->geom_type[g2];
    return mjCOLLISIONFUNC[t1][t2](model.get(), data.get(), contacts, g1, g2, margin);
  }
};

constexpr int kPairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};

// Without multiccd, every contact equals MuJoCo's: the same MPR on the same support points,
// whatever vertex each climb starts from.
TEST(ConvexNarrowPhase, MatchesMujocoSingleContact) {
  Fixture f(false);
  ASSERT_NE(f.model, nullptr);
  ConvexNarrowPhase narrow(f.model.get());
  Rng rng(3);
  int touching = 0;
  for (int trial = 0; trial < 300; ++trial) {
    for (const auto& pair : kPairs) {
      f.place(rng, pair[0], pair[1], rng.uniform(0.0, 0.002));
      const double margin = trial % 2 == 0 ? 0.0 : 0.002;
      ASSERT_TRUE(narrow.handles(f.model.get(), pair[0], pair[1]));
      mjContact expected[mjMAXCONPAIR], got[mjMAXCONPAIR];
      const int n = f.mujoco(expected, pair[0], pair[1], margin);
      ASSERT_EQ(narrow.collide(f.model.get(), f.data.get(), got, pair[0], pair[1], margin), n)
          << "trial " << trial;
      touching += n;
      for (int i = 0; i < n; ++i) {
        EXPECT_NEAR(got[i].dist, expected[i].dist, 1e-12);
        for (int k = 0; k < 3; ++k) {
          EXPECT_NEAR(got[i].pos[k], expected[i].pos[k], 1e-12);
          EXPECT_NEAR(got[i].frame[k], expected[i].frame[k], 1e-12);
        }
      }
    }
  }
  EXPECT_GT(touching, 800);
}

// With multiccd: the first contact is one of MuJoCo's to 1 µm (in ≤ 1 % of placements, where two
// faces touch, MPR's answer hops on a last-bit difference, but by < 0.5 mm); the extra ones share
// its depth, are distinct, lie within both geoms' reach, and come in about MuJoCo's number (the
// tilt axes may differ).
TEST(ConvexNarrowPhase, FindsExtraContactsLikeMujoco) {
  Fixture f(true);
  ASSERT_NE(f.model, nullptr);
  ConvexNarrowPhase narrow(f.model.get());
  Rng rng(4);
  int ours = 0, theirs = 0, touching = 0, hopped = 0;
  for (int trial = 0; trial < 300; ++trial) {
    for (const auto& pair : kPairs) {
      f.place(rng, pair[0], pair[1], rng.uniform(0.0, 0.002));
      mjContact expected[mjMAXCONPAIR], got[mjMAXCONPAIR];
      const int n_expected = f.mujoco(expected, pair[0], pair[1], 0.0);
      const int n = narrow.collide(f.model.get(), f.data.get(), got, pair[0], pair[1], 0.0);
      ASSERT_EQ(n > 0, n_expected > 0) << "trial " << trial;
      ASSERT_LE(n, 5);
      ours += n;
      theirs += n_expected;
      if (n == 0) continue;
      double nearest = INFINITY;
      for (int j = 0; j < n_expected; ++j) {
        const Vec3 gap =
            Eigen::Map<const Vec3>(got[0].pos) - Eigen::Map<const Vec3>(expected[j].pos);
        nearest = std::min(nearest, std::max(gap.norm(), std::abs(got[0].dist - expected[j].dist)));
      }
      EXPECT_LT(nearest, 5e-4) << "trial " << trial;
      hopped += nearest > 1e-6;
      ++touching;
      const double tolerance =
          1e-3 * std::min(f.model->geom_rbound[pair[0]], f.model->geom_rbound[pair[1]]);
      for (int i = 1; i < n; ++i) {
        EXPECT_EQ(got[i].dist, got[0].dist);
        const Vec3 at = Eigen::Map<const Vec3>(got[i].pos);
        for (int j = 0; j < i; ++j) {
          EXPECT_GT((at - Eigen::Map<const Vec3>(got[j].pos)).norm(), tolerance);
        }
        for (const int g : pair) {
          EXPECT_LT((at - Eigen::Map<const Vec3>(f.data->geom_xpos + 3 * g)).norm(),
                    f.model->geom_rbound[g] + 1e-6);
        }
      }
    }
  }
  EXPECT_GT(touching, 800);
  EXPECT_LE(hopped, touching / 100);
  EXPECT_GT(ours, theirs * 9 / 10);
  EXPECT_LT(ours, theirs * 11 / 10);
}

// Box–box pairs stay with MuJoCo's box collider; other models are not taken.
TEST(ConvexNarrowPhase, TakesOnlyItsModelsConvexPairs) {
  Fixture f(true), other(true);
  ASSERT_NE(f.model, nullptr);
  ASSERT_NE(other.model, nullptr);
  const ConvexNarrowPhase narrow(f.model.get());
  EXPECT_TRUE(narrow.handles(f.model.get(), 0, 1));
  EXPECT_FALSE(narrow.handles(other.model.get(), 0, 1));
  const char* boxes = R"(<mujoco><worldbody>
    <body><freejoint/><geom type="box" size="0.02 0.01 0.03"/></body>
    <body><freejoint/><geom type="box" size="0.02 0.01 0.03"/></body>
    <body><freejoint/><geom type="sphere" size="0.02"/></body></worldbody></mujoco>)";
  std::unique_ptr<mjModel, void (*)(mjModel*)> model(testing::load_model(boxes), mj_deleteModel);
  ASSERT_NE(model, nullptr);
  const ConvexNarrowPhase box_phase(model.get());
  EXPECT_FALSE(box_phase.handles(model.get(), 0, 1));
  EXPECT_FALSE(box_phase.handles(model.get(), 0, 2));
}

}  // namespace
}  // namespace graspecmf::sim
