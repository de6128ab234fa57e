#include <nlohmann/json.hpp>

#include "graspecmf/core/error.hpp"
#include "graspecmf/formats/format_codecs.hpp"

namespace graspecmf::formats {
namespace {

using nlohmann::json;

// The quality keys of ACRONYM's JSON ("quality_flex_" + the HDF5 dataset's name).
constexpr const char* kSuccessKey = "quality_flex_object_in_gripper";
constexpr const char* kClosingLinearKey = "quality_flex_object_motion_during_closing_linear";
constexpr const char* kClosingAngularKey = "quality_flex_object_motion_during_closing_angular";
constexpr const char* kShakingLinearKey = "quality_flex_object_motion_during_shaking_linear";
constexpr const char* kShakingAngularKey = "quality_flex_object_motion_during_shaking_angular";

json parse(std::string_view bytes, const std::string& what) {
  try {
    return json::parse(bytes);
  } catch (const json::exception& e) {
    throw Error(what + ": not valid JSON (" + e.what() + ")");
  }
}

// The member `key` of object `node`, or a null pointer; throws if node is not an object.
const json* member(const json& node, const std::string& key, const std::string& what) {
  if (!node.is_object()) throw Error(what + ": expected a JSON object");
  const auto it = node.find(key);
  return it == node.end() ? nullptr : &*it;
}

// The array of numbers (booleans count as 0 and 1) at `key`.
std::vector<double> numbers(const json& node, const std::string& key, const std::string& what) {
  if (!node.is_array()) throw Error(what + ": \"" + key + "\" must be an array");
  std::vector<double> values;
  for (const json& value : node) {
    if (value.is_boolean()) {
      values.push_back(value.get<bool>() ? 1.0 : 0.0);
    } else if (value.is_number()) {
      values.push_back(value.get<double>());
    } else {
      throw Error(what + ": \"" + key + "\" must hold only numbers");
    }
  }
  return values;
}

// The N×4×4 nested arrays at node, as matrices.
std::vector<Mat4> transforms(const json& node, const std::string& what) {
  if (!node.is_array()) throw Error(what + ": \"transforms\" must be an N×4×4 array");
  std::vector<Mat4> poses;
  for (const json& matrix : node) {
    if (!matrix.is_array() || matrix.size() != 4) {
      throw Error(what + ": transform " + std::to_string(poses.size()) + " is not 4×4");
    }
    Mat4 T;
    for (int r = 0; r < 4; ++r) {
      const std::vector<double> row =
          numbers(matrix[static_cast<std::size_t>(r)], "transforms", what);
      if (row.size() != 4) {
        throw Error(what + ": transform " + std::to_string(poses.size()) + " is not 4×4");
      }
      for (int c = 0; c < 4; ++c) T(r, c) = row[static_cast<std::size_t>(c)];
    }
    poses.push_back(T);
  }
  return poses;
}

json transforms_json(const std::vector<Mat4>& poses) {
  json list = json::array();
  for (const Mat4& T : poses) {
    json matrix = json::array();
    for (int r = 0; r < 4; ++r) matrix.push_back({T(r, 0), T(r, 1), T(r, 2), T(r, 3)});
    list.push_back(std::move(matrix));
  }
  return list;
}

// Success labels: the array at `key`, whose entries must be 0, 1 or booleans.
std::vector<std::int64_t> labels(const json& node, const std::string& key,
                                 const std::string& what) {
  std::vector<std::int64_t> out;
  for (const double value : numbers(node, key, what)) {
    if (value != 0 && value != 1) throw Error(what + ": \"" + key + "\" must hold 0 or 1");
    out.push_back(value != 0);
  }
  return out;
}

// Reads an optional per-grasp array into `out`.
void read_optional(const json& node, const char* key, const std::string& what,
                   std::vector<double>& out) {
  if (const json* value = member(node, key, what)) out = numbers(*value, key, what);
}

// The object's mesh path and scale when both are present as a string and a number.
std::optional<data::AcronymObjectInfo> object_info(const json* file, const json* scale) {
  if (!file || !scale || !file->is_string() || !scale->is_number()) return std::nullopt;
  data::AcronymObjectInfo info;
  info.file = file->get<std::string>();
  info.scale = scale->get<double>();
  return info;
}

std::string dumped(const json& document) {
  return document.dump(1) + "\n";
}

}  // namespace

bool is_acronym_json(std::string_view bytes, const std::string& what) {
  return member(parse(bytes, what), "transforms", what) != nullptr;
}

GraspSet decode_acronym_json(std::string_view bytes, const std::string& what) {
  const json document = parse(bytes, what);
  const json* poses = member(document, "transforms", what);
  if (!poses) throw Error(what + ": no \"transforms\" (not ACRONYM's JSON layout)");
  GraspSet grasps;
  grasps.poses = transforms(*poses, what);
  if (const json* success = member(document, kSuccessKey, what)) {
    data::GraspQualities q;
    q.object_in_gripper = labels(*success, kSuccessKey, what);
    read_optional(document, kClosingLinearKey, what, q.motion_closing_linear);
    read_optional(document, kClosingAngularKey, what, q.motion_closing_angular);
    read_optional(document, kShakingLinearKey, what, q.motion_shaking_linear);
    read_optional(document, kShakingAngularKey, what, q.motion_shaking_angular);
    grasps.qualities = std::move(q);
  }
  grasps.object =
      object_info(member(document, "object", what), member(document, "object_scale", what));
  return grasps;
}

std::string encode_acronym_json(const GraspSet& grasps) {
  json document;
  if (grasps.object) {
    document["object"] = grasps.object->file;
    document["object_scale"] = grasps.object->scale;
  }
  document["gripper"] = "panda";
  document["gripper_configuration"] = {0.04};
  document["transforms"] = transforms_json(grasps.poses);
  if (grasps.qualities) {
    const data::GraspQualities& q = *grasps.qualities;
    document[kSuccessKey] = q.object_in_gripper;
    const auto optional = [&](const char* key, const std::vector<double>& values) {
      if (!values.empty()) document[key] = values;
    };
    optional(kClosingLinearKey, q.motion_closing_linear);
    optional(kClosingAngularKey, q.motion_closing_angular);
    optional(kShakingLinearKey, q.motion_shaking_linear);
    optional(kShakingAngularKey, q.motion_shaking_angular);
  }
  return dumped(document);
}

GraspSet decode_plain_json(std::string_view bytes, const std::string& what) {
  const json document = parse(bytes, what);
  const json* block = member(document, "grasps", what);
  const json* poses = block ? member(*block, "transforms", what) : nullptr;
  if (!poses) throw Error(what + ": no \"grasps\": {\"transforms\": …} (not GraspGen's layout)");
  GraspSet grasps;
  grasps.poses = transforms(*poses, what);
  if (const json* success = member(*block, "object_in_gripper", what)) {
    grasps.qualities = data::GraspQualities{};
    grasps.qualities->object_in_gripper = labels(*success, "object_in_gripper", what);
  }
  read_optional(*block, "confidence", what, grasps.scores);
  read_optional(*block, "width", what, grasps.widths);
  if (const json* object = member(document, "object", what)) {
    grasps.object = object_info(member(*object, "file", what), member(*object, "scale", what));
  }
  return grasps;
}

std::string encode_plain_json(const GraspSet& grasps) {
  json document;
  if (grasps.object) {
    document["object"] = {{"file", grasps.object->file}, {"scale", grasps.object->scale}};
  }
  json block;
  block["transforms"] = transforms_json(grasps.poses);
  if (grasps.qualities) {
    std::vector<bool> success;
    for (const std::int64_t label : grasps.qualities->object_in_gripper)
      success.push_back(label != 0);
    block["object_in_gripper"] = success;
  }
  if (!grasps.scores.empty()) block["confidence"] = grasps.scores;
  if (!grasps.widths.empty()) block["width"] = grasps.widths;
  document["grasps"] = std::move(block);
  return dumped(document);
}

}  // namespace graspecmf::formats
