#include "graspecmf/nn/vector_field.hpp"

#include <string>
#include <utility>

#include "graspecmf/nn/checks.hpp"

namespace graspecmf::nn {

namespace {

constexpr int64_t kPoseVectors = 4;  // r1, r2, r3, p

}  // namespace

VectorFieldImpl::VectorFieldImpl(VectorFieldOptions options) : options_(std::move(options)) {
  detail::require(options_.z_channels >= 1, "VectorField: z_channels must be positive");
  detail::require(!options_.hidden_widths.empty(), "VectorField: hidden_widths must not be empty");
  const int64_t z = options_.z_channels;
  lift = register_module("lift", VNLinear(z + kPoseVectors, 1));
  int64_t in = z + kPoseVectors + 1;
  for (std::size_t l = 0; l < options_.hidden_widths.size(); ++l) {
    const int64_t width = options_.hidden_widths[l];
    detail::require(width >= 1, "VectorField: hidden widths must be positive");
    const int64_t z_inputs = l > 0 && options_.z_every_layer ? z : 0;
    layers.push_back(
        register_module("layer" + std::to_string(l),
                        VNLinearLeakyReLU(in + z_inputs, width, false, options_.slope)));
    in = width;
  }
  out = register_module("out", VNLinear(in, 2));
}

ObjectCondition VectorFieldImpl::condition(const torch::Tensor& z) const {
  const int64_t zc = options_.z_channels;
  detail::require_shape(z, "VectorField::condition: z", {-1, zc, 3});
  const auto& first = *layers.front();
  const auto weights = torch::cat({lift->weight.narrow(1, 0, zc), first.packed_weight(0, zc)});
  const auto z_last = z.transpose(1, 2);
  ObjectCondition condition{torch::linear(z_last, weights), {}};
  if (options_.z_every_layer) {
    for (std::size_t l = 1; l < layers.size(); ++l) {
      const auto& layer = *layers[l];
      const int64_t in = options_.hidden_widths[l - 1];
      condition.layer_terms.push_back(torch::linear(z_last, layer.packed_weight(in, zc)));
    }
  }
  return condition;
}

Velocity VectorFieldImpl::forward(const ObjectCondition& condition,
                                  const torch::Tensor& object_index, const torch::Tensor& rotation,
                                  const torch::Tensor& position, const torch::Tensor& time,
                                  const torch::Tensor& keep) const {
  const int64_t zc = options_.z_channels;
  const int64_t hidden = options_.hidden_widths.front();
  detail::require_shape(condition.z_terms, "VectorField: condition.z_terms",
                        {-1, 3, 1 + 2 * hidden});
  detail::require(condition.layer_terms.size() == (options_.z_every_layer ? layers.size() - 1 : 0),
                  "VectorField: condition.layer_terms does not match z_every_layer");
  detail::require_shape(rotation, "VectorField: rotation", {-1, 3, 3});
  const int64_t g = rotation.size(0);
  detail::require_shape(position, "VectorField: position", {g, 3});
  detail::require_shape(time, "VectorField: time", {g});
  detail::require(keep.defined() && keep.dim() == 1 && keep.size(0) == g &&
                      (keep.scalar_type() == torch::kFloat || keep.scalar_type() == torch::kBool),
                  "VectorField: keep must be a float32 or bool tensor [" + std::to_string(g) + "]");
  detail::require(object_index.defined() && object_index.scalar_type() == torch::kLong &&
                      object_index.dim() == 1 && object_index.size(0) == g,
                  "VectorField: object_index must be an int64 tensor [" + std::to_string(g) + "]");
  const int64_t objects = condition.z_terms.size(0);
  detail::require(g == 0 || (object_index.min().item<int64_t>() >= 0 &&
                             object_index.max().item<int64_t>() < objects),
                  "VectorField: object_index must lie in [0, " + std::to_string(objects) + ")");

  // First layer, channels last [G, 3, ·]: z terms gathered per grasp (zero for the null
  // condition) plus the pose vectors' terms, then the lifted time's.
  const auto& first = *layers.front();
  const auto pose = torch::cat({rotation, position.unsqueeze(2)}, 2);  // [G, 3, 4]: r1 r2 r3 p
  const auto pose_weights =
      torch::cat({lift->weight.narrow(1, zc, kPoseVectors), first.packed_weight(zc, kPoseVectors)});
  const auto keep_z = keep.to(torch::kFloat).view({g, 1, 1});
  const auto terms =
      torch::linear(pose, pose_weights) + keep_z * condition.z_terms.index_select(0, object_index);
  const auto lifted = time.view({g, 1, 1}) * terms.narrow(2, 0, 1);  // t·f_equi, [G, 3, 1]
  const auto both = terms.narrow(2, 1, 2 * hidden) +
                    torch::linear(lifted, first.packed_weight(zc + kPoseVectors, 1));
  auto h = vn_leaky_relu_packed(both, hidden, first.slope);  // channels last, [G, 3, ·]
  for (std::size_t l = 1; l < layers.size(); ++l) {
    // With z_every_layer, z's term (gathered per grasp) joins h's before the activation.
    const auto z_term = options_.z_every_layer
                            ? keep_z * condition.layer_terms[l - 1].index_select(0, object_index)
                            : torch::Tensor();
    h = layers[l]->forward_channels_last(h, z_term);
  }
  const auto velocity = out->forward(h.transpose(1, 2));  // [G, 2, 3]
  return {velocity.select(1, 0), velocity.select(1, 1)};
}

}  // namespace graspecmf::nn
