#include "graspecmf/models/model_folder.hpp"

#include <nlohmann/json.hpp>

#include "graspecmf/core/atomic_file.hpp"
#include "graspecmf/core/error.hpp"
#include "graspecmf/models/checkpoint.hpp"

namespace graspecmf::models {
namespace fs = std::filesystem;

TrainedModel load_trained_model(const fs::path& dir, c10::Device device) {
  const fs::path config_file = dir / kConfigFile;
  if (!fs::exists(config_file)) {
    throw Error(dir.string() + ": not a model or training run (no config.json)");
  }
  TrainedModel trained;
  trained.config = read_train_config(config_file);
  trained.model = make_generator(trained.config);
  GeneratorImpl& module = *trained.model;
  if (fs::exists(dir / kWeightsFile)) {
    trained.step = load_weights(dir / kWeightsFile, module);
  } else {
    TrainingState state;
    // With a weight average, the average overwrites the trained weights just loaded.
    load_checkpoint(dir / kCheckpointFile, module, nullptr, &state,
                    trained.config.ema_decay > 0 ? &module : nullptr);
    trained.step = state.step;
  }
  trained.model->to(device);
  trained.model->eval();
  return trained;
}

std::int64_t export_model(const fs::path& run_dir, const fs::path& out_dir) {
  const TrainedModel trained = load_trained_model(run_dir);
  std::error_code ec;
  fs::create_directories(out_dir, ec);
  if (ec) throw Error(out_dir.string() + ": cannot create the folder (" + ec.message() + ")");
  write_file_atomically(out_dir / kConfigFile, to_json(trained.config).dump(2) + "\n");
  save_weights(out_dir / kWeightsFile, *trained.model, trained.step);
  return trained.step;
}

std::vector<fs::path> model_folder_files(const fs::path& dir) {
  return {dir / kConfigFile, dir / kCheckpointFile, dir / kWeightsFile, dir / kLogFile,
          dir / kInitFile};
}

}  // namespace graspecmf::models
