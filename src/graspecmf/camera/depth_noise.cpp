#include "graspecmf/camera/depth_noise.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "graspecmf/core/error.hpp"
#include "graspecmf/core/random.hpp"

namespace graspecmf::camera {

void validate(const DepthNoise& n, const std::string& what) {
  for (const double v : {n.sigma_base, n.sigma_quadratic, n.sigma_angle, n.edge_jump, n.baseline,
                         n.subpixel, n.edge_dropout, n.random_dropout}) {
    if (!std::isfinite(v) || v < 0.0) throw Error(what + ": noise parameters must be at least 0");
  }
  if (n.edge_dropout > 1.0 || n.random_dropout > 1.0) {
    throw Error(what + ": a dropout probability must be at most 1");
  }
  if (!(n.grazing_start_degrees >= 0.0) || !(n.grazing_start_degrees < n.grazing_end_degrees) ||
      !(n.grazing_end_degrees <= 90.0)) {
    throw Error(what + ": need 0 ≤ grazing start < grazing end ≤ 90 degrees");
  }
  if (n.subpixel > 0.0 && n.baseline == 0.0) {
    throw Error(what + ": disparity quantisation needs a positive baseline");
  }
}

DepthImage noisy_depth(const RenderedView& view, const Intrinsics& intrinsics,
                       const DepthNoise& noise, std::uint64_t seed) {
  validate(noise, "noisy_depth");
  const DepthImage& exact = view.depth;
  DepthImage out = exact;
  Rng rng(seed);
  const double start = noise.grazing_start_degrees * M_PI / 180.0;
  const double end = noise.grazing_end_degrees * M_PI / 180.0;
  // True if a 4-neighbour of (u, v) has no reading or a depth more than edge_jump away.
  const auto at_edge = [&](int u, int v, float z) {
    const auto jump = [&](int uu, int vv) {
      if (uu < 0 || vv < 0 || uu >= exact.width || vv >= exact.height) return false;
      const float other = exact.at(uu, vv);
      return other == 0.0f || std::abs(other - z) > noise.edge_jump;
    };
    return jump(u + 1, v) || jump(u - 1, v) || jump(u, v + 1) || jump(u, v - 1);
  };
  const double quantum = noise.subpixel;
  const double focal_baseline = intrinsics.fx * noise.baseline;
  for (int v = 0; v < exact.height; ++v) {
    for (int u = 0; u < exact.width; ++u) {
      const std::size_t i = static_cast<std::size_t>(v) * exact.width + u;
      // Every pixel draws the same numbers, hit or not, so no pixel's fate shifts another's.
      const double lose = rng.uniform(), lose_at_edge = rng.uniform(), lose_grazing = rng.uniform();
      const double gauss = rng.normal();
      const double z = exact.metres[i];
      out.metres[i] = 0.0f;
      if (z == 0.0) continue;
      const double angle = std::acos(std::clamp<double>(view.incidence[i], 0.0, 1.0));
      const double grazing = std::clamp((angle - start) / (end - start), 0.0, 1.0);
      if (lose < noise.random_dropout || lose_grazing < grazing) continue;
      if (lose_at_edge < noise.edge_dropout && at_edge(u, v, exact.metres[i])) continue;
      const double capped = std::min(angle, end);
      const double sigma = noise.sigma_base + noise.sigma_quadratic * (z - 0.4) * (z - 0.4) +
                           noise.sigma_angle * capped * capped /
                               (std::sqrt(z) * (M_PI / 2 - capped) * (M_PI / 2 - capped));
      double measured = z + sigma * gauss;
      if (quantum > 0.0 && measured > 0.0) {
        const double disparity = std::round(focal_baseline / measured / quantum) * quantum;
        measured = disparity > 0.0 ? focal_baseline / disparity : 0.0;
      }
      out.metres[i] = measured > 0.0 ? static_cast<float>(measured) : 0.0f;
    }
  }
  return out;
}

}  // namespace graspecmf::camera
