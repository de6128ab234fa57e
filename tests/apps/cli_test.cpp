// End-to-end tests of the graspecmf command: exit codes, output and error lines.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "cli_support.hpp"
#include "graspecmf/core/output_lock.hpp"
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

// A tetrahedron with 5 cm legs and one face missing, at the sample's scale, as OBJ text.
std::string open_tetrahedron_obj() {
  const double s = 0.0002682457830986903;
  const double d = 0.05 / s, z = 0.07 / s;
  return "v 0 0 " + std::to_string(z) + "\nv " + std::to_string(d) + " 0 " + std::to_string(z) +
         "\nv 0 " + std::to_string(d) + " " + std::to_string(z) + "\nv 0 0 " +
         std::to_string(z + d) + "\nf 1 3 2\nf 1 2 4\nf 1 4 3\n";
}

// Sets $XDG_CACHE_HOME for the commands a test runs, and unsets it afterwards.
struct CacheHome {
  explicit CacheHome(const fs::path& dir) { ::setenv("XDG_CACHE_HOME", dir.c_str(), 1); }
  ~CacheHome() { ::unsetenv("XDG_CACHE_HOME"); }
};

TEST(Cli, InspectWrapsAnOpenMeshForItsVolumeUnlessToldNot) {
  ScratchDir dir;
  const CacheHome cache(dir / "cache");
  const fs::path grasps = dataset_with_mesh(dir, open_tetrahedron_obj());
  const CliRun r = run("inspect " + grasps.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("watertight       no (3 boundary"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("repaired         alpha wrap (alpha 1.73 mm"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("outward normals"), std::string::npos) << r.out;
  EXPECT_TRUE(fs::exists(dir / "cache" / "graspecmf" / "watertight"));
  const CliRun j = run("inspect --json " + grasps.string(), dir);
  ASSERT_EQ(j.exit_code, 0) << j.err;
  const nlohmann::json json = nlohmann::json::parse(j.out);
  EXPECT_EQ(json["mesh"]["watertight"], false);
  EXPECT_EQ(json["mesh"]["repair"]["wrapped"], true);
  EXPECT_EQ(json["mesh"]["repair"]["genus"], 0);
  EXPECT_LT(json["mesh"]["repair"]["hausdorff"].get<double>(), 0.003);
  EXPECT_GT(json["mesh"]["mass_properties"]["volume"].get<double>(), 0.0);
  const CliRun off = run("inspect --no-repair " + grasps.string(), dir);
  ASSERT_EQ(off.exit_code, 0) << off.err;
  EXPECT_EQ(off.out.find("repaired"), std::string::npos) << off.out;
  EXPECT_NE(off.out.find("volume           not computed"), std::string::npos) << off.out;
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

// The width and height in a PNG file's header, or {0, 0} if it is not a PNG.
std::array<int, 2> png_size(const fs::path& path) {
  const std::string bytes = read_file(path);
  if (bytes.size() < 24 || bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0) return {0, 0};
  auto big_endian = [&](std::size_t at) {
    int value = 0;
    for (std::size_t k = 0; k < 4; ++k)
      value = value * 256 + static_cast<unsigned char>(bytes[at + k]);
    return value;
  };
  return {big_endian(16), big_endian(20)};
}

TEST(CliView, WritesAPngContactSheetAloneOrWithThePage) {
  ScratchDir dir;
  const std::string grasps = sample_grasp_file().string();
  const fs::path png = dir / "sheet.png", html = dir / "view.html";
  const CliRun alone = run("view " + grasps + " --max 20 --png " + png.string(), dir);
  ASSERT_EQ(alone.exit_code, 0) << alone.err;
  EXPECT_NE(alone.out.find("wrote " + png.string()), std::string::npos) << alone.out;
  // Six 320-pixel views in 3 columns and 2 rows with 4-pixel gutters.
  EXPECT_EQ(png_size(png), (std::array<int, 2>{3 * 324 + 4, 2 * 324 + 4}));
  EXPECT_EQ(dir.num_files(), 1u);  // no temporary file left beside it
  fs::remove(png);
  const CliRun both =
      run("view " + grasps + " --max 20 --png " + png.string() + " --out " + html.string(), dir);
  ASSERT_EQ(both.exit_code, 0) << both.err;
  EXPECT_NE(png_size(png)[0], 0);
  EXPECT_NE(read_file(html).find("<canvas"), std::string::npos);
  expect_one_error_line(run("view " + grasps, dir), "--png");
  expect_one_error_line(run("view " + grasps + " --png " + (dir / "no/such/dir.png").string(), dir),
                        "dir.png");
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

// The sample mug's grasps on an open tetrahedron: simulate wraps it, with a note, unless told not
// to.
TEST(CliSimulate, WrapsAnOpenMeshUnlessToldNot) {
  ScratchDir dir;
  const CacheHome cache(dir / "cache");
  const fs::path grasps = dataset_with_mesh(dir, open_tetrahedron_obj());
  const CliRun r = run("simulate " + grasps.string() + " --every 500 --threads 2", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("is not watertight (3 boundary"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("using its alpha wrap"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("4 grasps"), std::string::npos) << r.out;
  expect_one_error_line(run("simulate " + grasps.string() + " --every 500 --no-repair", dir),
                        "not watertight");
}

// Moved by metres and turned about gravity, the object and its grasps get the same trials.
TEST(CliSimulate, MovedObjectGetsTheSameTrials) {
  ScratchDir dir;
  const std::string common = "simulate " + sample_grasp_file().string() +
                             " --every 250 --threads 2 --cache " + (dir / "cache").string();
  ASSERT_EQ(run(common + " --out " + (dir / "here.json").string(), dir).exit_code, 0);
  const CliRun moved =
      run(common + " --move 2.7 1.2 0 37 --out " + (dir / "there.json").string(), dir);
  ASSERT_EQ(moved.exit_code, 0) << moved.err;
  const nlohmann::json here = nlohmann::json::parse(read_file(dir / "here.json"));
  const nlohmann::json there = nlohmann::json::parse(read_file(dir / "there.json"));
  ASSERT_EQ(here["trials"].size(), 8u);
  for (std::size_t k = 0; k < 8; ++k) {
    EXPECT_EQ(here["trials"][k]["success"], there["trials"][k]["success"]) << k;
    EXPECT_EQ(here["trials"][k]["shaking_linear"], there["trials"][k]["shaking_linear"]) << k;
  }
  expect_one_error_line(run(common + " --move 1 2 nan 0", dir), "--move");
}

// An object 1000 times too large stops with the likely fix: --units for a mesh folder, the file's
// scale for an ACRONYM record.
TEST(CliUnits, WrongUnitsStopWithTheLikelyFix) {
  ScratchDir dir;
  fs::create_directories(dir / "mm");
  fs::copy_file(fs::path(GRASPECMF_DATA_DIR) / "real-object/mug-holes-mm.obj",
                dir / "mm" / "mug.obj");
  expect_one_error_line(run("make-dataset --meshes " + (dir / "mm").string() +
                                " --grasps 10 --out " + (dir / "ds").string(),
                            dir),
                        "if it is in mm, give --units mm (or --scale 0.001)");
  EXPECT_FALSE(fs::exists(dir / "ds" / "grasps"));
  const double s = 0.0002682457830986903;
  const std::string d = std::to_string(50.0 / s);
  const fs::path grasps =
      dataset_with_mesh(dir, "v 0 0 0\nv " + d + " 0 0\nv 0 " + d + " 0\nv 0 0 " + d +
                                 "\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  expect_one_error_line(run("simulate " + grasps.string() + " --every 500", dir),
                        "the file's scale is likely off by 0.001");
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

TEST(CliPrepareMesh, WrapsTheMillimetreMugWithHolesAndReadsTheCacheTheSecondTime) {
  ScratchDir dir;
  const std::string in = (fs::path(GRASPECMF_DATA_DIR) / "real-object/mug-holes-mm.obj").string();
  const std::string args = "prepare-mesh " + in + " --units mm --alpha 0.005 --offset 0.0002" +
                           " --cache " + (dir / "cache").string() + " --out " +
                           (dir / "mug.obj").string();
  const CliRun text = run(args, dir);
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("not watertight (16 boundary"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("wrap             alpha 5 mm, offset 0.2 mm (CGAL"), std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find("genus            - → 1"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("Hausdorff        "), std::string::npos) << text.out;
  const CliRun again = run(args + " --json", dir);
  ASSERT_EQ(again.exit_code, 0) << again.err;
  const nlohmann::json j = nlohmann::json::parse(again.out);
  EXPECT_EQ(j["wrapped"], true);
  EXPECT_EQ(j["from_cache"], true);
  EXPECT_EQ(j["scale"], 0.001);
  EXPECT_EQ(j["alpha"], 0.005);
  EXPECT_EQ(j["before"]["watertight"], false);
  EXPECT_TRUE(j["before"]["genus"].is_null());
  EXPECT_EQ(j["after"]["watertight"], true);
  EXPECT_EQ(j["after"]["consistently_oriented"], true);
  EXPECT_EQ(j["after"]["genus"], 1);
  EXPECT_GT(j["after"]["volume"].get<double>(), 8.72532e-05);
  EXPECT_LT(j["hausdorff"].get<double>(), 0.005);
  // The written mesh is closed, in metres, and what the report describes.
  const std::string written = read_file(dir / "mug.obj");
  EXPECT_NE(written.find(std::to_string(j["after"]["vertices"].get<int>()) + " vertices"),
            std::string::npos);
  // A closed mesh is written unchanged unless --force.
  const CliRun closed =
      run("prepare-mesh " + sample_mesh_file().string() +
              " --scale 0.0002682457830986903 --no-cache --out " + (dir / "closed.ply").string(),
          dir);
  ASSERT_EQ(closed.exit_code, 0) << closed.err;
  EXPECT_NE(closed.out.find("wrap             not needed"), std::string::npos) << closed.out;
  EXPECT_NE(closed.out.find("volume           8.72532e-05 m³ → 8.72532e-05 m³"), std::string::npos)
      << closed.out;
}

// An output path that names an input (directly, through "..", or by a link) is refused and the
// input is left as it was.
TEST(Cli, OutputThatIsAnInputIsRefused) {
  ScratchDir dir;
  const fs::path copy = dir / "grasps.h5";
  fs::copy_file(sample_grasp_file(), copy);
  fs::create_symlink(copy, dir / "link.h5");
  const std::string original = read_file(copy);
  const std::string root = " --mesh-root " + graspecmf::testing::sample_root().string();
  for (const std::string& out :
       {copy.string(), (dir / "sub/../grasps.h5").string(), (dir / "link.h5").string()}) {
    fs::create_directories(dir / "sub");
    expect_one_error_line(
        run("simulate " + copy.string() + root + " --every 500 --out " + out, dir),
        "is also the input");
    expect_one_error_line(run("view " + copy.string() + root + " --out " + out, dir),
                          "is also the input");
    expect_one_error_line(run("view " + copy.string() + root + " --png " + out, dir),
                          "is also the input");
  }
  EXPECT_EQ(read_file(copy), original);
}

// A long job's output held by another process (here the test itself) is refused with one line,
// and nothing is written; once it is free, the job runs.
TEST(Cli, ASecondWriterOfALongJobsOutputIsRefused) {
  ScratchDir dir;
  const std::string simulate = "simulate " + sample_grasp_file().string() +
                               " --every 1000 --threads 1 --cache " + (dir / "cache").string() +
                               " --out " + (dir / "r.h5").string();
  const std::string make_dataset = "make-dataset --mugs 1 --seed 5 --grasps 4 --threads 1 --out " +
                                   (dir / "ds").string() + " --cache " + (dir / "cache").string();
  fs::create_directories(dir / "ds");
  {
    const graspecmf::OutputLock file = graspecmf::OutputLock::file(dir / "r.h5");
    const graspecmf::OutputLock folder = graspecmf::OutputLock::folder(dir / "ds");
    expect_one_error_line(run(simulate, dir), "r.h5 is in use by another graspecmf process (pid ");
    expect_one_error_line(run(make_dataset, dir), "ds is in use by another graspecmf process");
    EXPECT_FALSE(fs::exists(dir / "r.h5"));
    EXPECT_FALSE(fs::exists(dir / "ds/manifest.json"));
  }
  EXPECT_EQ(run(simulate, dir).exit_code, 0);
  EXPECT_FALSE(fs::exists(dir / ".r.h5.lock"));
}

TEST(CliPrepareMesh, BadInput) {
  ScratchDir dir;
  const std::string in = (fs::path(GRASPECMF_DATA_DIR) / "real-object/mug-holes-mm.obj").string();
  expect_one_error_line(run("prepare-mesh " + in + " --units mm --out " + in, dir),
                        "is also the input");
  expect_one_error_line(
      run("prepare-mesh " + in + " --units mm --alpha 3mm --out " + (dir / "a.obj").string(), dir),
      "--alpha '3mm' is not a positive length");
  expect_one_error_line(
      run("prepare-mesh " + in + " --units mm --out " + (dir / "a.stl").string(), dir),
      "must end in .obj or .ply");
  expect_one_error_line(
      run("prepare-mesh " + (dir / "missing.obj").string() + " --out " + (dir / "a.obj").string(),
          dir),
      "no such file");
  EXPECT_FALSE(fs::exists(dir / "a.obj"));
  EXPECT_FALSE(fs::exists(dir / "a.stl"));
}

}  // namespace

namespace {

TEST(CliConvert, TheSampleMugRoundTripsThroughIsaacYamlAndBackToHdf5) {
  const ScratchDir dir;
  const std::string yaml = (dir / "mug.yaml").string(), h5 = (dir / "mug.h5").string();
  const CliRun to_yaml = run("convert " + sample_grasp_file().string() + " " + yaml, dir);
  ASSERT_EQ(to_yaml.exit_code, 0) << to_yaml.err;
  EXPECT_NE(to_yaml.out.find("2000 grasps, acronym → isaac; not kept: success labels (kept as "
                             "scores), object motions, the object's mesh path and scale"),
            std::string::npos)
      << to_yaml.out;
  // Back to ACRONYM's HDF5, which needs the object named.
  expect_one_error_line(run("convert " + yaml + " " + h5, dir), "--object");
  const CliRun back =
      run("convert " + yaml + " " + h5 + " --object meshes/Mug/m.obj --scale 0.5", dir);
  ASSERT_EQ(back.exit_code, 0) << back.err;
  const graspecmf::data::AcronymGraspFile original =
      graspecmf::data::read_acronym_file(sample_grasp_file());
  const graspecmf::data::AcronymGraspFile record = graspecmf::data::read_acronym_file(h5);
  ASSERT_EQ(record.size(), 2000u);
  EXPECT_EQ(record.object.file, "meshes/Mug/m.obj");
  EXPECT_EQ(record.object.scale, 0.5);
  for (std::size_t i = 0; i < record.size(); ++i) {
    ASSERT_LT((record.transforms[i] - original.transforms[i]).cwiseAbs().maxCoeff(), 1e-7) << i;
  }
}

TEST(CliConvert, BadInput) {
  const ScratchDir dir;
  const std::string mug = sample_grasp_file().string();
  expect_one_error_line(run("convert " + mug + " " + (dir / "x.csv").string(), dir), "extension");
  expect_one_error_line(run("convert " + mug + " " + mug, dir), "is also the input");
  expect_one_error_line(run("convert missing.npy " + (dir / "x.h5").string(), dir), "missing.npy");
  EXPECT_NE(run("convert " + mug + " x.npy --graspnet-depth 0.5", dir).exit_code, 0);
  EXPECT_FALSE(fs::exists("x.npy"));
}

}  // namespace
