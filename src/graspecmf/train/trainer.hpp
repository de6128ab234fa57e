#pragma once
// `graspecmf train`: flow-matching training of the GraspECMF model on an ACRONYM-style dataset
// folder, in a run folder that holds config.json, checkpoint.pt and log.jsonl
// (models/model_folder.hpp loads and exports the result).
// Interrupted runs (even kill -9) resume from the last checkpoint and continue bit for bit.

#include <c10/core/Device.h>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "graspecmf/models/train_config.hpp"

namespace graspecmf::train {

struct TrainCallbacks {
  std::function<void(std::int64_t step, std::int64_t total)> step;  // after every step
  std::function<void(const nlohmann::json& record)> record;         // each log.jsonl record
  // Before training: each dataset object left out (unreadable, no mesh, too few successes).
  std::function<void(const std::string& name, const std::string& reason)> skipped;
};

struct TrainResult {
  std::int64_t resumed_from = 0;  // the checkpoint's step, 0 for a fresh run
  std::int64_t steps = 0;         // steps completed in total
  double seconds = 0.0;           // wall time of this invocation
};

// Trains on the dataset's train split (splits.json beside grasps/, else a seeded 80/10/10 split),
// validating on its val split. `threads` sets LibTorch's intra-op threads; on the CPU results
// are reproducible for a given thread count. The model trains on `device`; the data sampler and
// the noise stay on the CPU, so they are the same on every device. A non-empty `init` (a model or
// run folder with the same network settings) gives a fresh run its starting weights (fine-tuning;
// recorded in the run's init.json, and a resume may only name the same one). Throws Error for a
// missing or unusable dataset or init model, a run folder made with another configuration or
// init, or an unwritable run folder.
TrainResult train(const models::TrainConfig& config, const std::filesystem::path& data_dir,
                  const std::filesystem::path& run_dir, int threads,
                  const TrainCallbacks& callbacks = {}, c10::Device device = c10::Device(c10::kCPU),
                  const std::filesystem::path& init = {});

}  // namespace graspecmf::train
