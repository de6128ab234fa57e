#include "graspecmf/sim/trial_config.hpp"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <utility>

#include "graspecmf/core/error.hpp"

namespace graspecmf::sim {
namespace {

// Every parameter once: its JSON name, its member, and whether zero is allowed.
struct Field {
  const char* name;
  double TrialConfig::*member;
  bool zero_allowed;
};
constexpr Field kFields[] = {
    {"timestep", &TrialConfig::timestep, false},
    {"gravity", &TrialConfig::gravity, true},
    {"friction", &TrialConfig::friction, false},
    {"torsional_friction", &TrialConfig::torsional_friction, true},
    {"friction_impedance_ratio", &TrialConfig::friction_impedance_ratio, false},
    {"contact_timeconst", &TrialConfig::contact_timeconst, false},
    {"contact_dmin", &TrialConfig::contact_dmin, false},
    {"contact_dmax", &TrialConfig::contact_dmax, false},
    {"contact_width", &TrialConfig::contact_width, false},
    {"default_density", &TrialConfig::default_density, false},
    {"hand_mass", &TrialConfig::hand_mass, false},
    {"finger_mass", &TrialConfig::finger_mass, false},
    {"finger_force", &TrialConfig::finger_force, false},
    {"finger_gain", &TrialConfig::finger_gain, false},
    {"finger_damping", &TrialConfig::finger_damping, true},
    {"finger_armature", &TrialConfig::finger_armature, true},
    {"close_duration", &TrialConfig::close_duration, false},
    {"settle_duration", &TrialConfig::settle_duration, true},
    {"lift_distance", &TrialConfig::lift_distance, true},
    {"lift_duration", &TrialConfig::lift_duration, false},
    {"shake_linear_amplitude", &TrialConfig::shake_linear_amplitude, true},
    {"shake_angular_amplitude", &TrialConfig::shake_angular_amplitude, true},
    {"shake_frequency", &TrialConfig::shake_frequency, false},
    {"shake_cycles", &TrialConfig::shake_cycles, true},
    {"max_relative_translation", &TrialConfig::max_relative_translation, false},
    {"max_relative_rotation", &TrialConfig::max_relative_rotation, false},
};

}  // namespace

void validate(const TrialConfig& config) {
  for (const Field& field : kFields) {
    const double value = config.*field.member;
    if (!std::isfinite(value) || value < 0.0 || (value == 0.0 && !field.zero_allowed)) {
      throw Error(std::string("trial config: ") + field.name + " must be " +
                  (field.zero_allowed ? "≥ 0" : "> 0") + ", got " + std::to_string(value));
    }
  }
  if (config.timestep > 0.01) throw Error("trial config: timestep must be at most 0.01 s");
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
  return json;
}

TrialConfig trial_config_from_json(const nlohmann::json& json) {
  if (!json.is_object()) throw Error("trial config: expected a JSON object");
  TrialConfig config;
  for (const auto& [key, value] : json.items()) {
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

TrialConfig read_trial_config(const std::string& path) {
  if (path.empty()) return {};
  std::ifstream in(path);
  if (!in) throw Error(path + ": cannot open trial config");
  try {
    return trial_config_from_json(nlohmann::json::parse(in));
  } catch (const nlohmann::json::exception& e) {
    throw Error(path + ": not valid JSON (" + e.what() + ")");
  }
}

}  // namespace graspecmf::sim
