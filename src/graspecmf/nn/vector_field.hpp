#pragma once
// The conditional vector field v_t(z, x) on SO(3) × R³ with the equivariant lifting layer
// (docs/method.md, "The vector field"). Inputs per grasp: its object's z (Z vectors), the pose (R's
// columns r1, r2, r3 and p) and the time t, lifted to the vector t·f_equi([z, r1, r2, r3, p]). The
// input list [z, r1, r2, r3, p, t·f_equi] (Z + 5 vectors) runs through a VN-MLP to (ω, v). With
// z_every_layer (not in the paper) every later hidden layer takes [h, z] too.

#include <torch/nn/module.h>
#include <torch/nn/pimpl.h>

#include <cstdint>
#include <vector>

#include "graspecmf/nn/vn_layers.hpp"

namespace graspecmf::nn {

struct VectorFieldOptions {
  int64_t z_channels = 341;  // vectors in z (the encoder's output)
  std::vector<int64_t> hidden_widths{256, 256, 128, 128, 128};  // VN-Linear+LeakyReLU layers
  double slope = kDefaultSlope;                                 // VN-LeakyReLU negative slope
  bool z_every_layer = false;  // z is also an input of hidden layers 2, 3, … (paper: first only)
};

// The parts of the layers that depend on z, computed once per object.
struct ObjectCondition {
  torch::Tensor z_terms;  // [O, 3, 1 + 2·hidden_widths[0]], channels last: f_equi, W_f, W_d
  // With z_every_layer, hidden layer l ≥ 1's [O, 3, 2·hidden_widths[l]] (W_f, W_d) at l − 1.
  std::vector<torch::Tensor> layer_terms;
};

// Velocities per grasp, both [G, 3] and in the same (scaled) units as the inputs.
struct Velocity {
  torch::Tensor omega;  // spatial angular velocity: Ṙ = [ω]× R
  torch::Tensor v;      // ṗ
};

class VectorFieldImpl : public torch::nn::Module {
 public:
  // Throws Error on an empty width list or a non-positive width or z_channels.
  explicit VectorFieldImpl(VectorFieldOptions options = {});

  // z [O, Z, 3] → the z terms of O objects. Throws Error on a wrong shape.
  ObjectCondition condition(const torch::Tensor& z) const;

  // The field for G grasps: grasp g belongs to object object_index[g] (int64 [G], into the
  // condition's O objects); rotation [G, 3, 3], position [G, 3], time [G]; keep [G] (float or
  // bool) is 1 for the conditional field and 0 for the null condition of classifier-free guidance
  // (z replaced by zeros). All float32. Throws Error on a wrong shape or an index out of range.
  Velocity forward(const ObjectCondition& condition, const torch::Tensor& object_index,
                   const torch::Tensor& rotation, const torch::Tensor& position,
                   const torch::Tensor& time, const torch::Tensor& keep) const;

  const VectorFieldOptions& options() const { return options_; }

  // Input channels: z at [0, Z), r1, r2, r3, p at [Z, Z + 4) and t·f_equi at Z + 4.
  VNLinear lift{nullptr};  // f_equi: the first Z + 4 inputs → 1 vector
  // The VN-MLP; layers[0] takes the Z + 5 inputs, a later one the previous layer's output and,
  // with z_every_layer, z after it.
  std::vector<VNLinearLeakyReLU> layers;
  VNLinear out{nullptr};  // → 2 vectors: ω, v

 private:
  VectorFieldOptions options_;
};
TORCH_MODULE(VectorField);

}  // namespace graspecmf::nn
