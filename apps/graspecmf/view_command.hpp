#pragma once
// `graspecmf view FILE.h5 [--mesh-root DIR] [--max N] [--successful-only] [--out view.html]
// [--png sheet.png]`: the object and its grasps as gripper markers (green = success, red = failure,
// blue = unlabelled) as an interactive 3-D page (--out) and/or a PNG contact sheet of six views
// (--png); at least one of the two is required. Both files are written atomically.

#include <CLI/CLI.hpp>

namespace graspecmf::apps {

// Registers the view subcommand on app.
void add_view_command(CLI::App& app);

}  // namespace graspecmf::apps
