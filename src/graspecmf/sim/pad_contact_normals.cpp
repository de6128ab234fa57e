#include "graspecmf/sim/pad_contact_normals.hpp"

#include <mujoco/mujoco.h>

#include <Eigen/Dense>
#include <cmath>

#include "graspecmf/core/error.hpp"
#include "graspecmf/gripper/panda.hpp"
#include "graspecmf/sim/grasp_scene.hpp"

namespace graspecmf::sim {
namespace {

using RowMajor = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;

// Contacts farther than this from the pad plane (into the finger) are not on the pad.
constexpr double kPlaneTolerance = 0.005;  // m

// Writes the normal and two tangents perpendicular to it into a MuJoCo contact frame.
void set_frame(mjContact& contact, const Eigen::Vector3d& normal) {
  const Eigen::Vector3d helper =
      std::abs(normal.x()) < 0.5 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d t1 = (helper - helper.dot(normal) * normal).normalized();
  const Eigen::Vector3d t2 = normal.cross(t1);
  for (int k = 0; k < 3; ++k) {
    contact.frame[k] = normal[k];
    contact.frame[3 + k] = t1[k];
    contact.frame[6 + k] = t2[k];
  }
}

}  // namespace

PadContactNormals::PadContactNormals(const mjModel* model, double inset)
    : left_body_(mj_name2id(model, mjOBJ_BODY, kLeftFinger)),
      right_body_(mj_name2id(model, mjOBJ_BODY, kRightFinger)),
      inset_(inset) {
  if (left_body_ < 0 || right_body_ < 0)
    throw Error("pad contact normals: the model has no fingers");
  if (!(inset >= 0.0)) throw Error("pad contact normals: inset must be ≥ 0");
}

void PadContactNormals::correct(const mjModel* m, const mjData* d, mjContact* contacts, int count,
                                int g1, int g2) const {
  // The finger of the pair and its side: the right finger's pad faces −x of its body frame.
  int body = -1;
  double side = 0.0;
  for (const int g : {g1, g2}) {
    if (m->geom_bodyid[g] == left_body_) body = left_body_, side = -1.0;
    if (m->geom_bodyid[g] == right_body_) body = right_body_, side = 1.0;
  }
  if (body < 0) return;
  const RowMajor R = Eigen::Map<const RowMajor>(d->xmat + 9 * body);
  const Eigen::Vector3d origin = Eigen::Map<const Eigen::Vector3d>(d->xpos + 3 * body);
  const Eigen::Vector3d pad_normal = R * Eigen::Vector3d(-side, 0.0, 0.0);
  namespace panda = gripper::panda;
  for (int k = 0; k < count; ++k) {
    mjContact& contact = contacts[k];
    // In the finger frame, mirrored for the left finger; the pad plane is x = 0 at zero opening.
    const Eigen::Vector3d p =
        R.transpose() * (Eigen::Map<const Eigen::Vector3d>(contact.pos) - origin);
    const double depth = side * p.x(), y = side * p.y(), z = p.z();
    const bool on_pad = depth < kPlaneTolerance && std::abs(y) <= panda::kPadHalfWidthY - inset_ &&
                        z >= panda::kPadBottomZ + inset_ && z <= panda::kFingertipZ - inset_;
    if (!on_pad) continue;
    const Eigen::Vector3d normal = Eigen::Map<const Eigen::Vector3d>(contact.frame);
    set_frame(contact, normal.dot(pad_normal) >= 0.0 ? pad_normal : Eigen::Vector3d(-pad_normal));
  }
}

}  // namespace graspecmf::sim
