#include "graspecmf/models/checkpoint.hpp"

#include <torch/serialize.h>

#include <algorithm>
#include <sstream>

#include "graspecmf/core/atomic_file.hpp"
#include "graspecmf/core/error.hpp"
#include "graspecmf/core/fnv1a.hpp"
#include "graspecmf/core/input_file.hpp"
#include "graspecmf/core/zip_archive.hpp"

namespace graspecmf::models {
namespace fs = std::filesystem;
namespace {

// Parameters and buffers as (name, shape), to detect a checkpoint of another configuration
// (LibTorch's load replaces a tensor whatever its shape, and ignores names it does not need).
std::vector<std::pair<std::string, std::vector<int64_t>>> layout(const torch::nn::Module& model) {
  std::vector<std::pair<std::string, std::vector<int64_t>>> result;
  for (const auto& item : model.named_parameters())
    result.emplace_back(item.key(), item.value().sizes().vec());
  for (const auto& item : model.named_buffers())
    result.emplace_back(item.key(), item.value().sizes().vec());
  return result;
}

// Reads the module saved under `key`, refusing one saved for another configuration.
void read_module(torch::serialize::InputArchive& archive, const std::string& key,
                 torch::nn::Module& module, const at::Tensor& count, const fs::path& path) {
  torch::serialize::InputArchive module_archive;
  if (!archive.try_read(key, module_archive)) {
    throw Error(path.string() + ": the checkpoint holds no " + key + " weights");
  }
  const auto expected = layout(module);
  module.load(module_archive);
  if (layout(module) != expected ||
      count.item<int64_t>() != static_cast<int64_t>(expected.size())) {
    throw Error(path.string() + ": the checkpoint was made for a different model configuration");
  }
}

// The archive entry holding the content hash of every other entry.
constexpr const char* kHashKey = "content_hash";

// Adds every tensor under archive (path name, type, shape, bytes), in key order, to hash; the top
// level's own content hash entry is left out.
void hash_archive(torch::serialize::InputArchive& archive, const std::string& prefix, Fnv1a& hash) {
  std::vector<std::string> keys = archive.keys();
  std::sort(keys.begin(), keys.end());
  for (const std::string& key : keys) {
    if (prefix.empty() && key == kHashKey) continue;
    const std::string name = prefix + key;
    at::Tensor tensor;
    torch::serialize::InputArchive child;
    if (archive.try_read(key, tensor)) {
      tensor = tensor.cpu().contiguous();
      hash.add(name.c_str(), name.size() + 1);
      hash.add_value(static_cast<int>(tensor.scalar_type()));
      for (const int64_t size : tensor.sizes()) hash.add_value(size);
      hash.add(tensor.data_ptr(), tensor.nbytes());
    } else if (archive.try_read(key, child)) {
      hash_archive(child, name + "/", hash);
    }
  }
}

// The content hash of a serialised archive's tensors.
int64_t content_hash(const std::string& bytes) {
  std::istringstream in(bytes);
  torch::serialize::InputArchive archive;
  archive.load_from(in);
  Fnv1a hash;
  hash_archive(archive, "", hash);
  return static_cast<int64_t>(hash.value());
}

// Writes the archive, with the content hash of its tensors, to path atomically, naming the path in
// any error. The archive is serialised in memory first, so that a disk error meets our checked
// writer, not LibTorch's (which can throw from a destructor and terminate the process).
void save_archive(torch::serialize::OutputArchive& archive, const fs::path& path) {
  std::ostringstream bytes;
  try {
    archive.save_to(bytes);
    archive.write(kHashKey, torch::tensor({content_hash(bytes.str())}, torch::kLong));
    bytes.str("");
    archive.save_to(bytes);
  } catch (const c10::Error& e) {
    throw Error(path.string() + ": cannot serialise " + e.what_without_backtrace());
  }
  write_file_atomically(path, bytes.str());
}

// The archive at path, its tensors on device, after checking its ZIP container (so that LibTorch's
// reader never parses a truncated or damaged file) and its content hash; throws Error if the file
// is missing, unreadable or damaged.
torch::serialize::InputArchive load_archive(const fs::path& path, c10::Device device) {
  const std::string bytes = read_input_file(path);
  check_zip_archive(bytes, path.string());
  torch::serialize::InputArchive archive;
  at::Tensor stored;
  Fnv1a hash;
  try {
    archive.load_from(bytes.data(), bytes.size(), device);
    if (!archive.try_read(kHashKey, stored)) {
      throw Error(path.string() +
                  ": carries no content hash, so damage cannot be detected (written before "
                  "graspecmf hashed its checkpoints); train or export it again");
    }
    hash_archive(archive, "", hash);
  } catch (const c10::Error& e) {
    throw Error(path.string() + ": unreadable or damaged (" + e.what_without_backtrace() + ")");
  }
  if (stored.numel() != 1 || stored.scalar_type() != torch::kLong ||
      stored.item<int64_t>() != static_cast<int64_t>(hash.value())) {
    throw Error(path.string() +
                ": damaged: its tensors do not match the content hash written with them");
  }
  return archive;
}

}  // namespace

void save_checkpoint(const fs::path& path, const torch::nn::Module& model,
                     const torch::optim::Optimizer& optimizer, const TrainingState& state,
                     const torch::nn::Module* average) {
  torch::serialize::OutputArchive archive, model_archive, optimizer_archive;
  model.save(model_archive);
  optimizer.save(optimizer_archive);
  archive.write("model", model_archive);
  if (average != nullptr) {
    torch::serialize::OutputArchive average_archive;
    average->save(average_archive);
    archive.write("average", average_archive);
  }
  archive.write("optimizer", optimizer_archive);
  archive.write("step", torch::tensor({state.step}, torch::kLong));
  archive.write("tensor_count", torch::tensor({static_cast<int64_t>(layout(model).size())}));
  const std::string& s = state.sampler_state;
  archive.write("sampler_state", torch::from_blob(const_cast<char*>(s.data()),
                                                  {static_cast<int64_t>(s.size())}, torch::kUInt8)
                                     .clone());
  archive.write("generator", state.generator);
  save_archive(archive, path);
}

void load_checkpoint(const fs::path& path, torch::nn::Module& model,
                     torch::optim::Optimizer* optimizer, TrainingState* state,
                     torch::nn::Module* average) {
  // Tensors land on the model's device, whichever device saved them.
  torch::serialize::InputArchive archive = load_archive(path, model.parameters().front().device());
  try {
    at::Tensor count;
    archive.read("tensor_count", count);
    read_module(archive, "model", model, count, path);
    if (average != nullptr) read_module(archive, "average", *average, count, path);
    if (optimizer != nullptr) {
      torch::serialize::InputArchive optimizer_archive;
      archive.read("optimizer", optimizer_archive);
      optimizer->load(optimizer_archive);
    }
    if (state != nullptr) {
      at::Tensor step, sampler;
      archive.read("step", step);
      archive.read("sampler_state", sampler);
      archive.read("generator", state->generator);
      state->generator = state->generator.cpu();  // the CPU generator's state
      state->step = step.item<int64_t>();
      sampler = sampler.cpu();
      const auto* bytes = sampler.data_ptr<uint8_t>();
      state->sampler_state.assign(bytes, bytes + sampler.numel());
    }
  } catch (const c10::Error& e) {
    throw Error(path.string() +
                ": checkpoint does not match this model configuration or is "
                "damaged (" +
                e.what_without_backtrace() + ")");
  }
}

void save_weights(const fs::path& path, const torch::nn::Module& model, std::int64_t step) {
  for (const at::Tensor& t : model.parameters()) {
    if (!t.device().is_cpu() || t.scalar_type() != torch::kFloat) {
      throw Error(path.string() + ": weights are written from a float32 model on the CPU");
    }
  }
  torch::serialize::OutputArchive archive, model_archive;
  model.save(model_archive);
  archive.write("weights", model_archive);
  archive.write("step", torch::tensor({step}, torch::kLong));
  archive.write("tensor_count", torch::tensor({static_cast<int64_t>(layout(model).size())}));
  save_archive(archive, path);
}

std::int64_t load_weights(const fs::path& path, torch::nn::Module& model) {
  torch::serialize::InputArchive archive = load_archive(path, model.parameters().front().device());
  try {
    at::Tensor count, step;
    archive.read("tensor_count", count);
    archive.read("step", step);
    read_module(archive, "weights", model, count, path);
    return step.item<int64_t>();
  } catch (const c10::Error& e) {
    throw Error(path.string() + ": not a weights file of this model configuration (" +
                e.what_without_backtrace() + ")");
  }
}

}  // namespace graspecmf::models
