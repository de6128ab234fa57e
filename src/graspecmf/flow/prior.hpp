#pragma once
// The prior p0 of the flow (METHOD §5): rotations Haar-uniform on SO(3), positions isotropic
// Gaussian. Both are invariant under rotations about the origin.

#include <ATen/core/Generator.h>

#include <cstdint>

#include "graspecmf/flow/pose_batch.hpp"

namespace graspecmf::flow {

// n poses with R Haar-uniform (normalised Gaussian quaternions) and p ~ N(0, position_std² I),
// drawn from generator in float64 and rounded to dtype (float32 or float64). The same generator
// state gives the same sample. Throws Error for n < 0, position_std < 0 or not finite, or another
// dtype.
PoseBatch sample_prior(int64_t n, double position_std, at::Generator& generator,
                       at::ScalarType dtype = at::kFloat);

}  // namespace graspecmf::flow
