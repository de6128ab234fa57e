#include "object_units.hpp"

#include "cli_checks.hpp"

namespace graspecmf::apps {

void SizeCheck::add_option(CLI::App* cmd) {
  cmd->add_flag("--allow-any-size", allow_any_size,
                "Accept objects outside 1 cm – 1 m (the size check catches wrong units or scale)");
}

void SizeCheck::check(const std::vector<geometry::Vec3>& points, const std::string& what,
                      geometry::ScaleSource source) const {
  if (!allow_any_size) geometry::require_plausible_size(points, what, source);
}

void ObjectUnits::add_options(CLI::App* cmd) {
  CLI::Option* scale_option = cmd->add_option("--scale", scale, "Input units to metres (a factor)")
                                  ->check(kPositiveFiniteNumber);
  cmd->add_option("--units", units, "Input units: mm, cm, m or in (instead of --scale)")
      ->check(CLI::IsMember({"mm", "cm", "m", "in"}))
      ->excludes(scale_option);
  size.add_option(cmd);
}

double ObjectUnits::metres_per_unit() const {
  return units.empty() ? scale : geometry::metres_per_unit(units);
}

}  // namespace graspecmf::apps
