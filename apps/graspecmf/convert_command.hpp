#pragma once
// `graspecmf convert IN OUT [--from F] [--to F] [--isaac-gripper-frame acronym|panda_hand]
// [--graspnet-depth D] [--graspnet-object-id K] [--object FILE --scale S]`: rewrites a grasp file
// in another format (by extension unless named), changing the gripper frame as each format needs
// (docs/formats.md); prints what the target format drops. OUT is written atomically.

#include <CLI/CLI.hpp>

namespace graspecmf::apps {

// Registers the convert subcommand on app.
void add_convert_command(CLI::App& app);

}  // namespace graspecmf::apps
