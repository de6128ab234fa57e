#include "graspecmf/sim/trial_config.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <nlohmann/json.hpp>
#include <utility>

#include "graspecmf/core/error.hpp"
#include "graspecmf/core/json_file.hpp"

namespace graspecmf::sim {
namespace {

// The values a parameter may take.
enum class Range { kPositive, kNonNegative, kAny };

// Every parameter once: its JSON name, its member, and its range (all must be finite).
struct Field {
  const char* name;
  double TrialConfig::*member;
  Range range;
};
constexpr Field kFields[] = {
    {"timestep", &TrialConfig::timestep, Range::kPositive},
    {"gravity", &TrialConfig::gravity, Range::kNonNegative},
    {"friction", &TrialConfig::friction, Range::kPositive},
    {"torsional_friction", &TrialConfig::torsional_friction, Range::kNonNegative},
    {"friction_impedance_ratio", &TrialConfig::friction_impedance_ratio, Range::kPositive},
    {"contact_timeconst", &TrialConfig::contact_timeconst, Range::kPositive},
    {"contact_reference_mass", &TrialConfig::contact_reference_mass, Range::kNonNegative},
    {"contact_dmin", &TrialConfig::contact_dmin, Range::kPositive},
    {"contact_dmax", &TrialConfig::contact_dmax, Range::kPositive},
    {"contact_width", &TrialConfig::contact_width, Range::kPositive},
    {"pad_normal_inset", &TrialConfig::pad_normal_inset, Range::kAny},
    {"default_density", &TrialConfig::default_density, Range::kPositive},
    {"hand_mass", &TrialConfig::hand_mass, Range::kPositive},
    {"finger_mass", &TrialConfig::finger_mass, Range::kPositive},
    {"finger_force", &TrialConfig::finger_force, Range::kPositive},
    {"finger_gain", &TrialConfig::finger_gain, Range::kPositive},
    {"finger_damping", &TrialConfig::finger_damping, Range::kNonNegative},
    {"finger_armature", &TrialConfig::finger_armature, Range::kNonNegative},
    {"close_duration", &TrialConfig::close_duration, Range::kPositive},
    {"settle_duration", &TrialConfig::settle_duration, Range::kNonNegative},
    {"lift_distance", &TrialConfig::lift_distance, Range::kNonNegative},
    {"lift_duration", &TrialConfig::lift_duration, Range::kPositive},
    {"shake_linear_amplitude", &TrialConfig::shake_linear_amplitude, Range::kNonNegative},
    {"shake_angular_amplitude", &TrialConfig::shake_angular_amplitude, Range::kNonNegative},
    {"shake_frequency", &TrialConfig::shake_frequency, Range::kPositive},
    {"shake_cycles", &TrialConfig::shake_cycles, Range::kNonNegative},
    {"max_relative_translation", &TrialConfig::max_relative_translation, Range::kPositive},
    {"max_relative_rotation", &TrialConfig::max_relative_rotation, Range::kPositive},
};

// The switches: JSON name and member (JSON true / false).
struct Switch {
  const char* name;
  bool TrialConfig::*member;
};
constexpr Switch kSwitches[] = {{"mujoco_convex", &TrialConfig::mujoco_convex},
                                {"legacy_object_frame", &TrialConfig::legacy_object_frame}};

// Steps one trial may take (the defaults take 1200): a bound on the time a config can cost.
constexpr double kMaxTrialSteps = 1e6;

}  // namespace

void validate(const TrialConfig& config) {
  for (const Field& field : kFields) {
    const double value = config.*field.member;
    const bool ok = field.range == Range::kAny           ? std::isfinite(value)
                    : field.range == Range::kNonNegative ? std::isfinite(value) && value >= 0.0
                                                         : std::isfinite(value) && value > 0.0;
    if (!ok) {
      throw Error(std::string("trial config: ") + field.name + " must be " +
                  (field.range == Range::kAny           ? "finite"
                   : field.range == Range::kNonNegative ? "≥ 0"
                                                        : "> 0") +
                  ", got " + std::to_string(value));
    }
  }
  if (config.timestep > 0.01) throw Error("trial config: timestep must be at most 0.01 s");
  const double duration = config.close_duration + config.settle_duration + config.lift_duration +
                          config.shake_cycles / config.shake_frequency;
  if (duration / config.timestep > kMaxTrialSteps) {
    throw Error("trial config: a trial would take " + std::to_string(duration / config.timestep) +
                " steps (phase durations / timestep); at most 1000000 are allowed");
  }
  if (config.contact_timeconst < 2.0 * config.timestep) {
    throw Error("trial config: contact_timeconst must be at least 2 × timestep");
  }
  if (!(config.contact_dmin <= config.contact_dmax && config.contact_dmax < 1.0)) {
    throw Error("trial config: need 0 < contact_dmin ≤ contact_dmax < 1");
  }
}

nlohmann::json to_json(const TrialConfig& config) {
  nlohmann::json json = nlohmann::json::object();
  for (const Field& field : kFields) json[field.name] = config.*field.member;
  for (const Switch& s : kSwitches) json[s.name] = config.*s.member;
  return json;
}

TrialConfig trial_config_from_json(const nlohmann::json& json) {
  if (!json.is_object()) throw Error("trial config: expected a JSON object");
  TrialConfig config;
  for (const auto& [key, value] : json.items()) {
    const auto* on_off = std::find_if(std::begin(kSwitches), std::end(kSwitches),
                                      [&name = key](const Switch& s) { return name == s.name; });
    if (on_off != std::end(kSwitches)) {
      if (!value.is_boolean()) throw Error("trial config: '" + key + "' must be true or false");
      config.*(on_off->member) = value.get<bool>();
      continue;
    }
    const Field* match = nullptr;
    for (const Field& field : kFields) {
      if (key == field.name) match = &field;
    }
    if (match == nullptr) throw Error("trial config: unknown parameter '" + key + "'");
    if (!value.is_number()) throw Error("trial config: '" + key + "' must be a number");
    config.*(match->member) = value.get<double>();
  }
  validate(config);
  return config;
}

nlohmann::json read_trial_config_json(const std::string& path) {
  if (path.empty()) return nlohmann::json::object();
  const nlohmann::json json = read_json_file(path);
  if (!json.is_object()) throw Error(path + ": a trial config must be a JSON object");
  return json;
}

TrialConfig read_trial_config(const std::string& path) {
  return trial_config_from_json(read_trial_config_json(path));
}

}  // namespace graspecmf::sim
