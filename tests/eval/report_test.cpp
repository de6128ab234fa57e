#include "graspecmf/eval/report.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <sstream>

#include "graspecmf/eval/partial_report.hpp"
#include "test_support.hpp"

namespace graspecmf::eval {
namespace {

using graspecmf::testing::expect_error;
using graspecmf::testing::ScratchDir;

sim::GraspOutcomes outcomes(std::size_t successes, std::size_t trials, std::size_t clear,
                            std::size_t clear_successes) {
  return {{successes, trials}, {clear_successes, clear}};
}

// Two objects: EMDs at three rotations, and (optionally) baselines, one with a floor, and
// simulated success.
EvaluationReport two_objects(bool baselines, bool success) {
  EvaluationReport r;
  r.model = "models/mugs";
  r.step = 48000;
  r.parameters = 1234;
  r.settings = {"rkmk4-20, guidance 2", "rkmk4", 20, 2.0, 8, {}};
  r.seed = 3;
  r.objects.push_back({"a", 50, {0.2, 0.3, 0.4}, 0.3, 1.5, {}, {}, {}, {}});
  r.objects.push_back({"b", 40, {0.5, 0.5, 0.5}, 0.5, 0.5, {}, {}, {}, {}});
  if (baselines) {
    r.objects[0].baselines = BaselineScores{1.5, "t1", 0.6, 50, 0.25};
    r.objects[1].baselines = BaselineScores{1.7, "t2", 0.4, 30, std::nullopt};
  }
  if (success) {
    r.objects[0].success = outcomes(40, 50, 45, 39);
    r.objects[1].success = outcomes(10, 40, 20, 10);
    if (baselines) {
      r.objects[0].nearest_success = outcomes(20, 50, 30, 18);
      r.objects[1].nearest_success = outcomes(20, 40, 40, 20);
    }
  }
  return r;
}

TEST(EvaluationReport, JsonHoldsTheObjectsAndTheirMeans) {
  const nlohmann::json j = to_json(two_objects(false, false));
  EXPECT_EQ(j["model"], "models/mugs");
  EXPECT_EQ(j["step"], 48000);
  EXPECT_EQ(j["parameters"], 1234);
  EXPECT_EQ(j["sampling"]["clouds"], 8);
  EXPECT_EQ(j["sampling"]["reject_collisions"], false);
  EXPECT_EQ(j["sampling"]["max_draws"], 0);
  ASSERT_EQ(j["objects"].size(), 2U);
  EXPECT_EQ(j["objects"][1]["n"], 40);
  EXPECT_DOUBLE_EQ(j["mean_emd"].get<double>(), 0.4);
  // Resampling two objects gives means 0.3, 0.4 and 0.5 only.
  EXPECT_DOUBLE_EQ(j["mean_emd_ci_95"][0].get<double>(), 0.3);
  EXPECT_DOUBLE_EQ(j["mean_emd_ci_95"][1].get<double>(), 0.5);
  // 2 s for 3 × (50 + 40) grasps.
  EXPECT_NEAR(j["sampling_seconds_per_100_grasps"].get<double>(), 200.0 / 270, 1e-12);
  EXPECT_EQ(j["objects"][0]["sampling_seconds"], 1.5);
  EXPECT_FALSE(j.contains("mean_nearest_emd"));
  EXPECT_FALSE(j.contains("success"));
  EXPECT_FALSE(j["objects"][0].contains("floor_emd"));
}

TEST(EvaluationReport, BaselinesAndSuccessAreSummed) {
  const nlohmann::json j = to_json(two_objects(true, true));
  EXPECT_DOUBLE_EQ(j["mean_random_emd"].get<double>(), 1.6);
  EXPECT_DOUBLE_EQ(j["mean_nearest_emd"].get<double>(), 0.5);
  // a is below its nearest object (0.3 < 0.6), b is not (0.5 > 0.4).
  EXPECT_EQ(j["objects_below_nearest"], 1);
  EXPECT_EQ(j["nearest_comparison"]["losses"], 1);
  // Only a has a floor: no mean floor, a floor comparison over one object.
  EXPECT_FALSE(j.contains("mean_floor_emd"));
  EXPECT_TRUE(j["objects"][1]["floor_emd"].is_null());
  EXPECT_EQ(j["floor_comparison"]["objects"], 1);
  EXPECT_NEAR(j["floor_comparison"]["median_model_excess"].get<double>(), 0.05, 1e-12);
  EXPECT_EQ(j["success"]["successes"], 50);
  EXPECT_EQ(j["success"]["trials"], 90);
  // By object: 80 % and 25 %.
  EXPECT_NEAR(j["success_rate_by_object"]["mean"].get<double>(), 0.525, 1e-12);
  EXPECT_NEAR(j["success_rate_by_object"]["ci_95"][0].get<double>(), 0.25, 1e-12);
  EXPECT_NEAR(j["success_rate_by_object"]["ci_95"][1].get<double>(), 0.8, 1e-12);
  EXPECT_NEAR(j["success"]["collision_rate"].get<double>(), 1 - 65.0 / 90, 1e-12);
  EXPECT_EQ(j["nearest_success"]["successes"], 40);
  EXPECT_EQ(j["nearest_success_comparison"]["wins"], 1);  // a: 80 % against 40 %
  EXPECT_EQ(j["objects"][0]["nearest_success"]["trials"], 50);
}

TEST(EvaluationReport, FilteredReportsCountTheGraspsThatPassed) {
  EvaluationReport r = two_objects(false, false);
  EXPECT_FALSE(to_json(r).contains("passed_fraction"));
  // a: 150 of its 3 × 50 grasps passed; b: 100 of 3 × 40, the rest filled the shortfall.
  r.objects[0].passed = 150;
  r.objects[1].passed = 100;
  const nlohmann::json j = to_json(r);
  EXPECT_EQ(j["objects"][1]["passed"], 100);
  EXPECT_DOUBLE_EQ(j["passed_fraction"].get<double>(), 250.0 / 270);
  EXPECT_NE(summary(r).find("; 92.6 % of the generated grasps passed the filter, the others are "
                            "rejected grasps"),
            std::string::npos)
      << summary(r);
  r.objects[1].passed = 120;  // all passed: nothing to say
  EXPECT_EQ(summary(r).find("passed the filter"), std::string::npos);
}

TEST(EvaluationReport, MarkdownRowsHaveTheHeadersColumns) {
  for (const bool baselines : {false, true}) {
    for (const bool success : {false, true}) {
      const EvaluationReport r = two_objects(baselines, success);
      std::istringstream table(markdown_table(r));
      std::vector<long> columns;
      for (std::string line; std::getline(table, line);) {
        columns.push_back(std::count(line.begin(), line.end(), '|'));
      }
      ASSERT_EQ(columns.size(), 4U);  // header, rule, two objects
      EXPECT_EQ(std::count(columns.begin(), columns.end(), columns[0]), 4) << baselines << success;
      EXPECT_EQ(columns[0], 5 + (baselines ? 3 : 0) + (success ? (baselines ? 2 : 1) : 0));
    }
  }
  const std::string page = to_markdown(two_objects(true, true));
  EXPECT_EQ(page.rfind("# EMD of models/mugs (step 48000; rkmk4-20, guidance 2)", 0), 0U) << page;
  EXPECT_NE(page.find("| a | 50 | 0.2000 0.3000 0.4000 | 0.3000 | 1.5000 | 0.6000 (t1) | 0.2500 |"),
            std::string::npos)
      << page;
  EXPECT_NE(page.find("0.4000 (t2, n = 30) | n/a |"), std::string::npos) << page;
  EXPECT_NE(page.find("mean EMD over 2 objects: 0.4000, 95 % bootstrap interval [0.3000, 0.5000] "
                      "(random grasps 1.6000"),
            std::string::npos)
      << page;
  EXPECT_NE(page.find("by object 52.5 %, 95 % interval [25.0, 80.0] %"), std::string::npos);
  EXPECT_NE(page.find("; sampling 0.741 s per 100 grasps"), std::string::npos);
  EXPECT_NE(page.find("simulated success 55.6 % (50 of 90 grasps"), std::string::npos) << page;
}

TEST(EvaluationReport, FilterNoteNamesTheChecks) {
  EXPECT_EQ(filter_note({}), "");
  gripper::GraspChecks refine;
  refine.refine = true;
  EXPECT_EQ(filter_note(refine), ", refined");
  gripper::GraspChecks both;
  both.collisions = both.shallow = true;
  EXPECT_EQ(filter_note(both), ", colliding and shallow grasps rejected");
}

void expect_same_outcomes(const std::optional<sim::GraspOutcomes>& a,
                          const std::optional<sim::GraspOutcomes>& b) {
  ASSERT_EQ(a.has_value(), b.has_value());
  if (!a) return;
  EXPECT_EQ(a->all.successes, b->all.successes);
  EXPECT_EQ(a->all.trials, b->all.trials);
  EXPECT_EQ(a->collision_free.successes, b->collision_free.successes);
  EXPECT_EQ(a->collision_free.trials, b->collision_free.trials);
}

// Every field equal, the doubles bit for bit.
void expect_same(const ObjectResult& a, const ObjectResult& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.n, b.n);
  EXPECT_EQ(a.emd, b.emd);
  EXPECT_EQ(a.mean_emd, b.mean_emd);
  EXPECT_EQ(a.sampling_seconds, b.sampling_seconds);
  EXPECT_EQ(a.passed, b.passed);
  ASSERT_EQ(a.baselines.has_value(), b.baselines.has_value());
  if (a.baselines) {
    EXPECT_EQ(a.baselines->random_emd, b.baselines->random_emd);
    EXPECT_EQ(a.baselines->nearest, b.baselines->nearest);
    EXPECT_EQ(a.baselines->nearest_emd, b.baselines->nearest_emd);
    EXPECT_EQ(a.baselines->nearest_n, b.baselines->nearest_n);
    EXPECT_EQ(a.baselines->floor_emd, b.baselines->floor_emd);
  }
  expect_same_outcomes(a.success, b.success);
  expect_same_outcomes(a.nearest_success, b.nearest_success);
}

TEST(EvaluationReport, ObjectEntriesRoundTrip) {
  EvaluationReport full = two_objects(true, true);
  full.objects[0].passed = 140;
  full.objects[1].passed = 100;
  full.objects[0].emd[1] = 0.1 + 0.2;  // not a short decimal: must still come back exactly
  full.objects[1].sampling_seconds = 1.0 / 3;
  for (const EvaluationReport& r : {full, two_objects(false, false)}) {
    for (const ObjectResult& o : r.objects) {
      expect_same(object_result_from_json(to_json(o)), o);
      // The entry is the report's, and read back from its text form.
      const nlohmann::json entry = to_json(r)["objects"][&o - r.objects.data()];
      EXPECT_EQ(entry, to_json(o));
      expect_same(object_result_from_json(nlohmann::json::parse(entry.dump())), o);
    }
  }
  nlohmann::json broken = to_json(full.objects[0]);
  broken["success"].erase("collision_free");
  expect_error([&] { object_result_from_json(broken); }, "no valid \"collision_free\"");
  broken = to_json(full.objects[0]);
  broken["emd"] = "0.3";
  expect_error([&] { object_result_from_json(broken); }, "no valid \"emd\"");
  expect_error([&] { object_result_from_json(nlohmann::json::array()); }, "no valid \"object\"");
}

TEST(PartialReport, ResumesOnlyTheSameEvaluation) {
  const ScratchDir dir;
  const std::filesystem::path path = dir / "report.json.partial";
  const nlohmann::json identity = {{"model", "m"}, {"seed", 3}, {"objects", {"a", "b", "c"}}};
  std::string note = "stale";
  EXPECT_TRUE(read_partial_report(path, identity, note).empty());  // no file: nothing to say
  EXPECT_EQ(note, "");
  const EvaluationReport r = two_objects(true, true);
  write_partial_report(path, identity, r.objects);
  const std::vector<ObjectResult> done = read_partial_report(path, identity, note);
  EXPECT_EQ(note, "");
  ASSERT_EQ(done.size(), 2U);
  expect_same(done[0], r.objects[0]);
  expect_same(done[1], r.objects[1]);
  nlohmann::json other = identity;
  other["seed"] = 4;
  EXPECT_TRUE(read_partial_report(path, other, note).empty());
  EXPECT_EQ(note, path.string() + " is from an evaluation with other settings; starting afresh");
  graspecmf::testing::write_file(path, "{\"identity\": ");  // cut short
  EXPECT_TRUE(read_partial_report(path, identity, note).empty());
  EXPECT_EQ(note, path.string() + " is not a partial evaluation report; starting afresh");
  nlohmann::json damaged = {{"identity", identity}, {"objects", {{{"object", "a"}}}}};
  graspecmf::testing::write_file(path, damaged.dump());
  EXPECT_TRUE(read_partial_report(path, identity, note).empty());
  EXPECT_NE(note.find("no valid \"n\"; starting afresh"), std::string::npos) << note;
}

TEST(EvaluationReport, EmptyOrMixedReportsAreErrors) {
  EvaluationReport empty;
  expect_error([&] { to_json(empty); }, "no objects");
  expect_error([&] { summary(empty); }, "no objects");
  EvaluationReport mixed = two_objects(true, false);
  mixed.objects[1].baselines.reset();
  expect_error([&] { to_json(mixed); }, "only some objects");
}

}  // namespace
}  // namespace graspecmf::eval
