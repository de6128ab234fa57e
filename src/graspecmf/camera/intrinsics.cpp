#include "graspecmf/camera/intrinsics.hpp"

#include <yaml-cpp/yaml.h>

#include <array>
#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "graspecmf/core/error.hpp"
#include "graspecmf/core/input_file.hpp"
#include "graspecmf/core/json_file.hpp"

namespace graspecmf::camera {
namespace {

constexpr std::uintmax_t kMaxIntrinsicsBytes = 1 << 20;

// The nine numbers of K, row by row, whichever way the file lays them out.
Intrinsics from_matrix(const std::vector<double>& K, const std::string& what) {
  if (K.size() != 9) {
    throw Error(what + ": the camera matrix has " + std::to_string(K.size()) +
                " numbers, not 9 (3 × 3)");
  }
  if (K[1] != 0.0 || K[3] != 0.0 || K[6] != 0.0 || K[7] != 0.0 || K[8] != 1.0) {
    throw Error(what + ": the camera matrix is not of the form [fx 0 cx; 0 fy cy; 0 0 1]");
  }
  Intrinsics k;
  k.fx = K[0];
  k.cx = K[2];
  k.fy = K[4];
  k.cy = K[5];
  return k;
}

std::vector<double> json_matrix(const nlohmann::json& node, const std::string& what) {
  if (!node.is_array()) throw Error(what + ": \"K\" must be a list of numbers");
  std::vector<double> K;
  for (const auto& entry : node) {
    if (entry.is_array()) {
      for (const auto& value : entry) K.push_back(value.get<double>());
    } else {
      K.push_back(entry.get<double>());
    }
  }
  return K;
}

Intrinsics read_json(const std::filesystem::path& path) {
  const std::string what = path.string();
  const nlohmann::json document = read_json_file(path);
  if (!document.is_object()) throw Error(what + ": expected a JSON object");
  Intrinsics k;
  try {
    if (document.contains("K")) {
      k = from_matrix(json_matrix(document["K"], what), what);
    } else {
      for (const char* key : {"fx", "fy", "cx", "cy"}) {
        if (!document.contains(key)) {
          throw Error(what + ": no \"" + std::string(key) +
                      "\" (give \"fx\", \"fy\", \"cx\", \"cy\" or the 3 × 3 \"K\")");
        }
      }
      k.fx = document["fx"].get<double>();
      k.fy = document["fy"].get<double>();
      k.cx = document["cx"].get<double>();
      k.cy = document["cy"].get<double>();
    }
    if (document.contains("width")) k.width = document["width"].get<int>();
    if (document.contains("height")) k.height = document["height"].get<int>();
  } catch (const nlohmann::json::exception&) {
    throw Error(what + ": the intrinsics must be numbers");
  }
  return k;
}

std::optional<YAML::Node> field(const YAML::Node& document,
                                std::initializer_list<const char*> keys) {
  for (const char* key : keys) {
    if (document[key]) return document[key];
  }
  return std::nullopt;
}

Intrinsics read_yaml(const std::filesystem::path& path) {
  const std::string what = path.string();
  const std::string text = read_input_file(path, kMaxIntrinsicsBytes);
  try {
    const YAML::Node document = YAML::Load(text);
    if (!document.IsMap()) throw Error(what + ": expected a YAML mapping");
    std::optional<YAML::Node> matrix = field(document, {"K", "k"});
    if (!matrix && document["camera_matrix"]) matrix = document["camera_matrix"]["data"];
    if (!matrix || !matrix->IsSequence()) {
      throw Error(what + ": no camera matrix (\"K\", \"k\" or \"camera_matrix: data\")");
    }
    Intrinsics k = from_matrix(matrix->as<std::vector<double>>(), what);
    if (auto width = field(document, {"width", "image_width"})) k.width = width->as<int>();
    if (auto height = field(document, {"height", "image_height"})) k.height = height->as<int>();
    return k;
  } catch (const YAML::Exception& e) {
    throw Error(what + ": " + e.what());
  }
}

}  // namespace

Intrinsics realsense_d435() {
  Intrinsics k;
  k.fx = k.fy = 615.0;
  k.cx = 319.5;
  k.cy = 239.5;
  k.width = 640;
  k.height = 480;
  return k;
}

void validate(const Intrinsics& k, const std::string& what) {
  const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (!positive(k.fx) || !positive(k.fy)) {
    throw Error(what + ": the focal lengths fx and fy must be positive");
  }
  if (!std::isfinite(k.cx) || !std::isfinite(k.cy)) {
    throw Error(what + ": the principal point cx, cy must be finite");
  }
  if (k.width < 0 || k.height < 0 || (k.width == 0) != (k.height == 0)) {
    throw Error(what + ": width and height must both be positive (or both left out)");
  }
}

Intrinsics read_intrinsics(const std::filesystem::path& path) {
  const std::string extension = lower_extension(path);
  Intrinsics k;
  if (extension == ".json") {
    k = read_json(path);
  } else if (extension == ".yaml" || extension == ".yml") {
    k = read_yaml(path);
  } else {
    throw Error(path.string() + ": intrinsics must be a .json or .yaml file");
  }
  validate(k, path.string());
  return k;
}

}  // namespace graspecmf::camera
