#pragma once
// Grasp files in the formats of the tools around graspecmf, read and written through one
// GraspSet: ACRONYM HDF5 and JSON, a plain JSON layout (GraspGen's), Isaac Sim's isaac_grasp YAML,
// GraspNet-1Billion GraspGroup .npy and Contact-GraspNet-style .npz. docs/formats.md gives each
// format's layout, frame change and what it cannot carry.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "graspecmf/formats/grasp_set.hpp"

namespace graspecmf::formats {

enum class GraspFormat { acronym, acronym_json, json, isaac, graspnet, contact_graspnet };

// Which gripper frame an isaac_grasp file's poses are of: ACRONYM's Panda frame, or the URDF/USD
// panda_hand frame Isaac Sim's Franka uses (ACRONYM's turned by −90° about z). automatic reads the
// file's gripper_frame field (ACRONYM's frame when it is absent) and writes panda_hand.
enum class IsaacGripperFrame { automatic, acronym, panda_hand };

// The frame named "auto", "acronym" or "panda_hand"; throws Error otherwise.
IsaacGripperFrame parse_isaac_gripper_frame(const std::string& name);

struct FormatOptions {
  std::optional<GraspFormat> format;  // unset: by extension (and, for .json, by content)
  IsaacGripperFrame isaac_gripper_frame = IsaacGripperFrame::automatic;
  double graspnet_depth = 0.01;  // GraspGroup depth written: grasp point 0.01 m inside the tips
  int graspnet_object_id = 0;    // GraspGroup object id written
};

// The format's command-line name ("acronym", "acronym-json", "json", "isaac", "graspnet",
// "contact-graspnet").
std::string format_name(GraspFormat format);
// Every format's name, in the order of GraspFormat.
std::vector<std::string> format_names();
// The format named `name`; throws Error listing the names otherwise.
GraspFormat parse_format(const std::string& name);
// The format a file name implies: .h5/.hdf5 acronym, .json json, .yaml/.yml isaac, .npy graspnet,
// .npz contact-graspnet; throws Error naming the path for any other extension.
GraspFormat format_of_path(const std::filesystem::path& path);

// What of the grasps a file in `format` cannot hold, in words ("scores", "object motions", …);
// empty when it keeps everything they carry.
std::vector<std::string> unkept_fields(const GraspSet& grasps, GraspFormat format);

// The grasps in the file. Throws Error "<path>: <why>" if it is missing, damaged, not in the
// format, or holds a pose that is not a finite rigid transform.
GraspSet read_grasps(const std::filesystem::path& path, const FormatOptions& options = {});

// Writes the grasps atomically (a failure leaves no file and keeps an old one). Throws Error
// naming the path if check_grasp_set fails or the format needs what the set lacks (ACRONYM HDF5:
// the object's mesh path and scale).
void write_grasps(const GraspSet& grasps, const std::filesystem::path& path,
                  const FormatOptions& options = {});

}  // namespace graspecmf::formats
