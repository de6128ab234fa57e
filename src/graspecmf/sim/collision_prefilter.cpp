#include "graspecmf/sim/collision_prefilter.hpp"

#include <mujoco/mujoco.h>

#include <Eigen/Dense>
#include <cmath>

namespace graspecmf::sim {
namespace {

// Boxes closer than this are always handed to the narrow phase.
constexpr double kSafetyGap = 1e-3;  // m

using RowMajor = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;

}  // namespace

CollisionPrefilter::CollisionPrefilter(const mjModel* model)
    : model_(model),
      boxed_(static_cast<std::size_t>(model->ngeom), false),
      center_(static_cast<std::size_t>(model->ngeom), Eigen::Vector3d::Zero()),
      half_(static_cast<std::size_t>(model->ngeom), Eigen::Vector3d::Zero()) {
  for (int g = 0; g < model->ngeom; ++g) {
    const auto i = static_cast<std::size_t>(g);
    if (model->geom_type[g] == mjGEOM_BOX) {
      half_[i] = Eigen::Map<const Eigen::Vector3d>(model->geom_size + 3 * g);
      boxed_[i] = true;
    } else if (model->geom_type[g] == mjGEOM_MESH) {
      // Mesh vertices are stored in the geom frame.
      const int mesh = model->geom_dataid[g];
      const float* v = model->mesh_vert + 3 * model->mesh_vertadr[mesh];
      Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
      for (int k = 0; k < model->mesh_vertnum[mesh]; ++k) {
        const Eigen::Vector3d p(v[3 * k], v[3 * k + 1], v[3 * k + 2]);
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
      }
      center_[i] = 0.5 * (lo + hi);
      half_[i] = 0.5 * (hi - lo);
      boxed_[i] = true;
    }
  }
}

bool CollisionPrefilter::apart(const mjModel* model, const mjData* data, int g1, int g2) const {
  const auto i = static_cast<std::size_t>(g1), j = static_cast<std::size_t>(g2);
  if (model != model_ || !boxed_[i] || !boxed_[j]) return false;
  const RowMajor Ra = Eigen::Map<const RowMajor>(data->geom_xmat + 9 * g1);
  const RowMajor Rb = Eigen::Map<const RowMajor>(data->geom_xmat + 9 * g2);
  const Eigen::Vector3d ca =
      Eigen::Map<const Eigen::Vector3d>(data->geom_xpos + 3 * g1) + Ra * center_[i];
  const Eigen::Vector3d cb =
      Eigen::Map<const Eigen::Vector3d>(data->geom_xpos + 3 * g2) + Rb * center_[j];
  const double gap = kSafetyGap + model->geom_margin[g1] + model->geom_margin[g2];
  const Eigen::Vector3d& a = half_[i];
  const Eigen::Vector3d& b = half_[j];
  // Separating-axis test of two oriented boxes: 3 + 3 face axes and 9 edge cross products.
  const Eigen::Matrix3d R = Ra.transpose() * Rb;  // b's axes in a's frame
  const Eigen::Matrix3d absR = R.cwiseAbs().array() + 1e-12;
  const Eigen::Vector3d t = Ra.transpose() * (cb - ca);
  for (int k = 0; k < 3; ++k) {
    if (std::abs(t[k]) > a[k] + absR.row(k).dot(b) + gap) return true;
    if (std::abs(t.dot(R.col(k))) > absR.col(k).dot(a) + b[k] + gap) return true;
  }
  for (int p = 0; p < 3; ++p) {
    const int p1 = (p + 1) % 3, p2 = (p + 2) % 3;
    for (int q = 0; q < 3; ++q) {
      const int q1 = (q + 1) % 3, q2 = (q + 2) % 3;
      const double ra = a[p1] * absR(p2, q) + a[p2] * absR(p1, q);
      const double rb = b[q1] * absR(p, q2) + b[q2] * absR(p, q1);
      // The axis a_p × b_q is not unit length; scale the gap by its length.
      const double length = std::sqrt(std::max(0.0, 1.0 - R(p, q) * R(p, q)));
      if (std::abs(t[p2] * R(p1, q) - t[p1] * R(p2, q)) > ra + rb + gap * length) return true;
    }
  }
  return false;
}

}  // namespace graspecmf::sim
