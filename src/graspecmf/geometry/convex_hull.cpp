#include "graspecmf/geometry/convex_hull.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "graspecmf/core/error.hpp"
#include "graspecmf/geometry/exact_predicates.hpp"

namespace graspecmf::geometry {

namespace {

// Quickhull with exact orientation tests: a point is outside a face only if it is strictly above
// its plane, so the visible faces always form a disc and the hull stays closed and convex.

class Quickhull {
 public:
  explicit Quickhull(const std::vector<Vec3>& points) : points_(points) {
    std::array<std::uint32_t, 4> simplex{};
    if (!initial_simplex(simplex)) return;
    start_simplex(simplex);
    for (std::uint32_t f = 0; f < faces_.size(); ++f) {
      if (faces_[f].alive && !faces_[f].outside.empty()) add_point(f);
    }
  }

  double volume() const {
    if (faces_.empty()) return 0.0;
    const Vec3& origin = points_[faces_.front().v[0]];
    double sum = 0.0;
    for (const Face& f : faces_) {
      if (!f.alive) continue;
      sum += (points_[f.v[0]] - origin)
                 .dot((points_[f.v[1]] - origin).cross(points_[f.v[2]] - origin));
    }
    return sum / 6.0;
  }

  // The hull's triangles, vertices numbered in order of first use.
  TriangleMesh mesh() const {
    TriangleMesh out;
    std::vector<std::uint32_t> vertex_of(points_.size(), ~std::uint32_t{0});
    for (const Face& f : faces_) {
      if (!f.alive) continue;
      Triangle tri{};
      for (int k = 0; k < 3; ++k) {
        if (vertex_of[f.v[k]] == ~std::uint32_t{0}) {
          vertex_of[f.v[k]] = static_cast<std::uint32_t>(out.vertices.size());
          out.vertices.push_back(points_[f.v[k]]);
        }
        tri[k] = vertex_of[f.v[k]];
      }
      out.triangles.push_back(tri);
    }
    return out;
  }

 private:
  struct Face {
    std::array<std::uint32_t, 3> v{};     // counter-clockwise seen from outside
    std::array<std::uint32_t, 3> next{};  // the face across edge v[i] → v[(i + 1) % 3]
    Vec3 normal = Vec3::Zero();           // (v1 − v0) × (v2 − v0): ranks outside points
    std::vector<std::uint32_t> outside;   // points strictly above this face, not yet added
    bool alive = true;
  };
  struct HorizonEdge {
    std::uint32_t face;  // visible face whose edge it is
    int edge;
  };

  bool above(const Face& f, std::uint32_t p) const {
    return orientation(points_[f.v[0]], points_[f.v[1]], points_[f.v[2]], points_[p]) > 0;
  }

  // Four points spanning a volume: the lowest point, the farthest from it, the farthest from
  // their line and the first of the farthest from their plane that is exactly off it.
  bool initial_simplex(std::array<std::uint32_t, 4>& s) const {
    if (points_.size() < 4) return false;
    const auto best = [&](const auto& score) {
      std::uint32_t arg = 0;
      for (std::uint32_t i = 1; i < points_.size(); ++i) {
        if (score(points_[i]) > score(points_[arg])) arg = i;
      }
      return arg;
    };
    s[0] = best([](const Vec3& p) { return -p.x(); });
    const Vec3 p0 = points_[s[0]];
    s[1] = best([&](const Vec3& p) { return (p - p0).squaredNorm(); });
    const Vec3 axis = points_[s[1]] - p0;
    s[2] = best([&](const Vec3& p) { return (p - p0).cross(axis).squaredNorm(); });
    const Vec3 normal = axis.cross(points_[s[2]] - p0);
    s[3] = best([&](const Vec3& p) { return std::abs(normal.dot(p - p0)); });
    for (std::uint32_t i = 0; orientation(p0, points_[s[1]], points_[s[2]], points_[s[3]]) == 0;
         ++i) {
      if (i == points_.size()) return false;
      s[3] = i;
    }
    return true;
  }

  std::uint32_t add_face(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    Face f;
    f.v = {a, b, c};
    f.normal = (points_[b] - points_[a]).cross(points_[c] - points_[a]);
    faces_.push_back(std::move(f));
    return static_cast<std::uint32_t>(faces_.size() - 1);
  }

  // Index of the edge b → a in face f (the twin of edge a → b).
  int twin_edge(std::uint32_t f, std::uint32_t a, std::uint32_t b) const {
    for (int k = 0; k < 3; ++k) {
      if (faces_[f].v[k] == b && faces_[f].v[(k + 1) % 3] == a) return k;
    }
    throw Error("convex_hull: broken face adjacency");
  }

  void start_simplex(std::array<std::uint32_t, 4> s) {
    if (orientation(points_[s[0]], points_[s[1]], points_[s[2]], points_[s[3]]) > 0) {
      std::swap(s[1], s[2]);  // the fourth point must lie below the first face
    }
    const std::array<std::array<std::uint32_t, 3>, 4> tetra = {
        {{s[0], s[1], s[2]}, {s[0], s[3], s[1]}, {s[1], s[3], s[2]}, {s[2], s[3], s[0]}}};
    for (const auto& t : tetra) add_face(t[0], t[1], t[2]);
    for (std::uint32_t f = 0; f < 4; ++f) {
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t a = faces_[f].v[k];
        const std::uint32_t b = faces_[f].v[(k + 1) % 3];
        for (std::uint32_t g = 0; g < 4; ++g) {
          for (int j = 0; j < 3; ++j) {
            if (faces_[g].v[j] == b && faces_[g].v[(j + 1) % 3] == a) faces_[f].next[k] = g;
          }
        }
      }
    }
    std::vector<std::uint32_t> rest;
    for (std::uint32_t i = 0; i < points_.size(); ++i) {
      if (std::find(s.begin(), s.end(), i) == s.end()) rest.push_back(i);
    }
    assign(rest, 0);
  }

  // Gives each point to the first face from `first` on that it lies strictly above; points above
  // none are inside the hull (or on it) and are dropped.
  void assign(const std::vector<std::uint32_t>& candidates, std::uint32_t first) {
    for (const std::uint32_t p : candidates) {
      for (std::uint32_t f = first; f < faces_.size(); ++f) {
        if (above(faces_[f], p)) {
          faces_[f].outside.push_back(p);
          break;
        }
      }
    }
  }

  // Depth-first walk over the faces visible from p, entering face f through edge `entry`; the
  // edges to invisible faces are collected in order around the horizon.
  void find_horizon(std::uint32_t f, int entry, std::uint32_t p) {
    visited_[f] = stamp_;
    visible_.push_back(f);
    for (int k = 0; k < 3; ++k) {
      const int e = (entry + k) % 3;
      const std::uint32_t g = faces_[f].next[e];
      if (visited_[g] == stamp_) continue;
      if (above(faces_[g], p)) {
        find_horizon(g, twin_edge(g, faces_[f].v[e], faces_[f].v[(e + 1) % 3]), p);
      } else {
        horizon_.push_back({f, e});
      }
    }
  }

  // Adds the point of face f's outside set farthest from its plane.
  void add_point(std::uint32_t f) {
    const Face& face = faces_[f];
    std::uint32_t p = face.outside.front();
    for (const std::uint32_t q : face.outside) {
      if (face.normal.dot(points_[q] - points_[p]) > 0.0) p = q;
    }
    ++stamp_;
    visited_.resize(faces_.size(), 0);
    visible_.clear();
    horizon_.clear();
    find_horizon(f, 0, p);

    std::vector<std::uint32_t> orphans;
    for (const std::uint32_t v : visible_) {
      for (const std::uint32_t q : faces_[v].outside) {
        if (q != p) orphans.push_back(q);
      }
      faces_[v].outside = {};
      faces_[v].alive = false;
    }
    const auto first = static_cast<std::uint32_t>(faces_.size());
    const auto n = static_cast<std::uint32_t>(horizon_.size());
    for (std::uint32_t k = 0; k < n; ++k) {
      const HorizonEdge edge = horizon_[k];
      const std::uint32_t a = faces_[edge.face].v[edge.edge];
      const std::uint32_t b = faces_[edge.face].v[(edge.edge + 1) % 3];
      const std::uint32_t outer = faces_[edge.face].next[edge.edge];
      const HorizonEdge following = horizon_[(k + 1) % n];
      if (faces_[following.face].v[following.edge] != b) {
        throw Error("convex_hull: the horizon is not a simple loop");
      }
      const std::uint32_t created = add_face(a, b, p);
      faces_[created].next = {outer, first + (k + 1) % n, first + (k + n - 1) % n};
      faces_[outer].next[twin_edge(outer, a, b)] = created;
    }
    assign(orphans, first);
  }

  const std::vector<Vec3>& points_;
  std::vector<Face> faces_;
  std::vector<std::uint32_t> visited_;  // stamp_ marks the faces visible from the current point
  std::uint32_t stamp_ = 0;
  std::vector<std::uint32_t> visible_;
  std::vector<HorizonEdge> horizon_;
};

}  // namespace

TriangleMesh convex_hull(const std::vector<Vec3>& points) {
  return Quickhull(points).mesh();
}

ConvexHull convex_hull_with_volume(const std::vector<Vec3>& points) {
  const Quickhull hull(points);
  return {hull.mesh(), hull.volume()};
}

}  // namespace graspecmf::geometry
