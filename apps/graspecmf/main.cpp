// The graspecmf command line: parses arguments, dispatches to a subcommand, and turns any error
// into one line on stderr (the first line of its message) with exit code 1.

#include <CLI/CLI.hpp>
#include <cstring>
#include <iostream>
#include <string>

#include "convert_command.hpp"
#include "graspecmf/core/error.hpp"
#include "graspecmf/core/heap_retention.hpp"
#include "graspecmf/core/version.hpp"
#include "inspect_command.hpp"
#include "make_dataset_command.hpp"
#include "prepare_mesh_command.hpp"
#include "render_view_command.hpp"
#ifdef GRASPECMF_WITH_TORCH
#include "blas_kernels.hpp"
#include "model_commands.hpp"
#endif
#include "simulate_command.hpp"
#include "view_command.hpp"

int main(int argc, char** argv) {
#ifdef GRASPECMF_WITH_TORCH
  if (argc > 1 && (std::strcmp(argv[1], "train") == 0 || std::strcmp(argv[1], "sample") == 0 ||
                   std::strcmp(argv[1], "evaluate") == 0)) {
    graspecmf::apps::prefer_fast_blas_kernels(argv);
    graspecmf::retain_freed_memory();
  }
#endif
  CLI::App app("graspecmf: SO(3)-equivariant 6-DoF grasp generation (GraspECMF)", "graspecmf");
  app.set_version_flag("--version", std::string("graspecmf ") + graspecmf::kVersion);
  app.require_subcommand(1);
  graspecmf::apps::add_inspect_command(app);
  graspecmf::apps::add_simulate_command(app);
  graspecmf::apps::add_make_dataset_command(app);
  graspecmf::apps::add_prepare_mesh_command(app);
  graspecmf::apps::add_view_command(app);
  graspecmf::apps::add_convert_command(app);
  graspecmf::apps::add_render_view_command(app);
#ifdef GRASPECMF_WITH_TORCH
  graspecmf::apps::add_model_commands(app);
#endif
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    // Our errors are one line; a library's (LibTorch's allocator, with its backtrace) may not be.
    std::cerr << "error: " << graspecmf::first_line(e.what()) << "\n";
    return 1;
  }
  return 0;
}
