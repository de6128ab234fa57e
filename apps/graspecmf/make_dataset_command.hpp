#pragma once
// `graspecmf make-dataset (--preset NAME | --mugs N [--seed S] | --meshes DIR [--scale S])
// --out DIR [--grasps 2000] [--threads T] [--density D] [--config trial.json] [--cache DIR]`:
// procedural mugs or the user's meshes, ACRONYM-style candidates labelled by the shake test,
// written as an ACRONYM-style dataset folder (resumable).

#include <CLI/CLI.hpp>

namespace graspecmf::apps {

// Registers the make-dataset subcommand on app.
void add_make_dataset_command(CLI::App& app);

}  // namespace graspecmf::apps
