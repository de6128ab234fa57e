#pragma once
// Every setting of a training run (docs/config.md lists every key), read from and written to JSON;
// the run folder keeps a copy, and a resumed run must use the same one.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <string>

#include "graspecmf/data/training_sampler.hpp"
#include "graspecmf/nn/grasp_flow_model.hpp"

namespace graspecmf::models {

// How grasps are drawn from a trained model (also the validation EMD's settings).
struct SamplingSettings {
  std::string solver = "rkmk4";  // euler, heun or rkmk4
  int steps = 20;
  double guidance = 2.0;       // classifier-free guidance weight w
  int clouds = 1;              // clouds of the object encoded and their z averaged (1 in the paper)
  std::size_t max_draws = 0;   // with a grasp filter, the most grasps drawn per call; 0: no limit
  bool fill_rejected = false;  // make up a filter's shortfall with rejected grasps, not an Error
};

// The settings of 6-DOF GraspNet's generators (model.type graspnet_vae and graspnet_gan).
struct GraspNetOptions {
  std::int64_t latent_size = 2;
  double radius = 0.02;          // the first ball query's radius, metres (× position_scale inside)
  std::int64_t centroids = 128;  // the first set abstraction's centroids (≤ encoder.points)
  double kl_weight = 0.01;       // β of the VAE loss
  double confidence_weight = 1.0;  // w_c of both losses
};

// The settings of SE(3)-DiffusionFields (model.type se3dif).
struct Se3DifOptions {
  // Queries near each object's surface per step for the auxiliary distance-field loss; 0 leaves
  // that loss out.
  std::size_t distance_points = 1000;
};

// Which generator to build and its network settings (docs/config.md, `model`).
struct ModelConfig {
  std::string type = "graspecmf";  // the generator (make_generator)
  nn::EncoderOptions encoder;      // its points also set the cloud size of every model
  nn::VectorFieldOptions field;    // field.z_channels follows encoder.out_channels
  GraspNetOptions graspnet;
  Se3DifOptions se3dif;
};

struct TrainConfig {
  ModelConfig model;
  data::TrainingSamplerOptions data;  // points follows model.encoder.points
  std::int64_t steps = 100000;
  double learning_rate = 1e-4;  // Adam
  // "constant", or "cosine": the rate falls from learning_rate at step 1 along half a cosine
  // period, to ≈ learning_rate · 2.5 / steps² at the last step (0 one step later).
  std::string learning_rate_schedule = "constant";
  double weight_decay = 1e-6;
  // Exponential moving average of the weights, updated after every step with decay
  // min(ema_decay, (1 + step) / (10 + step)); 0 turns it off. Validation, sample and evaluate
  // use the average when it is on.
  double ema_decay = 0.0;
  double cfg_drop = 0.2;            // probability of the null condition per grasp
  double prior_position_std = 1.0;  // in network units (× 1 / position_scale metres)
  std::uint64_t seed = 0;
  std::int64_t log_every = 10;
  std::int64_t checkpoint_every = 500;
  std::int64_t validate_every = 1000;   // 0: never
  std::size_t validation_grasps = 100;  // generated and reference grasps per object for EMD
  std::size_t validation_objects = 10;  // at most this many validation objects
  SamplingSettings sampling;
};

// The training sampler's options of a run: config.data, with the distance-field queries the model
// type needs (model.se3dif.distance_points for se3dif, none otherwise).
data::TrainingSamplerOptions sampler_options(const TrainConfig& config);

// The Adam learning rate of step 1 ≤ step ≤ config.steps under the config's schedule.
double learning_rate_at(const TrainConfig& config, std::int64_t step);

// Throws Error naming the first setting out of range.
void validate(const TrainConfig& config);
// Throws Error unless the solver is known, steps and clouds are in range and guidance is finite.
void validate(const SamplingSettings& settings);
nlohmann::json to_json(const TrainConfig& config);
// Missing keys keep their defaults; an unknown key or a wrong type is an Error.
TrainConfig train_config_from_json(const nlohmann::json& json);
// Reads a JSON config file; throws Error naming the file.
TrainConfig read_train_config(const std::filesystem::path& path);

}  // namespace graspecmf::models
