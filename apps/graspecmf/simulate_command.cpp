#include "simulate_command.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <thread>
#include <vector>

#include "graspecmf/core/atomic_file.hpp"
#include "graspecmf/core/error.hpp"
#include "graspecmf/core/output_lock.hpp"
#include "graspecmf/core/output_paths.hpp"
#include "graspecmf/core/progress.hpp"
#include "graspecmf/core/version.hpp"
#include "graspecmf/data/dataset.hpp"
#include "graspecmf/geometry/mesh_io.hpp"
#include "graspecmf/geometry/watertight_cache.hpp"
#include "graspecmf/sim/batch.hpp"
#include "graspecmf/sim/label_agreement.hpp"
#include "graspecmf/sim/scene_object.hpp"
#include "object_units.hpp"

namespace graspecmf::apps {
namespace fs = std::filesystem;
namespace {

struct SimulateOptions {
  std::string grasp_file, mesh_root, out, config_file, cache;
  int threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  std::size_t every = 1;
  bool compare_labels = false;
  SizeCheck size;
  bool no_repair = false;
  std::vector<double> move;  // x, y, z (m), yaw (degrees); empty: not moved
};

// The rigid motion of --move: a turn by yaw degrees about the gravity axis (z), then (x, y, z).
lie::Pose move_motion(const std::vector<double>& move) {
  lie::Pose motion;
  if (move.empty()) return motion;
  for (double v : move) {
    if (!std::isfinite(v)) throw Error("--move: every value must be a finite number");
  }
  motion.R = Eigen::AngleAxisd(move[3] * M_PI / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  motion.p = Eigen::Vector3d(move[0], move[1], move[2]);
  return motion;
}

nlohmann::json agreement_json(const sim::LabelAgreement& a) {
  return {{"count", a.count},
          {"accuracy", a.accuracy},
          {"both_success", a.both_success},
          {"both_failure", a.both_failure},
          {"reference_success_simulated_failure", a.only_reference_success},
          {"reference_failure_simulated_success", a.only_simulated_success},
          {"best_shaking_threshold", a.best_shaking_threshold},
          {"best_threshold_accuracy", a.best_threshold_accuracy}};
}

// The file's record restricted to the simulated grasps, with our labels and motion integrals.
data::AcronymGraspFile labelled_record(const data::AcronymGraspFile& record,
                                       const std::vector<std::size_t>& indices,
                                       const std::vector<sim::TrialResult>& results) {
  data::AcronymGraspFile out = record;
  out.transforms.clear();
  for (std::size_t i : indices) out.transforms.push_back(record.transforms[i]);
  out.qualities = sim::acronym_qualities(results);
  return out;
}

void run(const SimulateOptions& o) {
  require_distinct_output("--out", o.out, {o.grasp_file, o.config_file});
  std::optional<OutputLock> lock;  // held until the labels are written
  if (!o.out.empty()) lock.emplace(OutputLock::file(o.out));
  const sim::TrialConfig config = sim::read_trial_config(o.config_file);
  const data::AcronymGraspFile record = data::read_acronym_file(o.grasp_file);
  data::require_panda_gripper(record, o.grasp_file);
  if (o.compare_labels && !record.qualities) {
    throw Error(o.grasp_file + ": --compare-labels needs the file's object_in_gripper labels");
  }
  // Simulated where --move puts the object and its grasps; written back in the file's frame.
  const lie::Pose motion = move_motion(o.move);
  const data::AcronymGraspFile simulated = data::moved_rigidly(record, motion);
  const fs::path mesh_file = data::find_object_mesh(o.grasp_file, record.object.file, o.mesh_root);
  const geometry::TriangleMesh open_mesh = geometry::transformed(
      geometry::scaled(geometry::read_mesh(mesh_file), record.object.scale), motion);
  o.size.check(open_mesh.vertices, o.grasp_file + "'s object", geometry::ScaleSource::kFile);
  geometry::ClosedMeshOptions closing;
  closing.repair = !o.no_repair;
  const geometry::ClosedMesh closed =
      geometry::closed_mesh_for_simulation(open_mesh, mesh_file.string(), closing);
  if (closed.repaired)
    std::cerr << "note: " << geometry::repair_note(mesh_file.string(), closed.report) << "\n";
  const geometry::TriangleMesh& mesh = closed.mesh;
  const fs::path cache = o.cache.empty() ? sim::default_decomposition_cache() : fs::path(o.cache);
  const sim::SceneObject object = sim::make_scene_object(mesh, simulated.object, config, {}, cache);

  std::vector<std::size_t> indices;
  std::vector<lie::Pose> grasps;
  std::vector<std::int64_t> reference;
  for (std::size_t i = 0; i < record.size(); i += o.every) {
    indices.push_back(i);
    grasps.push_back(lie::Pose::from_matrix(simulated.transforms[i]));
    if (record.qualities) reference.push_back(record.qualities->object_in_gripper[i]);
  }
  ProgressLine progress("simulating", grasps.size());
  const auto start = std::chrono::steady_clock::now();
  const std::vector<sim::TrialResult> results =
      sim::run_trials(object, grasps, config, o.threads,
                      [&](std::size_t done, std::size_t) { progress.update(done); });
  progress.finish();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::size_t successes = 0, unstable = 0;
  for (const sim::TrialResult& r : results) {
    successes += r.success;
    unstable += r.unstable;
  }
  std::cout << fmt::format(
      "{} grasps, {} successful ({:.1f} %), {} unstable; {} convex parts; {:.1f} s on {} threads "
      "({:.1f} grasps/s)\n",
      results.size(), successes, 100.0 * successes / results.size(), unstable, object.parts.size(),
      seconds, o.threads, results.size() / seconds);

  nlohmann::json summary = {{"software_version", kVersion},
                            {"grasp_file", o.grasp_file},
                            {"config", sim::to_json(config)},
                            {"convex_parts", object.parts.size()},
                            {"seconds", seconds},
                            {"threads", o.threads}};
  if (o.compare_labels) {
    const sim::LabelAgreement a = sim::compare_labels(results, reference);
    std::cout << fmt::format(
        "agreement with the file's labels: {:.1f} % of {}\n"
        "                      simulated success  simulated failure\n"
        "  reference success   {:17}  {:17}\n"
        "  reference failure   {:17}  {:17}\n"
        "best threshold on shaking motion: {:.4g} ({:.1f} % agreement)\n",
        100.0 * a.accuracy, a.count, a.both_success, a.only_reference_success,
        a.only_simulated_success, a.both_failure, a.best_shaking_threshold,
        100.0 * a.best_threshold_accuracy);
    summary["agreement"] = agreement_json(a);
  }
  if (o.out.empty()) return;
  const data::AcronymGraspFile labelled = labelled_record(record, indices, results);
  if (fs::path(o.out).extension() == ".h5") {
    data::write_acronym_file(labelled, o.out);
    return;
  }
  nlohmann::json& trials = summary["trials"] = nlohmann::json::array();
  for (std::size_t k = 0; k < results.size(); ++k) {
    const sim::TrialResult& r = results[k];
    trials.push_back({{"index", indices[k]},
                      {"success", r.success},
                      {"unstable", r.unstable},
                      {"closing_linear", r.closing_linear},
                      {"closing_angular", r.closing_angular},
                      {"shaking_linear", r.shaking_linear},
                      {"shaking_angular", r.shaking_angular},
                      {"closing_slip", r.closing_slip},
                      {"shaking_slip", r.shaking_slip},
                      {"final_opening", r.final_opening}});
  }
  write_file_atomically(o.out, summary.dump(1) + "\n");
}

}  // namespace

void add_simulate_command(CLI::App& app) {
  auto o = std::make_shared<SimulateOptions>();
  CLI::App* cmd = app.add_subcommand(
      "simulate", "Label the grasps of an ACRONYM file with the MuJoCo shake test");
  cmd->add_option("file", o->grasp_file, "ACRONYM grasp file (.h5)")->required();
  cmd->add_option("--mesh-root", o->mesh_root, "Folder the file's object/file is relative to");
  cmd->add_option("--out", o->out,
                  "Write labels + motion metrics: .h5 (ACRONYM layout) or .json (with the config)");
  cmd->add_option("--threads", o->threads, "Worker threads")->check(CLI::Range(1, 256));
  cmd->add_option("--every", o->every, "Simulate every K-th grasp only")
      ->check(CLI::Range(1, 1000000));
  cmd->add_option("--config", o->config_file, "Trial parameters (JSON; defaults for missing keys)");
  cmd->add_option("--cache", o->cache, "Convex-decomposition cache folder");
  cmd->add_option("--move", o->move,
                  "Simulate the object and its grasps moved rigidly: X Y Z (m) YAW (degrees about "
                  "the gravity axis); labels should not change (a frame-invariance check)")
      ->expected(4);
  o->size.add_option(cmd);
  cmd->add_flag("--no-repair", o->no_repair,
                "Refuse an object mesh that is not a closed solid instead of alpha-wrapping it");
  cmd->add_flag("--compare-labels", o->compare_labels,
                "Report agreement with the file's object_in_gripper labels");
  cmd->callback([o] { run(*o); });
}

}  // namespace graspecmf::apps
