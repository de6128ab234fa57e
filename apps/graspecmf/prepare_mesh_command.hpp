#pragma once
// `graspecmf prepare-mesh IN --out OUT.obj [--units U | --scale S] [--alpha A] [--offset O]
// [--force] [--cache DIR] [--json]`: a user's mesh (open pieces, holes, flipped faces, any unit)
// made into a closed, outward metric solid by alpha wrapping, with a report of what changed.

#include <CLI/CLI.hpp>

namespace graspecmf::apps {

// Registers the prepare-mesh subcommand on app; running it writes OUT, prints the report to stdout
// and throws Error on failure.
void add_prepare_mesh_command(CLI::App& app);

}  // namespace graspecmf::apps
