#include "graspecmf/flow/pose_batch.hpp"

#include <ATen/CPUGeneratorImpl.h>

#include "graspecmf/core/error.hpp"

namespace graspecmf::flow {

void check_pose_batch(const PoseBatch& x, const std::string& where) {
  if (!x.R.defined() || !x.p.defined()) throw Error(where + ": undefined pose tensor");
  if (x.R.dim() != 3 || x.R.size(1) != 3 || x.R.size(2) != 3) {
    throw Error(where + ": rotations must have shape [B,3,3]");
  }
  if (x.p.dim() != 2 || x.p.size(1) != 3) throw Error(where + ": positions must have shape [B,3]");
  if (x.R.size(0) != x.p.size(0)) throw Error(where + ": rotations and positions differ in B");
  const auto dtype = x.R.scalar_type();
  if (dtype != at::kFloat && dtype != at::kDouble) {
    throw Error(where + ": poses must be float32 or float64");
  }
  if (x.p.scalar_type() != dtype || x.p.device() != x.R.device()) {
    throw Error(where + ": rotations and positions differ in dtype or device");
  }
}

void check_times(const at::Tensor& t, const PoseBatch& x, const std::string& where) {
  if (!t.defined() || t.dim() != 1 || t.size(0) != x.R.size(0)) {
    throw Error(where + ": times must have shape [B] with the batch size of the poses");
  }
  if (t.scalar_type() != x.R.scalar_type() || t.device() != x.R.device()) {
    throw Error(where + ": times must have the dtype and device of the poses");
  }
}

at::Generator make_generator(std::uint64_t seed) {
  return at::make_generator<at::CPUGeneratorImpl>(seed);
}

}  // namespace graspecmf::flow
