// The graspecmf Python module: a thin pybind11 layer over the C++ library (docs/python.md). Arrays
// cross as NumPy float64; compute runs with the GIL released; graspecmf::Error becomes
// graspecmf.Error with the same one-line message.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>
#include <torch/torch.h>

#include <optional>
#include <string>

#include "graspecmf/camera/camera_pose.hpp"
#include "graspecmf/camera/depth_image.hpp"
#include "graspecmf/camera/view_input.hpp"
#include "graspecmf/core/error.hpp"
#include "graspecmf/core/version.hpp"
#include "graspecmf/formats/grasp_files.hpp"
#include "graspecmf/geometry/mesh_io.hpp"
#include "graspecmf/geometry/object_size.hpp"
#include "graspecmf/geometry/point_cloud_io.hpp"
#include "graspecmf/geometry/watertight_cache.hpp"
#include "graspecmf/metrics/emd.hpp"
#include "graspecmf/models/bundled_model.hpp"
#include "graspecmf/models/device.hpp"
#include "graspecmf/models/object_grasps.hpp"
#include "graspecmf/sim/batch.hpp"
#include "graspecmf/sim/scene_object.hpp"

namespace py = pybind11;
using namespace graspecmf;

namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;
using Vec3 = Eigen::Vector3d;

// The factor from the caller's units to metres: `units` by name, else `scale`.
double metres_per_unit(const std::optional<std::string>& units, double scale) {
  if (units) {
    if (scale != 1.0) throw Error("give units or scale, not both");
    return geometry::metres_per_unit(*units);
  }
  if (!(scale > 0) || !std::isfinite(scale)) throw Error("scale must be a positive number");
  return scale;
}

// (N, 4, 4) poses from a NumPy array; throws Error naming `what` for any other shape.
std::vector<Eigen::Matrix4d> matrices(const Array& array, const std::string& what) {
  if (array.ndim() != 3 || array.shape(1) != 4 || array.shape(2) != 4) {
    throw Error(what + " must be an (N, 4, 4) array of poses");
  }
  std::vector<Eigen::Matrix4d> out(static_cast<std::size_t>(array.shape(0)));
  const double* data = array.data();
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i] = Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(data + 16 * i);
  }
  return out;
}

std::vector<lie::Pose> poses(const Array& array, const std::string& what) {
  std::vector<lie::Pose> out;
  for (const Eigen::Matrix4d& T : matrices(array, what)) out.push_back(lie::Pose::from_matrix(T));
  return out;
}

// An (N, 4, 4) float64 array of the matrices.
Array matrix_array(const std::vector<Eigen::Matrix4d>& Ts) {
  Array out({static_cast<py::ssize_t>(Ts.size()), py::ssize_t{4}, py::ssize_t{4}});
  double* data = out.mutable_data();
  for (std::size_t i = 0; i < Ts.size(); ++i) {
    Eigen::Map<Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(data + 16 * i) = Ts[i];
  }
  return out;
}

// A 1-D array of the values, moved into NumPy without a copy.
template <typename T>
py::array_t<T> vector_array(std::vector<T>&& values) {
  auto* owned = new std::vector<T>(std::move(values));
  py::capsule free(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<T>(static_cast<py::ssize_t>(owned->size()), owned->data(), free);
}

std::vector<double> doubles(const std::optional<Array>& array, const std::string& what) {
  if (!array) return {};
  if (array->ndim() != 1) throw Error(what + " must be a 1-D array");
  return {array->data(), array->data() + array->size()};
}

// A metric point cloud from an (N, 3) array or a point-cloud file.
std::vector<Vec3> cloud_of(const py::object& points, double metres) {
  std::vector<Vec3> cloud;
  if (py::isinstance<py::str>(points) || py::hasattr(points, "__fspath__")) {
    cloud = geometry::read_point_cloud(py::cast<std::filesystem::path>(points));
  } else {
    const Array array = py::cast<Array>(points);
    if (array.ndim() != 2 || array.shape(1) != 3) throw Error("points must be an (N, 3) array");
    const double* data = array.data();
    for (py::ssize_t i = 0; i < array.shape(0); ++i)
      cloud.emplace_back(data[3 * i], data[3 * i + 1], data[3 * i + 2]);
  }
  for (Vec3& p : cloud) p *= metres;
  return cloud;
}

formats::FormatOptions format_options(const std::optional<std::string>& format,
                                      const std::string& isaac_gripper_frame, double graspnet_depth,
                                      int graspnet_object_id) {
  formats::FormatOptions options;
  if (format) options.format = formats::parse_format(*format);
  options.isaac_gripper_frame = formats::parse_isaac_gripper_frame(isaac_gripper_frame);
  options.graspnet_depth = graspnet_depth;
  options.graspnet_object_id = graspnet_object_id;
  return options;
}

py::dict grasp_dict(formats::GraspSet&& grasps) {
  py::dict out;
  out["poses"] = matrix_array(grasps.poses);
  if (!grasps.scores.empty()) out["scores"] = vector_array(std::move(grasps.scores));
  if (!grasps.widths.empty()) out["widths"] = vector_array(std::move(grasps.widths));
  if (grasps.qualities) {
    data::GraspQualities& q = *grasps.qualities;
    std::vector<bool> success(q.object_in_gripper.begin(), q.object_in_gripper.end());
    out["success"] = py::array_t<bool>(py::cast(success));
    const auto optional = [&](const char* key, std::vector<double>& values) {
      if (!values.empty()) out[key] = vector_array(std::move(values));
    };
    optional("closing_linear", q.motion_closing_linear);
    optional("closing_angular", q.motion_closing_angular);
    optional("shaking_linear", q.motion_shaking_linear);
    optional("shaking_angular", q.motion_shaking_angular);
  }
  if (grasps.object) {
    out["object_file"] = grasps.object->file;
    out["object_scale"] = grasps.object->scale;
  }
  return out;
}

gripper::GraspChecks checks_of(bool reject_collisions, bool reject_shallow, bool refine) {
  gripper::GraspChecks checks;
  checks.collisions = reject_collisions;
  checks.shallow = reject_shallow;
  checks.refine = refine;
  return checks;
}

Array pose_array(const std::vector<lie::Pose>& grasps) {
  std::vector<Eigen::Matrix4d> Ts;
  for (const lie::Pose& g : grasps) Ts.push_back(g.matrix());
  return matrix_array(Ts);
}

bool is_path(const py::object& value) {
  return py::isinstance<py::str>(value) || py::hasattr(value, "__fspath__");
}

// The values of a 2-D array, row-major, with its height and width.
std::vector<double> image_values(const py::object& value, const std::string& what, int& height,
                                 int& width) {
  const Array array = py::cast<Array>(value);
  if (array.ndim() != 2 || array.shape(0) == 0 || array.shape(1) == 0 ||
      array.shape(0) > (1 << 14) || array.shape(1) > (1 << 14)) {
    throw Error(what + " must be an array of shape (height, width)");
  }
  height = static_cast<int>(array.shape(0));
  width = static_cast<int>(array.shape(1));
  return {array.data(), array.data() + array.size()};
}

// A depth image file (16-bit PNG in units of depth_unit, .npy) or an (H, W) array in metres.
camera::DepthImage depth_of(const py::object& depth, double depth_unit) {
  if (is_path(depth)) {
    return camera::read_depth_image(py::cast<std::filesystem::path>(depth), depth_unit);
  }
  int height = 0, width = 0;
  const std::vector<double> values = image_values(depth, "depth", height, width);
  return camera::depth_from_values(values, height, width, 1.0, "depth");
}

// Intrinsics from a file (.json, ROS .yaml) or a dict with fx, fy, cx, cy.
camera::Intrinsics intrinsics_of(const py::object& value) {
  if (is_path(value)) return camera::read_intrinsics(py::cast<std::filesystem::path>(value));
  if (!py::isinstance<py::dict>(value)) {
    throw Error("intrinsics must be a file or a dict with fx, fy, cx and cy");
  }
  const py::dict d = py::cast<py::dict>(value);
  for (const char* key : {"fx", "fy", "cx", "cy"}) {
    if (!d.contains(key)) throw Error(std::string("intrinsics: missing ") + key);
  }
  camera::Intrinsics k;
  k.fx = py::cast<double>(d["fx"]);
  k.fy = py::cast<double>(d["fy"]);
  k.cx = py::cast<double>(d["cx"]);
  k.cy = py::cast<double>(d["cy"]);
  camera::validate(k, "intrinsics");
  return k;
}

// No mask (None), a mask file, or an (H, W) array non-zero on the object.
std::vector<std::uint8_t> mask_of(const py::object& value, int width, int height) {
  if (value.is_none()) return {};
  if (is_path(value))
    return camera::read_mask(py::cast<std::filesystem::path>(value), width, height);
  int mask_height = 0, mask_width = 0;
  const std::vector<double> values = image_values(value, "mask", mask_height, mask_width);
  return camera::mask_from_values(values, mask_height, mask_width, width, height, "mask");
}

// The identity (None), a camera-pose file, or a 4 × 4 array T_base_camera.
lie::Pose camera_pose_of(const py::object& value) {
  if (value.is_none()) return {};
  if (is_path(value)) return camera::read_camera_pose(py::cast<std::filesystem::path>(value));
  const Array array = py::cast<Array>(value);
  if (array.ndim() != 2 || array.shape(0) != 4 || array.shape(1) != 4) {
    throw Error("camera_pose must be a 4 x 4 array");
  }
  return camera::camera_pose_from_matrix(
      Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(array.data()), "camera_pose");
}

// The model handle Python holds.
struct PyGraspModel {
  std::filesystem::path path;
  models::TrainedModel model;
  std::size_t passed = 0;  // grasps of the last sample call its filters kept (all without filters)

  static PyGraspModel load(const std::optional<std::filesystem::path>& path,
                           const std::string& device, int threads) {
    if (threads < 1) throw Error("threads must be at least 1");
    at::set_num_threads(threads);
    PyGraspModel out;
    out.path = path ? *path : models::bundled_model_dir();
    py::gil_scoped_release release;
    out.model = models::load_trained_model(out.path, models::parse_device(device));
    return out;
  }

  // The model's sampling settings with the keyword overrides.
  models::SamplingSettings settings_with(const std::optional<std::string>& solver,
                                         std::optional<int> steps, std::optional<double> guidance,
                                         std::optional<int> clouds,
                                         std::optional<std::size_t> max_draws,
                                         std::optional<bool> fill_rejected) const {
    models::SamplingSettings settings = model.config.sampling;
    if (solver) settings.solver = *solver;
    if (steps) settings.steps = *steps;
    if (guidance) settings.guidance = *guidance;
    if (clouds) settings.clouds = *clouds;
    if (max_draws) settings.max_draws = *max_draws;
    if (fill_rejected) settings.fill_rejected = *fill_rejected;
    models::validate(settings);
    return settings;
  }

  Array sample(const py::object& points, const std::optional<std::filesystem::path>& mesh,
               double scale, const std::optional<std::string>& units, std::size_t num,
               std::uint64_t seed, const std::optional<std::string>& solver,
               std::optional<int> steps, std::optional<double> guidance, std::optional<int> clouds,
               std::optional<std::size_t> max_draws, std::optional<bool> fill_rejected,
               bool reject_collisions, bool reject_shallow, bool refine, bool allow_any_size) {
    if (points.is_none() == !mesh) throw Error("give exactly one of points or mesh");
    const models::SamplingSettings settings =
        settings_with(solver, steps, guidance, clouds, max_draws, fill_rejected);
    const gripper::GraspChecks checks = checks_of(reject_collisions, reject_shallow, refine);
    const double metres = metres_per_unit(units, scale);
    const std::size_t count = models::input_points(model, settings);
    std::vector<Vec3> cloud;
    if (!mesh) cloud = cloud_of(points, metres);
    std::vector<lie::Pose> grasps;
    {
      py::gil_scoped_release release;
      models::ObjectPoints object;
      if (mesh) {
        const geometry::TriangleMesh metric = geometry::scaled(geometry::read_mesh(*mesh), metres);
        if (!allow_any_size)
          geometry::require_plausible_size(metric.vertices, mesh->string(),
                                           geometry::ScaleSource::kKeywords);
        object = models::object_points(metric, count, checks, seed);
      } else {
        if (!allow_any_size)
          geometry::require_plausible_size(cloud, "points", geometry::ScaleSource::kKeywords);
        object = models::object_points(std::move(cloud), count, checks, seed);
      }
      grasps = models::sample_object_grasps(model, object, num, settings, checks, seed, &passed);
    }
    return pose_array(grasps);
  }

  Array sample_view(const py::object& depth, const py::object& intrinsics, const py::object& mask,
                    const py::object& camera_pose, const std::string& table, double depth_unit,
                    double voxel, std::size_t num, std::uint64_t seed,
                    const std::optional<std::string>& solver, std::optional<int> steps,
                    std::optional<double> guidance, std::optional<int> clouds,
                    std::optional<std::size_t> max_draws, std::optional<bool> fill_rejected,
                    bool reject_collisions, bool reject_shallow, bool refine, bool allow_any_size) {
    const models::SamplingSettings settings =
        settings_with(solver, steps, guidance, clouds, max_draws, fill_rejected);
    const gripper::GraspChecks checks = checks_of(reject_collisions, reject_shallow, refine);
    const camera::DepthImage image = depth_of(depth, depth_unit);
    const camera::Intrinsics k = intrinsics_of(intrinsics);
    const std::vector<std::uint8_t> object_mask = mask_of(mask, image.width, image.height);
    const lie::Pose pose = camera_pose_of(camera_pose);
    camera::ViewOptions options;
    if (!(voxel >= 0.0 && voxel <= 0.05)) throw Error("voxel must be in [0, 0.05] m");
    options.voxel = voxel;
    camera::set_table(options, table, "table");
    std::vector<lie::Pose> grasps;
    {
      py::gil_scoped_release release;
      camera::ViewPoints view = camera::view_points(image, k, object_mask, pose, options, seed);
      if (!allow_any_size) {
        camera::check_view_size(view.object, "depth", [](bool) {
          return std::string(
              "check depth_unit (a 16-bit PNG's unit) and that a float array is in "
              "metres, or pass allow_any_size=True");
        });
      }
      const models::ObjectPoints object = models::object_points(
          std::move(view), static_cast<std::size_t>(model.config.model.encoder.points),
          static_cast<std::size_t>(settings.clouds), checks, seed);
      grasps = models::sample_object_grasps(model, object, num, settings, checks, seed, &passed);
    }
    return pose_array(grasps);
  }
};

py::dict simulate(const std::filesystem::path& mesh, const Array& grasps, double scale,
                  const std::optional<std::string>& units, int threads, bool repair,
                  bool allow_any_size) {
  if (threads < 1) throw Error("threads must be at least 1");
  const double metres = metres_per_unit(units, scale);
  const std::vector<lie::Pose> trials = poses(grasps, "grasps");
  std::vector<sim::TrialResult> results;
  {
    py::gil_scoped_release release;
    const geometry::TriangleMesh open = geometry::scaled(geometry::read_mesh(mesh), metres);
    if (!allow_any_size)
      geometry::require_plausible_size(open.vertices, mesh.string(),
                                       geometry::ScaleSource::kKeywords);
    geometry::ClosedMeshOptions closing;
    closing.repair = repair;
    const geometry::ClosedMesh closed =
        geometry::closed_mesh_for_simulation(open, mesh.string(), closing);
    data::AcronymObjectInfo info;
    info.file = mesh.string();
    info.scale = metres;
    const sim::TrialConfig config;
    const sim::SceneObject object =
        sim::make_scene_object(closed.mesh, info, config, {}, sim::default_decomposition_cache());
    results = sim::run_trials(object, trials, config, threads);
  }
  std::vector<bool> success;
  std::vector<double> closing_linear, closing_angular, shaking_linear, shaking_angular, opening;
  for (const sim::TrialResult& r : results) {
    success.push_back(r.success);
    closing_linear.push_back(r.closing_linear);
    closing_angular.push_back(r.closing_angular);
    shaking_linear.push_back(r.shaking_linear);
    shaking_angular.push_back(r.shaking_angular);
    opening.push_back(r.final_opening);
  }
  py::dict out;
  out["success"] = py::array_t<bool>(py::cast(success));
  out["closing_linear"] = vector_array(std::move(closing_linear));
  out["closing_angular"] = vector_array(std::move(closing_angular));
  out["shaking_linear"] = vector_array(std::move(shaking_linear));
  out["shaking_angular"] = vector_array(std::move(shaking_angular));
  out["final_opening"] = vector_array(std::move(opening));
  return out;
}

py::dict prepare_mesh(const std::filesystem::path& mesh,
                      const std::optional<std::filesystem::path>& out, double scale,
                      const std::optional<std::string>& units) {
  const double metres = metres_per_unit(units, scale);
  geometry::WatertightResult result;
  {
    py::gil_scoped_release release;
    const geometry::TriangleMesh metric = geometry::scaled(geometry::read_mesh(mesh), metres);
    result = geometry::cached_make_watertight(metric, {}, geometry::default_watertight_cache());
    if (out) geometry::write_mesh(result.mesh, *out);
  }
  Array vertices({static_cast<py::ssize_t>(result.mesh.vertices.size()), py::ssize_t{3}});
  for (std::size_t i = 0; i < result.mesh.vertices.size(); ++i) {
    for (int c = 0; c < 3; ++c)
      vertices.mutable_at(static_cast<py::ssize_t>(i), c) = result.mesh.vertices[i][c];
  }
  py::array_t<std::int64_t> faces(
      {static_cast<py::ssize_t>(result.mesh.triangles.size()), py::ssize_t{3}});
  for (std::size_t i = 0; i < result.mesh.triangles.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      faces.mutable_at(static_cast<py::ssize_t>(i), c) =
          static_cast<std::int64_t>(result.mesh.triangles[i][static_cast<std::size_t>(c)]);
    }
  }
  py::dict d;
  d["vertices"] = vertices;
  d["faces"] = faces;
  d["wrapped"] = result.report.wrapped;
  d["volume"] = result.report.volume_after;
  return d;
}

void write_grasps(const std::filesystem::path& path, const Array& poses_array,
                  const std::optional<Array>& scores, const std::optional<Array>& widths,
                  const std::optional<py::array_t<bool>>& success,
                  const std::optional<std::string>& object_file, double object_scale,
                  const std::optional<std::string>& format, const std::string& isaac_gripper_frame,
                  double graspnet_depth, int graspnet_object_id) {
  formats::GraspSet grasps;
  grasps.poses = matrices(poses_array, "poses");
  grasps.scores = doubles(scores, "scores");
  grasps.widths = doubles(widths, "widths");
  if (success) {
    grasps.qualities = data::GraspQualities{};
    for (py::ssize_t i = 0; i < success->size(); ++i) {
      grasps.qualities->object_in_gripper.push_back(success->data()[i] ? 1 : 0);
    }
  }
  if (object_file) {
    grasps.object = data::AcronymObjectInfo{};
    grasps.object->file = *object_file;
    grasps.object->scale = object_scale;
  }
  const formats::FormatOptions options =
      format_options(format, isaac_gripper_frame, graspnet_depth, graspnet_object_id);
  py::gil_scoped_release release;
  formats::write_grasps(grasps, path, options);
}

}  // namespace

PYBIND11_MODULE(graspecmf, m) {
  m.doc() = "graspecmf: SO(3)-equivariant 6-DoF grasp generation for the Franka Panda hand.";
  m.attr("__version__") = kVersion;
  py::register_exception<Error>(m, "Error", PyExc_RuntimeError);
  py::class_<PyGraspModel>(m, "GraspModel", "A trained grasp generator (model folder).")
      .def_static("load", &PyGraspModel::load, py::arg("path") = py::none(),
                  py::arg("device") = "cpu", py::arg("threads") = 1,
                  "Loads a model folder (config.json and model.pt, or a training run); the bundled "
                  "mug model when path is None. device: 'cpu', 'cuda' or 'cuda:N'. threads sets "
                  "LibTorch's CPU thread count for the whole process.")
      .def("sample", &PyGraspModel::sample, py::kw_only(), py::arg("points") = py::none(),
           py::arg("mesh") = py::none(), py::arg("scale") = 1.0, py::arg("units") = py::none(),
           py::arg("num") = 100, py::arg("seed") = 0, py::arg("solver") = py::none(),
           py::arg("steps") = py::none(), py::arg("guidance") = py::none(),
           py::arg("clouds") = py::none(), py::arg("max_draws") = py::none(),
           py::arg("fill_rejected") = py::none(), py::arg("reject_collisions") = false,
           py::arg("reject_shallow") = false, py::arg("refine") = false,
           py::arg("allow_any_size") = false,
           "Generates num grasps for one object, given as points (an (N, 3) array or a .xyz/.npy/"
           ".ply file) or as a mesh file (.obj/.stl/.ply/.glb). Units: coordinates times scale "
           "(or units='mm'|'cm'|'m'|'in') must be metres; objects outside 1 cm – 1 m are refused "
           "unless allow_any_size. Returns an (num, 4, 4) float64 array of poses "
           "T_input_gripper in the input's frame, in metres (its coordinates × scale), as ACRONYM "
           "stores grasps: poses of the ACRONYM Panda gripper frame "
           "(+z approach, fingers close along x, pad centre 0.1034 m along z; docs/gripper.md). "
           "solver/steps/guidance/clouds override the model's sampling settings; "
           "reject_collisions, reject_shallow and refine are the command line's grasp filters; "
           "max_draws and fill_rejected override how they give up (--max-draws, --fill-rejected); "
           "`passed` then says how many of the grasps passed.")
      .def("sample_view", &PyGraspModel::sample_view, py::kw_only(), py::arg("depth"),
           py::arg("intrinsics"), py::arg("mask") = py::none(), py::arg("camera_pose") = py::none(),
           py::arg("table") = "none", py::arg("depth_unit") = 0.001, py::arg("voxel") = 0.002,
           py::arg("num") = 100, py::arg("seed") = 0, py::arg("solver") = py::none(),
           py::arg("steps") = py::none(), py::arg("guidance") = py::none(),
           py::arg("clouds") = py::none(), py::arg("max_draws") = py::none(),
           py::arg("fill_rejected") = py::none(), py::arg("reject_collisions") = false,
           py::arg("reject_shallow") = false, py::arg("refine") = false,
           py::arg("allow_any_size") = false,
           "Generates num grasps for the object one depth camera sees, as `graspecmf sample "
           "--depth` does (docs/camera.md). depth: a 16-bit PNG (units of depth_unit metres) or "
           ".npy file, or an (H, W) array in metres (0 and NaN: no reading); intrinsics: a .json "
           "or ROS .yaml file or a dict with fx, fy, cx, cy; mask: a PNG/.npy file or an (H, W) "
           "array, non-zero on the object; camera_pose: a .json file or a 4 x 4 array "
           "T_base_camera; table: 'none', 'auto' (fitted) or 'a,b,c,d' in the output frame; no "
           "grasp reaches below it. Returns an (num, 4, 4) array of T_output_gripper in metres, "
           "in the camera frame or, with camera_pose, the base frame. The filters and their "
           "keywords are sample's.")
      .def_property_readonly(
          "passed", [](const PyGraspModel& self) { return self.passed; },
          "How many grasps of the last sample or sample_view call passed its filters: fewer "
          "than num only with fill_rejected (the rest are rejected grasps); num without filters.")
      .def_property_readonly("path", [](const PyGraspModel& self) { return self.path; })
      .def_property_readonly("type",
                             [](const PyGraspModel& self) { return self.model.config.model.type; })
      .def_property_readonly("sampler", [](const PyGraspModel& self) {
        return self.model.model->sampler(self.model.config.sampling);
      });
  m.def(
      "read_grasps",
      [](const std::filesystem::path& path, const std::optional<std::string>& format,
         const std::string& isaac_gripper_frame) {
        formats::GraspSet grasps;
        {
          py::gil_scoped_release release;
          grasps = formats::read_grasps(path, format_options(format, isaac_gripper_frame, 0.01, 0));
        }
        return grasp_dict(std::move(grasps));
      },
      py::arg("path"), py::kw_only(), py::arg("format") = py::none(),
      py::arg("isaac_gripper_frame") = "auto",
      "Reads a grasp file (ACRONYM .h5/.json, plain .json, Isaac .yaml, GraspNet .npy, "
      "Contact-GraspNet .npz; docs/formats.md) into a dict: poses (N, 4, 4) in the ACRONYM "
      "Panda gripper frame, and when the file has them scores, widths, success, the object "
      "motions, object_file and object_scale.");
  m.def("write_grasps", &write_grasps, py::arg("path"), py::arg("poses"), py::kw_only(),
        py::arg("scores") = py::none(), py::arg("widths") = py::none(),
        py::arg("success") = py::none(), py::arg("object_file") = py::none(),
        py::arg("object_scale") = 1.0, py::arg("format") = py::none(),
        py::arg("isaac_gripper_frame") = "auto", py::arg("graspnet_depth") = 0.01,
        py::arg("graspnet_object_id") = 0,
        "Writes (N, 4, 4) poses in the ACRONYM Panda gripper frame, atomically, in the format of "
        "the extension (or format=); ACRONYM .h5 needs object_file.");
  m.def(
      "write_acronym",
      [](const std::filesystem::path& path, const Array& poses_array,
         const std::string& object_file, double object_scale,
         const std::optional<py::array_t<bool>>& success) {
        write_grasps(path, poses_array, std::nullopt, std::nullopt, success, object_file,
                     object_scale, "acronym", "auto", 0.01, 0);
      },
      py::arg("path"), py::arg("poses"), py::kw_only(), py::arg("object_file"),
      py::arg("object_scale") = 1.0, py::arg("success") = py::none(),
      "write_grasps as an ACRONYM .h5 file: poses T_object_gripper in metres in the frame of "
      "object_file's mesh × object_scale.");
  m.def(
      "emd",
      [](const Array& a, const Array& b) {
        const std::vector<lie::Pose> pa = poses(a, "a"), pb = poses(b, "b");
        py::gil_scoped_release release;
        return metrics::earth_movers_distance(pa, pb, metrics::GraspDistance::geodesic);
      },
      py::arg("a"), py::arg("b"),
      "Earth Mover's Distance between two equally sized (N, 4, 4) pose sets, metres: the mean "
      "sqrt(θ² + |Δp|²) of the optimal one-to-one matching (the paper's metric).");
  m.def("simulate", &simulate, py::arg("mesh"), py::arg("grasps"), py::kw_only(),
        py::arg("scale") = 1.0, py::arg("units") = py::none(), py::arg("threads") = 1,
        py::arg("repair") = true, py::arg("allow_any_size") = false,
        "Simulates each (N, 4, 4) grasp (in the mesh's frame in metres, as sample returns them) on "
        "the "
        "mesh file with graspecmf's MuJoCo shake test (docs/simulator.md). An open mesh is "
        "wrapped first unless repair=False. Returns a dict of arrays: success, the ACRONYM "
        "motion measures and final_opening (m).");
  m.def("prepare_mesh", &prepare_mesh, py::arg("mesh"), py::arg("out") = py::none(), py::kw_only(),
        py::arg("scale") = 1.0, py::arg("units") = py::none(),
        "A closed, outward version of the mesh in metres (its alpha wrap when open; "
        "docs/prepare-mesh.md), written to out when given. Returns vertices, faces, wrapped and "
        "volume (m³).");
  m.def(
      "read_acronym",
      [](const std::filesystem::path& path) {
        formats::GraspSet grasps;
        {
          py::gil_scoped_release release;
          grasps = formats::read_grasps(path, format_options("acronym", "auto", 0.01, 0));
        }
        return grasp_dict(std::move(grasps));
      },
      py::arg("path"), "read_grasps for an ACRONYM .h5 file.");
}
