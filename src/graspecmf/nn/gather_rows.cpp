#include "graspecmf/nn/gather_rows.hpp"

#include <ATen/ATen.h>

#include <cstdint>
#include <vector>

namespace graspecmf::nn {

at::Tensor gather_rows(const at::Tensor& values, const at::Tensor& index) {
  const int64_t b = values.size(0), n = values.size(1);
  const auto offsets = at::arange(b, index.options()).view({b, 1}) * n;
  const auto flat = (index.reshape({b, -1}) + offsets).reshape({-1});
  std::vector<int64_t> shape(index.sizes().begin(), index.sizes().end());
  shape.insert(shape.end(), values.sizes().begin() + 2, values.sizes().end());
  return values.flatten(0, 1).index_select(0, flat).view(shape);
}

}  // namespace graspecmf::nn
