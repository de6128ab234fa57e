#pragma once
// Model folders: a released model (config.json and model.pt) or a training run (config.json,
// checkpoint.pt, log.jsonl, init.json): the names of their files, loading either as a model ready
// to sample, and exporting a run as a released model.

#include <c10/core/Device.h>

#include <cstdint>
#include <filesystem>
#include <vector>

#include "graspecmf/models/generator.hpp"
#include "graspecmf/models/train_config.hpp"

namespace graspecmf::models {

inline constexpr const char* kConfigFile = "config.json";
inline constexpr const char* kCheckpointFile = "checkpoint.pt";
inline constexpr const char* kWeightsFile = "model.pt";
inline constexpr const char* kLogFile = "log.jsonl";
inline constexpr const char* kInitFile = "init.json";  // the model a fine-tuning run started from

struct TrainedModel {
  TrainConfig config;
  Generator model;  // in eval mode
  std::int64_t step = 0;
};

// A model folder's configuration and weights, the model moved to `device`: a released model
// (config.json and model.pt, written by export_model) or a training run (config.json and the
// latest checkpoint, its weight average when ema_decay > 0). Throws Error if either file is
// missing, or the weights do not fit the configuration.
TrainedModel load_trained_model(const std::filesystem::path& dir,
                                c10::Device device = c10::Device(c10::kCPU));

// Writes the run's inference model into out_dir (created if needed): config.json and model.pt
// (the weight average when the run keeps one, float32, no optimiser state). Returns its step.
// Throws Error if the run cannot be loaded or out_dir cannot be written.
std::int64_t export_model(const std::filesystem::path& run_dir,
                          const std::filesystem::path& out_dir);

// The files a run or model folder may hold (config, checkpoint, weights, log, init record): the
// paths an output must never take.
std::vector<std::filesystem::path> model_folder_files(const std::filesystem::path& dir);

}  // namespace graspecmf::models
