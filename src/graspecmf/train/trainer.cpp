#include "graspecmf/train/trainer.hpp"

#include <torch/torch.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "graspecmf/core/atomic_file.hpp"
#include "graspecmf/core/error.hpp"
#include "graspecmf/core/output_lock.hpp"
#include "graspecmf/data/splits.hpp"
#include "graspecmf/data/training_sampler.hpp"
#include "graspecmf/eval/evaluation.hpp"
#include "graspecmf/flow/pose_batch.hpp"
#include "graspecmf/models/checkpoint.hpp"
#include "graspecmf/models/generator.hpp"
#include "graspecmf/models/model_folder.hpp"

namespace graspecmf::train {
namespace fs = std::filesystem;
using models::kCheckpointFile;
using models::kConfigFile;
using models::kInitFile;
using models::kLogFile;
using models::TrainConfig;
using models::TrainedModel;
using nlohmann::json;
namespace {

constexpr std::uint64_t kValidationSeed = 12345;

// Sets every parameter group's Adam learning rate.
void set_learning_rate(torch::optim::Adam& optimizer, double rate) {
  for (auto& group : optimizer.param_groups()) {
    static_cast<torch::optim::AdamOptions&>(group.options()).lr(rate);
  }
}

// The dataset's splits: splits.json beside grasps/ when present, else a seeded 80/10/10 split.
data::DatasetSplit dataset_split(const data::AcronymDataset& dataset, const fs::path& data_dir,
                                 std::uint64_t seed) {
  const fs::path file = data_dir / data::kSplitFileName;
  if (fs::exists(file)) return data::read_split_file(file);
  return data::random_split(dataset.names(), {0.1, 0.1}, seed);
}

// The split's objects that the dataset could use (the loader skips objects with fewer than 100
// successful grasps, missing meshes or unreadable files), at most `limit` of them.
std::vector<data::GraspObject> load_objects(const data::AcronymDataset& dataset,
                                            const std::vector<std::string>& names,
                                            std::size_t limit) {
  const std::vector<std::string> usable = dataset.names();
  std::vector<std::string> kept;
  for (const std::string& name : names) {
    if (std::find(usable.begin(), usable.end(), name) != usable.end()) kept.push_back(name);
  }
  if (kept.size() > limit) kept.resize(limit);
  return data::AcronymDataset::load(dataset.select(kept));
}

// One step's samples as tensors on device.
models::TrainingBatch to_tensors(const std::vector<data::ObjectSample>& samples,
                                 c10::Device device) {
  const auto copy = [](const std::vector<float>& values, std::vector<int64_t> shape) {
    return torch::from_blob(const_cast<float*>(values.data()), shape, torch::kFloat).clone();
  };
  std::vector<at::Tensor> points, rotations, positions, index, queries, distances;
  for (std::size_t o = 0; o < samples.size(); ++o) {
    const data::ObjectSample& s = samples[o];
    const auto n = static_cast<int64_t>(s.points.size() / 3);
    const auto g = static_cast<int64_t>(s.positions.size() / 3);
    points.push_back(copy(s.points, {n, 3}));
    rotations.push_back(copy(s.rotations, {g, 3, 3}));
    positions.push_back(copy(s.positions, {g, 3}));
    index.push_back(torch::full({g}, static_cast<int64_t>(o), torch::kLong));
    if (!s.distances.empty()) {  // the sampler drew distance targets
      const auto k = static_cast<int64_t>(s.distances.size());
      queries.push_back(copy(s.distance_points, {k, 3}));
      distances.push_back(copy(s.distances, {k}));
    }
  }
  models::TrainingBatch batch;
  batch.points = torch::stack(points).to(device);
  batch.object_index = torch::cat(index).to(device);
  batch.grasps = {torch::cat(rotations).to(device), torch::cat(positions).to(device)};
  if (!distances.empty()) {
    batch.distance_points = torch::stack(queries).to(device);
    batch.distances = torch::stack(distances).to(device);
  }
  return batch;
}

// Validation: the loss on a fixed batch of the validation objects and their mean EMD.
json validation_record(const models::Generator& model,
                       const std::vector<data::GraspObject>& objects, const TrainConfig& config,
                       std::int64_t step) {
  json record = {{"step", step}};
  if (objects.empty()) return record;
  model->eval();
  {
    torch::NoGradGuard no_grad;
    data::TrainingSamplerOptions options = models::sampler_options(config);
    options.objects_per_step = objects.size();
    data::TrainingSampler sampler(objects, options, kValidationSeed);
    at::Generator generator = flow::make_generator(kValidationSeed);
    const models::TrainingBatch batch = to_tensors(sampler.next_step(), model->device());
    record["val_loss"] = model->loss(batch, generator).item<double>();
  }
  double total = 0;
  for (const data::GraspObject& object : objects) {
    total += eval::evaluate_object(*model, object, config, {eval::test_rotations()[0]},
                                   config.validation_grasps, config.sampling, kValidationSeed)
                 .mean_emd;
  }
  record["val_emd"] = total / static_cast<double>(objects.size());
  model->train();
  return record;
}

// average ← keep·average + (1 − keep)·model, parameter by parameter (keep = 0 copies).
void blend_weights(const torch::nn::Module& average, const torch::nn::Module& model, double keep) {
  torch::NoGradGuard no_grad;
  const auto target = average.parameters();
  const auto source = model.parameters();
  for (std::size_t i = 0; i < target.size(); ++i) target[i].mul_(keep).add_(source[i], 1 - keep);
}

void append_line(const fs::path& path, const json& record) {
  append_file_text(path, record.dump() + "\n");
}

// Drops log records past the checkpoint's step, 0 without one (written by a run killed after its
// last checkpoint, or before its first).
void truncate_log(const fs::path& path, std::int64_t step) {
  if (!fs::exists(path)) return;
  std::ifstream in(path);
  std::string line, kept;
  while (std::getline(in, line)) {
    const json record = json::parse(line, nullptr, false);
    if (record.is_object() && record.value("step", std::int64_t{0}) <= step) kept += line + "\n";
  }
  write_file_atomically(path, kept);
}

// Creates and locks the run folder, or checks that it holds this configuration and removes the
// temporary files of a killed run; the run folder stays locked while the result lives.
[[nodiscard]] OutputLock prepare_run(const fs::path& run_dir, const TrainConfig& config) {
  std::error_code ec;
  fs::create_directories(run_dir, ec);
  if (ec) throw Error(run_dir.string() + ": cannot create the run folder (" + ec.message() + ")");
  OutputLock lock = OutputLock::folder(run_dir);
  remove_temporary_files(run_dir);
  const fs::path file = run_dir / kConfigFile;
  if (fs::exists(file)) {
    if (models::to_json(models::read_train_config(file)) != models::to_json(config)) {
      throw Error(run_dir.string() +
                  " holds a run with another configuration; choose another --out or remove it");
    }
    return lock;
  }
  write_file_atomically(file, models::to_json(config).dump(2) + "\n");
  return lock;
}

// The run's recorded init model (init.json), empty if it has none.
std::string recorded_init(const fs::path& run_dir) {
  const fs::path file = run_dir / kInitFile;
  if (!fs::exists(file)) return {};
  std::ifstream in(file);
  const json record = json::parse(in, nullptr, false);
  if (!record.is_object() || !record.contains("model") || !record["model"].is_string()) {
    throw Error(file.string() + ": damaged init record (remove the run folder and start again)");
  }
  return record["model"].get<std::string>();
}

// Checks `init` against the run folder's record: a resume may omit it, any other given init must
// be the recorded one, and a fresh start must name the recorded one if there is one. Returns
// init's absolute form (empty if not given).
std::string checked_init(const fs::path& run_dir, const fs::path& init, bool resuming) {
  const std::string given = init.empty() ? "" : fs::absolute(init).lexically_normal().string();
  const std::string recorded = recorded_init(run_dir);
  if (given == recorded || (resuming ? given.empty() : recorded.empty())) return given;
  if (recorded.empty()) {
    throw Error(run_dir.string() + " holds a run that did not start from a model; remove --init " +
                "or choose another --out");
  }
  throw Error(run_dir.string() + " holds a run that started from " + recorded +
              "; pass --init with that model or choose another --out");
}

// The init model on `device`, after checking that its network settings are the config's.
TrainedModel load_init_model(const fs::path& init, const TrainConfig& config, c10::Device device) {
  TrainedModel source = models::load_trained_model(init, device);
  if (models::to_json(source.config)["model"] != models::to_json(config)["model"]) {
    throw Error(init.string() +
                ": its network settings (\"model\") differ from the config's; --init needs the "
                "same network");
  }
  return source;
}

// Copies the init model's weights into model (and the weight average) and records the init
// (init_text, its absolute path) in the run folder.
void start_from(const TrainedModel& source, const std::string& init_text, const fs::path& run_dir,
                const models::Generator& model, const models::Generator& average) {
  blend_weights(*model, *source.model, 0.0);
  if (average) blend_weights(*average, *model, 0.0);
  write_file_atomically(run_dir / kInitFile,
                        json{{"model", init_text}, {"step", source.step}}.dump(2) + "\n");
}

}  // namespace

TrainResult train(const TrainConfig& config, const fs::path& data_dir, const fs::path& run_dir,
                  int threads, const TrainCallbacks& callbacks, c10::Device device,
                  const fs::path& init) {
  models::validate(config);
  if (threads < 1) throw Error("train: threads must be ≥ 1");
  at::set_num_threads(threads);
  // A bad init model is refused before the dataset loads and the run folder is made.
  std::optional<TrainedModel> source;
  if (!init.empty()) source = load_init_model(init, config, device);
  if (!fs::is_directory(data_dir)) throw Error(data_dir.string() + ": no such dataset folder");
  const data::AcronymDataset dataset = data::AcronymDataset::open(data_dir);
  if (callbacks.skipped) {
    for (const data::SkippedObject& s : dataset.skipped()) callbacks.skipped(s.name, s.reason);
  }
  const data::DatasetSplit split = dataset_split(dataset, data_dir, config.seed);
  torch::manual_seed(config.seed);
  const models::Generator model = models::make_generator(config);
  model->to(device);
  models::Generator average;  // the weight average, when ema_decay > 0
  if (config.ema_decay > 0) {
    average = models::make_generator(config);
    average->to(device);
    blend_weights(*average, *model, 0.0);
  }
  torch::optim::Adam optimizer(
      model->parameters(),
      torch::optim::AdamOptions(config.learning_rate).weight_decay(config.weight_decay));
  std::vector<data::GraspObject> training = load_objects(dataset, split.train, split.train.size());
  if (training.empty()) throw Error(data_dir.string() + ": no usable object in the train split");
  data::TrainingSampler sampler(std::move(training), models::sampler_options(config), config.seed);
  const std::vector<data::GraspObject> validation =
      load_objects(dataset, split.val, config.validation_objects);
  const OutputLock lock = prepare_run(run_dir, config);
  at::Generator generator = flow::make_generator(config.seed + 1);

  TrainResult result;
  const fs::path checkpoint = run_dir / kCheckpointFile;
  const bool resuming = fs::exists(checkpoint);
  const std::string init_text = checked_init(run_dir, init, resuming);
  if (resuming) {
    models::TrainingState state;
    models::load_checkpoint(checkpoint, *model, &optimizer, &state, average.get());
    sampler.restore(state.sampler_state);
    generator.set_state(state.generator);
    result.resumed_from = state.step;
  } else if (source) {
    start_from(*source, init_text, run_dir, model, average);
  }
  truncate_log(run_dir / kLogFile, result.resumed_from);
  const auto save = [&](std::int64_t step) {
    models::save_checkpoint(checkpoint, *model, optimizer,
                            {step, sampler.state(), generator.get_state()}, average.get());
  };

  model->train();
  const auto start = std::chrono::steady_clock::now();
  auto interval_start = start;
  double interval_loss = 0;
  std::int64_t interval_steps = 0;
  for (std::int64_t step = result.resumed_from + 1; step <= config.steps; ++step) {
    const at::Tensor loss = model->loss(to_tensors(sampler.next_step(), device), generator);
    optimizer.zero_grad();
    loss.backward();
    set_learning_rate(optimizer, models::learning_rate_at(config, step));
    optimizer.step();
    if (average) {
      const auto s = static_cast<double>(step);
      blend_weights(*average, *model, std::min(config.ema_decay, (1 + s) / (10 + s)));
    }
    interval_loss += loss.item<double>();
    ++interval_steps;
    if (step % config.log_every == 0 || step == config.steps) {
      const auto now = std::chrono::steady_clock::now();
      const json record = {
          {"step", step},
          {"loss", interval_loss / static_cast<double>(interval_steps)},
          {"learning_rate", models::learning_rate_at(config, step)},
          {"seconds_per_step",
           std::chrono::duration<double>(now - interval_start).count() / interval_steps},
          {"threads", threads},
          {"device", device.str()}};
      append_line(run_dir / kLogFile, record);
      if (callbacks.record) callbacks.record(record);
      interval_start = now;
      interval_loss = 0;
      interval_steps = 0;
    }
    if ((config.validate_every > 0 && step % config.validate_every == 0) || step == config.steps) {
      const json record = validation_record(average ? average : model, validation, config, step);
      append_line(run_dir / kLogFile, record);
      if (callbacks.record) callbacks.record(record);
    }
    if (step % config.checkpoint_every == 0 || step == config.steps) save(step);
    if (callbacks.step) callbacks.step(step, config.steps);
  }
  result.steps = config.steps;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace graspecmf::train
