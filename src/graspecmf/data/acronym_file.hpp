#pragma once
// ACRONYM per-object grasp files (HDF5): the in-memory record, a validating reader and a writer
// that reproduces the original layout exactly (dataset paths, types, chunking, deflate level).

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "graspecmf/lie/se3.hpp"

namespace graspecmf::data {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Mat4 = Eigen::Matrix4d;

// /grasps/qualities/flex/*: one entry per grasp.
struct GraspQualities {
  std::vector<std::int64_t> object_in_gripper;  // 1 = success
  std::vector<double> motion_closing_linear, motion_closing_angular;
  std::vector<double> motion_shaking_linear, motion_shaking_angular;
};

// /object/*. Optional fields are absent in files that lack them and are then not written.
struct AcronymObjectInfo {
  std::string file;    // mesh path relative to the dataset root
  double scale = 1.0;  // metric vertices = raw vertices × scale
  std::optional<double> density, friction, mass, volume;
  std::optional<Vec3> com;
  std::optional<Mat3> inertia;  // as stored: ACRONYM's off-diagonal sign (see standard_inertia)
};

struct AcronymGraspFile {
  std::vector<Mat4> transforms;  // T_object_gripper, metres, in the scaled mesh frame
  std::optional<GraspQualities> qualities;
  std::string gripper_type = "panda";
  std::optional<double> gripper_configuration;  // finger joint (half opening), 0.04 for panda
  AcronymObjectInfo object;

  std::size_t size() const { return transforms.size(); }
  // Number of grasps whose object_in_gripper is non-zero (0 without qualities).
  std::size_t num_successful() const;
  // The transforms whose object_in_gripper is non-zero, as poses.
  std::vector<lie::Pose> successful_grasps() const;
};

// Reads an ACRONYM grasp file. Requires /grasps/transforms (N×4×4), /object/file and /object/scale;
// quality arrays, when present, must have N entries. Throws Error naming file and dataset. The
// file is first read in a child process (core/isolated_call.hpp), because libhdf5 can crash, abort
// or hang on a damaged file: such a file gives an Error too, also when reading takes longer than
// `limit` (by default 60 s plus 1 s per 10 MB).
AcronymGraspFile read_acronym_file(const std::filesystem::path& path);
AcronymGraspFile read_acronym_file(const std::filesystem::path& path, std::chrono::seconds limit);

// Reads each of paths as read_acronym_file does, calling use(i, record) for each file read and
// refuse(i, message) for each that gives an Error, in order. All files are first read in one child
// process (one more after each file libhdf5 crashed or hung on), so a dataset costs one fork, not
// one per file.
void read_acronym_files(const std::vector<std::filesystem::path>& paths,
                        const std::function<void(std::size_t, AcronymGraspFile&&)>& use,
                        const std::function<void(std::size_t, const std::string&)>& refuse);

// Writes the record in ACRONYM's layout, atomically (a failure leaves no file and keeps any old
// one). Throws Error if array lengths disagree or a number is not finite.
void write_acronym_file(const AcronymGraspFile& record, const std::filesystem::path& path);

// Throws Error naming path unless the record's grasps are for the Franka Panda hand ("franka_panda"
// or "panda"), the only gripper graspecmf simulates and trains for.
void require_panda_gripper(const AcronymGraspFile& record, const std::filesystem::path& path);

// The standard inertia tensor (positive off-diagonal = −∫xy dm) from ACRONYM's stored one, whose
// off-diagonal entries carry the opposite sign.
Mat3 standard_inertia(const Mat3& acronym_inertia);

// The record after its object and grasps move rigidly together by `motion` (applied to the scaled
// mesh frame): transforms and centre of mass moved, inertia rotated; labels and the rest kept.
AcronymGraspFile moved_rigidly(const AcronymGraspFile& record, const lie::Pose& motion);

}  // namespace graspecmf::data
