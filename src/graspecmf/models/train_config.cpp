#include "graspecmf/models/train_config.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <type_traits>

#include "graspecmf/core/error.hpp"
#include "graspecmf/core/json_file.hpp"
#include "graspecmf/flow/sampler.hpp"
#include "graspecmf/models/generator.hpp"

namespace graspecmf::models {
using nlohmann::json;
namespace {

// Reads json[key] into value when present; a wrong type is an Error naming the key. Integer
// settings take only integers within the type's range (12.7 or -1 for a count is an error, not
// 12 or 2^64 - 1).
template <typename T>
void read(const json& j, const char* key, T& value, const std::string& section) {
  if (!j.contains(key)) return;
  const json& v = j.at(key);
  const std::string name = "train config: " + section + key;
  if constexpr (std::is_integral_v<T> && !std::is_same_v<T, bool>) {
    if (!v.is_number_integer()) throw Error(name + " must be an integer");
    constexpr auto kMax = static_cast<std::uint64_t>(std::numeric_limits<T>::max());
    const bool negative = !v.is_number_unsigned() && v.get<std::int64_t>() < 0;
    const bool in_range =
        negative ? std::is_signed_v<T> &&
                       v.get<std::int64_t>() >= std::int64_t{std::numeric_limits<T>::min()}
                 : v.get<std::uint64_t>() <= kMax;
    if (!in_range) throw Error(name + " is out of range");
    value = v.get<T>();
  } else if constexpr (std::is_same_v<T, std::vector<int64_t>>) {
    if (!v.is_array()) throw Error(name + " must be a list of integers");
    std::vector<int64_t> list;
    for (const json& item : v) {
      if (!item.is_number_integer()) throw Error(name + " must be a list of integers");
      list.push_back(item.get<int64_t>());
    }
    value = list;
  } else {
    try {
      value = v.get<T>();
    } catch (const json::exception&) {
      throw Error(name + " has the wrong type");
    }
  }
}

// Throws Error if j has a key outside `known`.
void only(const json& j, std::initializer_list<const char*> known, const std::string& section) {
  if (!j.is_object()) throw Error("train config: " + section + " must be an object");
  for (const auto& item : j.items()) {
    // A named copy: C++17 lambdas cannot capture a structured binding (clang before 16 refuses).
    const std::string key = item.key();
    if (std::none_of(known.begin(), known.end(), [&](const char* k) { return key == k; })) {
      throw Error("train config: unknown setting " + section + key);
    }
  }
}

// Reads json[key], a list of two numbers [lo, hi], when present.
void read_range(const json& j, const char* key, double& lo, double& hi,
                const std::string& section) {
  if (!j.contains(key)) return;
  const json& v = j.at(key);
  if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number()) {
    throw Error("train config: " + section + key + " must be a list of two numbers [min, max]");
  }
  lo = v[0].get<double>();
  hi = v[1].get<double>();
}

constexpr std::size_t kMaxLayers = 64;
constexpr int64_t kMaxWidth = 4096;
constexpr double kMaxTensorBytes = 16.0 * (1 << 30);

}  // namespace

double learning_rate_at(const TrainConfig& c, std::int64_t step) {
  if (c.learning_rate_schedule == "constant") return c.learning_rate;
  const double progress = static_cast<double>(step - 1) / static_cast<double>(c.steps);
  return 0.5 * c.learning_rate * (1 + std::cos(M_PI * progress));
}

void validate(const TrainConfig& c) {
  const std::vector<std::string>& types = model_types();
  if (std::find(types.begin(), types.end(), c.model.type) == types.end()) {
    std::string known;
    for (const std::string& type : types) known += (known.empty() ? "" : ", ") + type;
    throw Error("train config: unknown model.type " + c.model.type + " (known: " + known + ")");
  }
  if (c.model.type != "graspecmf" && c.model.field.z_every_layer) {
    throw Error("train config: model.field.z_every_layer is a graspecmf setting");
  }
  const auto widths_in_range = [](const std::vector<int64_t>& widths) {
    return !widths.empty() && widths.size() <= kMaxLayers &&
           std::all_of(widths.begin(), widths.end(),
                       [](int64_t w) { return w > 0 && w <= kMaxWidth; });
  };
  const GraspNetOptions& g = c.model.graspnet;
  for (const double value :
       {c.model.encoder.slope, c.model.field.slope, c.data.position_scale, c.learning_rate,
        c.weight_decay, c.prior_position_std, g.radius, g.kl_weight, g.confidence_weight}) {
    // JSON has no NaN, but 1e999 parses as infinity.
    if (!std::isfinite(value)) throw Error("train config: every number must be finite");
  }
  const nn::EncoderOptions& e = c.model.encoder;
  if (!(e.slope >= 0 && e.slope < 1) || !(c.model.field.slope >= 0 && c.model.field.slope < 1)) {
    throw Error("train config: the VN-LeakyReLU slopes must be in [0, 1)");
  }
  if (!widths_in_range(e.widths)) {
    throw Error("train config: encoder widths must be 1 to 64 layers of 1 to 4096 channels");
  }
  if (e.k < 1 || e.k > 256 || e.out_channels < 1 || e.out_channels > kMaxWidth || e.points < e.k ||
      e.points > 100000) {
    throw Error("train config: need 1 ≤ k ≤ 256, 1 ≤ out_channels ≤ 4096 and k ≤ points ≤ 100000");
  }
  if (g.latent_size < 1 || g.latent_size > 64 || !(g.radius > 0) || g.centroids < 4 ||
      !(g.kl_weight >= 0) || !(g.confidence_weight >= 0)) {
    throw Error(
        "train config: model.graspnet needs 1 ≤ latent_size ≤ 64, radius > 0, "
        "centroids ≥ 4 and non-negative weights");
  }
  if (c.model.se3dif.distance_points > 100000) {
    throw Error("train config: model.se3dif.distance_points must be at most 100000");
  }
  if (c.model.type.rfind("graspnet_", 0) == 0 && g.centroids > e.points) {
    throw Error("train config: model.graspnet.centroids must not exceed encoder.points");
  }
  if (!widths_in_range(c.model.field.hidden_widths)) {
    throw Error("train config: field hidden_widths must be 1 to 64 layers of 1 to 4096 channels");
  }
  if (c.data.objects_per_step < 1 || c.data.objects_per_step > 1024 ||
      c.data.grasps_per_object > 100000) {
    throw Error("train config: need 1 ≤ objects_per_step ≤ 1024 and grasps_per_object ≤ 100000");
  }
  const double edge_bytes =
      12.0 * static_cast<double>(c.data.objects_per_step) * static_cast<double>(e.points) *
      static_cast<double>(e.k) *
      static_cast<double>(*std::max_element(e.widths.begin(), e.widths.end()));
  if (edge_bytes > kMaxTensorBytes) {
    throw Error("train config: one encoder layer would need about " +
                std::to_string(static_cast<long long>(edge_bytes / (1 << 20))) +
                " MiB (objects_per_step × points × k × width × 12 bytes; the limit is 16 GiB)");
  }
  if (!(c.data.position_scale > 0)) throw Error("train config: position_scale must be > 0");
  if (!(c.data.stretch >= 0 && c.data.stretch < 0.5)) {
    throw Error("train config: data.stretch must be in [0, 0.5)");
  }
  camera::validate(c.data.views, "train config: data.views");
  if (c.steps < 1 || c.steps > 1000000000) throw Error("train config: steps must be in [1, 10^9]");
  if (!(c.learning_rate > 0) || !(c.weight_decay >= 0)) {
    throw Error("train config: learning_rate must be > 0 and weight_decay ≥ 0");
  }
  if (c.learning_rate_schedule != "constant" && c.learning_rate_schedule != "cosine") {
    throw Error("train config: learning_rate_schedule must be constant or cosine");
  }
  if (!(c.ema_decay >= 0 && c.ema_decay < 1))
    throw Error("train config: ema_decay must be in [0, 1)");
  if (!(c.cfg_drop >= 0 && c.cfg_drop <= 1))
    throw Error("train config: cfg_drop must be in [0, 1]");
  if (!(c.prior_position_std > 0)) throw Error("train config: prior_position_std must be > 0");
  if (c.log_every < 1 || c.checkpoint_every < 1 || c.validate_every < 0) {
    throw Error("train config: log_every and checkpoint_every must be ≥ 1, validate_every ≥ 0");
  }
  if (c.validation_grasps < 1 || c.validation_grasps > 100000) {
    throw Error("train config: validation_grasps must be in [1, 100000]");
  }
  try {
    validate(c.sampling);
  } catch (const Error& error) {
    throw Error(std::string("train config: ") + error.what());
  }
}

void validate(const SamplingSettings& s) {
  flow::parse_solver(s.solver);
  if (s.steps < 1 || s.steps > 10000) throw Error("sampling steps must be in [1, 10000]");
  if (!std::isfinite(s.guidance)) throw Error("guidance must be finite");
  if (s.clouds < 1 || s.clouds > 1024) throw Error("sampling clouds must be in [1, 1024]");
}

json to_json(const TrainConfig& c) {
  const nn::EncoderOptions& e = c.model.encoder;
  const GraspNetOptions& g = c.model.graspnet;
  return {{"model",
           {{"type", c.model.type},
            {"encoder",
             {{"widths", e.widths},
              {"k", e.k},
              {"out_channels", e.out_channels},
              {"points", e.points},
              {"slope", e.slope}}},
            {"field",
             {{"hidden_widths", c.model.field.hidden_widths},
              {"slope", c.model.field.slope},
              {"z_every_layer", c.model.field.z_every_layer}}},
            {"graspnet",
             {{"latent_size", g.latent_size},
              {"radius", g.radius},
              {"centroids", g.centroids},
              {"kl_weight", g.kl_weight},
              {"confidence_weight", g.confidence_weight}}},
            {"se3dif", {{"distance_points", c.model.se3dif.distance_points}}}}},
          {"data",
           {{"objects_per_step", c.data.objects_per_step},
            {"grasps_per_object", c.data.grasps_per_object},
            {"position_scale", c.data.position_scale},
            {"augmentation", data::to_string(c.data.augmentation)},
            {"stretch", c.data.stretch},
            {"input", data::to_string(c.data.input)},
            {"views",
             {{"elevation", {c.data.views.min_elevation, c.data.views.max_elevation}},
              {"distance", {c.data.views.min_distance, c.data.views.max_distance}},
              {"noise", c.data.views.noisy}}}}},
          {"steps", c.steps},
          {"learning_rate", c.learning_rate},
          {"learning_rate_schedule", c.learning_rate_schedule},
          {"weight_decay", c.weight_decay},
          {"ema_decay", c.ema_decay},
          {"cfg_drop", c.cfg_drop},
          {"prior_position_std", c.prior_position_std},
          {"seed", c.seed},
          {"log_every", c.log_every},
          {"checkpoint_every", c.checkpoint_every},
          {"validate_every", c.validate_every},
          {"validation_grasps", c.validation_grasps},
          {"validation_objects", c.validation_objects},
          {"sampling",
           {{"solver", c.sampling.solver},
            {"steps", c.sampling.steps},
            {"guidance", c.sampling.guidance},
            {"clouds", c.sampling.clouds},
            {"max_draws", c.sampling.max_draws},
            {"fill_rejected", c.sampling.fill_rejected}}}};
}

TrainConfig train_config_from_json(const json& j) {
  TrainConfig c;
  only(j,
       {"model", "data", "steps", "learning_rate", "learning_rate_schedule", "weight_decay",
        "ema_decay", "cfg_drop", "prior_position_std", "seed", "log_every", "checkpoint_every",
        "validate_every", "validation_grasps", "validation_objects", "sampling"},
       "");
  if (j.contains("model")) {
    const json& m = j["model"];
    only(m, {"type", "encoder", "field", "graspnet", "se3dif"}, "model.");
    read(m, "type", c.model.type, "model.");
    if (m.contains("encoder")) {
      const json& e = m["encoder"];
      only(e, {"widths", "k", "out_channels", "points", "slope"}, "model.encoder.");
      read(e, "widths", c.model.encoder.widths, "model.encoder.");
      read(e, "k", c.model.encoder.k, "model.encoder.");
      read(e, "out_channels", c.model.encoder.out_channels, "model.encoder.");
      read(e, "points", c.model.encoder.points, "model.encoder.");
      read(e, "slope", c.model.encoder.slope, "model.encoder.");
    }
    if (m.contains("field")) {
      const json& f = m["field"];
      only(f, {"hidden_widths", "slope", "z_every_layer"}, "model.field.");
      read(f, "hidden_widths", c.model.field.hidden_widths, "model.field.");
      read(f, "slope", c.model.field.slope, "model.field.");
      read(f, "z_every_layer", c.model.field.z_every_layer, "model.field.");
    }
    if (m.contains("graspnet")) {
      const json& g = m["graspnet"];
      GraspNetOptions& o = c.model.graspnet;
      only(g, {"latent_size", "radius", "centroids", "kl_weight", "confidence_weight"},
           "model.graspnet.");
      read(g, "latent_size", o.latent_size, "model.graspnet.");
      read(g, "radius", o.radius, "model.graspnet.");
      read(g, "centroids", o.centroids, "model.graspnet.");
      read(g, "kl_weight", o.kl_weight, "model.graspnet.");
      read(g, "confidence_weight", o.confidence_weight, "model.graspnet.");
    }
    if (m.contains("se3dif")) {
      only(m["se3dif"], {"distance_points"}, "model.se3dif.");
      read(m["se3dif"], "distance_points", c.model.se3dif.distance_points, "model.se3dif.");
    }
  }
  if (j.contains("data")) {
    const json& d = j["data"];
    only(d,
         {"objects_per_step", "grasps_per_object", "position_scale", "augmentation", "stretch",
          "input", "views"},
         "data.");
    read(d, "objects_per_step", c.data.objects_per_step, "data.");
    read(d, "grasps_per_object", c.data.grasps_per_object, "data.");
    read(d, "position_scale", c.data.position_scale, "data.");
    std::string augmentation = data::to_string(c.data.augmentation);
    read(d, "augmentation", augmentation, "data.");
    c.data.augmentation = data::parse_augmentation(augmentation);
    read(d, "stretch", c.data.stretch, "data.");
    std::string input = data::to_string(c.data.input);
    read(d, "input", input, "data.");
    c.data.input = data::parse_cloud_input(input);
    if (d.contains("views")) {
      const json& v = d["views"];
      camera::ViewSampling& views = c.data.views;
      only(v, {"elevation", "distance", "noise"}, "data.views.");
      read_range(v, "elevation", views.min_elevation, views.max_elevation, "data.views.");
      read_range(v, "distance", views.min_distance, views.max_distance, "data.views.");
      read(v, "noise", views.noisy, "data.views.");
    }
  }
  read(j, "steps", c.steps, "");
  read(j, "learning_rate", c.learning_rate, "");
  read(j, "learning_rate_schedule", c.learning_rate_schedule, "");
  read(j, "weight_decay", c.weight_decay, "");
  read(j, "ema_decay", c.ema_decay, "");
  read(j, "cfg_drop", c.cfg_drop, "");
  read(j, "prior_position_std", c.prior_position_std, "");
  read(j, "seed", c.seed, "");
  read(j, "log_every", c.log_every, "");
  read(j, "checkpoint_every", c.checkpoint_every, "");
  read(j, "validate_every", c.validate_every, "");
  read(j, "validation_grasps", c.validation_grasps, "");
  read(j, "validation_objects", c.validation_objects, "");
  if (j.contains("sampling")) {
    const json& s = j["sampling"];
    only(s, {"solver", "steps", "guidance", "clouds", "max_draws", "fill_rejected"}, "sampling.");
    read(s, "solver", c.sampling.solver, "sampling.");
    read(s, "steps", c.sampling.steps, "sampling.");
    read(s, "guidance", c.sampling.guidance, "sampling.");
    read(s, "clouds", c.sampling.clouds, "sampling.");
    read(s, "max_draws", c.sampling.max_draws, "sampling.");
    read(s, "fill_rejected", c.sampling.fill_rejected, "sampling.");
  }
  c.model.field.z_channels = c.model.encoder.out_channels;
  c.data.points = static_cast<std::size_t>(c.model.encoder.points);
  validate(c);
  return c;
}

data::TrainingSamplerOptions sampler_options(const TrainConfig& config) {
  data::TrainingSamplerOptions options = config.data;
  options.distance_points = config.model.type == "se3dif" ? config.model.se3dif.distance_points : 0;
  return options;
}

TrainConfig read_train_config(const std::filesystem::path& path) {
  const json j = read_json_file(path);
  try {
    return train_config_from_json(j);
  } catch (const Error& e) {
    throw Error(path.string() + ": " + e.what());
  }
}

}  // namespace graspecmf::models
