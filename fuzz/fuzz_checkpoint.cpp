// Fuzzes checkpoint and weights loading (train::load_checkpoint, train::load_weights): the ZIP
// container check, then LibTorch's archive reader and graspecmf's layout and content-hash checks,
// into a small model. The seeds fuzz/corpus/checkpoint/ are that model's weights and checkpoint:
// GRASPECMF_FUZZ_WRITE_SEEDS=DIR build-fuzz/fuzz/fuzz_checkpoint writes them into DIR and exits.
#include <ATen/CPUGeneratorImpl.h>
#include <torch/optim/adam.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "fuzz_input_file.hpp"
#include "graspecmf/nn/grasp_flow_model.hpp"
#include "graspecmf/train/checkpoint.hpp"

namespace {

// The model, optimiser and average the seeds were written from.
struct Target {
  Target() {
    graspecmf::nn::GraspFlowModelOptions options;
    options.encoder = {{4, 4}, 4, 4, 8};
    options.field.z_channels = 4;
    options.field.hidden_widths = {4};
    model = graspecmf::nn::GraspFlowModel(options);
    average = graspecmf::nn::GraspFlowModel(options);
    optimizer = std::make_unique<torch::optim::Adam>(model->parameters());
  }
  graspecmf::nn::GraspFlowModel model{nullptr}, average{nullptr};
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
  graspecmf::train::save_weights(dir / "weights.pt", *t.model, 1);
  graspecmf::train::TrainingState state;
  state.step = 1;
  state.sampler_state = "sampler state";
  state.generator = at::detail::getDefaultCPUGenerator().get_state();
  graspecmf::train::save_checkpoint(dir / "checkpoint.pt", *t.model, *t.optimizer, state,
                                    &*t.average);
  std::cout << "wrote " << (dir / "weights.pt") << " and " << (dir / "checkpoint.pt") << "\n";
  std::exit(0);
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return graspecmf::fuzz::read_input_as_file(data, size, ".pt", [](const auto& path) {
    Target& t = target();
    try {
      graspecmf::train::load_weights(path, *t.model);
    } catch (const graspecmf::Error&) {
      graspecmf::train::TrainingState state;
      graspecmf::train::load_checkpoint(path, *t.model, t.optimizer.get(), &state, &*t.average);
    }
  });
}
