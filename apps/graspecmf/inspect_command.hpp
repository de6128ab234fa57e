#pragma once
// `graspecmf inspect FILE.h5 [--mesh-root DIR] [--json]`: summary of an ACRONYM grasp file and its
// mesh, with the file's stored volume and centre of mass checked against the mesh.

#include <CLI/CLI.hpp>

namespace graspecmf::apps {

// Registers the inspect subcommand on app; running it prints to stdout and throws Error on failure.
void add_inspect_command(CLI::App& app);

}  // namespace graspecmf::apps
