#pragma once
// A batch of grasp poses on tensors, the state of the flow on SO(3) × R³, and a seeded CPU random
// generator for the flow's sampling functions.

#include <ATen/core/Generator.h>
#include <ATen/core/Tensor.h>

#include <cstdint>
#include <string>

namespace graspecmf::flow {

// B poses x = (R, p): R [B,3,3] rotations (columns: gripper axes in the frame of the object),
// p [B,3] positions. Both tensors share one floating dtype (float32 or float64) and device.
struct PoseBatch {
  at::Tensor R;
  at::Tensor p;
};

// Throws Error (naming `where`) unless x.R is [B,3,3] and x.p is [B,3] with the same B, dtype and
// device, and the dtype is float32 or float64.
void check_pose_batch(const PoseBatch& x, const std::string& where);

// Throws Error (naming `where`) unless t is [B] with the dtype and device of x.
void check_times(const at::Tensor& t, const PoseBatch& x, const std::string& where);

// A CPU generator seeded with seed; the same seed gives the same stream of every sampling function.
at::Generator make_generator(std::uint64_t seed);

}  // namespace graspecmf::flow
