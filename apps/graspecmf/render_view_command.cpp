#include "render_view_command.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_checks.hpp"
#include "graspecmf/camera/camera_pose.hpp"
#include "graspecmf/camera/depth_noise.hpp"
#include "graspecmf/camera/depth_render.hpp"
#include "graspecmf/camera/partial_view.hpp"
#include "graspecmf/core/atomic_file.hpp"
#include "graspecmf/core/error.hpp"
#include "graspecmf/core/output_paths.hpp"
#include "graspecmf/core/random.hpp"
#include "graspecmf/geometry/mesh_io.hpp"
#include "object_units.hpp"

namespace graspecmf::apps {
namespace {
namespace fs = std::filesystem;

struct RenderViewArgs {
  std::string mesh, out, intrinsics, noise = "default";
  ObjectUnits units;
  int views = 1;
  std::uint64_t seed = 0;
  double azimuth = -1.0, elevation = -1.0, distance = -1.0;  // < 0: drawn from the seed
};

// The ranges the cameras are drawn from when not given.
const camera::ViewSampling kDrawn;

void write_intrinsics(const camera::Intrinsics& k, const fs::path& path) {
  const nlohmann::json document = {{"fx", k.fx}, {"fy", k.fy},       {"cx", k.cx},
                                   {"cy", k.cy}, {"width", k.width}, {"height", k.height}};
  write_file_atomically(path, document.dump(2) + "\n");
}

void run_render_view(const RenderViewArgs& a) {
  require_distinct_output("--out", a.out, {a.mesh, a.intrinsics});
  geometry::TriangleMesh mesh =
      geometry::scaled(geometry::read_mesh(a.mesh), a.units.metres_per_unit());
  a.units.size.check(mesh.vertices, a.mesh);
  const camera::Intrinsics k =
      a.intrinsics.empty() ? camera::realsense_d435() : camera::read_intrinsics(a.intrinsics);
  if (k.width == 0) throw Error(a.intrinsics + ": the intrinsics must give width and height");
  const geometry::BoundingBox box = geometry::bounding_box(mesh);
  // The mesh stands as it is on a table at its lowest point; the camera aims at its middle.
  const geometry::Plane table{lie::Vec3::UnitZ(), -box.min.z()};
  const geometry::MeshRayCaster caster(mesh);
  const camera::DepthNoise noise;
  fs::create_directories(a.out);
  Rng rng(a.seed);
  for (int view = 0; view < a.views; ++view) {
    // Every view makes its whole draw, so that --azimuth etc. never shift the other draws.
    camera::ViewDraw draw = camera::draw_view(kDrawn, rng);
    if (a.azimuth >= 0.0) draw.azimuth = a.azimuth;
    if (a.elevation >= 0.0) draw.elevation = a.elevation;
    if (a.distance > 0.0) draw.distance = a.distance;
    const lie::Pose pose = camera::camera_above(box, draw.azimuth, draw.elevation, draw.distance);
    const auto start = std::chrono::steady_clock::now();
    camera::RenderedView rendered = camera::render_view(caster, k, pose, table);
    if (a.noise == "default")
      rendered.depth = camera::noisy_depth(rendered, k, noise, draw.noise_seed);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const fs::path dir =
        a.views == 1 ? fs::path(a.out) : fs::path(a.out) / fmt::format("view-{:03d}", view);
    fs::create_directories(dir);
    camera::write_depth_png(rendered.depth, dir / "depth.png");
    camera::write_mask_png(rendered.object_mask, k.width, k.height, dir / "mask.png");
    write_intrinsics(k, dir / "intrinsics.json");
    camera::write_camera_pose(pose, dir / "camera_pose.json");
    std::cout << fmt::format(
        "{}: azimuth {:.1f}°, elevation {:.1f}°, distance {:.3f} m, {} object "
        "pixels, rendered in {:.2f} s\n",
        dir.string(), draw.azimuth, draw.elevation, draw.distance,
        std::count(rendered.object_mask.begin(), rendered.object_mask.end(), 1), seconds);
  }
}

}  // namespace

void add_render_view_command(CLI::App& app) {
  auto a = std::make_shared<RenderViewArgs>();
  CLI::App* cmd = app.add_subcommand(
      "render-view", "Depth images of a mesh on a table, with mask, intrinsics and camera pose");
  cmd->add_option("--mesh", a->mesh, "Object mesh (.obj/.stl/.ply/.glb/.gltf); z is up")
      ->required();
  a->units.add_options(cmd);
  cmd->add_option("--out", a->out,
                  "Folder for depth.png (16-bit, mm), mask.png, intrinsics.json and "
                  "camera_pose.json (T_mesh_camera); one view-NNN folder per view when --views > 1")
      ->required();
  cmd->add_option("--views", a->views, "Views to render")
      ->check(CLI::Range(1, 10000))
      ->capture_default_str();
  cmd->add_option("--seed", a->seed, "Seed of the cameras (and of the noise)")
      ->capture_default_str();
  cmd->add_option("--azimuth", a->azimuth,
                  "Camera azimuth about z, degrees (default: drawn in [0, 360))")
      ->check(CLI::Range(0.0, 360.0));
  cmd->add_option("--elevation", a->elevation,
                  "Camera elevation above the table, degrees (default: drawn in [30, 70])")
      ->check(CLI::Range(1.0, 89.0));
  cmd->add_option("--distance", a->distance,
                  "Camera distance to the object's middle, m (default: drawn in [0.45, 0.7])")
      ->check(CLI::Range(0.15, 5.0));
  cmd->add_option("--intrinsics", a->intrinsics,
                  "Camera intrinsics (.json or ROS .yaml, with width and height; default: 640 × "
                  "480, fx = fy = 615 px, like a RealSense D435)");
  cmd->add_option("--noise", a->noise, "Depth camera noise: default (docs/camera.md) or none")
      ->check(CLI::IsMember({"default", "none"}))
      ->capture_default_str();
  cmd->callback([a] { run_render_view(*a); });
}

}  // namespace graspecmf::apps
