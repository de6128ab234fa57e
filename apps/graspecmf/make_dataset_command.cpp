#include "make_dataset_command.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <thread>
#include <vector>

#include "cli_checks.hpp"
#include "graspecmf/core/error.hpp"
#include "graspecmf/core/output_paths.hpp"
#include "graspecmf/core/progress.hpp"
#include "graspecmf/dataset/make_dataset.hpp"
#include "graspecmf/geometry/mesh_io.hpp"
#include "object_units.hpp"

namespace graspecmf::apps {
namespace {

struct Preset {
  const char* name;
  std::size_t mugs, val, test, grasps;
  std::uint64_t seed;
  // The trial settings (sim::TrialConfig JSON) that give the contact model the preset was
  // labelled with; a --config may not set them.
  const char* fixed_trial;
  geometry::MugFamily family;
  std::size_t attempts_per_grasp;  // surface points drawn per requested candidate; 0: the default
};
// mugs-v1: the project's first training set (docs/dataset.md): 130 mugs × 2000 candidates, 100
// train / 10 val / 20 test, labelled before the simulator had pad normals and its own convex
// collider. mugs-v2: the same labelling budget spread over twice the shapes (200 mugs × 1000
// candidates, 150 / 20 / 30), labelled with both, in the mesh frame (before 2026-12-04). mugs-v3:
// the varied family (flared lips, uneven surfaces, cups without handles, wider sizes), 180 mugs ×
// 300 candidates, 140 / 15 / 25, labelled in the simulation frame; the bundled model's first
// training set. mugs-v4: 160 new mugs of the varied family with 20 times mugs-v3's draw budget, so
// that small and wide mugs get their 300 candidates and enter the split (the bundled model's
// fine-tuning set).
constexpr Preset kPresets[] = {
    {"mugs-v1", 130, 10, 20, 2000, 20261122,
     R"({"pad_normal_inset": -1.0, "mujoco_convex": true, "legacy_object_frame": true,
         "contact_reference_mass": 0.0})",
     geometry::MugFamily::classic, 0},
    {"mugs-v2", 200, 20, 30, 1000, 20261202,
     R"({"legacy_object_frame": true, "contact_reference_mass": 0.0})",
     geometry::MugFamily::classic, 0},
    {"mugs-v3", 180, 15, 25, 300, 20261204,
     R"({"legacy_object_frame": false, "contact_reference_mass": 0.0130879738})",
     geometry::MugFamily::varied, 0},
    {"mugs-v4", 160, 15, 25, 300, 20261206,
     R"({"legacy_object_frame": false, "contact_reference_mass": 0.0130879738})",
     geometry::MugFamily::varied, 1000}};

struct MakeDatasetArgs {
  std::string preset, meshes, out, config_file, cache, family = "varied";
  std::size_t mugs = 0, grasps = 2000;
  std::uint64_t seed = 0;
  bool grasps_given = false, seed_given = false, no_repair = false;
  ObjectUnits units;  // of --meshes
  double density = 150.0;
  int threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
};

dataset::MakeDatasetOptions options_from(const MakeDatasetArgs& a) {
  const int sources = !a.preset.empty() + (a.mugs > 0) + !a.meshes.empty();
  if (sources != 1) throw Error("make-dataset: give exactly one of --preset, --mugs or --meshes");
  require_distinct_output("--out", a.out, {a.config_file}, {a.meshes});
  dataset::MakeDatasetOptions o;
  o.out = a.out;
  o.seed = a.seed;
  o.density = a.density;
  o.threads = a.threads;
  o.cache = a.cache;
  o.repair = !a.no_repair;
  nlohmann::json trial = sim::read_trial_config_json(a.config_file);
  o.candidates.num_grasps = a.grasps;
  if (!a.preset.empty()) {
    const auto* preset = std::find_if(std::begin(kPresets), std::end(kPresets),
                                      [&](const Preset& p) { return a.preset == p.name; });
    if (preset == std::end(kPresets)) {
      std::vector<std::string> known;
      for (const Preset& p : kPresets) known.emplace_back(p.name);
      throw Error("make-dataset: unknown preset '" + a.preset +
                  "' (known: " + fmt::format("{}", fmt::join(known, ", ")) + ")");
    }
    if (a.grasps_given || a.seed_given) {
      throw Error(std::string("make-dataset: --preset ") + preset->name +
                  " fixes the candidates per object and the seed; remove --grasps and --seed");
    }
    o.candidates.num_grasps = preset->grasps;
    o.candidates.max_attempts = preset->attempts_per_grasp * preset->grasps;
    o.preset = preset->name;
    o.seed = preset->seed;
    o.objects = dataset::procedural_mug_sources(preset->mugs, preset->seed, preset->family);
    o.val_count = preset->val;
    o.test_count = preset->test;
    const nlohmann::json fixed = nlohmann::json::parse(preset->fixed_trial);
    for (const auto& [key, value] : fixed.items()) {
      if (trial.contains(key)) {
        throw Error(std::string("make-dataset: --preset ") + preset->name + " fixes " + key +
                    " (the contact model it was labelled with); remove it from --config");
      }
      trial[key] = value;
    }
  } else if (a.mugs > 0) {
    o.objects =
        dataset::procedural_mug_sources(a.mugs, a.seed, geometry::mug_family_from_string(a.family));
  } else {
    o.objects = dataset::mesh_folder_sources(a.meshes, a.units.metres_per_unit());
    // Wrong units would make every object of the folder fail: say so once, before labelling.
    for (const dataset::ObjectSource& s : o.objects) {
      geometry::TriangleMesh mesh;
      try {
        mesh = geometry::read_mesh(s.mesh_file);
      } catch (const Error&) {
        continue;  // make_dataset reports an unreadable mesh and skips its object
      }
      a.units.size.check(geometry::scaled(mesh, s.scale).vertices, s.mesh_file.string());
    }
  }
  o.trial = sim::trial_config_from_json(trial);
  return o;
}

void run(const MakeDatasetArgs& a) {
  const dataset::MakeDatasetOptions o = options_from(a);
  std::unique_ptr<ProgressLine> progress;
  dataset::DatasetProgress callbacks;
  callbacks.trials = [&](std::size_t done, std::size_t total) {
    if (!progress) {  // the output folder has been checked by now
      std::cerr << fmt::format("make-dataset: {} objects × {} candidates into {} on {} threads\n",
                               o.objects.size(), o.candidates.num_grasps, o.out.string(),
                               o.threads);
      progress = std::make_unique<ProgressLine>("grasps", total);
    }
    progress->update(done);
  };
  std::size_t made = 0, resumed = 0, skipped = 0;
  callbacks.object = [&](const dataset::ObjectOutcome& r) {
    if (!r.skipped.empty()) {
      ++skipped;
      std::cerr << "\nskipped " << r.name << ": " << r.skipped << "\n";
    } else {
      if (!r.repaired.empty()) std::cerr << "\nnote: " << r.repaired << "\n";
      ++(r.resumed ? resumed : made);
    }
  };
  const std::vector<dataset::ObjectOutcome> outcomes = dataset::make_dataset(o, callbacks);
  if (progress) progress->finish();
  std::size_t with_100 = 0, usable = 0;
  for (const dataset::ObjectOutcome& r : outcomes) {
    if (!r.skipped.empty()) continue;
    ++usable;
    with_100 += r.successful >= 100;
  }
  std::cout << fmt::format(
      "{} objects: {} made, {} already there, {} skipped; {} of {} have ≥ 100 successful "
      "grasps\nwrote {}/manifest.json, splits.json, preview.png\n",
      outcomes.size(), made, resumed, skipped, with_100, usable, o.out.string());
}

}  // namespace

void add_make_dataset_command(CLI::App& app) {
  auto a = std::make_shared<MakeDatasetArgs>();
  CLI::App* cmd = app.add_subcommand(
      "make-dataset", "Generate an ACRONYM-style dataset: objects, grasp candidates, sim labels");
  cmd->add_option(
      "--preset", a->preset,
      "Named dataset: mugs-v1 (130 mugs × 2000 candidates, 100/10/20 split, legacy contact "
      "model), mugs-v2 (200 mugs × 1000 candidates, 150/20/30, mesh-frame simulator) or mugs-v3 "
      "(180 varied mugs × 300 candidates, 140/15/25, current simulator)");
  cmd->add_option("--mugs", a->mugs, "Number of procedural mugs")->check(CLI::Range(1, 100000));
  cmd->add_option("--family", a->family,
                  "Procedural family of --mugs: varied (default) or classic (mugs-v1/v2 shapes)")
      ->check(CLI::IsMember({"varied", "classic"}));
  CLI::Option* seed = cmd->add_option("--seed", a->seed, "Seed for mugs, candidates and the split");
  cmd->add_option(
      "--meshes", a->meshes,
      "Folder of your own .obj/.stl/.ply/.glb/.gltf meshes (open ones are alpha-wrapped)");
  a->units.add_options(cmd);
  cmd->add_option("--density", a->density, "Object density, kg/m³ (ACRONYM: 150)")
      ->check(kPositiveFiniteNumber);
  CLI::Option* grasps =
      cmd->add_option("--grasps", a->grasps, "Candidates per object (default 2000)")
          ->check(CLI::Range(1, 1000000));
  cmd->add_option("--threads", a->threads, "Worker threads")->check(CLI::Range(1, 256));
  cmd->add_option("--out", a->out, "Output folder (resumed if it holds the same dataset)")
      ->required();
  cmd->add_option("--config", a->config_file, "Trial parameters (JSON; defaults for missing keys)");
  cmd->add_option("--cache", a->cache, "Convex-decomposition cache folder");
  cmd->add_flag("--no-repair", a->no_repair,
                "Skip --meshes meshes that are not closed solids instead of wrapping them");
  cmd->callback([a, seed, grasps] {
    a->seed_given = seed->count() > 0;
    a->grasps_given = grasps->count() > 0;
    run(*a);
  });
}

}  // namespace graspecmf::apps
