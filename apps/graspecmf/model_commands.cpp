#include "model_commands.hpp"

#include <fmt/format.h>
#include <torch/torch.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "cli_checks.hpp"
#include "depth_input.hpp"
#include "graspecmf/core/atomic_file.hpp"
#include "graspecmf/core/error.hpp"
#include "graspecmf/core/output_paths.hpp"
#include "graspecmf/core/progress.hpp"
#include "graspecmf/data/acronym_file.hpp"
#include "graspecmf/data/splits.hpp"
#include "graspecmf/eval/evaluate.hpp"
#include "graspecmf/eval/partial_report.hpp"
#include "graspecmf/formats/grasp_files.hpp"
#include "graspecmf/geometry/mesh_io.hpp"
#include "graspecmf/geometry/object_size.hpp"
#include "graspecmf/geometry/point_cloud_io.hpp"
#include "graspecmf/gripper/cloud_grasp_filter.hpp"
#include "graspecmf/gripper/panda.hpp"
#include "graspecmf/models/bundled_model.hpp"
#include "graspecmf/models/device.hpp"
#include "graspecmf/models/model_folder.hpp"
#include "graspecmf/models/object_grasps.hpp"
#include "graspecmf/sim/trial_config.hpp"
#include "graspecmf/train/trainer.hpp"
#include "object_units.hpp"

namespace graspecmf::apps {
namespace fs = std::filesystem;
using nlohmann::json;
namespace {

constexpr int kDefaultThreads = 1;

// ---- train ----

struct TrainArgs {
  std::string config, data, out, init;
  int threads = kDefaultThreads;
  std::string device = "cpu";
};

void run_train(const TrainArgs& a) {
  std::vector<fs::path> input_folders{a.data};
  if (!a.init.empty()) input_folders.emplace_back(a.init);
  require_distinct_output("--out", a.out, {a.config}, input_folders);
  const models::TrainConfig config = models::read_train_config(a.config);
  const c10::Device device = models::parse_device(a.device);
  std::unique_ptr<ProgressLine> progress;
  train::TrainCallbacks callbacks;
  callbacks.step = [&](std::int64_t step, std::int64_t total) {
    if (!progress)
      progress = std::make_unique<ProgressLine>("training", static_cast<std::size_t>(total));
    progress->update(static_cast<std::size_t>(step));
  };
  callbacks.record = [&](const json& record) {
    if (record.contains("val_emd")) {
      std::cerr << fmt::format("\nstep {}: validation loss {:.4f}, EMD {:.4f}\n",
                               record["step"].get<std::int64_t>(), record["val_loss"].get<double>(),
                               record["val_emd"].get<double>());
    }
  };
  callbacks.skipped = [](const std::string& name, const std::string& reason) {
    std::cerr << "note: not training on " << name << ": " << reason << "\n";
  };
  const train::TrainResult result =
      train::train(config, a.data, a.out, a.threads, callbacks, device, a.init);
  if (progress) progress->finish();
  std::cout << fmt::format(
      "{} steps done{} in {}; run folder {}\n", result.steps,
      result.resumed_from > 0 ? fmt::format(" (resumed from step {})", result.resumed_from) : "",
      format_duration(result.seconds), a.out);
}

// ---- sampling settings, shared by sample and evaluate ----

// Command-line overrides of a run's sampling settings; unset ones keep the run's.
struct SamplingOverrides {
  std::string solver;
  int steps = 0;                                               // 0: the run's
  double guidance = std::numeric_limits<double>::quiet_NaN();  // NaN: the run's
  int clouds = 0;                                              // 0: the run's
  std::size_t max_draws = 0;                                   // 0: the run's
  bool fill_rejected = false;                                  // false: the run's

  models::SamplingSettings apply(models::SamplingSettings settings) const {
    if (!solver.empty()) settings.solver = solver;
    if (steps > 0) settings.steps = steps;
    if (!std::isnan(guidance)) settings.guidance = guidance;
    if (clouds > 0) settings.clouds = clouds;
    if (max_draws > 0) settings.max_draws = max_draws;
    if (fill_rejected) settings.fill_rejected = true;
    return settings;
  }
};

void add_sampling_options(CLI::App* cmd, SamplingOverrides& o) {
  cmd->add_option("--solver", o.solver, "euler, heun or rkmk4 (default: the run's)");
  cmd->add_option("--steps", o.steps, "ODE steps")->check(CLI::Range(1, 100000));
  cmd->add_option("--guidance", o.guidance,
                  "Classifier-free guidance weight (0 = unconditional; default: the run's)")
      ->check(kFiniteNumber);
  cmd->add_option("--clouds", o.clouds,
                  "Encode this many point clouds of the object and average their z (default: "
                  "the run's, 1 as in the paper)")
      ->check(CLI::Range(1, 64));
  cmd->add_option("--max-draws", o.max_draws,
                  "With --reject-collisions or --reject-shallow: draw at most this many grasps "
                  "(per test rotation for evaluate) before giving up (default: the run's, "
                  "0: up to 8 rounds); not in the paper")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1} << 30));
  cmd->add_flag("--fill-rejected", o.fill_rejected,
                "With the filters: when fewer grasps pass than asked for (after --max-draws or 8 "
                "rounds), make up the shortfall with the first rejected grasps instead of "
                "stopping (default: the run's); not in the paper");
}

void add_device_option(CLI::App* cmd, std::string& device) {
  cmd->add_option("--device", device,
                  "cpu (default), or cuda / cuda:N with a CUDA build of LibTorch");
}

// --reject-collisions and --reject-shallow, checking `whose` grasps against `points`.
void add_filter_flags(CLI::App* cmd, gripper::GraspChecks& checks, const std::string& whose,
                      const std::string& points) {
  cmd->add_flag(
      "--refine", checks.refine,
      fmt::format("Move each of {} whose open hand holds any of {} back along its approach "
                  "axis (≤ {:g} cm) and sideways along its closing axis (≤ {:g} cm) by "
                  "the least step of a {:g} mm grid that frees it; not in the paper",
                  whose, points, 100 * gripper::kRefineMaxRetreat,
                  100 * gripper::kRefineMaxSideShift, 1000 * gripper::kRefineStep));
  cmd->add_flag(
      "--reject-collisions", checks.collisions,
      "Keep only " + whose + " whose open hand holds none of " + points + "; not in the paper");
  cmd->add_flag("--reject-shallow", checks.shallow,
                fmt::format("Keep only {} with some of {} between the open fingers at least "
                            "{:g} cm below the fingertips; not in the paper",
                            whose, points, 100 * gripper::kMinGraspDepth));
}

// ---- sample ----

struct SampleArgs {
  std::string model, mesh, points, acronym, mesh_root, out;
  ObjectUnits units;
  DepthInput view;
  std::string object_mesh;  // recorded as the output's object for --points and --depth
  double object_scale = 1.0;
  SamplingOverrides sampling;
  gripper::GraspChecks checks;
  std::size_t num = 100;
  int threads = kDefaultThreads;
  std::string device = "cpu";
  std::uint64_t seed = 0;
};

// The object as sample sees it (models::ObjectPoints) and the record to write beside the grasps.
struct SampleInput {
  models::ObjectPoints points;
  data::AcronymObjectInfo info;
};

// points_per_cloud × clouds: the model's input points.
SampleInput sample_input(const SampleArgs& a, std::size_t points_per_cloud, std::size_t clouds) {
  const std::size_t points = points_per_cloud * clouds;
  const int sources = !a.mesh.empty() + !a.points.empty() + !a.acronym.empty() + a.view.given();
  if (sources != 1) {
    throw Error("sample: give exactly one of --mesh, --points, --acronym or --depth");
  }
  if (!a.object_mesh.empty() && a.points.empty() && !a.view.given()) {
    throw Error("sample: --object-mesh is for --points and --depth (a mesh input records itself)");
  }
  SampleInput input;
  data::AcronymObjectInfo& info = input.info;
  if (a.view.given()) {
    if (!a.units.units.empty() || a.units.scale != 1.0) {
      throw Error(
          "sample: --units and --scale do not apply to --depth (its unit is fixed by the "
          "file: millimetres in a PNG unless --depth-unit, metres in a float .npy)");
    }
    camera::ViewPoints view = a.view.read(a.seed);
    if (!a.units.size.allow_any_size) a.view.check_size(view.object);
    info.file = a.object_mesh.empty() ? a.view.depth : a.object_mesh;
    info.scale = a.object_mesh.empty() ? 1.0 : a.object_scale;
    input.points =
        models::object_points(std::move(view), points_per_cloud, clouds, a.checks, a.seed);
    return input;
  }
  if (!a.points.empty()) {
    std::vector<Eigen::Vector3d> cloud = geometry::read_point_cloud(a.points);
    for (Eigen::Vector3d& p : cloud) p *= a.units.metres_per_unit();
    a.units.size.check(cloud, a.points);
    // The output says how the file's units map to metres.
    info.file = a.object_mesh.empty() ? a.points : a.object_mesh;
    info.scale = a.object_mesh.empty() ? a.units.metres_per_unit() : a.object_scale;
    input.points = models::object_points(std::move(cloud), points, a.checks, a.seed);
    return input;
  }
  geometry::TriangleMesh mesh;
  if (!a.mesh.empty()) {
    mesh = geometry::scaled(geometry::read_mesh(a.mesh), a.units.metres_per_unit());
    a.units.size.check(mesh.vertices, a.mesh);
    info.file = a.mesh;
    info.scale = a.units.metres_per_unit();
  } else {
    const data::AcronymGraspFile record = data::read_acronym_file(a.acronym);
    info = record.object;
    mesh = geometry::scaled(
        geometry::read_mesh(data::find_object_mesh(a.acronym, info.file, a.mesh_root)), info.scale);
    a.units.size.check(mesh.vertices, a.acronym + "'s object", geometry::ScaleSource::kFile);
  }
  input.points = models::object_points(mesh, points, a.checks, a.seed);
  return input;
}

void run_sample(const SampleArgs& a) {
  const fs::path model = models::model_or_bundled(a.model);
  std::vector<fs::path> inputs = models::model_folder_files(model);
  inputs.insert(inputs.end(), {a.mesh, a.points, a.acronym, a.object_mesh});
  for (const fs::path& file : a.view.files()) inputs.push_back(file);
  require_distinct_output("--out", a.out, inputs);
  at::set_num_threads(a.threads);
  const models::TrainedModel trained =
      models::load_trained_model(model, models::parse_device(a.device));
  const models::SamplingSettings settings = a.sampling.apply(trained.config.sampling);
  const SampleInput input =
      sample_input(a, static_cast<std::size_t>(trained.config.model.encoder.points),
                   static_cast<std::size_t>(settings.clouds));
  const auto start = std::chrono::steady_clock::now();
  std::size_t passed = 0;
  const std::vector<lie::Pose> grasps = models::sample_object_grasps(
      trained, input.points, a.num, settings, a.checks, a.seed, &passed);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  formats::GraspSet record;
  for (const lie::Pose& g : grasps) record.poses.push_back(g.matrix());
  record.object = input.info;
  formats::write_grasps(record, a.out);
  const std::string shortfall =
      passed < a.num ? fmt::format("; only {} passed, the rest are rejected grasps", passed) : "";
  std::cout << fmt::format("{} grasps ({}{}{}) in {:.2f} s → {}\n", a.num,
                           trained.model->sampler(settings), eval::filter_note(a.checks), shortfall,
                           seconds, a.out);
}

// ---- evaluate ----

struct EvaluateArgs {
  std::string model, data, split = "test", acronym, mesh_root, out, markdown, train_data;
  std::string sim_config, cache;  // for --success
  bool baselines = false, views = false, table = false;
  SizeCheck size;  // of an --acronym object
  gripper::GraspChecks checks;
  SamplingOverrides sampling;
  std::size_t num = 0;
  std::size_t success = 0;  // grasps simulated per object and rotation; 0: no simulation
  std::uint64_t seed = 0;
  int threads = kDefaultThreads;
  std::string device = "cpu";
};

// The objects of one split of a dataset folder with splits.json.
std::vector<data::GraspObject> split_objects(const std::string& root, const std::string& split) {
  if (!fs::is_directory(root)) throw Error(root + ": no such dataset folder");
  const data::AcronymDataset dataset = data::AcronymDataset::open(root);
  const fs::path split_file = fs::path(root) / data::kSplitFileName;
  if (!fs::exists(split_file)) throw Error(split_file.string() + ": no split file");
  const std::vector<data::GraspObject> objects =
      data::AcronymDataset::load(dataset.select(data::read_split_file(split_file).part(split)));
  if (objects.empty()) throw Error(root + ": the " + split + " split is empty");
  return objects;
}

std::vector<data::GraspObject> evaluation_objects(const EvaluateArgs& a) {
  if (a.data.empty() == a.acronym.empty()) {
    throw Error("evaluate: give exactly one of --data or --acronym");
  }
  if (!a.acronym.empty()) {
    const data::AcronymGraspFile record = data::read_acronym_file(a.acronym);
    data::require_panda_gripper(record, a.acronym);
    data::GraspObject object;
    object.name = fs::path(a.acronym).stem().string();
    object.mesh = geometry::scaled(
        geometry::read_mesh(data::find_object_mesh(a.acronym, record.object.file, a.mesh_root)),
        record.object.scale);
    a.size.check(object.mesh.vertices, a.acronym + "'s object", geometry::ScaleSource::kFile);
    object.grasps = record.successful_grasps();
    object.info = record.object;
    if (object.grasps.empty()) throw Error(a.acronym + ": no successful grasps to compare with");
    return {object};
  }
  return split_objects(a.data, a.split);
}

void run_evaluate(const EvaluateArgs& a) {
  const std::string model = models::model_or_bundled(a.model).string();
  std::vector<fs::path> inputs = models::model_folder_files(model);
  inputs.insert(inputs.end(), {a.acronym, a.sim_config});
  for (const auto& [option, out] : {std::pair{"--out", a.out}, {"--markdown", a.markdown}}) {
    require_distinct_output(option, out, inputs, {a.data, a.train_data});
  }
  require_distinct_output("--markdown", a.markdown, {a.out});
  at::set_num_threads(a.threads);
  const models::TrainedModel trained =
      models::load_trained_model(model, models::parse_device(a.device));
  const std::vector<data::GraspObject> objects = evaluation_objects(a);
  std::vector<data::GraspObject> training;
  if (a.baselines) {
    const std::string root = a.train_data.empty() ? a.data : a.train_data;
    if (root.empty()) throw Error("evaluate: --baselines with --acronym needs --train-data DIR");
    training = split_objects(root, "train");
  }
  if (a.success == 0 && !(a.sim_config.empty() && a.cache.empty())) {
    throw Error("evaluate: --sim-config and --cache apply only with --success K");
  }
  eval::EvaluationOptions options;
  options.num = a.num;
  options.success = a.success;
  options.checks = a.checks;
  if (a.views) options.input.views = camera::ViewSampling();
  options.input.table = a.table;
  options.sampling = a.sampling.apply(trained.config.sampling);
  options.seed = a.seed;
  options.threads = a.threads;
  options.trial = sim::read_trial_config(a.sim_config);
  options.cache = a.cache;
  eval::EvaluationCallbacks callbacks;
  callbacks.note = [](const std::string& text) { std::cerr << "note: " << text << "\n"; };
  // With --out, the finished objects are kept in OUT.partial until the report is written, and a
  // rerun of the same evaluation resumes from them.
  const fs::path partial = a.out.empty() ? fs::path() : fs::path(a.out + ".partial");
  std::vector<eval::ObjectResult> resumed;
  nlohmann::json identity;
  if (!partial.empty()) {
    identity = eval::evaluation_identity(trained, model, objects, a.baselines, options);
    std::string why;
    resumed = eval::read_partial_report(partial, identity, why);
    if (!why.empty()) callbacks.note(why);
    if (!resumed.empty()) {
      callbacks.note(fmt::format("resuming after {} of {} objects, from {}", resumed.size(),
                                 objects.size(), partial.string()));
    }
    callbacks.finished = [&](const std::vector<eval::ObjectResult>& done) {
      eval::write_partial_report(partial, identity, done);
    };
  }
  ProgressLine progress("evaluating", objects.size());
  callbacks.progress = [&](std::size_t done, std::size_t) { progress.update(done); };
  const eval::EvaluationReport report = eval::evaluate_model(
      trained, model, objects, a.baselines ? &training : nullptr, options, callbacks, resumed);
  progress.finish();
  std::cout << eval::markdown_table(report) << eval::summary(report) << "\n";
  if (!a.out.empty()) write_file_atomically(a.out, eval::to_json(report).dump(1) + "\n");
  if (!a.markdown.empty()) write_file_atomically(a.markdown, eval::to_markdown(report));
  if (!partial.empty()) fs::remove(partial);
}

}  // namespace

void add_model_commands(CLI::App& app) {
  auto t = std::make_shared<TrainArgs>();
  CLI::App* train_cmd =
      app.add_subcommand("train", "Train the GraspECMF model on a dataset folder");
  train_cmd->add_option("--config", t->config, "Training config (JSON, e.g. configs/cpu.json)")
      ->required();
  train_cmd->add_option("--data", t->data, "ACRONYM-style dataset folder")->required();
  train_cmd->add_option("--out", t->out, "Run folder (resumed if it holds this config)")
      ->required();
  train_cmd->add_option("--threads", t->threads, "LibTorch threads")->check(CLI::Range(1, 256));
  train_cmd->add_option("--init", t->init,
                        "Start from this model's weights (a model or run folder with the same "
                        "network settings, e.g. models/mugs): fine-tuning");
  add_device_option(train_cmd, t->device);
  train_cmd->callback([t] { run_train(*t); });

  auto x = std::make_shared<std::pair<std::string, std::string>>();
  CLI::App* export_cmd = app.add_subcommand(
      "export-model",
      "Write a run's inference model: config.json and float32 weights, no optimiser");
  export_cmd->add_option("--model", x->first, "Run folder of a trained model")->required();
  export_cmd->add_option("--out", x->second, "Output folder (config.json, model.pt)")->required();
  export_cmd->callback([x] {
    require_distinct_output("--out", x->second, {}, {x->first});
    const std::int64_t step = models::export_model(x->first, x->second);
    std::cout << fmt::format("exported step {} of {} → {}\n", step, x->first, x->second);
  });

  auto s = std::make_shared<SampleArgs>();
  CLI::App* sample_cmd = app.add_subcommand("sample", "Generate grasps for an object");
  sample_cmd->add_option("--model", s->model,
                         "Trained run or exported model folder (default: the bundled mugs model)");
  sample_cmd->add_option("--mesh", s->mesh, "Object mesh (.obj/.stl/.ply/.glb/.gltf)");
  sample_cmd->add_option("--points", s->points, "Point cloud (.xyz/.txt/.npy/.ply)");
  s->units.add_options(sample_cmd);
  s->view.add_options(sample_cmd);
  sample_cmd->add_option("--object-mesh", s->object_mesh,
                         "With --points or --depth: the object's mesh, in the output frame, to "
                         "record in the output so that simulate and view can use it (default: "
                         "the input file is recorded)");
  sample_cmd
      ->add_option("--object-scale", s->object_scale,
                   "Metres per unit of --object-mesh (recorded as its scale)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  sample_cmd->add_option("--acronym", s->acronym, "ACRONYM grasp file naming the object");
  sample_cmd->add_option("--mesh-root", s->mesh_root, "Folder the ACRONYM file's mesh is in");
  sample_cmd->add_option("--num", s->num, "Grasps to generate (at most 10^6)")
      ->check(CLI::Range(1, 1000000));
  add_sampling_options(sample_cmd, s->sampling);
  add_filter_flags(sample_cmd, s->checks, "grasps",
                   "the object's points (every point of --points, or a dense surface sample of "
                   "the mesh)");
  sample_cmd->add_option("--seed", s->seed, "Seed for the cloud and the prior");
  sample_cmd->add_option("--threads", s->threads, "LibTorch threads")->check(CLI::Range(1, 256));
  add_device_option(sample_cmd, s->device);
  sample_cmd
      ->add_option("--out", s->out,
                   "Output grasps: .h5 (ACRONYM), .json, .yaml (Isaac Sim), .npy (GraspNet) "
                   "or .npz (Contact-GraspNet); docs/formats.md")
      ->required();
  sample_cmd->callback([s] { run_sample(*s); });

  auto e = std::make_shared<EvaluateArgs>();
  CLI::App* eval_cmd = app.add_subcommand("evaluate", "EMD of a trained model against real grasps");
  eval_cmd->add_option("--model", e->model,
                       "Trained run or exported model folder (default: the bundled mugs model)");
  eval_cmd->add_option("--data", e->data, "Dataset folder with splits.json");
  eval_cmd->add_option("--split", e->split, "train, val or test");
  eval_cmd->add_option("--acronym", e->acronym, "A single ACRONYM grasp file instead");
  eval_cmd->add_option("--mesh-root", e->mesh_root, "Folder the ACRONYM file's mesh is in");
  e->size.add_option(eval_cmd);
  eval_cmd->add_option("--num", e->num, "Grasps per object and rotation (default: all successful)");
  add_sampling_options(eval_cmd, e->sampling);
  add_filter_flags(eval_cmd, e->checks,
                   "generated grasps (and, with --baselines, nearest-object grasps)",
                   "a dense surface sample of the object");
  eval_cmd->add_option("--seed", e->seed, "Seed for clouds, references and the prior");
  eval_cmd->add_option("--threads", e->threads, "LibTorch threads")->check(CLI::Range(1, 256));
  add_device_option(eval_cmd, e->device);
  eval_cmd->add_flag("--views", e->views,
                     "Give the model one random camera's noisy view of each object per rotation "
                     "instead of its whole surface (docs/camera.md)");
  eval_cmd->add_flag("--table", e->table,
                     "Keep the grasps above the table the object stands on (its lowest z)");
  eval_cmd->add_flag("--baselines", e->baselines,
                     "Also report random grasps, the nearest training object's grasps and the "
                     "sampling floor (two disjoint draws of the object's own grasps; needs 2n)");
  eval_cmd->add_option("--train-data", e->train_data,
                       "Dataset whose train split the nearest-object baseline searches");
  eval_cmd
      ->add_option("--success", e->success,
                   "Also simulate the first K generated grasps of each rotation (and, with "
                   "--baselines, K of the nearest object's) and report the success rate; "
                   "the paper uses 100")
      ->check(CLI::Range(std::size_t{1}, std::size_t{100000}));
  eval_cmd->add_option("--sim-config", e->sim_config,
                       "Trial config for --success (JSON, as for simulate --config)");
  eval_cmd->add_option("--cache", e->cache, "Convex-decomposition cache folder for --success");
  eval_cmd->add_option("--out", e->out, "JSON report");
  eval_cmd->add_option("--markdown", e->markdown, "Markdown report");
  eval_cmd->callback([e] { run_evaluate(*e); });
}

}  // namespace graspecmf::apps
