#pragma once
// `graspecmf evaluate` as a library call: a trained model judged on objects with known successful
// grasps, by EMD at the fixed test rotations, optionally against the reference baselines and in
// the simulator (docs/evaluation.md).

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "graspecmf/data/dataset.hpp"
#include "graspecmf/eval/evaluation.hpp"
#include "graspecmf/eval/report.hpp"
#include "graspecmf/gripper/cloud_grasp_filter.hpp"
#include "graspecmf/models/model_folder.hpp"
#include "graspecmf/sim/trial_config.hpp"

namespace graspecmf::eval {

struct EvaluationOptions {
  std::size_t num = 0;      // grasps per object and rotation; 0: as many as it has successful
  std::size_t success = 0;  // the first K grasps of each rotation simulated; 0: no simulation
  gripper::GraspChecks checks;
  InputSetting input;  // whole surfaces or single views, with or without the table
  models::SamplingSettings sampling;
  std::uint64_t seed = 0;  // clouds, reference grasps, the prior and the bootstrap
  int threads = 1;         // simulator threads
  sim::TrialConfig trial;
  std::filesystem::path cache;  // convex decompositions; empty: sim::default_decomposition_cache
};

struct EvaluationCallbacks {
  std::function<void(std::size_t done, std::size_t total)> progress;  // after every object
  std::function<void(const std::string& text)> note;  // e.g. that an open mesh was closed
  // After every object evaluated here: the results so far, resumed ones included (to save them).
  std::function<void(const std::vector<ObjectResult>& done)> finished;
};

// Evaluates `model` (loaded from the folder `model_name`) on each object; with `training`, also the
// reference baselines, whose nearest-object search covers those objects. The first objects take
// the `resumed` results of an interrupted run of the same evaluation as they are (each object's
// result depends only on it and the options). Throws Error if objects is empty, if `resumed` does
// not name the first objects in order, or as evaluate_object, evaluate_baselines and the simulator.
EvaluationReport evaluate_model(const models::TrainedModel& model, const std::string& model_name,
                                const std::vector<data::GraspObject>& objects,
                                const std::vector<data::GraspObject>* training,
                                const EvaluationOptions& options,
                                const EvaluationCallbacks& callbacks = {},
                                const std::vector<ObjectResult>& resumed = {});

// What the saved results of an evaluate_model run must match to be resumed: the model (folder,
// step, parameters, device), the objects' names, whether there are baselines, and every option
// that changes a result (all but threads and the cache).
nlohmann::json evaluation_identity(const models::TrainedModel& model, const std::string& model_name,
                                   const std::vector<data::GraspObject>& objects, bool baselines,
                                   const EvaluationOptions& options);

}  // namespace graspecmf::eval
