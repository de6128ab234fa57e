#include "graspecmf/sim/grasp_trial.hpp"

#include <mujoco/mujoco.h>

#include <cmath>
#include <mutex>
#include <stdexcept>
#include <string>

#include "graspecmf/core/error.hpp"
#include "graspecmf/gripper/panda.hpp"
#include "graspecmf/sim/collision_hooks.hpp"
#include "graspecmf/sim/collision_prefilter.hpp"
#include "graspecmf/sim/convex_narrow_phase.hpp"
#include "graspecmf/sim/pad_contact_normals.hpp"

namespace graspecmf::sim {
namespace {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

// MuJoCo's default error handler exits the process; ours throws, and warnings are only counted
// (in mjData::warning), never printed.
void install_mujoco_handlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    mju_user_error = [](const char* message) { throw Error(std::string("MuJoCo: ") + message); };
    mju_user_warning = [](const char*) {};
  });
}

// The model from MJCF text, through a one-file virtual file system.
mjModel* compile(const std::string& xml) {
  auto vfs = std::make_unique<mjVFS>();
  mj_defaultVFS(vfs.get());
  const char* name = "scene.xml";
  if (mj_makeEmptyFileVFS(vfs.get(), name, static_cast<int>(xml.size())) != 0) {
    throw Error("MuJoCo: cannot create the in-memory scene file");
  }
  std::copy(xml.begin(), xml.end(), static_cast<char*>(vfs->filedata[vfs->nfile - 1]));
  char error[1000] = "";
  mjModel* model = mj_loadXML(name, vfs.get(), error, sizeof(error));
  mj_deleteVFS(vfs.get());
  if (model == nullptr) throw Error(std::string("MuJoCo rejected the grasp scene: ") + error);
  return model;
}

lie::Pose body_pose(const mjData* d, int body) {
  lie::Pose pose;
  pose.p = Eigen::Map<const Vec3>(d->xpos + 3 * body);
  pose.R = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(d->xmat + 9 * body);
  return pose;
}

// Writes a pose as MuJoCo's position + (w, x, y, z) quaternion.
void write_pose(const lie::Pose& pose, double* pos, double* quat) {
  const Eigen::Quaterniond q(pose.R);
  std::copy(pose.p.data(), pose.p.data() + 3, pos);
  quat[0] = q.w();
  quat[1] = q.x();
  quat[2] = q.y();
  quat[3] = q.z();
}

// The finger targets end this far past closed, so a held object is squeezed at the force limit.
constexpr double kSqueezePastClosed = 0.01;

// A smooth 0 → 1 ramp over [0, 1].
double ramp(double s) {
  return s <= 0 ? 0.0 : s >= 1 ? 1.0 : 0.5 - 0.5 * std::cos(M_PI * s);
}

}  // namespace

struct GraspSimulator::Impl {
  TrialConfig config;
  mjModel* model = nullptr;
  mjData* data = nullptr;
  int object_body = -1, hand_body = -1, left_body = -1, right_body = -1;
  int object_qpos = -1, hand_qpos = -1, left_qpos = -1, right_qpos = -1;
  int mocap = -1;
  std::unique_ptr<CollisionPrefilter> prefilter;
  std::unique_ptr<ConvexNarrowPhase> convex;       // null when config.mujoco_convex
  std::unique_ptr<PadContactNormals> pad_normals;  // null when config.pad_normal_inset < 0

  int steps(double duration) const {
    return static_cast<int>(std::lround(duration / config.timestep));
  }

  lie::Pose frame;  // simulation_frame: the world frame of the scene, in object coordinates

  // The object's pose in the hand frame.
  lie::Pose relative_pose() const {
    return lie::compose(lie::inverse(body_pose(data, hand_body)), body_pose(data, object_body));
  }

  bool stable() const {
    for (int i = 0; i < mjNWARNING; ++i) {
      if (data->warning[i].number > 0) return false;
    }
    for (int i = 0; i < model->nq; ++i) {
      if (!std::isfinite(data->qpos[i])) return false;
    }
    return true;
  }

  // Steps `count` times with the target at target_at(step); adds the relative motion to the
  // integrals (slip: the path length of the object point `tracked`, given in the object frame).
  // Returns false as soon as the simulation becomes unstable.
  template <typename TargetAt>
  bool advance(int count, TargetAt&& target_at, double& linear, double& angular, double& slip,
               const Vec3& tracked) {
    lie::Pose previous = relative_pose();
    for (int i = 0; i < count; ++i) {
      write_pose(target_at(i), data->mocap_pos + 3 * mocap, data->mocap_quat + 4 * mocap);
      mj_step(model, data);
      if (!stable()) return false;
      const lie::Pose current = relative_pose();
      linear += (current.p - previous.p).norm();
      angular += lie::so3_distance(previous.R, current.R);
      slip += (lie::apply(current, tracked) - lie::apply(previous, tracked)).norm();
      previous = current;
    }
    return true;
  }

  // True if some object geom touches a geom of the given body.
  bool touches(int body) const {
    for (int i = 0; i < data->ncon; ++i) {
      const int b1 = model->geom_bodyid[data->contact[i].geom1];
      const int b2 = model->geom_bodyid[data->contact[i].geom2];
      if ((b1 == body && b2 == object_body) || (b2 == body && b1 == object_body)) return true;
    }
    return false;
  }
};

GraspSimulator::GraspSimulator(const SceneObject& object, const TrialConfig& config)
    : impl_(std::make_unique<Impl>()) {
  install_mujoco_handlers();
  impl_->config = config;
  impl_->frame = simulation_frame(object, config);
  impl_->model = compile(grasp_scene_mjcf(
      config.legacy_object_frame ? object : expressed_in(object, impl_->frame), config));
  impl_->data = mj_makeData(impl_->model);
  Impl& s = *impl_;
  const auto body = [&](const char* name) { return mj_name2id(s.model, mjOBJ_BODY, name); };
  const auto joint_qpos = [&](const char* name) {
    return s.model->jnt_qposadr[mj_name2id(s.model, mjOBJ_JOINT, name)];
  };
  s.object_body = body(kObjectBody);
  s.hand_body = body(kHandBody);
  s.left_body = body(kLeftFinger);
  s.right_body = body(kRightFinger);
  s.object_qpos = s.model->jnt_qposadr[s.model->body_jntadr[s.object_body]];
  s.hand_qpos = s.model->jnt_qposadr[s.model->body_jntadr[s.hand_body]];
  s.left_qpos = joint_qpos(kLeftFinger);
  s.right_qpos = joint_qpos(kRightFinger);
  s.mocap = s.model->body_mocapid[body(kTargetBody)];
  s.prefilter = std::make_unique<CollisionPrefilter>(s.model);
  if (!config.mujoco_convex) s.convex = std::make_unique<ConvexNarrowPhase>(s.model);
  if (config.pad_normal_inset >= 0.0) {
    s.pad_normals = std::make_unique<PadContactNormals>(s.model, config.pad_normal_inset);
  }
}

GraspSimulator::~GraspSimulator() {
  mj_deleteData(impl_->data);
  mj_deleteModel(impl_->model);
}

TrialResult GraspSimulator::run(const lie::Pose& object_grasp) {
  Impl& s = *impl_;
  const lie::Pose grasp =
      s.config.legacy_object_frame
          ? object_grasp
          : lie::quantized(lie::compose(lie::inverse(s.frame), object_grasp), kRoundOffGrid);
  const TrialConfig& c = s.config;
  mjModel* m = s.model;
  mjData* d = s.data;
  const CollisionHooksScope hooks(m, {s.prefilter.get(), s.convex.get(), s.pad_normals.get()});
  if (s.convex) s.convex->reset();
  mj_resetData(m, d);
  write_pose(lie::Pose{}, d->qpos + s.object_qpos, d->qpos + s.object_qpos + 3);
  write_pose(grasp, d->qpos + s.hand_qpos, d->qpos + s.hand_qpos + 3);
  const double open = 0.5 * gripper::panda::kMaxOpening;
  d->qpos[s.left_qpos] = d->qpos[s.right_qpos] = open;
  d->ctrl[0] = d->ctrl[1] = open;
  m->opt.gravity[2] = 0.0;
  mj_forward(m, d);

  TrialResult result;
  const auto finish_unstable = [&] {
    result.unstable = true;
    return result;
  };
  // Close in place, gravity off (the object must not fall before it is held): the finger targets
  // move steadily from open to past closed over the first 3/4 of the phase, so the fingers meet
  // the object slowly and the force limit decides the squeeze.
  const int close_steps = s.steps(c.close_duration);
  const auto at_grasp = [&](int) { return grasp; };
  const auto closing = [&](int i) {
    const double fraction = std::min(1.0, (i + 1.0) / (0.75 * close_steps));
    d->ctrl[0] = d->ctrl[1] = open - (open + kSqueezePastClosed) * fraction;
    return grasp;
  };
  const Vec3 pad_center_in_hand(0, 0, gripper::panda::kPadCenterZ);
  // In the world frame, which is the object frame at the start.
  const Vec3 pad_center = lie::apply(grasp, pad_center_in_hand);
  if (!s.advance(close_steps, closing, result.closing_linear, result.closing_angular,
                 result.closing_slip, pad_center)) {
    return finish_unstable();
  }
  const lie::Pose held = s.relative_pose();
  const Vec3 held_point = lie::apply(lie::inverse(held), pad_center_in_hand);
  m->opt.gravity[2] = -c.gravity;

  // Settle, lift against the approach axis, then shake along it and about the gripper y axis
  // through the finger-pad centre.
  const Vec3 approach = grasp.R.col(2);
  const int lift_steps = s.steps(c.lift_duration);
  const auto lifted = [&](double fraction) {
    lie::Pose target = grasp;
    target.p -= approach * c.lift_distance * ramp(fraction);
    return target;
  };
  const double period_steps = 1.0 / (c.shake_frequency * c.timestep);
  const auto shaken = [&](int i) {
    const double phase = std::sin(2.0 * M_PI * i / period_steps);
    lie::Pose target = lifted(1.0);
    const Mat3 turn = lie::so3_exp(grasp.R.col(1) * c.shake_angular_amplitude * phase);
    const Vec3 pivot = pad_center - approach * c.lift_distance;
    target.R = turn * target.R;
    target.p = turn * (target.p - pivot) + pivot + approach * c.shake_linear_amplitude * phase;
    return target;
  };
  double ignored_linear = 0, ignored_angular = 0, ignored_slip = 0;
  if (!s.advance(s.steps(c.settle_duration), at_grasp, ignored_linear, ignored_angular,
                 ignored_slip, held_point) ||
      !s.advance(
          lift_steps, [&](int i) { return lifted((i + 1.0) / lift_steps); }, result.shaking_linear,
          result.shaking_angular, result.shaking_slip, held_point) ||
      !s.advance(static_cast<int>(std::lround(c.shake_cycles * period_steps)), shaken,
                 result.shaking_linear, result.shaking_angular, result.shaking_slip, held_point)) {
    return finish_unstable();
  }

  const lie::Pose now = s.relative_pose();
  result.final_opening = d->qpos[s.left_qpos] + d->qpos[s.right_qpos];
  const bool held_by_both = s.touches(s.left_body) && s.touches(s.right_body);
  result.success = held_by_both && (now.p - held.p).norm() < c.max_relative_translation &&
                   lie::so3_distance(now.R, held.R) < c.max_relative_rotation;
  return result;
}

}  // namespace graspecmf::sim
