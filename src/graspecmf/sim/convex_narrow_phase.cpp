#include "graspecmf/sim/convex_narrow_phase.hpp"

#include <ccd/ccd.h>
#include <ccd/vec3.h>
#include <mujoco/mujoco.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <utility>

namespace graspecmf::sim {

using Vec3 = Eigen::Vector3d;
using RowMajor = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;

struct ConvexNarrowPhase::Shape {
  bool is_box = false;
  Vec3 half = Vec3::Zero();  // box half sizes
  std::vector<Vec3> vertices;
  std::vector<int> first_neighbour;  // vertices.size() + 1 offsets into neighbours
  std::vector<int> neighbours;
};

namespace {

// MuJoCo's multiccd parameters: the tilt of each extra MPR run, and how far (relative to the
// smaller bounding radius) a new contact must lie from the others to count.
constexpr double kPerturbationAngle = 1e-3;  // rad
constexpr double kDistinctRelative = 1e-3;

// A geom as libccd sees it: its shape at a world pose, with margin and the climb's start.
struct Placed {
  const ConvexNarrowPhase::Shape* shape;
  RowMajor R;
  Vec3 p;
  double margin;
  int* warm;
};

// The shape's farthest point along `dir` (geom frame). Hull vertices: climb the neighbour graph
// from *warm, which a convex hull turns into the global maximum; *warm keeps the answer.
Vec3 local_support(const ConvexNarrowPhase::Shape& shape, const Vec3& dir, int* warm) {
  if (shape.is_box) return shape.half.cwiseProduct(dir.cwiseSign());
  int best = *warm;
  double best_dot = shape.vertices[static_cast<std::size_t>(best)].dot(dir);
  for (bool moved = true; moved;) {
    moved = false;
    const int from = best;
    for (int k = shape.first_neighbour[static_cast<std::size_t>(from)];
         k < shape.first_neighbour[static_cast<std::size_t>(from) + 1]; ++k) {
      const int next = shape.neighbours[static_cast<std::size_t>(k)];
      const double dot = shape.vertices[static_cast<std::size_t>(next)].dot(dir);
      if (dot > best_dot) {
        best_dot = dot;
        best = next;
        moved = true;
      }
    }
  }
  *warm = best;
  return shape.vertices[static_cast<std::size_t>(best)];
}

void support(const void* object, const ccd_vec3_t* dir, ccd_vec3_t* out) {
  const auto& placed = *static_cast<const Placed*>(object);
  const Vec3 local_dir = placed.R.transpose() * Vec3(dir->v[0], dir->v[1], dir->v[2]);
  const Vec3 local =
      local_support(*placed.shape, local_dir, placed.warm) + local_dir * (0.5 * placed.margin);
  Eigen::Map<Vec3>(out->v) = placed.R * local + placed.p;
}

void center(const void* object, ccd_vec3_t* out) {
  Eigen::Map<Vec3>(out->v) = static_cast<const Placed*>(object)->p;
}

// One MPR run; on overlap with a defined direction, writes the contact as MuJoCo does.
bool penetration(const Placed& a, const Placed& b, const ccd_t& ccd, double margin,
                 mjContact* contact) {
  ccd_real_t depth = 0;
  ccd_vec3_t dir, pos;
  if (ccdMPRPenetration(&a, &b, &ccd, &depth, &dir, &pos) != 0) return false;
  if (ccdVec3Eq(&dir, ccd_vec3_origin)) return false;
  contact->dist = margin - depth;
  for (int i = 0; i < 3; ++i) {
    contact->pos[i] = pos.v[i];
    contact->frame[i] = dir.v[i];
    contact->frame[3 + i] = 0.0;
  }
  return true;
}

// `placed` turned by `turn` about `origin`.
Placed turned(const Placed& placed, const Eigen::Matrix3d& turn, const Vec3& origin) {
  Placed result = placed;
  result.R = turn * placed.R;
  result.p = origin + turn * (placed.p - origin);
  return result;
}

// Two unit tangents completing the unit normal n to a right-handed frame.
std::pair<Vec3, Vec3> tangents(const Vec3& n) {
  Vec3 axis = Vec3::Zero();
  int smallest = 0;
  n.cwiseAbs().minCoeff(&smallest);
  axis[smallest] = 1.0;
  const Vec3 t1 = n.cross(axis).normalized();
  return {t1, n.cross(t1)};
}

}  // namespace

ConvexNarrowPhase::ConvexNarrowPhase(const mjModel* model)
    : model_(model),
      shape_of_geom_(static_cast<std::size_t>(model->ngeom), -1),
      warm_start_(static_cast<std::size_t>(model->ngeom), 0) {
  for (int g = 0; g < model->ngeom; ++g) {
    Shape shape;
    if (model->geom_type[g] == mjGEOM_BOX) {
      shape.is_box = true;
      shape.half = Eigen::Map<const Vec3>(model->geom_size + 3 * g);
    } else if (model->geom_type[g] == mjGEOM_MESH &&
               model->mesh_graphadr[model->geom_dataid[g]] >= 0) {
      // mesh_graph: vertex count, face count, per hull vertex its first edge and its mesh
      // vertex, then each vertex's neighbour list ended by −1.
      const int mesh = model->geom_dataid[g];
      const int* graph = model->mesh_graph + model->mesh_graphadr[mesh];
      const int count = graph[0];
      const int* edge_start = graph + 2;
      const int* mesh_vertex = graph + 2 + count;
      const int* edges = graph + 2 + 2 * count;
      const float* v = model->mesh_vert + 3 * model->mesh_vertadr[mesh];
      shape.first_neighbour.push_back(0);
      for (int i = 0; i < count; ++i) {
        const float* xyz = v + 3 * mesh_vertex[i];
        shape.vertices.emplace_back(xyz[0], xyz[1], xyz[2]);
        for (const int* e = edges + edge_start[i]; *e >= 0; ++e) shape.neighbours.push_back(*e);
        shape.first_neighbour.push_back(static_cast<int>(shape.neighbours.size()));
      }
    } else {
      continue;
    }
    shape_of_geom_[static_cast<std::size_t>(g)] = static_cast<int>(shapes_.size());
    shapes_.push_back(std::move(shape));
  }
}

ConvexNarrowPhase::~ConvexNarrowPhase() = default;

bool ConvexNarrowPhase::handles(const mjModel* model, int g1, int g2) const {
  if (model != model_) return false;
  const auto i = static_cast<std::size_t>(g1), j = static_cast<std::size_t>(g2);
  // Box–box pairs keep MuJoCo's dedicated box collider.
  return shape_of_geom_[i] >= 0 && shape_of_geom_[j] >= 0 &&
         (model->geom_type[g1] == mjGEOM_MESH || model->geom_type[g2] == mjGEOM_MESH);
}

void ConvexNarrowPhase::reset() {
  std::fill(warm_start_.begin(), warm_start_.end(), 0);
}

int ConvexNarrowPhase::collide(const mjModel* model, const mjData* data, mjContact* contacts,
                               int g1, int g2, double margin) {
  const auto place = [&](int g) {
    const auto i = static_cast<std::size_t>(g);
    return Placed{&shapes_[static_cast<std::size_t>(shape_of_geom_[i])],
                  Eigen::Map<const RowMajor>(data->geom_xmat + 9 * g),
                  Eigen::Map<const Vec3>(data->geom_xpos + 3 * g), margin, &warm_start_[i]};
  };
  const Placed a = place(g1), b = place(g2);
  ccd_t ccd;
  CCD_INIT(&ccd);
  ccd.first_dir = ccdFirstDirDefault;
  ccd.support1 = ccd.support2 = support;
  ccd.center1 = ccd.center2 = center;
  ccd.max_iterations = static_cast<unsigned long>(model->opt.mpr_iterations);
  ccd.mpr_tolerance = model->opt.mpr_tolerance;
  if (!penetration(a, b, ccd, margin, &contacts[0])) return 0;
  if ((model->opt.enableflags & mjENBL_MULTICCD) == 0) return 1;

  // Tilt g1 one way and g2 the other about each tangent through the first contact; every
  // distinct new contact joins, with the first contact's depth.
  int count = 1;
  const Vec3 origin = Eigen::Map<const Vec3>(contacts[0].pos);
  const auto [t1, t2] = tangents(Eigen::Map<const Vec3>(contacts[0].frame));
  const double tolerance =
      kDistinctRelative * std::min(model->geom_rbound[g1], model->geom_rbound[g2]);
  for (const Vec3& axis : {t1, t2}) {
    for (const double angle : {-kPerturbationAngle, kPerturbationAngle}) {
      const Eigen::Matrix3d turn = Eigen::AngleAxisd(angle, axis).toRotationMatrix();
      mjContact& candidate = contacts[count];
      if (!penetration(turned(a, turn, origin), turned(b, turn.transpose(), origin), ccd, margin,
                       &candidate)) {
        continue;
      }
      const Vec3 at = Eigen::Map<const Vec3>(candidate.pos);
      bool distinct = true;
      for (int k = 0; k < count && distinct; ++k) {
        distinct = (at - Eigen::Map<const Vec3>(contacts[k].pos)).norm() > tolerance;
      }
      if (distinct) {
        candidate.dist = contacts[0].dist;
        ++count;
      }
    }
  }
  return count;
}

}  // namespace graspecmf::sim
