#pragma once
// `graspecmf view FILE.h5 [--mesh-root DIR] [--max N] [--successful-only] --out view.html`: an
// interactive 3-D page of the object and its grasps as gripper markers (green = success, red =
// failure, blue = unlabelled).

#include <CLI/CLI.hpp>

namespace graspecmf::apps {

// Registers the view subcommand on app.
void add_view_command(CLI::App& app);

}  // namespace graspecmf::apps
