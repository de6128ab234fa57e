#pragma once
// `graspecmf simulate FILE.h5 [--mesh-root DIR] [--out results.h5|.json] [--threads N]
// [--compare-labels] [--config trial.json] [--every K] [--cache DIR]`: labels the file's grasps
// with the MuJoCo shake test.

#include <CLI/CLI.hpp>

namespace graspecmf::apps {

// Registers the simulate subcommand on app.
void add_simulate_command(CLI::App& app);

}  // namespace graspecmf::apps
