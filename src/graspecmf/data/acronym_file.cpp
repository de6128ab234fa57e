#include "graspecmf/data/acronym_file.hpp"

#include <chrono>
#include <cmath>
#include <utility>

#include "graspecmf/core/error.hpp"
#include "graspecmf/core/isolated_call.hpp"
#include "graspecmf/data/hdf5_file.hpp"

namespace graspecmf::data {
namespace fs = std::filesystem;

namespace {

constexpr const char* kTransforms = "grasps/transforms";
constexpr const char* kQualities = "grasps/qualities/flex/";
constexpr const char* kSuccess = "object_in_gripper";
constexpr const char* kClosingLinear = "object_motion_during_closing_linear";
constexpr const char* kClosingAngular = "object_motion_during_closing_angular";
constexpr const char* kShakingLinear = "object_motion_during_shaking_linear";
constexpr const char* kShakingAngular = "object_motion_during_shaking_angular";

// HDF5 arrays are row-major; Eigen's default is column-major (vectors must stay column-major).
template <int Rows, int Cols>
using RowMajorMatrix =
    Eigen::Matrix<double, Rows, Cols, (Cols == 1 ? Eigen::ColMajor : Eigen::RowMajor)>;

std::string quality_path(const char* name) {
  return std::string(kQualities) + name;
}

std::string shape_text(const Shape& shape) {
  std::string text = "(";
  for (std::size_t i = 0; i < shape.size(); ++i) text += (i ? ", " : "") + std::to_string(shape[i]);
  return text + ")";
}

// Deviation from a rigid transform tolerated in a file: float32 poses keep about 1e-7; 1e-4 still
// refuses scaled or sheared ones.
constexpr double kMaxRigidityError = 1e-4;

std::vector<Mat4> read_transforms(const Hdf5Reader& file, const fs::path& path) {
  const Shape shape = file.shape(kTransforms);
  if (shape.size() != 3 || shape[1] != 4 || shape[2] != 4) {
    throw Error(path.string() + ": /" + kTransforms + " has shape " + shape_text(shape) +
                ", expected (N, 4, 4)");
  }
  const std::vector<double> values = file.read_doubles(kTransforms);
  std::vector<Mat4> transforms(shape[0]);
  for (std::size_t i = 0; i < shape[0]; ++i) {
    transforms[i] = Eigen::Map<const RowMajorMatrix<4, 4>>(&values[16 * i]);
    if (!(lie::rigidity_error(transforms[i]) <= kMaxRigidityError)) {
      throw Error(path.string() + ": /" + kTransforms + "[" + std::to_string(i) +
                  "] is not a rigid transform (rotation and translation, last row 0 0 0 1)");
    }
  }
  return transforms;
}

template <typename T>
void read_per_grasp(const Hdf5Reader& file, const fs::path& path, const char* name, std::size_t n,
                    std::vector<T>& out) {
  const std::string dataset = quality_path(name);
  if (!file.has_dataset(dataset)) return;
  if constexpr (std::is_same_v<T, double>) {
    out = file.read_doubles(dataset);
  } else {
    out = file.read_int64s(dataset);
  }
  if (out.size() != n) {
    throw Error(path.string() + ": /" + dataset + " has " + std::to_string(out.size()) +
                " entries but there are " + std::to_string(n) + " grasps");
  }
}

std::optional<double> read_optional_double(const Hdf5Reader& file, const std::string& name) {
  if (!file.has_dataset(name)) return std::nullopt;
  return file.read_double(name);
}

template <int Rows, int Cols>
std::optional<Eigen::Matrix<double, Rows, Cols>> read_optional_matrix(const Hdf5Reader& file,
                                                                      const fs::path& path,
                                                                      const std::string& name) {
  if (!file.has_dataset(name)) return std::nullopt;
  const std::vector<double> values = file.read_doubles(name);
  if (values.size() != static_cast<std::size_t>(Rows * Cols)) {
    throw Error(path.string() + ": /" + name + " should hold " + std::to_string(Rows * Cols) +
                " numbers, holds " + std::to_string(values.size()));
  }
  return Eigen::Map<const RowMajorMatrix<Rows, Cols>>(values.data());
}

void require_finite(const fs::path& path, const std::string& what, double value) {
  if (!std::isfinite(value)) throw Error(path.string() + ": " + what + " is not finite");
}

void check_writable(const AcronymGraspFile& record, const fs::path& path) {
  const std::size_t n = record.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (!record.transforms[i].allFinite()) {
      throw Error(path.string() + ": grasp " + std::to_string(i) + " has a non-finite transform");
    }
  }
  if (record.qualities) {
    const GraspQualities& q = *record.qualities;
    for (const std::size_t size : {q.object_in_gripper.size(), q.motion_closing_linear.size(),
                                   q.motion_closing_angular.size(), q.motion_shaking_linear.size(),
                                   q.motion_shaking_angular.size()}) {
      if (size != 0 && size != n) {
        throw Error(path.string() + ": a quality array has " + std::to_string(size) +
                    " entries but there are " + std::to_string(n) + " grasps");
      }
    }
  }
  require_finite(path, "object scale", record.object.scale);
  if (record.object.file.empty()) throw Error(path.string() + ": object file name is empty");
}

template <typename T>
void write_per_grasp(Hdf5Writer& writer, const char* name, const std::vector<T>& values) {
  if (values.empty()) return;
  if constexpr (std::is_same_v<T, double>) {
    writer.write_doubles(quality_path(name), values, {values.size()});
  } else {
    writer.write_int64s(quality_path(name), values, {values.size()});
  }
}

void write_optional_double(Hdf5Writer& writer, const std::string& name,
                           const std::optional<double>& value) {
  if (value) writer.write_double(name, *value);
}

template <typename Matrix>
void write_matrix(Hdf5Writer& writer, const std::string& name, const Matrix& m,
                  const Shape& shape) {
  std::vector<double> values(static_cast<std::size_t>(m.size()));
  Eigen::Map<RowMajorMatrix<Matrix::RowsAtCompileTime, Matrix::ColsAtCompileTime>> row_major(
      values.data());
  row_major = m;
  writer.write_doubles(name, values, shape);
}

}  // namespace

std::size_t AcronymGraspFile::num_successful() const {
  if (!qualities) return 0;
  std::size_t count = 0;
  for (const std::int64_t label : qualities->object_in_gripper) count += label != 0;
  return count;
}

std::vector<lie::Pose> AcronymGraspFile::successful_grasps() const {
  std::vector<lie::Pose> grasps;
  if (!qualities) return grasps;
  for (std::size_t i = 0; i < transforms.size(); ++i) {
    if (qualities->object_in_gripper[i] != 0)
      grasps.push_back(lie::Pose::from_matrix(transforms[i]));
  }
  return grasps;
}

namespace {

// read_acronym_file's work, in this process.
AcronymGraspFile read_acronym_file_here(const fs::path& path) {
  const Hdf5Reader file(path);
  for (const char* required : {kTransforms, "object/file", "object/scale"}) {
    if (!file.has_dataset(required)) {
      throw Error(path.string() + ": not an ACRONYM grasp file (no /" + std::string(required) +
                  ")");
    }
  }
  AcronymGraspFile record;
  record.transforms = read_transforms(file, path);
  const std::size_t n = record.transforms.size();
  if (file.has_dataset(quality_path(kSuccess))) {
    GraspQualities q;
    read_per_grasp(file, path, kSuccess, n, q.object_in_gripper);
    for (std::size_t i = 0; i < n; ++i) {
      if (q.object_in_gripper[i] != 0 && q.object_in_gripper[i] != 1) {
        throw Error(path.string() + ": /" + quality_path(kSuccess) + "[" + std::to_string(i) +
                    "] is " + std::to_string(q.object_in_gripper[i]) + "; labels are 0 or 1");
      }
    }
    read_per_grasp(file, path, kClosingLinear, n, q.motion_closing_linear);
    read_per_grasp(file, path, kClosingAngular, n, q.motion_closing_angular);
    read_per_grasp(file, path, kShakingLinear, n, q.motion_shaking_linear);
    read_per_grasp(file, path, kShakingAngular, n, q.motion_shaking_angular);
    record.qualities = std::move(q);
  }
  if (file.has_dataset("gripper/type")) record.gripper_type = file.read_string("gripper/type");
  record.gripper_configuration = read_optional_double(file, "gripper/configuration");

  AcronymObjectInfo& object = record.object;
  object.file = file.read_string("object/file");
  object.scale = file.read_double("object/scale");
  if (!std::isfinite(object.scale) || object.scale <= 0) {
    throw Error(path.string() + ": /object/scale must be a positive number");
  }
  object.density = read_optional_double(file, "object/density");
  object.friction = read_optional_double(file, "object/friction");
  object.mass = read_optional_double(file, "object/mass");
  object.volume = read_optional_double(file, "object/volume");
  object.com = read_optional_matrix<3, 1>(file, path, "object/com");
  object.inertia = read_optional_matrix<3, 3>(file, path, "object/inertia");
  for (const auto& [name, value] : {std::pair{"density", object.density},
                                    {"friction", object.friction},
                                    {"mass", object.mass},
                                    {"volume", object.volume}}) {
    if (value && !(std::isfinite(*value) && *value > 0)) {
      throw Error(path.string() + ": /object/" + name + " must be a positive number, not " +
                  std::to_string(*value));
    }
  }
  if (object.inertia && !(object.inertia->allFinite() && object.inertia->trace() > 0)) {
    throw Error(path.string() + ": /object/inertia must be finite with a positive trace");
  }
  return record;
}

// The default time limit of a child's read of one of paths: 60 s plus 1 s per 10 MB of the
// largest.
std::chrono::seconds read_limit(const std::vector<fs::path>& paths) {
  std::uintmax_t largest = 0;
  for (const fs::path& path : paths) {
    std::error_code ec;
    const std::uintmax_t bytes = fs::file_size(path, ec);
    if (!ec) largest = std::max(largest, bytes);
  }
  return std::chrono::seconds(60 + largest / 10'000'000);
}

// Reads paths in child processes; entry i is the Error message for paths[i] when the child's read
// threw it or libhdf5 crashed or hung on the file, empty when the child read it.
std::vector<std::string> child_refusals(const std::vector<fs::path>& paths,
                                        std::chrono::seconds limit) {
  std::vector<std::string> refusals(paths.size());
  for (std::size_t start = 0; start < paths.size();) {
    const IsolatedOutcome probe = run_isolated_steps(
        paths.size() - start, [&](std::size_t i) { read_acronym_file_here(paths[start + i]); },
        limit);
    std::copy(probe.refusals.begin(), probe.refusals.end(),
              refusals.begin() + static_cast<std::ptrdiff_t>(start));
    if (probe.completed) break;
    const std::size_t bad = start + probe.finished;
    refusals[bad] = paths[bad].string() + ": damaged HDF5 file (the HDF5 library " + probe.failure +
                    " reading it)";
    start = bad + 1;
  }
  return refusals;
}

}  // namespace

AcronymGraspFile read_acronym_file(const fs::path& path) {
  return read_acronym_file(path, read_limit({path}));
}

AcronymGraspFile read_acronym_file(const fs::path& path, std::chrono::seconds limit) {
  const std::vector<std::string> refusal = child_refusals({path}, limit);
  if (!refusal[0].empty()) throw Error(refusal[0]);
  return read_acronym_file_here(path);
}

void read_acronym_files(const std::vector<fs::path>& paths,
                        const std::function<void(std::size_t, AcronymGraspFile&&)>& use,
                        const std::function<void(std::size_t, const std::string&)>& refuse) {
  const std::vector<std::string> refusals = child_refusals(paths, read_limit(paths));
  for (std::size_t i = 0; i < paths.size(); ++i) {
    if (!refusals[i].empty()) {  // refused in the child: not read a second time
      refuse(i, refusals[i]);
      continue;
    }
    std::optional<AcronymGraspFile> record;
    try {
      record = read_acronym_file_here(paths[i]);
    } catch (const Error& e) {
      refuse(i, e.what());
      continue;
    }
    use(i, std::move(*record));
  }
}

void write_acronym_file(const AcronymGraspFile& record, const fs::path& path) {
  check_writable(record, path);
  Hdf5Writer writer(path);
  const std::size_t n = record.size();
  std::vector<double> transforms(16 * n);
  for (std::size_t i = 0; i < n; ++i) {
    Eigen::Map<RowMajorMatrix<4, 4>> row_major(&transforms[16 * i]);
    row_major = record.transforms[i];
  }
  writer.write_doubles(kTransforms, transforms, {n, 4, 4});
  if (record.qualities) {
    const GraspQualities& q = *record.qualities;
    write_per_grasp(writer, kSuccess, q.object_in_gripper);
    write_per_grasp(writer, kClosingAngular, q.motion_closing_angular);
    write_per_grasp(writer, kClosingLinear, q.motion_closing_linear);
    write_per_grasp(writer, kShakingAngular, q.motion_shaking_angular);
    write_per_grasp(writer, kShakingLinear, q.motion_shaking_linear);
  }
  if (record.gripper_configuration) {
    writer.write_doubles("gripper/configuration", {*record.gripper_configuration}, {1});
  }
  writer.write_string("gripper/type", record.gripper_type);
  const AcronymObjectInfo& object = record.object;
  if (object.com) write_matrix(writer, "object/com", *object.com, {3});
  write_optional_double(writer, "object/density", object.density);
  writer.write_string("object/file", object.file);
  write_optional_double(writer, "object/friction", object.friction);
  if (object.inertia) write_matrix(writer, "object/inertia", *object.inertia, {3, 3});
  write_optional_double(writer, "object/mass", object.mass);
  writer.write_double("object/scale", object.scale);
  write_optional_double(writer, "object/volume", object.volume);
  writer.close();
}

void require_panda_gripper(const AcronymGraspFile& record, const fs::path& path) {
  if (record.gripper_type != "franka_panda" && record.gripper_type != "panda") {
    throw Error(path.string() + ": gripper type '" + record.gripper_type +
                "' is not supported (only the Franka Panda hand: franka_panda or panda)");
  }
}

Mat3 standard_inertia(const Mat3& acronym_inertia) {
  Mat3 standard = -acronym_inertia;
  standard.diagonal() = acronym_inertia.diagonal();
  return standard;
}

AcronymGraspFile moved_rigidly(const AcronymGraspFile& record, const lie::Pose& motion) {
  AcronymGraspFile out = record;
  for (Mat4& T : out.transforms) T = lie::compose(motion, lie::Pose::from_matrix(T)).matrix();
  AcronymObjectInfo& object = out.object;
  if (object.com) object.com = lie::apply(motion, *object.com);
  // The stored sign convention flips with an involution, so rotate the standard tensor.
  if (object.inertia) {
    object.inertia =
        standard_inertia(motion.R * standard_inertia(*object.inertia) * motion.R.transpose());
  }
  return out;
}

}  // namespace graspecmf::data
