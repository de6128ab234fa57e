#pragma once
// The compute device of train, sample and evaluate (`--device`): the CPU, or a CUDA GPU where
// this LibTorch build and the machine have one.

#include <c10/core/Device.h>

#include <string>

namespace graspecmf::models {

// "cpu", "cuda" or "cuda:N" as a device. Throws Error for another name, or for a CUDA device
// when LibTorch sees no CUDA GPU (Debian's LibTorch is CPU-only) or has fewer than N + 1.
c10::Device parse_device(const std::string& name);

}  // namespace graspecmf::models
