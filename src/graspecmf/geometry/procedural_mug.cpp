#include "graspecmf/geometry/procedural_mug.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include "graspecmf/core/error.hpp"

namespace graspecmf::geometry {
namespace {

using Vec2 = Eigen::Vector2d;

constexpr double kPi = 3.14159265358979323846;
constexpr int kSegments = 72;            // vertices around the axis
constexpr double kWallStep = 0.003;      // m between outer-wall rings
constexpr double kInnerStep = 0.004;     // m between inner-wall rings
constexpr double kBottomStep = 0.006;    // m between the rings of the bottom discs
constexpr int kRimArcSteps = 8;          // segments of a rounded rim
constexpr double kTubeStep = 0.0025;     // m between handle cross-sections
constexpr double kHandleMargin = 0.002;  // m between a handle footprint and the base or rim
constexpr double kMinBend = 0.6;         // handle centreline curvature radius ≥ this × thickness
constexpr double kMinInnerRadius = 0.003;
constexpr int kDentWaves = 5;            // smooth terms of a rough surface
constexpr double kJitterShare = 0.3;     // share of the roughness that is per-vertex jitter
constexpr double kRoughnessRamp = 0.01;  // m: the roughness fades to 0 towards the axis

// The radius of the body shape alone, before any flare.
double body_radius_at(const MugParameters& mug, double s) {
  switch (mug.body) {
    case MugBody::straight:
      return mug.outer_radius;
    case MugBody::tapered:
      return mug.outer_radius * (1.0 + mug.body_amount * s);
    case MugBody::barrel:
      return mug.outer_radius * (1.0 + mug.body_amount * std::sin(kPi * s));
    case MugBody::waisted:
      return mug.outer_radius * (1.0 - mug.body_amount * std::sin(kPi * s));
  }
  return mug.outer_radius;
}

// Height fraction where the flare begins (1 when there is none).
double flare_start(const MugParameters& mug) {
  return mug.flare > 0.0 ? 1.0 - mug.flare_height : 1.0;
}

double outer_radius_at(const MugParameters& mug, double z) {
  const double s = z / mug.height;
  const double start = flare_start(mug);
  double radius = body_radius_at(mug, s);
  if (mug.flare > 0.0 && s > start) {
    radius += mug.flare * std::pow((s - start) / mug.flare_height, 2);
  }
  return radius;
}

// The radial displacement of a rough mug's surface: smooth dents that depend on (angle, height)
// only, so the inner and outer walls move together, plus seeded per-vertex jitter.
class SurfaceNoise {
 public:
  explicit SurfaceNoise(const MugParameters& mug) : mug_(mug), rng_(mug.roughness_seed) {
    if (mug.roughness <= 0.0) return;
    for (int i = 0; i < kDentWaves; ++i) {
      Wave w;
      w.amplitude = rng_.uniform(0.5, 1.0);
      w.turns = 1 + static_cast<int>(rng_.index(6));
      w.half_waves = rng_.uniform(0.5, 3.0);
      w.phase_angle = rng_.uniform(0.0, 2.0 * kPi);
      w.phase_height = rng_.uniform(0.0, 2.0 * kPi);
      total_ += w.amplitude;
      waves_.push_back(w);
    }
  }

  // The displacement of the next vertex at (angle, height, radius); call once per vertex, in a
  // fixed order (the jitter is drawn from the seeded stream).
  double next(double theta, double z, double r) {
    if (waves_.empty()) return 0.0;
    double dent = 0.0;
    for (const Wave& w : waves_) {
      dent += w.amplitude * std::sin(w.turns * theta + w.phase_angle) *
              std::cos(kPi * w.half_waves * z / mug_.height + w.phase_height);
    }
    const double jitter = rng_.uniform(-1.0, 1.0);
    const double fade = std::min(1.0, r / kRoughnessRamp);
    return mug_.roughness * fade * ((1.0 - kJitterShare) * dent / total_ + kJitterShare * jitter);
  }

 private:
  struct Wave {
    double amplitude = 0, half_waves = 0, phase_angle = 0, phase_height = 0;
    int turns = 0;
  };
  const MugParameters& mug_;
  Rng rng_;
  std::vector<Wave> waves_;
  double total_ = 0.0;
};

// Height where the outer wall ends and the rim begins.
double wall_top(const MugParameters& mug) {
  return mug.rim == MugRim::rounded ? mug.height - 0.5 * mug.wall : mug.height;
}

// The handle centreline in wall-offset coordinates (distance from the outer wall, height).
struct HandlePath {
  double a = 0;    // farthest offset of the centreline from the wall
  double b = 0;    // half the height between the attachments
  double rho = 0;  // corner radius of a D loop
};

HandlePath handle_path(const MugParameters& mug) {
  HandlePath path;
  path.a = mug.handle_clearance + 0.5 * mug.handle_thickness;
  path.b = 0.5 * (mug.handle_high - mug.handle_low) * mug.height;
  path.rho =
      std::clamp(0.5 * std::min(path.a, path.b), kMinBend * mug.handle_thickness,
                 std::max(kMinBend * mug.handle_thickness, std::min(path.a - 0.003, path.b)));
  return path;
}

// The first geometric inconsistency of the parameters, or "" when they are valid.
std::string problem(const MugParameters& mug) {
  const auto outside = [](double v, double lo, double hi) {
    return !std::isfinite(v) || v < lo || v > hi;
  };
  if (outside(mug.height, 0.03, 0.3)) return "height must be in [0.03, 0.3] m";
  if (outside(mug.outer_radius, 0.01, 0.15)) return "outer_radius must be in [0.01, 0.15] m";
  if (outside(mug.wall, 0.001, 0.02)) return "wall must be in [0.001, 0.02] m";
  if (outside(mug.base, 0.001, 0.5 * mug.height)) return "base must be in [0.001 m, height / 2]";
  const double amount_limit = mug.body == MugBody::tapered ? 0.5 : 0.3;
  if (outside(mug.body_amount, mug.body == MugBody::tapered ? -0.5 : 0.0, amount_limit)) {
    return "body_amount is out of range for the body shape";
  }
  if (outside(mug.flare, 0.0, 0.02)) return "flare must be in [0, 0.02] m";
  if (mug.flare > 0.0 && outside(mug.flare_height, 0.03, 0.5)) {
    return "flare_height must be in [0.03, 0.5] when there is a flare";
  }
  if (outside(mug.roughness, 0.0, std::min(0.002, 0.25 * mug.wall))) {
    return "roughness must be in [0, min(0.002 m, wall / 4)]";
  }
  for (int i = 0; i <= 100; ++i) {
    if (outer_radius_at(mug, mug.height * i / 100.0) - mug.wall < kMinInnerRadius) {
      return "the wall leaves no cavity (outer radius − wall < 3 mm somewhere)";
    }
  }
  if (mug.handle == MugHandle::none) return "";
  const double t = mug.handle_thickness;
  if (outside(t, 0.003, 0.03)) return "handle_thickness must be in [0.003, 0.03] m";
  if (outside(mug.handle_width, 0.5 * t, 0.04)) {
    return "handle_width must be in [handle_thickness / 2, 0.04] m";
  }
  if (outside(mug.handle_clearance, 0.005, 0.1))
    return "handle_clearance must be in [0.005, 0.1] m";
  if (!(0.0 < mug.handle_low && mug.handle_low < mug.handle_high && mug.handle_high < 1.0)) {
    return "need 0 < handle_low < handle_high < 1";
  }
  const double z_low = mug.handle_low * mug.height, z_high = mug.handle_high * mug.height;
  if (z_low - 0.5 * t < kHandleMargin || z_high + 0.5 * t > wall_top(mug) - kHandleMargin) {
    return "the handle's attachments do not fit between the base and the rim";
  }
  if (z_high + 0.5 * t > flare_start(mug) * mug.height) {
    return "the handle's upper attachment reaches into the flare";
  }
  if ((z_high - z_low) - t < 2.0 * kWallStep) return "the handle's attachments overlap";
  if (mug.handle_width > 0.5 * outer_radius_at(mug, z_low) ||
      mug.handle_width > 0.5 * outer_radius_at(mug, z_high)) {
    return "handle_width is too large for the mug's radius";
  }
  const HandlePath path = handle_path(mug);
  const double min_bend = kMinBend * t;
  if (mug.handle == MugHandle::c_shape &&
      (path.b * path.b / path.a < min_bend || path.a * path.a / path.b < min_bend)) {
    return "the C handle bends too tightly for its thickness (change clearance or attachments)";
  }
  if (mug.handle == MugHandle::d_loop && path.rho > std::min(path.a - 0.003, path.b)) {
    return "the D handle's corners bend too tightly for its thickness";
  }
  return "";
}

// The closed section of the solid in the (r, z) half-plane, counter-clockwise, from the axis at
// the bottom to the axis on the inner bottom; the outer wall is a uniform run of points.
struct Profile {
  std::vector<Vec2> points;
  std::size_t wall_begin = 0;  // index of the outer wall's point at z = 0
  std::size_t wall_steps = 0;  // segments of the outer wall
  double wall_dz = 0;
};

Profile make_profile(const MugParameters& mug) {
  Profile profile;
  auto& p = profile.points;
  const double r0 = outer_radius_at(mug, 0.0);
  const int bottom = std::max(2, static_cast<int>(std::ceil(r0 / kBottomStep)));
  for (int i = 0; i < bottom; ++i) p.emplace_back(r0 * i / bottom, 0.0);
  const double top = wall_top(mug);
  profile.wall_begin = p.size();
  profile.wall_steps = static_cast<std::size_t>(std::ceil(top / kWallStep));
  profile.wall_dz = top / static_cast<double>(profile.wall_steps);
  for (std::size_t k = 0; k <= profile.wall_steps; ++k) {
    const double z = top * static_cast<double>(k) / static_cast<double>(profile.wall_steps);
    p.emplace_back(outer_radius_at(mug, z), z);
  }
  const double inner_top = outer_radius_at(mug, top) - mug.wall;
  if (mug.rim == MugRim::rounded) {
    const Vec2 center(inner_top + 0.5 * mug.wall, top);
    for (int j = 1; j < kRimArcSteps; ++j) {
      const double angle = kPi * j / kRimArcSteps;
      p.push_back(center + 0.5 * mug.wall * Vec2(std::cos(angle), std::sin(angle)));
    }
  }
  const int inner = std::max(2, static_cast<int>(std::ceil((top - mug.base) / kInnerStep)));
  for (int k = 0; k <= inner; ++k) {
    const double z = top - (top - mug.base) * k / inner;
    p.emplace_back(outer_radius_at(mug, z) - mug.wall, z);
  }
  const double rb = outer_radius_at(mug, mug.base) - mug.wall;
  const int inner_bottom = std::max(2, static_cast<int>(std::ceil(rb / kBottomStep)));
  for (int i = 1; i <= inner_bottom; ++i) {
    p.emplace_back(rb * (1.0 - static_cast<double>(i) / inner_bottom), mug.base);
  }
  return profile;
}

// Vertices of the surface of revolution: one per profile point on the axis, kSegments otherwise.
class RevolvedGrid {
 public:
  RevolvedGrid(const MugParameters& mug, const Profile& profile, TriangleMesh& mesh) {
    SurfaceNoise noise(mug);
    const std::size_t n = profile.points.size();
    first_.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
      const Vec2& q = profile.points[k];
      first_[k] = static_cast<std::uint32_t>(mesh.vertices.size());
      if (on_axis(k, n)) {
        mesh.vertices.emplace_back(0.0, 0.0, q.y());
        continue;
      }
      for (int j = 0; j < kSegments; ++j) {
        const double theta = 2.0 * kPi * j / kSegments;
        const double r = q.x() + noise.next(theta, q.y(), q.x());
        mesh.vertices.emplace_back(r * std::cos(theta), r * std::sin(theta), q.y());
      }
    }
  }

  static bool on_axis(std::size_t k, std::size_t n) { return k == 0 || k + 1 == n; }
  std::uint32_t at(std::size_t k, int j) const {
    const std::size_t n = first_.size();
    if (on_axis(k, n)) return first_[k];
    return first_[k] + static_cast<std::uint32_t>(((j % kSegments) + kSegments) % kSegments);
  }

 private:
  std::vector<std::uint32_t> first_;
};

// One handle attachment: a block of outer-wall cells removed from the grid, and its boundary
// loop, ordered by angle around the block centre in the (width, normal) plane of the handle.
struct Footprint {
  std::size_t k0 = 0, rows = 0;  // profile segments [k0, k0 + rows)
  int half_columns = 0;          // angular cells [−half_columns, half_columns)
  bool contains(std::size_t k, int j) const {
    const int jj = j >= kSegments / 2 ? j - kSegments : j;
    return k >= k0 && k < k0 + rows && jj >= -half_columns && jj < half_columns;
  }
};

// The boundary of a footprint as integer (u, v) pairs: u ∈ [−m, m] across, v ∈ [−rows, rows] (odd
// steps of 2) along the handle's normal, sorted by angle; normal_sign = +1 maps v to +z.
std::vector<std::pair<int, int>> footprint_loop(const Footprint& f) {
  const int m = f.half_columns;
  const int n = static_cast<int>(f.rows);
  std::vector<std::pair<int, int>> loop;
  for (int u = -m; u <= m; ++u) {
    for (int v = -n; v <= n; v += 2) {
      if (u == -m || u == m || v == -n || v == n) loop.emplace_back(u, v);
    }
  }
  std::sort(loop.begin(), loop.end(), [&](const auto& a, const auto& b) {
    return std::atan2(static_cast<double>(a.second) / n, static_cast<double>(a.first) / m) <
           std::atan2(static_cast<double>(b.second) / n, static_cast<double>(b.first) / m);
  });
  return loop;
}

// Dense samples of the handle centreline in wall-offset coordinates, from the upper attachment to
// the lower one.
std::vector<Vec2> handle_centreline(const MugParameters& mug) {
  const HandlePath path = handle_path(mug);
  const double z_high = mug.handle_high * mug.height, z_low = mug.handle_low * mug.height;
  const double z_mid = 0.5 * (z_high + z_low);
  constexpr int kDense = 2000;
  std::vector<Vec2> points;
  if (mug.handle == MugHandle::c_shape) {
    for (int i = 0; i <= kDense; ++i) {
      const double phi = 0.5 * kPi - kPi * i / kDense;
      points.emplace_back(path.a * std::cos(phi), z_mid + path.b * std::sin(phi));
    }
    return points;
  }
  // D loop: out, a quarter turn, down, a quarter turn, back in; sampled at about equal spacing.
  const double rho = path.rho;
  const auto line = [&](const Vec2& from, const Vec2& to) {
    const int steps = std::max(1, static_cast<int>((to - from).norm() / 2e-4));
    for (int i = 0; i < steps; ++i) points.push_back(from + (to - from) * i / steps);
  };
  const auto arc = [&](const Vec2& center, double from, double to) {
    const int steps = std::max(1, static_cast<int>(std::abs(to - from) * rho / 2e-4));
    for (int i = 0; i < steps; ++i) {
      const double angle = from + (to - from) * i / steps;
      points.push_back(center + rho * Vec2(std::cos(angle), std::sin(angle)));
    }
  };
  line({0.0, z_high}, {path.a - rho, z_high});
  arc({path.a - rho, z_high - rho}, 0.5 * kPi, 0.0);
  line({path.a, z_high - rho}, {path.a, z_low + rho});
  arc({path.a - rho, z_low + rho}, 0.0, -0.5 * kPi);
  line({path.a - rho, z_low}, {0.0, z_low});
  points.emplace_back(0.0, z_low);
  return points;
}

Footprint make_footprint(const MugParameters& mug, const Profile& profile, double z_center,
                         int half_columns) {
  Footprint f;
  f.rows = std::max<std::size_t>(
      1, static_cast<std::size_t>(std::lround(mug.handle_thickness / profile.wall_dz)));
  const double first_row = z_center / profile.wall_dz - 0.5 * static_cast<double>(f.rows);
  f.k0 = profile.wall_begin + static_cast<std::size_t>(std::max(1L, std::lround(first_row)));
  f.half_columns = half_columns;
  return f;
}

// Adds the handle tube: rings along the centreline, the first and last being the footprints'
// boundary loops in the wall grid.
void add_handle(const MugParameters& mug, const RevolvedGrid& grid, const Footprint& upper,
                const Footprint& lower, TriangleMesh& mesh) {
  const std::vector<std::pair<int, int>> loop = footprint_loop(upper);
  const auto footprint_ring = [&](const Footprint& f, double normal_sign) {
    std::vector<std::uint32_t> ring;
    for (const auto& [u, v] : loop) {
      const auto row = static_cast<std::size_t>((static_cast<int>(f.rows) + normal_sign * v) / 2);
      ring.push_back(grid.at(f.k0 + row, u));
    }
    return ring;
  };
  // The centreline in space and its arc length.
  std::vector<Vec3> line;
  for (const Vec2& q : handle_centreline(mug)) {
    line.emplace_back(outer_radius_at(mug, q.y()) + q.x(), 0.0, q.y());
  }
  std::vector<double> length(line.size(), 0.0);
  for (std::size_t i = 1; i < line.size(); ++i) {
    length[i] = length[i - 1] + (line[i] - line[i - 1]).norm();
  }
  const int rings = std::max(4, static_cast<int>(std::ceil(length.back() / kTubeStep)));
  std::vector<std::vector<std::uint32_t>> tube{footprint_ring(upper, 1.0)};
  std::size_t cursor = 1;
  for (int r = 1; r < rings; ++r) {
    const double s = length.back() * r / rings;
    while (length[cursor] < s) ++cursor;
    const double w = (s - length[cursor - 1]) / (length[cursor] - length[cursor - 1]);
    const Vec3 center = line[cursor - 1] + w * (line[cursor] - line[cursor - 1]);
    const Vec3 tangent =
        (line[std::min(cursor + 1, line.size() - 1)] - line[cursor - 1]).normalized();
    const Vec3 normal(-tangent.z(), 0.0, tangent.x());
    std::vector<std::uint32_t> ring;
    for (const auto& [u, v] : loop) {
      const Vec2 dir =
          Vec2(static_cast<double>(u) / upper.half_columns, static_cast<double>(v) / upper.rows)
              .normalized();
      ring.push_back(static_cast<std::uint32_t>(mesh.vertices.size()));
      mesh.vertices.push_back(center + 0.5 * mug.handle_width * dir.x() * Vec3::UnitY() +
                              0.5 * mug.handle_thickness * dir.y() * normal);
    }
    tube.push_back(std::move(ring));
  }
  tube.push_back(footprint_ring(lower, -1.0));
  const std::size_t count = loop.size();
  for (std::size_t r = 0; r + 1 < tube.size(); ++r) {
    for (std::size_t i = 0; i < count; ++i) {
      const std::size_t next = (i + 1) % count;
      mesh.triangles.push_back({tube[r][i], tube[r][next], tube[r + 1][next]});
      mesh.triangles.push_back({tube[r][i], tube[r + 1][next], tube[r + 1][i]});
    }
  }
}

}  // namespace

void validate(const MugParameters& mug) {
  if (const std::string message = problem(mug); !message.empty()) {
    throw Error("mug parameters: " + message);
  }
}

namespace {

// The ranges one family draws from (uniform unless noted).
struct FamilyRanges {
  double height[2], radius[2], wall[2], base[2], taper, bulge[2];
  double no_handle;  // probability
  double round_section, round_thickness[2], flat_thickness[2], flat_ratio[2], max_width;
  double clearance[2], low[2], min_span, high_floor, high_ceiling;
  double flare_probability, flare[2], flare_height[2];
  double rough_probability, roughness[2];
};

// mugs-v1 / mugs-v2: the draws and their order must not change, or those presets change.
FamilyRanges classic_ranges() {
  FamilyRanges f{};
  f.height[0] = 0.07, f.height[1] = 0.13;
  f.radius[0] = 0.032, f.radius[1] = 0.052;
  f.wall[0] = 0.0025, f.wall[1] = 0.006;
  f.base[0] = 0.003, f.base[1] = 0.01;
  f.taper = 0.25;
  f.bulge[0] = 0.05, f.bulge[1] = 0.15;
  f.no_handle = 0.06;
  f.round_section = 0.6;
  f.round_thickness[0] = 0.006, f.round_thickness[1] = 0.015;
  f.flat_thickness[0] = 0.006, f.flat_thickness[1] = 0.009;
  f.flat_ratio[0] = 1.6, f.flat_ratio[1] = 2.4;
  f.max_width = 0.02;
  f.clearance[0] = 0.015, f.clearance[1] = 0.035;
  f.low[0] = 0.15, f.low[1] = 0.45;
  f.min_span = 0.3, f.high_floor = 0.55, f.high_ceiling = 0.9;
  return f;  // no flares, smooth
}

// mugs-v3. Handles that do not fit are redrawn with the whole mug, so the drawn 12 % without a
// handle end up about 21 % of the mugs, and the 30 % flared about 20 %.
FamilyRanges varied_ranges() {
  FamilyRanges f = classic_ranges();
  f.height[0] = 0.05, f.height[1] = 0.16;
  f.radius[0] = 0.026, f.radius[1] = 0.058;
  f.wall[0] = 0.0015, f.wall[1] = 0.008;
  f.base[0] = 0.003, f.base[1] = 0.02;
  f.taper = 0.35;
  f.bulge[0] = 0.03, f.bulge[1] = 0.2;
  f.no_handle = 0.12;
  f.round_section = 0.55;
  f.round_thickness[0] = 0.005, f.round_thickness[1] = 0.018;
  f.flat_thickness[0] = 0.005, f.flat_thickness[1] = 0.01;
  f.flat_ratio[0] = 1.4, f.flat_ratio[1] = 2.8;
  f.max_width = 0.025;
  f.clearance[0] = 0.008, f.clearance[1] = 0.04;
  f.low[0] = 0.08, f.low[1] = 0.5;
  f.min_span = 0.25, f.high_floor = 0.45, f.high_ceiling = 0.95;
  f.flare_probability = 0.3;
  f.flare[0] = 0.0015, f.flare[1] = 0.008;
  f.flare_height[0] = 0.08, f.flare_height[1] = 0.3;
  f.rough_probability = 0.35;
  f.roughness[0] = 0.0002, f.roughness[1] = 0.0012;
  return f;
}

MugParameters draw(Rng& rng, const FamilyRanges& f) {
  const auto pick = [&](const double(&range)[2]) { return rng.uniform(range[0], range[1]); };
  MugParameters mug;
  mug.height = pick(f.height);
  mug.outer_radius = pick(f.radius);
  mug.wall = pick(f.wall);
  mug.base = pick(f.base);
  mug.body = static_cast<MugBody>(rng.index(4));
  mug.body_amount = mug.body == MugBody::straight  ? 0.0
                    : mug.body == MugBody::tapered ? rng.uniform(-f.taper, f.taper)
                                                   : pick(f.bulge);
  mug.rim = rng.uniform() < 0.5 ? MugRim::flat : MugRim::rounded;
  if (rng.uniform() < f.no_handle) {
    mug.handle = MugHandle::none;
  } else {
    mug.handle = rng.uniform() < 0.5 ? MugHandle::c_shape : MugHandle::d_loop;
  }
  mug.section = rng.uniform() < f.round_section ? HandleSection::round : HandleSection::flat;
  if (mug.section == HandleSection::round) {
    mug.handle_thickness = pick(f.round_thickness);
    mug.handle_width = mug.handle_thickness;
  } else {
    mug.handle_thickness = pick(f.flat_thickness);
    mug.handle_width = std::min(f.max_width, mug.handle_thickness * pick(f.flat_ratio));
  }
  mug.handle_clearance = pick(f.clearance);
  mug.handle_low = pick(f.low);
  mug.handle_high =
      rng.uniform(std::max(mug.handle_low + f.min_span, f.high_floor), f.high_ceiling);
  // Drawn only by families that have them, so the classic family's stream is unchanged.
  if (f.flare_probability > 0.0 && rng.uniform() < f.flare_probability) {
    mug.flare = pick(f.flare);
    mug.flare_height = pick(f.flare_height);
  }
  if (f.rough_probability > 0.0 && rng.uniform() < f.rough_probability) {
    mug.roughness = std::min(pick(f.roughness), 0.25 * mug.wall);
    mug.roughness_seed = rng.next_u64();
  }
  return mug;
}

}  // namespace

MugParameters random_mug_parameters(Rng& rng, MugFamily family) {
  const FamilyRanges ranges = family == MugFamily::classic ? classic_ranges() : varied_ranges();
  for (;;) {
    // Redraw the rare combinations that do not fit (e.g. a thick handle on a short span).
    MugParameters mug = draw(rng, ranges);
    if (problem(mug).empty()) return mug;
  }
}

TriangleMesh mug_mesh(const MugParameters& mug) {
  validate(mug);
  const Profile profile = make_profile(mug);
  TriangleMesh mesh;
  const RevolvedGrid grid(mug, profile, mesh);
  std::vector<Footprint> footprints;
  if (mug.handle != MugHandle::none) {
    const double z_low = mug.handle_low * mug.height, z_high = mug.handle_high * mug.height;
    const double radius = 0.5 * (outer_radius_at(mug, z_low) + outer_radius_at(mug, z_high));
    const int half_columns = std::max(
        1,
        static_cast<int>(std::lround(0.5 * mug.handle_width / (radius * 2.0 * kPi / kSegments))));
    footprints.push_back(make_footprint(mug, profile, z_high, half_columns));
    footprints.push_back(make_footprint(mug, profile, z_low, half_columns));
  }
  const std::size_t n = profile.points.size();
  for (std::size_t k = 0; k + 1 < n; ++k) {
    for (int j = 0; j < kSegments; ++j) {
      if (std::any_of(footprints.begin(), footprints.end(),
                      [&](const Footprint& f) { return f.contains(k, j); })) {
        continue;
      }
      const std::uint32_t a = grid.at(k, j), b = grid.at(k, j + 1);
      const std::uint32_t c = grid.at(k + 1, j + 1), d = grid.at(k + 1, j);
      if (!RevolvedGrid::on_axis(k, n)) mesh.triangles.push_back({a, b, c});
      if (!RevolvedGrid::on_axis(k + 1, n)) mesh.triangles.push_back({a, c, d});
    }
  }
  if (!footprints.empty()) add_handle(mug, grid, footprints[0], footprints[1], mesh);
  return mesh;
}

std::string to_string(MugBody body) {
  switch (body) {
    case MugBody::straight:
      return "straight";
    case MugBody::tapered:
      return "tapered";
    case MugBody::barrel:
      return "barrel";
    case MugBody::waisted:
      return "waisted";
  }
  return "?";
}

std::string to_string(MugRim rim) {
  return rim == MugRim::flat ? "flat" : "rounded";
}

std::string to_string(MugHandle handle) {
  switch (handle) {
    case MugHandle::none:
      return "none";
    case MugHandle::c_shape:
      return "c_shape";
    case MugHandle::d_loop:
      return "d_loop";
  }
  return "?";
}

std::string to_string(HandleSection section) {
  return section == HandleSection::round ? "round" : "flat";
}

std::string to_string(MugFamily family) {
  return family == MugFamily::classic ? "classic" : "varied";
}

MugFamily mug_family_from_string(const std::string& name) {
  if (name == "classic") return MugFamily::classic;
  if (name == "varied") return MugFamily::varied;
  throw Error("unknown mug family '" + name + "' (choose classic or varied)");
}

}  // namespace graspecmf::geometry
