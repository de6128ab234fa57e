#include "graspecmf/eval/evaluate.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <optional>

#include "graspecmf/core/error.hpp"
#include "graspecmf/eval/evaluation.hpp"
#include "graspecmf/geometry/ray_cast.hpp"
#include "graspecmf/geometry/watertight_cache.hpp"
#include "graspecmf/sim/batch.hpp"
#include "graspecmf/sim/scene_object.hpp"

namespace graspecmf::eval {
namespace {

// The first `count` grasps of a list (all of them if it is shorter).
std::vector<lie::Pose> first(const std::vector<lie::Pose>& grasps, std::size_t count) {
  return {grasps.begin(),
          grasps.begin() + static_cast<std::ptrdiff_t>(std::min(count, grasps.size()))};
}

// Simulated outcomes of the first `count` grasps of each list, summed over the lists.
sim::GraspOutcomes simulated_outcomes(const sim::SceneObject& scene,
                                      const geometry::MeshRayCaster& mesh,
                                      const std::vector<std::vector<lie::Pose>>& lists,
                                      std::size_t count, const sim::TrialConfig& config,
                                      int threads) {
  sim::GraspOutcomes total;
  for (const std::vector<lie::Pose>& grasps : lists) {
    total += sim::grasp_outcomes(scene, mesh, first(grasps, count), config, threads);
  }
  return total;
}

// The model's (and, with baselines, the nearest object's) grasps of one object in the simulator.
void simulate(const data::GraspObject& object, const ObjectEvaluation& e,
              const BaselineEvaluation* baseline, const EvaluationOptions& o,
              const EvaluationCallbacks& callbacks, ObjectResult& result) {
  // The simulator needs a closed solid: an open mesh is alpha-wrapped, with a note.
  const geometry::ClosedMesh closed =
      geometry::closed_mesh_for_simulation(object.mesh, object.name);
  if (closed.repaired && callbacks.note) {
    callbacks.note(geometry::repair_note(object.name, closed.report));
  }
  const sim::SceneObject scene =
      sim::make_scene_object(closed.mesh, object.info, o.trial, {},
                             o.cache.empty() ? sim::default_decomposition_cache() : o.cache);
  const geometry::MeshRayCaster mesh(closed.mesh);
  result.success = simulated_outcomes(scene, mesh, e.generated, o.success, o.trial, o.threads);
  if (baseline != nullptr) {
    result.nearest_success =
        simulated_outcomes(scene, mesh, {baseline->nearest_grasps}, o.success, o.trial, o.threads);
  }
}

// The report's model and settings, without objects.
EvaluationReport report_header(const models::TrainedModel& model, const std::string& model_name,
                               const EvaluationOptions& o) {
  EvaluationReport report;
  report.model = model_name;
  report.step = model.step;
  for (const at::Tensor& p : model.model->parameters()) report.parameters += p.numel();
  report.settings = {model.model->sampler(o.sampling),
                     o.sampling.solver,
                     o.sampling.steps,
                     o.sampling.guidance,
                     o.sampling.clouds,
                     o.checks,
                     to_string(o.input),
                     o.sampling.max_draws,
                     o.sampling.fill_rejected};
  report.seed = o.seed;
  return report;
}

}  // namespace

EvaluationReport evaluate_model(const models::TrainedModel& model, const std::string& model_name,
                                const std::vector<data::GraspObject>& objects,
                                const std::vector<data::GraspObject>* training,
                                const EvaluationOptions& o, const EvaluationCallbacks& callbacks,
                                const std::vector<ObjectResult>& resumed) {
  if (objects.empty()) throw Error("evaluate: no objects to evaluate on");
  if (resumed.size() > objects.size()) throw Error("evaluate: more resumed results than objects");
  for (std::size_t i = 0; i < resumed.size(); ++i) {
    if (resumed[i].name != objects[i].name) {
      throw Error("evaluate: resumed result " + std::to_string(i + 1) + " is of " +
                  resumed[i].name + ", not " + objects[i].name);
    }
  }
  std::optional<TrainingShapes> shapes;
  if (training != nullptr && resumed.size() < objects.size()) {
    shapes.emplace(*training, o.seed, o.input.views);
  }
  EvaluationReport report = report_header(model, model_name, o);
  report.objects = resumed;
  if (callbacks.progress && !resumed.empty()) callbacks.progress(resumed.size(), objects.size());
  for (std::size_t i = resumed.size(); i < objects.size(); ++i) {
    const data::GraspObject& object = objects[i];
    const std::size_t n = o.num == 0 ? object.grasps.size() : o.num;
    const ObjectFilter filter = object_filter(object, o.checks, o.seed);
    const ObjectEvaluation e = evaluate_object(*model.model, object, model.config, test_rotations(),
                                               n, o.sampling, o.seed, filter, o.input);
    ObjectResult& result = report.objects.emplace_back();
    result.name = e.name;
    result.n = e.n;
    result.emd = e.emd;
    result.mean_emd = e.mean_emd;
    result.sampling_seconds = e.sampling_seconds;
    result.passed = e.passed;
    std::optional<BaselineEvaluation> baseline;
    if (shapes) {
      baseline.emplace(evaluate_baselines(object, *shapes, n, o.seed, filter, o.input,
                                          e.views.empty() ? nullptr : &e.views.front()));
      result.baselines = baseline->scores;
    }
    if (o.success > 0) simulate(object, e, baseline ? &*baseline : nullptr, o, callbacks, result);
    if (callbacks.finished) callbacks.finished(report.objects);
    if (callbacks.progress) callbacks.progress(i + 1, objects.size());
  }
  return report;
}

nlohmann::json evaluation_identity(const models::TrainedModel& model, const std::string& model_name,
                                   const std::vector<data::GraspObject>& objects, bool baselines,
                                   const EvaluationOptions& o) {
  const EvaluationReport header = report_header(model, model_name, o);
  nlohmann::json names = nlohmann::json::array();
  for (const data::GraspObject& object : objects) names.push_back(object.name);
  return {{"model", header.model},
          {"step", header.step},
          {"parameters", header.parameters},
          {"device", model.model->parameters().front().device().str()},
          {"sampling", to_json(header.settings)},
          {"seed", header.seed},
          {"num", o.num},
          {"success", o.success},
          {"trial", sim::to_json(o.trial)},
          {"baselines", baselines},
          {"objects", names}};
}

}  // namespace graspecmf::eval
