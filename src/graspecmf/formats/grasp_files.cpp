#include "graspecmf/formats/grasp_files.hpp"

#include <array>
#include <vector>

#include "graspecmf/core/atomic_file.hpp"
#include "graspecmf/core/error.hpp"
#include "graspecmf/core/input_file.hpp"
#include "graspecmf/core/json_file.hpp"
#include "graspecmf/formats/format_codecs.hpp"
#include "graspecmf/gripper/panda.hpp"

namespace graspecmf::formats {
namespace fs = std::filesystem;
namespace {

// Each format's name and which of a GraspSet's fields it stores.
struct FormatFacts {
  GraspFormat format;
  const char* name;
  bool labels, motions, scores, widths, object;
};

constexpr std::array<FormatFacts, 6> kFormats{{
    {GraspFormat::acronym, "acronym", true, true, false, false, true},
    {GraspFormat::acronym_json, "acronym-json", true, true, false, false, true},
    {GraspFormat::json, "json", true, false, true, true, true},
    {GraspFormat::isaac, "isaac", false, false, true, true, false},
    {GraspFormat::graspnet, "graspnet", false, false, true, true, false},
    {GraspFormat::contact_graspnet, "contact-graspnet", false, false, true, true, false},
}};

const FormatFacts& facts(GraspFormat format) {
  for (const FormatFacts& f : kFormats) {
    if (f.format == format) return f;
  }
  throw Error("unknown grasp format");
}

}  // namespace

std::string format_name(GraspFormat format) {
  return facts(format).name;
}

std::vector<std::string> format_names() {
  std::vector<std::string> names;
  for (const FormatFacts& f : kFormats) names.emplace_back(f.name);
  return names;
}

IsaacGripperFrame parse_isaac_gripper_frame(const std::string& name) {
  if (name == "auto") return IsaacGripperFrame::automatic;
  if (name == "acronym") return IsaacGripperFrame::acronym;
  if (name == "panda_hand") return IsaacGripperFrame::panda_hand;
  throw Error("unknown isaac_grasp gripper frame '" + name + "' (auto, acronym or panda_hand)");
}

GraspFormat parse_format(const std::string& name) {
  std::string known;
  for (const FormatFacts& f : kFormats) {
    if (name == f.name) return f.format;
    known += std::string(known.empty() ? "" : ", ") + f.name;
  }
  throw Error("unknown grasp format '" + name + "' (known: " + known + ")");
}

GraspFormat format_of_path(const fs::path& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".h5" || ext == ".hdf5") return GraspFormat::acronym;
  if (ext == ".json") return GraspFormat::json;
  if (ext == ".yaml" || ext == ".yml") return GraspFormat::isaac;
  if (ext == ".npy") return GraspFormat::graspnet;
  if (ext == ".npz") return GraspFormat::contact_graspnet;
  throw Error(path.string() +
              ": cannot tell the grasp format from the extension (.h5, .json, .yaml, .npy or "
              ".npz; or name it with --format)");
}

std::vector<std::string> unkept_fields(const GraspSet& grasps, GraspFormat format) {
  const FormatFacts& f = facts(format);
  const data::GraspQualities* q = grasps.qualities ? &*grasps.qualities : nullptr;
  std::vector<std::string> lost;
  if (q && !f.labels)
    lost.emplace_back(grasps.scores.empty() ? "success labels (kept as scores)" : "success labels");
  if (q && !q->motion_closing_linear.empty() && !f.motions) lost.emplace_back("object motions");
  if (!grasps.scores.empty() && !f.scores) lost.emplace_back("scores");
  if (!grasps.widths.empty() && !f.widths) lost.emplace_back("widths");
  if (grasps.object && !f.object) lost.emplace_back("the object's mesh path and scale");
  return lost;
}

GraspSet read_grasps(const fs::path& path, const FormatOptions& options) {
  const GraspFormat format = options.format ? *options.format : format_of_path(path);
  const std::string what = path.string();
  GraspSet grasps;
  if (format == GraspFormat::acronym) {
    const data::AcronymGraspFile record = data::read_acronym_file(path);
    data::require_panda_gripper(record, path);
    grasps = from_acronym(record);
  } else {
    // Parsed YAML and JSON take tens of times their size: they get JSON's cap.
    const bool text = format != GraspFormat::graspnet && format != GraspFormat::contact_graspnet;
    const std::string bytes = read_input_file(path, text ? kMaxJsonFileBytes : kMaxInputFileBytes);
    switch (format) {
      case GraspFormat::json:
        grasps = !options.format && is_acronym_json(bytes, what) ? decode_acronym_json(bytes, what)
                                                                 : decode_plain_json(bytes, what);
        break;
      case GraspFormat::acronym_json:
        grasps = decode_acronym_json(bytes, what);
        break;
      case GraspFormat::isaac:
        grasps = decode_isaac_yaml(bytes, what, options.isaac_gripper_frame);
        break;
      case GraspFormat::graspnet:
        grasps = decode_graspnet_npy(bytes, what);
        break;
      case GraspFormat::contact_graspnet:
        grasps = decode_contact_graspnet_npz(bytes, what);
        break;
      case GraspFormat::acronym:
        break;
    }
  }
  check_grasp_set(grasps, what);
  return grasps;
}

void write_grasps(const GraspSet& grasps, const fs::path& path, const FormatOptions& options) {
  const GraspFormat format = options.format ? *options.format : format_of_path(path);
  const std::string what = path.string();
  check_grasp_set(grasps, what);
  if (format == GraspFormat::graspnet &&
      !(options.graspnet_depth >= 0 && options.graspnet_depth <= gripper::panda::kFingertipZ)) {
    throw Error(what + ": the GraspNet depth must lie in [0, 0.1122] m (the finger length)");
  }
  switch (format) {
    case GraspFormat::acronym:
      data::write_acronym_file(to_acronym(grasps, what), path);
      return;
    case GraspFormat::acronym_json:
      return write_file_atomically(path, encode_acronym_json(grasps));
    case GraspFormat::json:
      return write_file_atomically(path, encode_plain_json(grasps));
    case GraspFormat::isaac:
      return write_file_atomically(path, encode_isaac_yaml(grasps, options.isaac_gripper_frame));
    case GraspFormat::graspnet:
      return write_file_atomically(
          path, encode_graspnet_npy(grasps, options.graspnet_depth, options.graspnet_object_id));
    case GraspFormat::contact_graspnet:
      return write_file_atomically(path, encode_contact_graspnet_npz(grasps));
  }
}

}  // namespace graspecmf::formats
