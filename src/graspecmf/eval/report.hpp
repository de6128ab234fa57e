#pragma once
// The result of `graspecmf evaluate` as a value: per-object EMDs, reference baselines and simulated
// success, with the summary statistics derived from them and the JSON and Markdown forms the
// command writes (docs/evaluation.md). Torch-free.

#include <cstddef>
#include <cstdint>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

#include "graspecmf/gripper/cloud_grasp_filter.hpp"
#include "graspecmf/sim/batch.hpp"

namespace graspecmf::eval {

// The scores of the reference baselines on one object (evaluate --baselines).
struct BaselineScores {
  double random_emd = 0.0;    // uniformly random grasps around the object
  std::string nearest;        // the training object closest in shape
  double nearest_emd = 0.0;   // its successful grasps, moved to this object's centroid
  std::size_t nearest_n = 0;  // grasps in that comparison: n, or fewer if it has fewer than n
  // The sampling floor: the reference against a disjoint second draw of the object's own grasps,
  // when it has at least 2n successful grasps.
  std::optional<double> floor_emd;
};

struct ObjectResult {
  std::string name;
  std::size_t n = 0;        // grasps compared per rotation
  std::vector<double> emd;  // one per test rotation
  double mean_emd = 0.0;
  double sampling_seconds = 0.0;  // wall time drawing its n grasps at every rotation
  std::optional<BaselineScores> baselines;
  std::optional<sim::GraspOutcomes> success;          // the model's grasps in the simulator
  std::optional<sim::GraspOutcomes> nearest_success;  // the nearest object's grasps
  // With a grasp filter: how many of its n grasps per rotation, all rotations together, passed it
  // (fewer than all only when the sampling filled a shortfall with rejected grasps).
  std::optional<std::size_t> passed;
};

// How the grasps were drawn.
struct ReportSettings {
  std::string sampler;  // the generator's own words (GeneratorImpl::sampler)
  std::string solver;
  int steps = 0;
  double guidance = 0.0;
  int clouds = 1;
  gripper::GraspChecks checks;
  std::string input = "full";  // "full" or "views", maybe " above the table" (to_string)
  std::size_t max_draws = 0;   // with the filters, the most grasps drawn per rotation; 0: no limit
  bool fill_rejected = false;  // a shortfall made up with rejected grasps instead of an error
};

struct EvaluationReport {
  std::string model;  // the model folder
  std::int64_t step = 0;
  std::int64_t parameters = 0;  // the model's trained numbers
  ReportSettings settings;
  std::uint64_t seed = 0;  // also the seed of the paired comparisons' bootstrap
  std::vector<ObjectResult> objects;
};

// The report as `evaluate --out` writes it: settings, per-object entries and the summary values
// (mean EMDs, paired comparisons against the nearest object, the floor comparison, success).
// Throws Error for a report without objects.
nlohmann::json to_json(const EvaluationReport& report);
// The report's "sampling" entry.
nlohmann::json to_json(const ReportSettings& settings);
// One object's entry in the report's JSON: "object", "n", "emd", "mean_emd", "sampling_seconds"
// and whichever of "passed", the baselines' and the success fields it has.
nlohmann::json to_json(const ObjectResult& object);
// The ObjectResult of such an entry (numbers round-trip exactly). Throws Error naming the entry's
// missing or malformed field.
ObjectResult object_result_from_json(const nlohmann::json& entry);
// The per-object Markdown table (one row per object; baseline and success columns when present).
std::string markdown_table(const EvaluationReport& report);
// The one-paragraph summary printed under the table. Throws Error for a report without objects.
std::string summary(const EvaluationReport& report);
// The `evaluate --markdown` document: a title naming the model and settings, table and summary.
std::string to_markdown(const EvaluationReport& report);
// The filter in a summary: "", or e.g. ", refined, colliding and shallow grasps rejected".
std::string filter_note(const gripper::GraspChecks& checks);

}  // namespace graspecmf::eval
