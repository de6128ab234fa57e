#include "graspecmf/sim/pad_contact_normals.hpp"

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <cstring>
#include <memory>

#include "box_object.hpp"
#include "graspecmf/core/error.hpp"
#include "graspecmf/lie/so3.hpp"
#include "graspecmf/sim/grasp_scene.hpp"
#include "load_model.hpp"

namespace graspecmf::sim {
namespace {

using Vec3 = Eigen::Vector3d;
using RowMajor = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;

class PadContactNormalsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    model_.reset(testing::load_model(grasp_scene_mjcf(testing::box_object(), TrialConfig{})));
    ASSERT_NE(model_, nullptr);
    data_.reset(mj_makeData(model_.get()));
    // The hand at a tilted pose, fingers 3 cm open each.
    const int hand = model_->jnt_qposadr[model_->body_jntadr[body(kHandBody)]];
    const Eigen::Quaterniond q(lie::so3_exp(Vec3(0.3, -1.1, 0.7)));
    const double pose[7] = {0.1, -0.05, 0.2, q.w(), q.x(), q.y(), q.z()};
    std::copy(pose, pose + 7, data_->qpos + hand);
    for (const char* finger : {kLeftFinger, kRightFinger}) {
      data_->qpos[model_->jnt_qposadr[model_->body_jntadr[body(finger)]]] = 0.03;
    }
    mj_kinematics(model_.get(), data_.get());
  }

  int body(const char* name) const { return mj_name2id(model_.get(), mjOBJ_BODY, name); }
  int geom_of(const char* name) const {
    for (int g = 0; g < model_->ngeom; ++g) {
      if (model_->geom_bodyid[g] == body(name)) return g;
    }
    return -1;
  }
  RowMajor rotation(const char* name) const {
    return Eigen::Map<const RowMajor>(data_->xmat + 9 * body(name));
  }
  // A contact at p, given in the right finger's frame (mirrored for the left one), with normal n
  // given in the same frame.
  mjContact contact(const char* finger, const Vec3& p, const Vec3& n) const {
    const double side = std::strcmp(finger, kRightFinger) == 0 ? 1.0 : -1.0;
    const Vec3 mirror(side, side, 1.0);
    const Vec3 world = Eigen::Map<const Vec3>(data_->xpos + 3 * body(finger)) +
                       rotation(finger) * mirror.cwiseProduct(p);
    const Vec3 normal = (rotation(finger) * mirror.cwiseProduct(n)).normalized();
    mjContact c{};
    for (int k = 0; k < 3; ++k) {
      c.pos[k] = world[k];
      c.frame[k] = normal[k];
    }
    return c;
  }
  static Vec3 normal_of(const mjContact& c) { return Eigen::Map<const Vec3>(c.frame); }

  std::unique_ptr<mjModel, void (*)(mjModel*)> model_{nullptr, mj_deleteModel};
  std::unique_ptr<mjData, void (*)(mjData*)> data_{nullptr, mj_deleteData};
};

// Contacts well inside either pad take its normal, with the original orientation sign and an
// orthonormal frame; contacts near the pad's edges, behind it, or between other geoms keep theirs.
TEST_F(PadContactNormalsTest, OnlyContactsWellInsideThePadTakeItsNormal) {
  const PadContactNormals pads(model_.get(), 0.003);
  const int object = geom_of(kObjectBody);
  const Vec3 tilted(-0.5, 0.1, 0.86);  // towards the fingertip, as MPR reports near the tip
  for (const char* finger : {kRightFinger, kLeftFinger}) {
    const int g = geom_of(finger);
    const Vec3 pad_normal =
        rotation(finger) * Vec3(std::strcmp(finger, kRightFinger) == 0 ? -1 : 1, 0, 0);
    mjContact inside[2] = {contact(finger, {0.0005, 0.004, 0.100}, tilted),
                           contact(finger, {-0.001, -0.005, 0.108}, -tilted)};
    pads.correct(model_.get(), data_.get(), inside, 2, object, g);
    EXPECT_LT((normal_of(inside[0]) - pad_normal).norm(), 1e-12) << finger;
    EXPECT_LT((normal_of(inside[1]) + pad_normal).norm(), 1e-12) << finger;
    for (const mjContact& c : inside) {
      const Eigen::Map<const RowMajor> frame(c.frame);
      EXPECT_LT((frame * frame.transpose() - Eigen::Matrix3d::Identity()).norm(), 1e-12);
      EXPECT_GT(frame.determinant(), 0.0);
    }
    mjContact outside[4] = {contact(finger, {0.0, 0.0, 0.110}, tilted),     // 2.2 mm from the tip
                            contact(finger, {0.0, 0.0065, 0.100}, tilted),  // 2.2 mm from a side
                            contact(finger, {0.0, 0.0, 0.096}, tilted),     // 1.4 mm from the base
                            contact(finger, {0.008, 0.0, 0.100}, tilted)};  // inside the finger
    const mjContact before[4] = {outside[0], outside[1], outside[2], outside[3]};
    pads.correct(model_.get(), data_.get(), outside, 4, g, object);
    for (int k = 0; k < 4; ++k) {
      EXPECT_EQ(std::memcmp(&outside[k], &before[k], sizeof(mjContact)), 0) << finger << " " << k;
    }
  }
  // The palm is not a finger: its contacts are left alone.
  mjContact palm = contact(kRightFinger, {0.0005, 0.004, 0.100}, tilted);
  const mjContact before = palm;
  pads.correct(model_.get(), data_.get(), &palm, 1, geom_of(kHandBody), object);
  EXPECT_EQ(std::memcmp(&palm, &before, sizeof(mjContact)), 0);
}

TEST_F(PadContactNormalsTest, BadArgumentsAreErrors) {
  EXPECT_THROW(PadContactNormals(model_.get(), -0.001), Error);
  std::unique_ptr<mjModel, void (*)(mjModel*)> bare(
      testing::load_model("<mujoco><worldbody><geom type='sphere' size='1'/></worldbody></mujoco>"),
      mj_deleteModel);
  ASSERT_NE(bare, nullptr);
  EXPECT_THROW(PadContactNormals(bare.get(), 0.003), Error);
}

}  // namespace
}  // namespace graspecmf::sim
