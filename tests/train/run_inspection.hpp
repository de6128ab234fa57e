#pragma once
// What training tests read back from a model or run folder: parameters and logged losses.

#include <torch/torch.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "graspecmf/models/model_folder.hpp"
#include "test_support.hpp"

namespace graspecmf::testing {

// A model's parameters, flattened into one tensor.
inline at::Tensor flat_parameters(const models::Generator& model) {
  std::vector<at::Tensor> flat;
  for (const at::Tensor& p : model->parameters()) flat.push_back(p.flatten());
  return torch::cat(flat);
}

// The model parameters a run loads for sampling and evaluation.
inline at::Tensor run_parameters(const std::filesystem::path& run) {
  return flat_parameters(models::load_trained_model(run).model);
}

// The losses of a run's log, line by line (timings differ between runs).
inline std::vector<double> logged_losses(const std::filesystem::path& run) {
  std::vector<double> out;
  std::istringstream lines(read_file(run / "log.jsonl"));
  std::string line;
  while (std::getline(lines, line)) {
    const auto record = nlohmann::json::parse(line);
    if (record.contains("loss")) out.push_back(record["loss"]);
  }
  return out;
}

}  // namespace graspecmf::testing
