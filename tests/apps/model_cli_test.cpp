// End-to-end tests of graspecmf train / sample / evaluate on a tiny model and dataset.

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

#include "../train/tiny_dataset.hpp"
#include "cli_support.hpp"
#include "graspecmf/core/output_lock.hpp"
#include "graspecmf/data/acronym_file.hpp"
#include "graspecmf/geometry/mesh_io.hpp"
#include "graspecmf/gripper/cloud_grasp_filter.hpp"

namespace {
namespace fs = std::filesystem;
using graspecmf::testing::CliRun;
using graspecmf::testing::expect_error_after_progress;
using graspecmf::testing::expect_one_error_line;
using graspecmf::testing::read_file;
using graspecmf::testing::run;
using graspecmf::testing::run_on_full_disk;
using graspecmf::testing::ScratchDir;
using graspecmf::testing::temporary_files;
using graspecmf::testing::write_file;

// A model small enough to train in a second.
constexpr const char* kTinyConfig = R"({
  "model": {"encoder": {"widths": [4, 4, 4, 4, 4], "k": 4, "out_channels": 6, "points": 32},
            "field": {"hidden_widths": [8, 8]}, "graspnet": {"centroids": 8}},
  "data": {"objects_per_step": 2, "grasps_per_object": 8},
  "steps": 4, "log_every": 2, "checkpoint_every": 2, "validate_every": 0,
  "validation_grasps": 4, "sampling": {"steps": 2}
})";

// Every model type trains, samples and evaluates through the same commands.
TEST(CliModel, EveryModelTypeTrainsSamplesAndEvaluates) {
  ScratchDir dir;
  const fs::path data = graspecmf::testing::tiny_dataset(dir);
  for (const std::string type :
       {"graspecmf", "flow_dgcnn", "graspnet_vae", "graspnet_gan", "se3dif"}) {
    nlohmann::json config = nlohmann::json::parse(kTinyConfig);
    config["model"]["type"] = type;
    write_file(dir / (type + ".json"), config.dump());
    const std::string run_dir = (dir / type).string();
    const auto trained = run("train --config " + (dir / (type + ".json")).string() + " --data " +
                                 data.string() + " --out " + run_dir,
                             dir);
    ASSERT_EQ(trained.exit_code, 0) << type << trained.err;
    const std::string out = (dir / (type + ".h5")).string();
    const auto sampled = run("sample --model " + run_dir + " --mesh " +
                                 (data / "meshes/Box/b0.obj").string() + " --num 5 --out " + out,
                             dir);
    ASSERT_EQ(sampled.exit_code, 0) << type << sampled.err;
    EXPECT_EQ(graspecmf::data::read_acronym_file(out).size(), 5u) << type;
    const auto evaluated = run("evaluate --model " + run_dir + " --data " + data.string() +
                                   " --split val --num 4 --steps 2",
                               dir);
    ASSERT_EQ(evaluated.exit_code, 0) << type << evaluated.err;
    EXPECT_NE(evaluated.out.find("mean EMD over 1 objects"), std::string::npos) << evaluated.out;
  }
}

TEST(CliModel, TrainSampleEvaluate) {
  ScratchDir dir;
  const fs::path data = graspecmf::testing::tiny_dataset(dir);
  write_file(dir / "tiny.json", kTinyConfig);
  const std::string run_dir = (dir / "run").string();
  const auto trained = run("train --config " + (dir / "tiny.json").string() + " --data " +
                               data.string() + " --out " + run_dir,
                           dir);
  ASSERT_EQ(trained.exit_code, 0) << trained.err;
  EXPECT_NE(trained.out.find("4 steps done"), std::string::npos) << trained.out;
  EXPECT_TRUE(fs::exists(dir / "run/checkpoint.pt"));

  const std::string out = (dir / "grasps.h5").string();
  const auto sampled =
      run("sample --model " + run_dir + " --mesh " + (data / "meshes/Box/b0.obj").string() +
              " --num 7 --device cpu --out " + out,
          dir);
  ASSERT_EQ(sampled.exit_code, 0) << sampled.err;
  const graspecmf::data::AcronymGraspFile record = graspecmf::data::read_acronym_file(out);
  EXPECT_EQ(record.size(), 7u);
  EXPECT_EQ(record.object.file, (data / "meshes/Box/b0.obj").string());

  // An exported model (float32 weights, no optimiser) gives the run's grasps bit for bit.
  const std::string exported = (dir / "exported").string();
  const auto export_run = run("export-model --model " + run_dir + " --out " + exported, dir);
  ASSERT_EQ(export_run.exit_code, 0) << export_run.err;
  EXPECT_TRUE(fs::exists(dir / "exported/model.pt"));
  EXPECT_LT(fs::file_size(dir / "exported/model.pt"), fs::file_size(dir / "run/checkpoint.pt"));
  const std::string out_exported = (dir / "grasps-exported.h5").string();
  ASSERT_EQ(run("sample --model " + exported + " --mesh " + (data / "meshes/Box/b0.obj").string() +
                    " --num 7 --device cpu --out " + out_exported,
                dir)
                .exit_code,
            0);
  EXPECT_EQ(graspecmf::data::read_acronym_file(out_exported).transforms, record.transforms);
  expect_one_error_line(
      run("export-model --model " + (dir / "nowhere").string() + " --out " + (dir / "x").string(),
          dir),
      "no config.json");

  // --refine: grasps move, none is dropped, and the note says so.
  const auto refined_run =
      run("sample --model " + run_dir + " --mesh " + (data / "meshes/Box/b0.obj").string() +
              " --num 7 --seed 3 --refine --out " + out,
          dir);
  ASSERT_EQ(refined_run.exit_code, 0) << refined_run.err;
  EXPECT_NE(refined_run.out.find(", refined"), std::string::npos) << refined_run.out;
  EXPECT_EQ(graspecmf::data::read_acronym_file(out).size(), 7u);

  // --reject-collisions: every grasp's open hand is clear of the dense surface sample it checks.
  const auto clear_run =
      run("sample --model " + run_dir + " --mesh " + (data / "meshes/Box/b0.obj").string() +
              " --num 7 --seed 3 --reject-collisions --out " + out,
          dir);
  ASSERT_EQ(clear_run.exit_code, 0) << clear_run.err;
  EXPECT_NE(clear_run.out.find("colliding grasps rejected"), std::string::npos) << clear_run.out;
  const std::vector<Eigen::Vector3d> filter_points = graspecmf::gripper::filter_cloud(
      graspecmf::geometry::read_mesh((data / "meshes/Box/b0.obj").string()), 3);
  const graspecmf::gripper::CloudGraspFilter checker(filter_points, {true, false});
  const graspecmf::data::AcronymGraspFile clear_record = graspecmf::data::read_acronym_file(out);
  ASSERT_EQ(clear_record.size(), 7u);
  for (const auto& T : clear_record.transforms) {
    EXPECT_FALSE(checker.in_collision(graspecmf::lie::Pose::from_matrix(T)));
  }
  // The untrained model's grasps rarely hold the box deep between the fingers: --reject-shallow
  // ends in one clear error rather than fewer grasps than asked for.
  expect_one_error_line(
      run("sample --model " + run_dir + " --mesh " + (data / "meshes/Box/b0.obj").string() +
              " --num 7 --seed 3 --reject-collisions --reject-shallow --out " + out,
          dir),
      "pass the grasp filter");
  const auto short_run =
      run("sample --model " + run_dir + " --mesh " + (data / "meshes/Box/b0.obj").string() +
              " --num 7 --seed 3 --reject-collisions --reject-shallow --max-draws 20 "
              "--fill-rejected --out " +
              out,
          dir);
  ASSERT_EQ(short_run.exit_code, 0) << short_run.err;
  EXPECT_NE(short_run.out.find("passed, the rest are rejected grasps"), std::string::npos)
      << short_run.out;
  EXPECT_EQ(graspecmf::data::read_acronym_file(out).size(), 7u);
  // Points filling a 40 cm cube reach deep into nearly any hand: every grasp kept holds some of
  // them (of the whole file, not only the model's subset) at least kMinGraspDepth in.
  std::ofstream filled(dir / "filled.xyz");
  std::vector<Eigen::Vector3d> cube;
  for (int i = 0; i <= 40; ++i) {
    for (int j = 0; j <= 40; ++j) {
      for (int k = 0; k <= 40; ++k) {
        cube.push_back(0.01 * Eigen::Vector3d(i - 20, j - 20, k - 20));
        filled << cube.back().transpose() << "\n";
      }
    }
  }
  filled.close();
  const auto deep_run =
      run("sample --model " + run_dir + " --points " + (dir / "filled.xyz").string() +
              " --num 7 --seed 3 --reject-shallow --out " + out,
          dir);
  ASSERT_EQ(deep_run.exit_code, 0) << deep_run.err;
  EXPECT_NE(deep_run.out.find("shallow grasps rejected"), std::string::npos) << deep_run.out;
  const graspecmf::gripper::CloudGraspFilter depth(cube, {false, true});
  const graspecmf::data::AcronymGraspFile deep_record = graspecmf::data::read_acronym_file(out);
  ASSERT_EQ(deep_record.size(), 7u);
  for (const auto& T : deep_record.transforms) {
    EXPECT_GE(depth.depth(graspecmf::lie::Pose::from_matrix(T)),
              graspecmf::gripper::kMinGraspDepth);
  }

  // The same cloud in centimetres with --units cm: the same grasps, and the file records the scale.
  std::ofstream filled_cm(dir / "filled-cm.xyz");
  for (const Eigen::Vector3d& p : cube) filled_cm << (100.0 * p).transpose() << "\n";
  filled_cm.close();
  const std::string out_cm = (dir / "grasps-cm.h5").string();
  ASSERT_EQ(run("sample --model " + run_dir + " --points " + (dir / "filled-cm.xyz").string() +
                    " --units cm --num 7 --seed 3 --reject-shallow --out " + out_cm,
                dir)
                .exit_code,
            0);
  const graspecmf::data::AcronymGraspFile cm_record = graspecmf::data::read_acronym_file(out_cm);
  EXPECT_DOUBLE_EQ(cm_record.object.scale, 0.01);
  ASSERT_EQ(cm_record.size(), 7u);
  for (std::size_t i = 0; i < 7; ++i) {
    EXPECT_TRUE(cm_record.transforms[i].isApprox(deep_record.transforms[i], 1e-6)) << i;
  }

  const auto evaluated =
      run("evaluate --model " + run_dir + " --data " + data.string() +
              " --split val --num 4 --baselines --solver euler --steps 3 --guidance 1.5 --out " +
              (dir / "report.json").string() + " --success 2 --threads 2 --cache " +
              (dir / "cache").string(),
          dir);
  ASSERT_EQ(evaluated.exit_code, 0) << evaluated.err;
  EXPECT_NE(evaluated.out.find("mean EMD over 1 objects"), std::string::npos) << evaluated.out;
  EXPECT_NE(evaluated.out.find("nearest training object"), std::string::npos) << evaluated.out;
  EXPECT_NE(evaluated.out.find("below the nearest object on"), std::string::npos) << evaluated.out;
  // The report records the sampling settings used, and the sampling floor (120 ≥ 2 × 4 grasps).
  const nlohmann::json report = nlohmann::json::parse(read_file(dir / "report.json"));
  EXPECT_EQ(report["sampling"]["solver"], "euler");
  EXPECT_EQ(report["sampling"]["steps"], 3);
  EXPECT_EQ(report["sampling"]["guidance"], 1.5);
  EXPECT_TRUE(report["objects"][0]["floor_emd"].is_number());
  // The win count agrees with the per-object numbers; the nearest object compared all 4 grasps.
  const nlohmann::json& object = report["objects"][0];
  EXPECT_EQ(report["objects_below_nearest"].get<int>(),
            object["mean_emd"].get<double>() < object["nearest_emd"].get<double>() ? 1 : 0);
  EXPECT_EQ(object["nearest_n"], 4);
  // With one object the paired comparison is that object's difference, without spread.
  const nlohmann::json& comparison = report["nearest_comparison"];
  EXPECT_EQ(comparison["wins"], report["objects_below_nearest"]);
  EXPECT_DOUBLE_EQ(comparison["mean_difference"].get<double>(),
                   object["nearest_emd"].get<double>() - object["mean_emd"].get<double>());
  EXPECT_EQ(comparison["ci_95"][0], comparison["mean_difference"]);
  EXPECT_EQ(comparison["ci_95"][1], comparison["mean_difference"]);
  EXPECT_EQ(comparison["sign_test_p"], 1.0);
  EXPECT_NE(evaluated.out.find("sign test p = 1"), std::string::npos) << evaluated.out;
  // The one object has a floor, so the perfect-sampler comparison covers it.
  const nlohmann::json& floored = report["floor_comparison"];
  EXPECT_EQ(floored["objects"], 1);
  EXPECT_EQ(floored["model_below_nearest"], report["objects_below_nearest"]);
  EXPECT_EQ(floored["floor_below_nearest"].get<int>(),
            object["floor_emd"].get<double>() < object["nearest_emd"].get<double>() ? 1 : 0);
  EXPECT_DOUBLE_EQ(floored["median_model_excess"].get<double>(),
                   object["mean_emd"].get<double>() - object["floor_emd"].get<double>());
  // --success 2 simulates 2 generated grasps per rotation and 2 of the nearest object's.
  EXPECT_EQ(object["success"]["trials"], 6);
  EXPECT_EQ(object["nearest_success"]["trials"], 2);
  EXPECT_EQ(report["success"], object["success"]);
  const double rate = object["success"]["rate"].get<double>();
  EXPECT_DOUBLE_EQ(rate, object["success"]["successes"].get<double>() / 6.0);
  EXPECT_DOUBLE_EQ(report["nearest_success_comparison"]["mean_difference"].get<double>(),
                   rate - object["nearest_success"]["rate"].get<double>());
  // The collision-free part is a subset, and the rate its complement's fraction.
  const auto& clear = object["success"]["collision_free"];
  EXPECT_LE(clear["trials"].get<int>(), 6);
  EXPECT_LE(clear["successes"].get<int>(), object["success"]["successes"].get<int>());
  EXPECT_DOUBLE_EQ(object["success"]["collision_rate"].get<double>(),
                   1.0 - clear["trials"].get<double>() / 6.0);
  EXPECT_NE(evaluated.out.find("simulated success"), std::string::npos) << evaluated.out;
  EXPECT_NE(evaluated.out.find("start in collision"), std::string::npos) << evaluated.out;

  // The filter is recorded with the sampling settings. Every grasp of the nearest box collides
  // with the val box here, so the baseline fails with one clear error.
  const std::string reject = "evaluate --model " + run_dir + " --data " + data.string() +
                             " --split val --num 4 --reject-collisions --out " +
                             (dir / "rejected.json").string();
  const auto rejected = run(reject + " --max-draws 1000", dir);
  ASSERT_EQ(rejected.exit_code, 0) << rejected.err;
  expect_one_error_line(run(reject + " --baselines", dir), "passes the grasp filter on it");
  const nlohmann::json rejected_report = nlohmann::json::parse(read_file(dir / "rejected.json"));
  EXPECT_TRUE(rejected_report["sampling"]["reject_collisions"].get<bool>());
  EXPECT_FALSE(rejected_report["sampling"]["reject_shallow"].get<bool>());
  EXPECT_EQ(rejected_report["sampling"]["max_draws"], 1000);
  EXPECT_FALSE(report["sampling"]["reject_collisions"].get<bool>());
  // As with sample, the untrained model's grasps are too rarely deep for --reject-shallow.
  expect_one_error_line(run(reject + " --reject-shallow", dir), "pass the grasp filter");
  expect_one_error_line(run(reject + " --reject-shallow --max-draws 10", dir),
                        "within the limit of 10 draws");
  // With --fill-rejected the shortfall is made up and counted.
  const auto filled_run = run(reject + " --reject-shallow --max-draws 10 --fill-rejected", dir);
  ASSERT_EQ(filled_run.exit_code, 0) << filled_run.err;
  const nlohmann::json filled_report = nlohmann::json::parse(read_file(dir / "rejected.json"));
  EXPECT_TRUE(filled_report["sampling"]["fill_rejected"].get<bool>());
  EXPECT_LT(filled_report["passed_fraction"].get<double>(), 1.0);
  EXPECT_LE(filled_report["objects"][0]["passed"].get<std::size_t>(), 12U);  // of 3 × 4
  expect_one_error_line(run(reject + " --max-draws 3", dir), "fewer than the 4 asked for");
}

// An evaluation stopped after its objects were done (here by a Markdown report it cannot write)
// resumes from OUT.partial when rerun; a file from something else is replaced.
TEST(CliModel, EvaluateResumesFromThePartialReport) {
  ScratchDir dir;
  const fs::path data = graspecmf::testing::tiny_dataset(dir);
  write_file(dir / "tiny.json", kTinyConfig);
  const std::string run_dir = (dir / "run").string();
  ASSERT_EQ(run("train --config " + (dir / "tiny.json").string() + " --data " + data.string() +
                    " --out " + run_dir,
                dir)
                .exit_code,
            0);
  const fs::path out = dir / "report.json", partial = dir / "report.json.partial";
  const std::string evaluate = "evaluate --model " + run_dir + " --data " + data.string() +
                               " --split train --num 4 --seed 5 --out " + out.string() +
                               " --markdown ";
  const auto emds = [&] {
    std::vector<double> all;
    const nlohmann::json report = nlohmann::json::parse(read_file(out));
    for (const auto& o : report["objects"]) {
      for (double e : o["emd"]) all.push_back(e);
    }
    return all;
  };
  expect_error_after_progress(run(evaluate + (dir / "missing/report.md").string(), dir), "missing");
  ASSERT_TRUE(fs::exists(partial));
  const std::vector<double> first = emds();
  ASSERT_EQ(first.size(), 6U);  // two boxes, three rotations
  fs::remove(out);
  const auto resumed = run(evaluate + (dir / "report.md").string(), dir);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.err.find("note: resuming after 2 of 2 objects, from " + partial.string()),
            std::string::npos)
      << resumed.err;
  EXPECT_EQ(emds(), first);
  EXPECT_FALSE(fs::exists(partial));
  write_file(partial, "not json");
  const auto afresh = run(evaluate + (dir / "report.md").string(), dir);
  ASSERT_EQ(afresh.exit_code, 0) << afresh.err;
  EXPECT_NE(
      afresh.err.find(partial.string() + " is not a partial evaluation report; starting afresh"),
      std::string::npos)
      << afresh.err;
  EXPECT_EQ(afresh.err.find("resuming"), std::string::npos) << afresh.err;
  EXPECT_EQ(emds(), first);
  EXPECT_FALSE(fs::exists(partial));
}

TEST(CliModel, BadInput) {
  ScratchDir dir;
  const fs::path data = graspecmf::testing::tiny_dataset(dir);
  write_file(dir / "tiny.json", kTinyConfig);
  const std::string run_dir = (dir / "run").string();
  expect_one_error_line(run("train --config " + (dir / "tiny.json").string() + " --data " +
                                (dir / "missing").string() + " --out " + run_dir,
                            dir),
                        "no such dataset folder");
  expect_one_error_line(run("train --config " + (dir / "tiny.json").string() + " --data " +
                                data.string() + " --out " + run_dir + " --device gpu",
                            dir),
                        "unknown device 'gpu'");
  ASSERT_EQ(run("train --config " + (dir / "tiny.json").string() + " --data " + data.string() +
                    " --out " + run_dir,
                dir)
                .exit_code,
            0);
  {  // a run folder in use by another process
    const graspecmf::OutputLock held = graspecmf::OutputLock::folder(run_dir);
    expect_one_error_line(run("train --config " + (dir / "tiny.json").string() + " --data " +
                                  data.string() + " --out " + run_dir,
                              dir),
                          "run is in use by another graspecmf process");
  }
  // A checkpoint with a bit flipped every 4 KB (in tensors' bytes, and maybe in the archive's
  // structure: either way the file is refused as damaged).
  fs::create_directories(dir / "damaged");
  fs::copy_file(dir / "run/config.json", dir / "damaged/config.json");
  std::string bytes = read_file(dir / "run/checkpoint.pt");
  for (std::size_t i = 2048; i < bytes.size(); i += 4096)
    bytes[i] = static_cast<char>(bytes[i] ^ 4);
  write_file(dir / "damaged/checkpoint.pt", bytes);
  const CliRun damaged =
      run("sample --model " + (dir / "damaged").string() + " --mesh " +
              (data / "meshes/Box/b0.obj").string() + " --out " + (dir / "g.h5").string(),
          dir);
  expect_one_error_line(damaged, "checkpoint.pt: ");
  EXPECT_NE(damaged.err.find("damaged"), std::string::npos) << damaged.err;
  const CliRun too_many = run("sample --model " + run_dir + " --mesh " +
                                  (data / "meshes/Box/b0.obj").string() + " --num 1000001",
                              dir);
  EXPECT_NE(too_many.exit_code, 0);
  EXPECT_NE(too_many.err.find("--num"), std::string::npos) << too_many.err;
  write_file(dir / "empty.xyz", "# no points\n");
  expect_one_error_line(run("sample --model " + run_dir + " --points " +
                                (dir / "empty.xyz").string() + " --out " + (dir / "g.h5").string(),
                            dir),
                        "empty");
  write_file(dir / "nan.xyz", "0 0 0\n1 nan 0\n");
  expect_one_error_line(run("sample --model " + run_dir + " --points " +
                                (dir / "nan.xyz").string() + " --out " + (dir / "g.h5").string(),
                            dir),
                        "nan.xyz");
  expect_one_error_line(run("sample --model " + (dir / "nowhere").string() + " --points " +
                                (dir / "nan.xyz").string() + " --out " + (dir / "g.h5").string(),
                            dir),
                        "not a model or training run");
  // A checkpoint from a different configuration.
  fs::create_directories(dir / "other");
  std::string wider = kTinyConfig;
  wider.replace(wider.find("[8, 8]"), 6, "[8, 16]");
  write_file(dir / "other/config.json", wider);
  fs::copy_file(dir / "run/checkpoint.pt", dir / "other/checkpoint.pt");
  expect_one_error_line(run("evaluate --model " + (dir / "other").string() + " --data " +
                                data.string() + " --split val",
                            dir),
                        "different model configuration");
  expect_one_error_line(run("evaluate --model " + run_dir, dir),
                        "exactly one of --data or --acronym");
  expect_one_error_line(
      run("evaluate --model " + run_dir + " --data " + data.string() + " --split val --device tpu",
          dir),
      "unknown device 'tpu'");
}

// Outputs that name an input, and options that cannot be applied, are refused.
TEST(CliModel, RefusesOutputsOntoInputsAndNonFiniteGuidance) {
  ScratchDir dir;
  const fs::path data = graspecmf::testing::tiny_dataset(dir);
  write_file(dir / "tiny.json", kTinyConfig);
  const std::string run_dir = (dir / "run").string();
  expect_one_error_line(run("train --config " + (dir / "tiny.json").string() + " --data " +
                                data.string() + " --out " + data.string(),
                            dir),
                        "is also the input");
  ASSERT_EQ(run("train --config " + (dir / "tiny.json").string() + " --data " + data.string() +
                    " --out " + run_dir,
                dir)
                .exit_code,
            0);
  const std::string config = read_file(dir / "run/config.json");
  const std::string mesh = (data / "meshes/Box/b0.obj").string();
  ASSERT_EQ(run("sample --model " + run_dir + " --mesh " + mesh + " --num 7 --out " +
                    (dir / "g.h5").string(),
                dir)
                .exit_code,
            0);
  const std::string grasps = read_file(dir / "g.h5");
  expect_one_error_line(
      run("sample --model " + run_dir + " --acronym " + (dir / "g.h5").string() + " --mesh-root " +
              dir.path().string() + " --num 7 --out " + (dir / "g.h5").string(),
          dir),
      "is also the input");
  EXPECT_EQ(read_file(dir / "g.h5"), grasps);
  expect_one_error_line(run("sample --model " + run_dir + " --mesh " + mesh + " --num 7 --out " +
                                (dir / "run/config.json").string(),
                            dir),
                        "is also the input");
  expect_one_error_line(run("evaluate --model " + run_dir + " --data " + data.string() +
                                " --split val --out " + (dir / "run/config.json").string(),
                            dir),
                        "is also the input");
  EXPECT_EQ(read_file(dir / "run/config.json"), config);
  // Fine-tuning into the init model's own folder would overwrite it.
  expect_one_error_line(run("train --config " + (dir / "tiny.json").string() + " --data " +
                                data.string() + " --init " + run_dir + " --out " + run_dir,
                            dir),
                        "is also the input");
  EXPECT_EQ(read_file(dir / "run/config.json"), config);
  const auto nan = run("sample --model " + run_dir + " --mesh " + mesh +
                           " --num 7 --guidance nan --out " + (dir / "n.h5").string(),
                       dir);
  EXPECT_NE(nan.exit_code, 0);
  EXPECT_NE(nan.err.find("--guidance: must be a finite number"), std::string::npos) << nan.err;
  EXPECT_FALSE(fs::exists(dir / "n.h5"));
}

// On a full disk train and sample stop with one error line and leave no temporary file; the
// resumed run logs every step once.
TEST(CliModel, FullDisk) {
  ScratchDir dir;
  const fs::path data = graspecmf::testing::tiny_dataset(dir);
  write_file(dir / "tiny.json", kTinyConfig);
  const std::string train = "train --config " + (dir / "tiny.json").string() + " --data " +
                            data.string() + " --out " + (dir / "run").string();
  // Room for the run's config and log lines, not for its first checkpoint.
  graspecmf::testing::expect_error_after_progress(
      run_on_full_disk(train, dir, 8000), "cannot write " + (dir / "run/checkpoint.pt").string());
  EXPECT_TRUE(temporary_files(dir / "run").empty());
  ASSERT_EQ(run(train, dir).exit_code, 0);
  std::istringstream log(read_file(dir / "run/log.jsonl"));
  std::vector<std::int64_t> steps;
  for (std::string line; std::getline(log, line);) {
    steps.push_back(nlohmann::json::parse(line)["step"].get<std::int64_t>());
  }
  EXPECT_EQ(steps, (std::vector<std::int64_t>{2, 4, 4}));  // losses at 2 and 4, validation at 4

  const fs::path out = dir / "grasps.h5";
  expect_one_error_line(
      run_on_full_disk("sample --model " + (dir / "run").string() + " --mesh " +
                           (data / "meshes/Box/b0.obj").string() + " --num 7 --out " + out.string(),
                       dir, 1500),
      "cannot write " + out.string());
  EXPECT_FALSE(fs::exists(out));
  EXPECT_TRUE(temporary_files(dir.path()).empty());
}

}  // namespace
