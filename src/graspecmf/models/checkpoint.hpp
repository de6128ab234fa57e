#pragma once
// One training checkpoint file: the model's parameters, the optimizer's state and everything else
// a resumed run needs to continue bit for bit (step, data sampler state, flow generator state);
// and inference-only weight files (a released model).

#include <torch/nn/module.h>
#include <torch/optim/optimizer.h>

#include <cstdint>
#include <filesystem>
#include <string>

namespace graspecmf::models {

struct TrainingState {
  std::int64_t step = 0;      // steps completed
  std::string sampler_state;  // data::TrainingSampler::state()
  at::Tensor generator;       // the flow generator's get_state()
};

// Writes the checkpoint atomically (a failure leaves any old file untouched). `average`, when
// given, is the moving average of the weights (a module of model's configuration).
void save_checkpoint(const std::filesystem::path& path, const torch::nn::Module& model,
                     const torch::optim::Optimizer& optimizer, const TrainingState& state,
                     const torch::nn::Module* average = nullptr);
// Loads parameters onto model's device into model (and, when given, the optimizer state, the
// training state and the weight average). Throws Error if the file is missing, unreadable, made for
// a different configuration, or lacks a requested weight average.
void load_checkpoint(const std::filesystem::path& path, torch::nn::Module& model,
                     torch::optim::Optimizer* optimizer = nullptr, TrainingState* state = nullptr,
                     torch::nn::Module* average = nullptr);

// Writes inference-only weights atomically: the module's parameters and buffers (no optimiser or
// sampler state) and the step they were trained for. Throws Error unless the model is float32 on
// the CPU.
void save_weights(const std::filesystem::path& path, const torch::nn::Module& model,
                  std::int64_t step);
// Loads weights written by save_weights into model, on its device; returns their step. Throws Error
// if the file is missing, damaged or made for a different configuration.
std::int64_t load_weights(const std::filesystem::path& path, torch::nn::Module& model);

}  // namespace graspecmf::models
