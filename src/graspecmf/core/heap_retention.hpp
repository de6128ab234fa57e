#pragma once
// Keeps freed memory in the process's heap for reuse. A training step or an ODE solve allocates
// and frees the same tensors again and again; by default glibc serves large ones with fresh mmap
// pages and returns freed heap tops to the kernel, so every step page-faults its tensors back in
// (docs/model.md, "Speed": 1.4× on a training step, 3× on sampling 1000 grasps).

#include <cstddef>

namespace graspecmf {

// Blocks up to this size come from the heap instead of their own mmap (glibc's 64-bit maximum).
inline constexpr std::size_t kHeapBlockLimit = std::size_t{32} << 20;
// Free memory at the heap's top is returned to the kernel only beyond this size.
inline constexpr std::size_t kRetainedFreeMemory = std::size_t{256} << 20;

// Sets glibc's mmap and trim thresholds to the limits above, unless the environment already sets
// malloc tunables (GLIBC_TUNABLES, MALLOC_MMAP_THRESHOLD_ or MALLOC_TRIM_THRESHOLD_), which then
// win. Returns whether it changed them; a no-op returning false on other C libraries.
bool retain_freed_memory();

}  // namespace graspecmf
