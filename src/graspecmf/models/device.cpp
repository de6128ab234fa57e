#include "graspecmf/models/device.hpp"

#include <torch/cuda.h>

#include "graspecmf/core/error.hpp"

namespace graspecmf::models {

c10::Device parse_device(const std::string& name) {
  const Error unknown("unknown device '" + name + "' (expected cpu, cuda or cuda:N)");
  const bool cuda = name == "cuda" || name.rfind("cuda:", 0) == 0;
  if (name != "cpu" && !cuda) throw unknown;
  if (!cuda) return c10::Device(c10::kCPU);
  if (!torch::cuda::is_available()) {
    throw Error("device '" + name +
                "': LibTorch sees no CUDA GPU here (Debian's LibTorch is "
                "CPU-only; build against a CUDA LibTorch on a GPU machine)");
  }
  try {
    const c10::Device device(name);
    if (device.has_index() && device.index() >= static_cast<int>(torch::cuda::device_count())) {
      throw Error("device '" + name + "': only " + std::to_string(torch::cuda::device_count()) +
                  " CUDA GPU(s) are visible");
    }
    return device;
  } catch (const c10::Error&) {
    throw unknown;
  }
}

}  // namespace graspecmf::models
