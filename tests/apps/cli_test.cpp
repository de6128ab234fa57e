// End-to-end tests of the graspecmf command: exit codes, output and error lines.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "cli_support.hpp"
#include "graspecmf/data/acronym_file.hpp"
#include "graspecmf/data/hdf5_file.hpp"
#include "test_support.hpp"

namespace {
namespace fs = std::filesystem;
using graspecmf::testing::CliRun;
using graspecmf::testing::expect_one_error_line;
using graspecmf::testing::read_file;
using graspecmf::testing::run;
using graspecmf::testing::sample_grasp_file;
using graspecmf::testing::sample_mesh_file;
using graspecmf::testing::ScratchDir;

TEST(Cli, VersionAndHelp) {
  ScratchDir dir;
  const CliRun version = run("--version", dir);
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_EQ(version.out.rfind("graspecmf ", 0), 0u) << version.out;
  const CliRun help = run("inspect --help", dir);
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("--mesh-root"), std::string::npos);
  EXPECT_NE(run("", dir).exit_code, 0);
  EXPECT_NE(run("no-such-command", dir).exit_code, 0);
}

TEST(Cli, InspectSampleMug) {
  ScratchDir dir;
  const CliRun r = run("inspect " + sample_grasp_file().string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("2000 (1290 successful"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("genus 1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("rigid transforms all"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("8.72532e-05"), std::string::npos) << r.out;
}

TEST(Cli, InspectJsonCarriesTheSameNumbers) {
  ScratchDir dir;
  const CliRun r = run("inspect --json " + sample_grasp_file().string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["grasps"]["count"], 2000);
  EXPECT_EQ(j["grasps"]["successful"], 1290);
  EXPECT_LT(j["grasps"]["max_rigidity_error"].get<double>(), 2e-10);
  EXPECT_EQ(j["mesh"]["vertices"], 1167);
  EXPECT_EQ(j["mesh"]["triangles"], 2334);
  EXPECT_EQ(j["mesh"]["watertight"], true);
  EXPECT_EQ(j["mesh"]["genus"], 1);
  const auto& mass = j["mesh"]["mass_properties"];
  EXPECT_LT(mass["volume_relative_difference"].get<double>(), 1e-4);
  EXPECT_LT(mass["com_offset_relative_to_size"].get<double>(), 1e-4);
  EXPECT_LT(mass["mass_relative_difference"].get<double>(), 1e-4);
  EXPECT_LT(mass["inertia_relative_difference"].get<double>(), 1e-4);
  EXPECT_NEAR(j["mesh"]["bbox_min"][1].get<double>(), -0.0630, 1e-4);
  EXPECT_NEAR(j["mesh"]["bbox_max"][2].get<double>(), 0.1525, 1e-4);
  EXPECT_EQ(j["object"]["volume"], 8.72532e-05);
}

TEST(Cli, MissingFile) {
  ScratchDir dir;
  expect_one_error_line(run("inspect " + (dir / "missing.h5").string(), dir), "no such file");
}

TEST(Cli, NotAnHdf5File) {
  ScratchDir dir;
  std::ofstream(dir / "fake.h5") << "plain text";
  expect_one_error_line(run("inspect " + (dir / "fake.h5").string(), dir), "not an HDF5 file");
}

TEST(Cli, HdfFileWithoutTransforms) {
  ScratchDir dir;
  {
    graspecmf::data::Hdf5Writer writer(dir / "labels_only.h5");
    writer.write_int64s("grasps/qualities/flex/object_in_gripper", {1, 0, 1}, {3});
    writer.close();
  }
  expect_one_error_line(run("inspect " + (dir / "labels_only.h5").string(), dir),
                        "no /grasps/transforms");
}

// Copies the sample into a dataset folder whose mesh is replaced by `mesh_text`.
fs::path dataset_with_mesh(const ScratchDir& dir, const std::string& mesh_text) {
  fs::create_directories(dir / "set" / "grasps");
  fs::create_directories(dir / "set" / "meshes" / "Mug");
  const fs::path grasps = dir / "set" / "grasps" / sample_grasp_file().filename();
  fs::copy_file(sample_grasp_file(), grasps);
  std::ofstream(dir / "set" / "meshes" / "Mug" / sample_mesh_file().filename()) << mesh_text;
  return grasps;
}

TEST(Cli, TruncatedObj) {
  ScratchDir dir;
  const std::string mesh = read_file(sample_mesh_file());
  const fs::path grasps = dataset_with_mesh(dir, mesh.substr(0, mesh.size() * 6 / 10));
  expect_one_error_line(run("inspect " + grasps.string(), dir), "truncated");
}

TEST(Cli, MeshWithNan) {
  ScratchDir dir;
  const fs::path grasps = dataset_with_mesh(
      dir, "v 0 0 0\nv 1 0 0\nv 0 nan 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  expect_one_error_line(run("inspect " + grasps.string(), dir), "finite");
}

TEST(Cli, EmptyMesh) {
  ScratchDir dir;
  const fs::path grasps = dataset_with_mesh(dir, "");
  expect_one_error_line(run("inspect " + grasps.string(), dir), "no faces");
}

TEST(Cli, MeshRootOption) {
  ScratchDir dir;
  fs::create_directories(dir / "elsewhere");
  fs::copy_file(sample_grasp_file(), dir / "elsewhere" / "mug.h5");
  expect_one_error_line(run("inspect " + (dir / "elsewhere" / "mug.h5").string(), dir),
                        "does not exist");
  const CliRun ok = run("inspect " + (dir / "elsewhere" / "mug.h5").string() + " --mesh-root " +
                            graspecmf::testing::sample_root().string(),
                        dir);
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
}

}  // namespace

namespace {

TEST(CliSimulate, LabelsAFewGraspsAndWritesBothFormats) {
  ScratchDir dir;
  const std::string common = "simulate " + sample_grasp_file().string() +
                             " --every 500 --threads 2 --cache " + (dir / "cache").string();
  const CliRun json_run = run(common + " --compare-labels --out " + (dir / "r.json").string(), dir);
  ASSERT_EQ(json_run.exit_code, 0) << json_run.err;
  EXPECT_NE(json_run.out.find("4 grasps"), std::string::npos) << json_run.out;
  EXPECT_NE(json_run.out.find("agreement with the file's labels"), std::string::npos);
  const nlohmann::json j = nlohmann::json::parse(read_file(dir / "r.json"));
  EXPECT_EQ(j["trials"].size(), 4u);
  EXPECT_EQ(j["trials"][1]["index"], 500);
  EXPECT_EQ(j["agreement"]["count"], 4);
  EXPECT_TRUE(j["config"].contains("finger_force"));

  const CliRun h5_run = run(common + " --out " + (dir / "r.h5").string(), dir);
  ASSERT_EQ(h5_run.exit_code, 0) << h5_run.err;
  const graspecmf::data::AcronymGraspFile labelled =
      graspecmf::data::read_acronym_file(dir / "r.h5");
  ASSERT_EQ(labelled.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(labelled.qualities->object_in_gripper[k],
              j["trials"][k]["success"].get<bool>() ? 1 : 0);  // same labels on a rerun
  }
}

TEST(CliSimulate, BadInput) {
  ScratchDir dir;
  expect_one_error_line(run("simulate " + (dir / "missing.h5").string(), dir), "no such file");
  graspecmf::testing::write_file(dir / "bad.json", R"({"finger_force": -5})");
  expect_one_error_line(
      run("simulate " + sample_grasp_file().string() + " --config " + (dir / "bad.json").string(),
          dir),
      "finger_force");
  EXPECT_NE(run("simulate " + sample_grasp_file().string() + " --threads 0", dir).exit_code, 0);
}

TEST(CliView, WritesAnHtmlPageOfTheSampleGrasps) {
  ScratchDir dir;
  const std::string out = (dir / "view.html").string();
  const CliRun r = run("view " + sample_grasp_file().string() + " --max 50 --out " + out, dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("50 of 2000 grasps"), std::string::npos) << r.out;
  const std::string html = read_file(out);
  EXPECT_NE(html.find("<canvas"), std::string::npos);
  // 50 markers of 4 segments (stem, bar, two fingers), 9 numbers each.
  const std::string open = R"(<script id="scene" type="application/json">)";
  const std::size_t start = html.find(open) + open.size();
  const auto scene =
      nlohmann::json::parse(html.substr(start, html.find("</script>", start) - start));
  EXPECT_EQ(scene["segments"].size() % 9, 0u);
  EXPECT_GE(scene["segments"].size(), 50u * 9u);
  expect_one_error_line(run("view " + (dir / "missing.h5").string() + " --out " + out, dir),
                        "missing.h5");
}

TEST(CliMakeDataset, MakesAndResumesASmallMugDataset) {
  ScratchDir dir;
  const std::string args = "make-dataset --mugs 1 --seed 5 --grasps 4 --threads 1 --out " +
                           (dir / "ds").string() + " --cache " + (dir / "cache").string();
  const CliRun first = run(args, dir);
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_NE(first.out.find("1 objects: 1 made, 0 already there, 0 skipped"), std::string::npos)
      << first.out;
  EXPECT_TRUE(fs::exists(dir / "ds/grasps/Mug_mug-5-0000_1.h5"));
  const CliRun again = run(args, dir);
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.out.find("0 made, 1 already there"), std::string::npos) << again.out;
  const CliRun inspect = run("inspect " + (dir / "ds/grasps/Mug_mug-5-0000_1.h5").string(), dir);
  EXPECT_EQ(inspect.exit_code, 0) << inspect.err;
  EXPECT_NE(inspect.out.find("watertight       yes"), std::string::npos) << inspect.out;
}

TEST(CliMakeDataset, BadInput) {
  ScratchDir dir;
  graspecmf::testing::write_file(dir / "file", "x");
  expect_one_error_line(run("make-dataset --mugs 1 --out " + (dir / "file/ds").string(), dir),
                        "cannot create the output folder");
  expect_one_error_line(run("make-dataset --preset mugs-v9 --out " + (dir / "a").string(), dir),
                        "unknown preset");
  graspecmf::testing::write_file(dir / "inset.json", R"({"pad_normal_inset": 0.003})");
  expect_one_error_line(run("make-dataset --preset mugs-v1 --config " +
                                (dir / "inset.json").string() + " --out " + (dir / "e").string(),
                            dir),
                        "mugs-v1 fixes pad_normal_inset");
  graspecmf::testing::write_file(dir / "list.json", "[1]");
  expect_one_error_line(run("make-dataset --preset mugs-v1 --config " +
                                (dir / "list.json").string() + " --out " + (dir / "e").string(),
                            dir),
                        "a trial config must be a JSON object");
  expect_one_error_line(
      run("make-dataset --preset mugs-v2 --grasps 10 --out " + (dir / "e").string(), dir),
      "mugs-v2 fixes the candidates per object and the seed");
  expect_one_error_line(
      run("make-dataset --preset mugs-v1 --seed 3 --out " + (dir / "e").string(), dir),
      "mugs-v1 fixes the candidates per object and the seed");
  // Without --config the preset's own settings apply and the run reaches the output folder.
  fs::create_directories(dir / "f");
  graspecmf::testing::write_file(dir / "f/manifest.json", R"({"options": {}})");
  for (const char* preset : {"mugs-v1", "mugs-v2"}) {
    expect_one_error_line(
        run(std::string("make-dataset --preset ") + preset + " --out " + (dir / "f").string(), dir),
        "made with other options");
  }
  expect_one_error_line(run("make-dataset --mugs 2 --meshes " + dir.path().string() + " --out " +
                                (dir / "b").string(),
                            dir),
                        "exactly one of");
  expect_one_error_line(
      run("make-dataset --meshes " + (dir / "none").string() + " --out " + (dir / "c").string(),
          dir),
      "not a folder");
  EXPECT_NE(run("make-dataset --mugs 1 --grasps 0 --out " + (dir / "d").string(), dir).exit_code,
            0);
}

}  // namespace
