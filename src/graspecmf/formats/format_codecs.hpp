#pragma once
// The per-format encoders and decoders behind grasp_files.hpp: bytes to GraspSet and back. Decoders
// throw Error "<what>: <why>"; check_grasp_set runs on their result in read_grasps.

#include <string>
#include <string_view>

#include "graspecmf/formats/grasp_files.hpp"

namespace graspecmf::formats {

// ACRONYM's and 6-DOF GraspNet's flat JSON: "transforms", "quality_flex_*", "object",
// "object_scale".
GraspSet decode_acronym_json(std::string_view bytes, const std::string& what);
std::string encode_acronym_json(const GraspSet& grasps);

// GraspGen's per-object JSON: {"object": {file, scale}, "grasps": {transforms, object_in_gripper,
// confidence, width}}.
GraspSet decode_plain_json(std::string_view bytes, const std::string& what);
std::string encode_plain_json(const GraspSet& grasps);

// True when a .json document holds ACRONYM's flat layout rather than GraspGen's.
bool is_acronym_json(std::string_view bytes, const std::string& what);

// Isaac Sim's isaac_grasp YAML (format_version 1.0).
GraspSet decode_isaac_yaml(std::string_view bytes, const std::string& what,
                           IsaacGripperFrame frame);
std::string encode_isaac_yaml(const GraspSet& grasps, IsaacGripperFrame frame);

// GraspNet-1Billion GraspGroup arrays, (N, 17).
GraspSet decode_graspnet_npy(std::string_view bytes, const std::string& what);
std::string encode_graspnet_npy(const GraspSet& grasps, double depth, int object_id);

// Contact-GraspNet's result arrays as plain .npz members.
GraspSet decode_contact_graspnet_npz(std::string_view bytes, const std::string& what);
std::string encode_contact_graspnet_npz(const GraspSet& grasps);

}  // namespace graspecmf::formats
