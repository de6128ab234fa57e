#pragma once
// Input checks shared by the nn layer; each failure throws graspecmf::Error with one line that
// names the function, the input and the shape or value it got.

#include <ATen/core/Tensor.h>

#include <cstdint>
#include <initializer_list>
#include <sstream>
#include <string>

#include "graspecmf/core/error.hpp"

namespace graspecmf::nn::detail {

// "[2, 3, 4]" for a tensor of that shape; "*" marks an entry of `expected` that may be anything.
inline std::string shape_string(std::initializer_list<int64_t> sizes) {
  std::ostringstream out;
  out << '[';
  const char* separator = "";
  for (const int64_t size : sizes) {
    out << separator;
    if (size < 0) {
      out << '*';
    } else {
      out << size;
    }
    separator = ", ";
  }
  out << ']';
  return out.str();
}

// Throws unless `tensor` is a defined float32 tensor whose shape matches `expected` (−1 = any).
inline void require_shape(const at::Tensor& tensor, const std::string& what,
                          std::initializer_list<int64_t> expected) {
  bool ok = tensor.defined() && tensor.dim() == static_cast<int64_t>(expected.size());
  int64_t axis = 0;
  for (const int64_t size : expected) {
    if (!ok) break;
    ok = size < 0 || tensor.size(axis) == size;
    ++axis;
  }
  if (ok && tensor.scalar_type() == at::kFloat) return;
  std::ostringstream got;
  if (!tensor.defined()) {
    got << "an undefined tensor";
  } else {
    got << tensor.scalar_type() << ' ' << tensor.sizes();
  }
  throw Error(what + " must be a float32 tensor of shape " + shape_string(expected) + ", got " +
              got.str());
}

// Throws Error(message) unless `condition` holds.
inline void require(bool condition, const std::string& message) {
  if (!condition) throw Error(message);
}

// Throws unless points is a float32 [B, N, 3] batch of clouds with B ≥ 1, N ≥ k and every
// coordinate finite; `what` names the encoder in the message.
void require_clouds(const at::Tensor& points, const std::string& what, int64_t k);

}  // namespace graspecmf::nn::detail
