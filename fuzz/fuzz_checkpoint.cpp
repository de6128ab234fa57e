// Fuzzes checkpoint and weights loading (models::load_checkpoint, models::load_weights): the ZIP
// container check, then LibTorch's archive reader and graspecmf's layout and content-hash checks,
// into a small model. The seeds fuzz/corpus/checkpoint/ are that model's weights and checkpoint:
// GRASPECMF_FUZZ_WRITE_SEEDS=DIR build-fuzz/fuzz/fuzz_checkpoint writes them into DIR and exits.
#include <ATen/CPUGeneratorImpl.h>
#include <torch/optim/adam.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "fuzz_input_file.hpp"
#include "graspecmf/models/checkpoint.hpp"
#include "graspecmf/models/generator.hpp"

namespace {

// The model, optimiser and average the seeds were written from.
struct Target {
  Target() {
    graspecmf::models::TrainConfig config;
    config.model.encoder = {{4, 4}, 4, 4, 8};
    config.model.field.z_channels = 4;
    config.model.field.hidden_widths = {4};
    model = graspecmf::models::make_generator(config);
    average = graspecmf::models::make_generator(config);
    optimizer = std::make_unique<torch::optim::Adam>(model->parameters());
  }
  graspecmf::models::Generator model, average;
  std::unique_ptr<torch::optim::Adam> optimizer;
};

Target& target() {
  static Target t;
  return t;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  const char* seeds = std::getenv("GRASPECMF_FUZZ_WRITE_SEEDS");
  if (seeds == nullptr) return 0;
  torch::manual_seed(0);
  Target& t = target();
  torch::Tensor loss = torch::zeros({});  // one step, so that Adam has state to save
  for (const torch::Tensor& p : t.model->parameters()) loss = loss + p.square().sum();
  loss.backward();
  t.optimizer->step();
  const std::filesystem::path dir(seeds);
  graspecmf::models::save_weights(dir / "weights.pt", *t.model, 1);
  graspecmf::models::TrainingState state;
  state.step = 1;
  state.sampler_state = "sampler state";
  state.generator = at::detail::getDefaultCPUGenerator().get_state();
  graspecmf::models::save_checkpoint(dir / "checkpoint.pt", *t.model, *t.optimizer, state,
                                     &*t.average);
  std::cout << "wrote " << (dir / "weights.pt") << " and " << (dir / "checkpoint.pt") << "\n";
  std::exit(0);
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return graspecmf::fuzz::read_input_as_file(data, size, ".pt", [](const auto& path) {
    Target& t = target();
    try {
      graspecmf::models::load_weights(path, *t.model);
    } catch (const graspecmf::Error&) {
      graspecmf::models::TrainingState state;
      graspecmf::models::load_checkpoint(path, *t.model, t.optimizer.get(), &state, &*t.average);
    }
  });
}
