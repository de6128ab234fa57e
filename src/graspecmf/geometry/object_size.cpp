#include "graspecmf/geometry/object_size.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "graspecmf/core/error.hpp"

namespace graspecmf::geometry {

const std::vector<LengthUnit>& length_units() {
  static const std::vector<LengthUnit> units = {
      {"mm", 0.001}, {"cm", 0.01}, {"m", 1.0}, {"in", 0.0254}};
  return units;
}

double metres_per_unit(const std::string& name) {
  for (const LengthUnit& unit : length_units()) {
    if (name == unit.name) return unit.metres;
  }
  throw Error("unknown unit '" + name + "' (choose mm, cm, m or in)");
}

double largest_side(const std::vector<Vec3>& points) {
  if (points.empty()) return 0.0;
  Vec3 lo = points.front(), hi = points.front();
  for (const Vec3& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).maxCoeff();
}

namespace {

// A length in the most readable of m, cm, mm, µm, or km.
std::string length_text(double metres) {
  if (metres >= 1000.0) return fmt::format("{:.3g} km", metres / 1000.0);
  if (metres >= 1.0) return fmt::format("{:.3g} m", metres);
  if (metres >= 0.01) return fmt::format("{:.3g} cm", metres * 100.0);
  if (metres >= 0.001) return fmt::format("{:.3g} mm", metres * 1000.0);
  return fmt::format("{:.3g} µm", metres * 1e6);
}

}  // namespace

void require_plausible_size(const std::vector<Vec3>& points, const std::string& what,
                            ScaleSource source) {
  if (points.empty()) return;
  const double size = largest_side(points);
  if (size >= kMinObjectSize && size <= kMaxObjectSize) return;
  // How the caller spells the options: command-line flags or Python keywords.
  const bool keywords = source == ScaleSource::kKeywords;
  const std::string units = keywords ? "units='{0}'" : "--units {0}";
  const std::string scale = keywords ? "scale={:.3g}" : "--scale {:.3g}";
  // The unit that, read instead of metres, puts the size nearest 10 cm (in log scale) and in range.
  std::string hint;
  double best = INFINITY;
  for (const LengthUnit& unit : length_units()) {
    const double metric = size * unit.metres;
    if (unit.metres == 1.0 || metric < kMinObjectSize || metric > kMaxObjectSize) continue;
    const double distance = std::abs(std::log(metric / 0.1));
    if (distance < best) {
      best = distance;
      hint = source != ScaleSource::kFile
                 ? fmt::format(fmt::runtime("; if it is in {0}, give " + units + " (or " +
                                            (keywords ? "scale={1:g}" : "--scale {1:g}") +
                                            "), which makes it {2}"),
                               unit.name, unit.metres, length_text(metric))
                 : fmt::format(
                       "; the file's scale is likely off by {0:g} (the mesh in {1}), "
                       "which would make it {2}",
                       unit.metres, unit.name, length_text(metric));
    }
  }
  if (hint.empty() && size > 0.0) {
    hint = source != ScaleSource::kFile
               ? fmt::format(fmt::runtime("; " + scale + " would make it 10 cm"), 0.1 / size)
               : fmt::format("; check the file's scale (×{:.3g} would make it 10 cm)", 0.1 / size);
  }
  throw Error(fmt::format(
      "{} is {} across, {} than a graspable object ({} to {}){}, or {} to go on", what,
      length_text(size), size < kMinObjectSize ? "smaller" : "larger", length_text(kMinObjectSize),
      length_text(kMaxObjectSize), hint, keywords ? "allow_any_size=True" : "--allow-any-size"));
}

}  // namespace graspecmf::geometry
