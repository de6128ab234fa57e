#include "graspecmf/eval/report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <numeric>

#include "graspecmf/core/error.hpp"
#include "graspecmf/metrics/paired_comparison.hpp"

namespace graspecmf::eval {
using nlohmann::json;
namespace {

// Whether every object has the optional part `member` (a report has all or none of each).
template <typename Member>
bool all_have(const EvaluationReport& report, Member member) {
  const auto has = [&](const ObjectResult& o) { return (o.*member).has_value(); };
  const bool all = std::all_of(report.objects.begin(), report.objects.end(), has);
  if (!all && std::any_of(report.objects.begin(), report.objects.end(), has)) {
    throw Error("evaluation report: only some objects have baselines or success results");
  }
  return all && !report.objects.empty();
}

void require_objects(const EvaluationReport& report) {
  if (report.objects.empty()) throw Error("evaluation report: no objects");
}

// The mean of f(object) over the objects.
template <typename F>
double mean_over(const EvaluationReport& report, F f) {
  double total = 0;
  for (const ObjectResult& o : report.objects) total += f(o);
  return total / static_cast<double>(report.objects.size());
}

json success_json(const sim::SuccessCount& c) {
  return {{"successes", c.successes}, {"trials", c.trials}, {"rate", c.rate()}};
}

// The success count's JSON plus the collision rate and the success of the collision-free grasps.
json outcomes_json(const sim::GraspOutcomes& o) {
  json j = success_json(o.all);
  j["collision_rate"] = o.collision_rate();
  j["collision_free"] = success_json(o.collision_free);
  return j;
}

// "71.0 % (12 % collide)" for a table cell.
std::string outcomes_cell(const sim::GraspOutcomes& o) {
  return fmt::format("{:.1f} % ({:.0f} % collide)", 100 * o.all.rate(), 100 * o.collision_rate());
}

json comparison_json(const metrics::PairedComparison& c) {
  return {{"wins", c.wins},
          {"losses", c.losses},
          {"sign_test_p", c.sign_test_p},
          {"mean_difference", c.mean_difference},
          {"ci_95", {c.ci_low, c.ci_high}}};
}

// The statistics the JSON and the summary share, computed once.
struct Derived {
  bool baselines = false, success = false;
  double mean_random = 0, mean_nearest = 0;
  metrics::MeanInterval emd;                  // the mean over objects of their mean EMDs
  std::optional<metrics::MeanInterval> rate;  // the mean over objects of their success rates
  double seconds_per_100 = 0;                 // sampling wall time per 100 generated grasps
  std::optional<double> passed;  // the fraction of generated grasps the filter kept, if one ran
  metrics::PairedComparison nearest;              // model EMD against nearest-object EMD
  std::optional<double> mean_floor;               // when every object has a floor
  std::optional<metrics::FloorComparison> floor;  // when some object has one
  sim::GraspOutcomes model_success, nearest_success;
  metrics::PairedComparison success_comparison;  // failure rates, model against nearest
};

Derived derive(const EvaluationReport& r) {
  require_objects(r);
  Derived d;
  d.baselines = all_have(r, &ObjectResult::baselines);
  d.success = all_have(r, &ObjectResult::success);
  std::vector<double> emds;
  double seconds = 0, grasps = 0;
  for (const ObjectResult& o : r.objects) {
    emds.push_back(o.mean_emd);
    seconds += o.sampling_seconds;
    grasps += static_cast<double>(o.n * o.emd.size());
  }
  d.emd = metrics::bootstrap_mean(emds, r.seed);
  d.seconds_per_100 = grasps > 0 ? 100 * seconds / grasps : 0;
  if (all_have(r, &ObjectResult::passed) && grasps > 0) {
    double passed = 0;
    for (const ObjectResult& o : r.objects) passed += static_cast<double>(*o.passed);
    d.passed = passed / grasps;
  }
  if (d.baselines) {
    std::vector<double> nearest, floored_model, floored_nearest, floors;
    for (const ObjectResult& o : r.objects) {
      nearest.push_back(o.baselines->nearest_emd);
      if (o.baselines->floor_emd) {
        floored_model.push_back(o.mean_emd);
        floored_nearest.push_back(o.baselines->nearest_emd);
        floors.push_back(*o.baselines->floor_emd);
      }
    }
    d.mean_random = mean_over(r, [](const ObjectResult& o) { return o.baselines->random_emd; });
    d.mean_nearest = mean_over(r, [](const ObjectResult& o) { return o.baselines->nearest_emd; });
    d.nearest = metrics::compare_paired(emds, nearest, r.seed);
    if (floors.size() == r.objects.size()) {
      d.mean_floor =
          std::accumulate(floors.begin(), floors.end(), 0.0) / static_cast<double>(floors.size());
    }
    if (!floors.empty()) {
      d.floor = metrics::compare_with_floor(floored_model, floored_nearest, floors);
    }
  }
  if (d.success) {
    std::vector<double> rates, model_failures, nearest_failures;  // failures: lower is better
    for (const ObjectResult& o : r.objects) {
      d.model_success += *o.success;
      rates.push_back(o.success->all.rate());
      model_failures.push_back(1 - rates.back());
      if (d.baselines) {
        if (!o.nearest_success) {
          throw Error("evaluation report: " + o.name + " lacks the nearest object's success");
        }
        d.nearest_success += *o.nearest_success;
        nearest_failures.push_back(1 - o.nearest_success->all.rate());
      }
    }
    d.rate = metrics::bootstrap_mean(rates, r.seed);
    if (d.baselines) {
      d.success_comparison = metrics::compare_paired(model_failures, nearest_failures, r.seed);
    }
  }
  return d;
}

}  // namespace

std::string filter_note(const gripper::GraspChecks& checks) {
  const std::string refined = checks.refine ? ", refined" : "";
  if (!checks.rejects()) return refined;
  return fmt::format("{}, {} grasps rejected", refined,
                     checks.collisions && checks.shallow ? "colliding and shallow"
                     : checks.collisions                 ? "colliding"
                                                         : "shallow");
}

json to_json(const ReportSettings& s) {
  return {{"sampler", s.sampler},
          {"solver", s.solver},
          {"steps", s.steps},
          {"guidance", s.guidance},
          {"clouds", s.clouds},
          {"refine", s.checks.refine},
          {"reject_collisions", s.checks.collisions},
          {"reject_shallow", s.checks.shallow},
          {"max_draws", s.max_draws},
          {"fill_rejected", s.fill_rejected},
          {"input", s.input}};
}

json to_json(const ObjectResult& o) {
  json entry = {{"object", o.name},
                {"n", o.n},
                {"emd", o.emd},
                {"mean_emd", o.mean_emd},
                {"sampling_seconds", o.sampling_seconds}};
  if (o.passed) entry["passed"] = *o.passed;
  if (o.baselines) {
    const BaselineScores& b = *o.baselines;
    entry["random_emd"] = b.random_emd;
    entry["nearest_training_object"] = b.nearest;
    entry["nearest_emd"] = b.nearest_emd;
    entry["nearest_n"] = b.nearest_n;
    entry["floor_emd"] = b.floor_emd ? json(*b.floor_emd) : json(nullptr);
  }
  if (o.success) entry["success"] = outcomes_json(*o.success);
  if (o.nearest_success) entry["nearest_success"] = outcomes_json(*o.nearest_success);
  return entry;
}

ObjectResult object_result_from_json(const json& entry) {
  std::string field = "object";
  try {
    const auto get = [&](const json& from, const char* key) -> const json& {
      field = key;
      return from.at(key);
    };
    const auto outcomes = [&](const json& j) {
      sim::GraspOutcomes o;
      o.all = {get(j, "successes").get<std::size_t>(), get(j, "trials").get<std::size_t>()};
      const json& clear = get(j, "collision_free");
      o.collision_free = {get(clear, "successes").get<std::size_t>(),
                          get(clear, "trials").get<std::size_t>()};
      return o;
    };
    ObjectResult o;
    o.name = get(entry, "object").get<std::string>();
    o.n = get(entry, "n").get<std::size_t>();
    o.emd = get(entry, "emd").get<std::vector<double>>();
    o.mean_emd = get(entry, "mean_emd").get<double>();
    o.sampling_seconds = get(entry, "sampling_seconds").get<double>();
    if (entry.contains("passed")) o.passed = get(entry, "passed").get<std::size_t>();
    if (entry.contains("random_emd")) {
      BaselineScores& b = o.baselines.emplace();
      b.random_emd = get(entry, "random_emd").get<double>();
      b.nearest = get(entry, "nearest_training_object").get<std::string>();
      b.nearest_emd = get(entry, "nearest_emd").get<double>();
      b.nearest_n = get(entry, "nearest_n").get<std::size_t>();
      const json& floor = get(entry, "floor_emd");
      if (!floor.is_null()) b.floor_emd = floor.get<double>();
    }
    if (entry.contains("success")) o.success = outcomes(get(entry, "success"));
    if (entry.contains("nearest_success")) {
      o.nearest_success = outcomes(get(entry, "nearest_success"));
    }
    return o;
  } catch (const json::exception&) {
    throw Error("evaluation report: an object entry has no valid \"" + field + "\"");
  }
}

json to_json(const EvaluationReport& r) {
  const Derived d = derive(r);
  json objects = json::array();
  for (const ObjectResult& o : r.objects) objects.push_back(to_json(o));
  json j = {{"model", r.model},
            {"step", r.step},
            {"parameters", r.parameters},
            {"sampling", to_json(r.settings)},
            {"seed", r.seed},
            {"objects", objects},
            {"mean_emd", d.emd.mean},
            {"mean_emd_ci_95", {d.emd.low, d.emd.high}},
            {"sampling_seconds_per_100_grasps", d.seconds_per_100}};
  if (d.baselines) {
    j["mean_random_emd"] = d.mean_random;
    j["mean_nearest_emd"] = d.mean_nearest;
    j["objects_below_nearest"] = d.nearest.wins;
    j["nearest_comparison"] = comparison_json(d.nearest);
    if (d.mean_floor) j["mean_floor_emd"] = *d.mean_floor;
    if (d.floor) {
      j["floor_comparison"] = {{"objects", d.floor->objects},
                               {"model_below_nearest", d.floor->model_wins},
                               {"floor_below_nearest", d.floor->floor_wins},
                               {"median_model_excess", d.floor->median_excess}};
    }
  }
  if (d.passed) j["passed_fraction"] = *d.passed;
  if (d.success) {
    j["success"] = outcomes_json(d.model_success);
    j["success_rate_by_object"] = {{"mean", d.rate->mean}, {"ci_95", {d.rate->low, d.rate->high}}};
    if (d.baselines) {
      j["nearest_success"] = outcomes_json(d.nearest_success);
      j["nearest_success_comparison"] = comparison_json(d.success_comparison);
    }
  }
  return j;
}

std::string markdown_table(const EvaluationReport& r) {
  const bool baselines = all_have(r, &ObjectResult::baselines);
  const bool success = all_have(r, &ObjectResult::success);
  std::string table = baselines ? "| object | n | EMD (3 rotations) | mean | random | nearest "
                                  "training object | floor |"
                                : "| object | n | EMD (3 rotations) | mean |";
  if (success) table += baselines ? " success | nearest's success |" : " success |";
  const auto columns = std::count(table.begin(), table.end(), '|') - 1;
  table += "\n|";
  for (std::ptrdiff_t c = 0; c < columns; ++c) table += "---|";
  table += "\n";
  for (const ObjectResult& o : r.objects) {
    table += fmt::format("| {} | {} | {:.4f} |", o.name, o.n, fmt::join(o.emd, " "));
    table += fmt::format(" {:.4f} |", o.mean_emd);
    if (baselines) {
      const BaselineScores& b = *o.baselines;
      table += fmt::format(" {:.4f} | {:.4f} ({}{}) | {} |", b.random_emd, b.nearest_emd, b.nearest,
                           b.nearest_n < o.n ? fmt::format(", n = {}", b.nearest_n) : "",
                           b.floor_emd ? fmt::format("{:.4f}", *b.floor_emd) : "n/a");
    }
    if (success) {
      table += " " + outcomes_cell(*o.success) + " |";
      if (baselines) table += " " + outcomes_cell(*o.nearest_success) + " |";
    }
    table += "\n";
  }
  return table;
}

std::string summary(const EvaluationReport& r) {
  const Derived d = derive(r);
  const std::size_t count = r.objects.size();
  std::string text =
      fmt::format("mean EMD over {} objects: {:.4f}, 95 % bootstrap interval [{:.4f}, {:.4f}]",
                  count, d.emd.mean, d.emd.low, d.emd.high);
  if (d.baselines) {
    const metrics::PairedComparison& c = d.nearest;
    text += fmt::format(
        " (random grasps {:.4f}, nearest training object {:.4f}; the model is below the nearest "
        "object on {} of {}, sign test p = {:.3g}; nearest minus model: mean {:+.4f}, 95 % "
        "bootstrap interval [{:+.4f}, {:+.4f}])",
        d.mean_random, d.mean_nearest, c.wins, count, c.sign_test_p, c.mean_difference, c.ci_low,
        c.ci_high);
    if (d.mean_floor) text += fmt::format("; sampling floor {:.4f}", *d.mean_floor);
    if (d.floor) {
      text += fmt::format(
          "; on the {} objects with a floor, the model is below the nearest object on {}, a "
          "second draw of each object's own grasps (a perfect sampler) on {}, and the model's "
          "median excess over the floor is {:+.4f}",
          d.floor->objects, d.floor->model_wins, d.floor->floor_wins, d.floor->median_excess);
    }
  }
  if (d.success) {
    const sim::GraspOutcomes& s = d.model_success;
    text += fmt::format(
        "; simulated success {:.1f} % ({} of {} grasps; {:.1f} % start in collision with the "
        "object, {:.1f} % success among the others; by object {:.1f} %, 95 % interval "
        "[{:.1f}, {:.1f}] %)",
        100 * s.all.rate(), s.all.successes, s.all.trials, 100 * s.collision_rate(),
        100 * s.collision_free.rate(), 100 * d.rate->mean, 100 * d.rate->low, 100 * d.rate->high);
    if (d.baselines) {
      const metrics::PairedComparison& c = d.success_comparison;
      text += fmt::format(
          " against {:.1f} % for the nearest training object's grasps ({:.1f} % in collision; "
          "the model is higher on {} objects, lower on {}, sign test p = {:.3g})",
          100 * d.nearest_success.all.rate(), 100 * d.nearest_success.collision_rate(), c.wins,
          c.losses, c.sign_test_p);
    }
  }
  if (d.passed && *d.passed < 1) {
    text += fmt::format(
        "; {:.1f} % of the generated grasps passed the filter, the others are "
        "rejected grasps that make up the shortfall",
        100 * *d.passed);
  }
  return text + fmt::format("; sampling {:.3g} s per 100 grasps", d.seconds_per_100);
}

std::string to_markdown(const EvaluationReport& r) {
  const ReportSettings& s = r.settings;
  const std::string input = s.input == "full" ? "" : "; input: " + s.input;
  return fmt::format("# EMD of {} (step {}; {}{}{})\n\n{}\n{}\n", r.model, r.step, s.sampler,
                     filter_note(s.checks), input, markdown_table(r), summary(r));
}

}  // namespace graspecmf::eval
