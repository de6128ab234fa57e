#pragma once
// The options every command that reads a user's mesh or point cloud shares: the size check that
// catches wrong units (--allow-any-size skips it), and the units themselves (--units or --scale).

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "graspecmf/geometry/object_size.hpp"

namespace graspecmf::apps {

struct SizeCheck {
  bool allow_any_size = false;

  // Adds --allow-any-size to cmd.
  void add_option(CLI::App* cmd);
  // geometry::require_plausible_size on metric points, unless --allow-any-size.
  void check(const std::vector<geometry::Vec3>& points, const std::string& what,
             geometry::ScaleSource source = geometry::ScaleSource::kOptions) const;
};

struct ObjectUnits {
  double scale = 1.0;  // --scale: input units to metres
  std::string units;   // --units mm|cm|m|in; excludes --scale
  SizeCheck size;

  // Adds --units, --scale (mutually exclusive) and --allow-any-size to cmd.
  void add_options(CLI::App* cmd);
  // The factor from input units to metres, from --units or --scale.
  double metres_per_unit() const;
};

}  // namespace graspecmf::apps
