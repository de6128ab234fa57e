#pragma once
// `graspecmf render-view --mesh M [--units U | --scale S] --out DIR [--views N] [--seed S]
// [--azimuth A --elevation E --distance D] [--intrinsics K] [--noise default|none]`: depth
// images of a mesh standing on a table, as a camera above the table sees it, with the object's
// mask, the intrinsics and the camera pose, ready for `sample --depth`.

#include <CLI/CLI.hpp>

namespace graspecmf::apps {

// Registers the render-view subcommand on app; running it writes the views under --out and throws
// Error on failure.
void add_render_view_command(CLI::App& app);

}  // namespace graspecmf::apps
